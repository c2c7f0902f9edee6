// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/assembly/assembly_params.hpp"

#include "blockdyn/base/number_text.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "blockdyn/model/assembly/contact_point.hpp"
#include "blockdyn/model/assembly/interface_faces.hpp"
#include "blockdyn/model/common/polygon.hpp"

namespace blockdyn {

namespace {

// Blocks below a millimetre are grains, not blocks: their contact and rocking time scales
// (sqrt(m / k) falls with the size) make a run of seconds cost billions of steps.
constexpr double kMinBlockSize = 1e-3;
constexpr const char* kMinBlockSizeWhy =
    " (smaller blocks are grains: their contact time scale makes a run of seconds take billions of steps)";

// Penetration d(t) and its rate of a unit-frequency oscillator d'' + 2 z d' + d = 0 after
// touching down with d(0) = 0, d'(0) = 1.
void drop(double z, double t, double& d, double& v) {
  if (z < 1.0) {
    const double wd = std::sqrt(1.0 - z * z), e = std::exp(-z * t);
    d = e * std::sin(wd * t) / wd;
    v = e * (std::cos(wd * t) - z / wd * std::sin(wd * t));
  } else if (z == 1.0) {
    d = t * std::exp(-t);
    v = (1.0 - t) * std::exp(-t);
  } else {
    const double g = std::sqrt(z * z - 1.0), r1 = -z + g, r2 = -z - g;
    d = (std::exp(r1 * t) - std::exp(r2 * t)) / (2.0 * g);
    v = (r1 * std::exp(r1 * t) - r2 * std::exp(r2 * t)) / (2.0 * g);
  }
}

// Restitution of the drop with damping ratio z when the force d + 2 z d' is released as it
// vanishes (it is positive at touchdown and changes sign exactly once).
double restitution_of_ratio(double z) {
  if (z == 0.0) return 1.0;
  auto force = [z](double t) {
    double d, v;
    drop(z, t, d, v);
    return d + 2.0 * z * v;
  };
  double lo = 0.0, hi = 1e-3;
  while (force(hi) > 0.0) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e9) return 0.0;
  }
  for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (force(mid) > 0.0 ? lo : hi) = mid;
  }
  double d, v;
  drop(z, hi, d, v);
  return -v;
}

}  // namespace

double restitution_of_damping(double c, double m, double k) {
  // Two points of stiffness k and damping c under mass m: omega^2 = 2k/m, zeta = c / sqrt(2 k m).
  return restitution_of_ratio(c / std::sqrt(2.0 * k * m));
}

double damping_for_restitution(double e, double m, double k) {
  if (!(e > 0.0 && e <= 1.0)) throw std::invalid_argument("restitution = " + number_text(e, 6) + " must be in (0, 1]");
  if (e == 1.0) return 0.0;
  double lo = 0.0, hi = 1.0;
  while (restitution_of_ratio(hi) > e) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e6) throw std::invalid_argument("restitution = " + number_text(e, 6) + " is too small (>= 1e-4)");
  }
  for (int k2 = 0; k2 < 200 && hi - lo > 1e-14 * hi; ++k2) {
    const double mid = 0.5 * (lo + hi);
    (restitution_of_ratio(mid) > e ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) * std::sqrt(2.0 * k * m);
}

namespace {

AssemblyBlock make_block(std::string name, double b, double h, const PresetOptions& o) {
  AssemblyBlock k;
  k.name = std::move(name);
  k.width = b;
  k.height = h;
  k.mass = o.density * b * h * o.thickness;
  return k;
}

// Turns a block about the ground-frame point `pivot` by theta (from its upright pose).
void turn_about(AssemblyBlock& k, const Vec2& pivot, double theta) {
  const BodyRotation q = BodyRotation::of(theta);
  const Vec2 r = q.offset(k.x - pivot.x, k.y - pivot.y);
  k.x = pivot.x + r.x;
  k.y = pivot.y + r.y;
  k.theta = theta;
}

// A circular arch of n equal voussoirs with radial joints (chords for the intrados and extrados),
// voussoir 0 at the left springing; the springings' centreline points at y = 0.
void build_arch(Assembly& a, const PresetOptions& o) {
  if (o.voussoirs < 1 || o.voussoirs > kMaxStaticBlocks)
    throw std::invalid_argument("voussoirs = " + std::to_string(o.voussoirs) + " must be in [1, " +
                                std::to_string(kMaxStaticBlocks) + "]");
  if (!(o.radius >= kMinBlockSize && o.radius <= 1e3))
    throw std::invalid_argument("radius = " + number_text(o.radius, 6) + " must be in [1e-3, 1000] m");
  if (!(o.thickness_ratio > 0 && o.thickness_ratio < 2))
    throw std::invalid_argument("thickness-ratio = " + number_text(o.thickness_ratio, 6) + " must be in (0, 2)");
  if (!(o.embrace > 0 && o.embrace <= 180))
    throw std::invalid_argument("embrace = " + number_text(o.embrace, 6) + " must be in (0, 180] degrees");
  const int n = o.voussoirs;
  // A voussoir spanning 180 degrees or more is no convex block (one over a semicircle has its four
  // corners on one line).
  if (!(o.embrace / n < 180.0))
    throw std::invalid_argument("voussoirs = " + std::to_string(n) + " over embrace = " + number_text(o.embrace, 6) +
                                " degrees: each voussoir must span less than 180 degrees (give at least " +
                                std::to_string(int(std::floor(o.embrace / 180.0)) + 1) + ")");
  const double R = o.radius, ri = R * (1 - 0.5 * o.thickness_ratio), re = R * (1 + 0.5 * o.thickness_ratio);
  const double half = 0.5 * o.embrace * M_PI / 180.0, step = 2.0 * half / n, yc = -R * std::cos(half);
  auto at = [&](double r, double phi) { return Vec2{r * std::cos(phi), yc + r * std::sin(phi)}; };
  for (int k = 0; k < n; ++k) {
    const double pa = 0.5 * M_PI + half - k * step, pb = 0.5 * M_PI + half - (k + 1) * step;
    AssemblyBlock b = polygon_block("voussoir " + std::to_string(k), {at(ri, pa), at(ri, pb), at(re, pb), at(re, pa)},
                                    0.0, o.density, o.thickness);
    b.name = "voussoir " + std::to_string(k);
    const double size = std::fmax(b.width, b.height), least = std::fmin(b.width, b.height);
    if (size > 1e3)
      throw std::invalid_argument("radius = " + number_text(o.radius, 6) +
                                  " m, thickness-ratio = " + number_text(o.thickness_ratio, 6) +
                                  " and voussoirs = " + std::to_string(n) + " make voussoirs " + number_text(size, 6) +
                                  " m across: at most 1000 m (a smaller radius or more voussoirs)");
    if (least < kMinBlockSize)
      throw std::invalid_argument("radius = " + number_text(o.radius, 6) +
                                  " m, thickness-ratio = " + number_text(o.thickness_ratio, 6) +
                                  " and voussoirs = " + std::to_string(n) + " make voussoirs " + number_text(least, 6) +
                                  " m thin: at least 1e-3 m" + kMinBlockSizeWhy);
    a.blocks.push_back(b);
  }
  // Edge 1 of a voussoir is its joint towards the right springing, edge 3 towards the left.
  AssemblyInterface left{-1, 0, o.ground_law, -1, 3};
  a.interfaces.push_back(left);
  for (int k = 1; k < n; ++k) a.interfaces.push_back({k - 1, k, o.block_law, 1, 3});
  a.interfaces.push_back({-1, n - 1, o.ground_law, -1, 1});
}

}  // namespace

AssemblyBlock polygon_block(const std::string& what, const std::vector<Vec2>& vertices, double mass, double density,
                            double thickness) {
  if (const std::string why = polygon_problem(vertices); !why.empty())
    throw std::invalid_argument(what + ".vertices: the polygon " + why);
  const PolygonProperties p = polygon_properties(vertices);
  AssemblyBlock b;
  b.name = what;
  b.width = p.width;
  b.height = p.height;
  b.x = p.centroid.x;
  b.y = p.centroid.y;
  b.gyration_sq = p.gyration_sq;
  b.mass = mass > 0 ? mass : density * thickness * p.area;
  for (const Vec2& v : vertices) b.vertices.push_back(v - p.centroid);
  return b;
}

Assembly make_preset(const std::string& name, const PresetOptions& o) {
  if (!(o.slenderness >= 0.1 && o.slenderness <= 100))
    throw std::invalid_argument("slenderness = " + number_text(o.slenderness, 6) + " must be in [0.1, 100]");
  if (!(o.block_width >= kMinBlockSize && o.block_width <= 100))
    throw std::invalid_argument("block-width = " + number_text(o.block_width, 6) + " must be in [1e-3, 100] m" +
                                (o.block_width < kMinBlockSize ? kMinBlockSizeWhy : ""));
  if (!(o.thickness > 0 && o.thickness <= 100))
    throw std::invalid_argument("thickness = " + number_text(o.thickness, 6) + " must be in (0, 100] m");
  if (!(o.density > 0 && o.density <= 1e5))
    throw std::invalid_argument("density = " + number_text(o.density, 6) + " must be in (0, 1e5] kg/m^3");
  if (!(std::fabs(o.tilt) < 1.5))
    throw std::invalid_argument("tilt = " + number_text(o.tilt, 6) + " must be in (-1.5, 1.5) rad");
  const double b = o.block_width, h = o.slenderness * b, g = 9.81;
  const double s = o.tilt >= 0 ? 1.0 : -1.0;  // theta > 0 turns about the left base corner
  Assembly a;
  a.preset = name;
  a.contact = o.contact;
  // Rigid contacts do not settle: a factor 0 on every spring sink below.
  const double settle = info(o.contact).springs ? 1.0 : 0.0;
  if (name == "block") {
    AssemblyBlock k = make_block("block", b, h, o);
    const double sink =
        settle * (o.tilt == 0 ? k.mass * g / (2 * o.ground_law.k_normal) : k.mass * g / o.ground_law.k_normal);
    k.y = 0.5 * h;
    turn_about(k, {-s * 0.5 * b, 0}, o.tilt);
    k.y -= sink;
    a.blocks = {k};
    a.interfaces = {{-1, 0, o.ground_law}};
  } else if (name == "column") {
    if (o.drums < 1 || o.drums > 8)
      throw std::invalid_argument("drums = " + std::to_string(o.drums) + " must be in [1, 8]");
    const double hd = h / o.drums;
    double total = 0;
    for (int k = 0; k < o.drums; ++k) {
      a.blocks.push_back(make_block("drum " + std::to_string(k), b, hd, o));
      total += a.blocks.back().mass;
    }
    double sink = 0, above = total;
    for (int k = 0; k < o.drums; ++k) {
      const ContactLaw& law = k == 0 ? o.ground_law : o.block_law;
      sink += settle * (o.tilt == 0 ? 0.5 : 1.0) * above * g / law.k_normal;
      above -= a.blocks[k].mass;
      AssemblyBlock& d = a.blocks[k];
      d.y = (k + 0.5) * hd;
      turn_about(d, {-s * 0.5 * b, 0}, o.tilt);
      d.y -= sink;
      a.interfaces.push_back({k - 1, k, law});
    }
  } else if (name == "trilith") {
    const double L = o.lintel_length > 0 ? o.lintel_length : h;
    const double xc = 0.5 * L - o.overhang - 0.5 * b;  // column centres at -xc, +xc
    if (!(xc > 0.5 * b))
      throw std::invalid_argument("trilith: the lintel (length " + number_text(L, 6) + " m, overhang " +
                                  number_text(o.overhang, 6) + " m) must span a clear opening between the columns");
    if (!(L <= 1e3)) throw std::invalid_argument("lintel-length = " + number_text(L, 6) + " must be at most 1000 m");
    AssemblyBlock c0 = make_block("left column", b, h, o), c1 = make_block("right column", b, h, o);
    AssemblyBlock li = make_block("lintel", L, b, o);
    const double sink_g = settle * (o.tilt == 0 ? 0.5 : 1.0) * (c0.mass + 0.5 * li.mass) * g / o.ground_law.k_normal;
    const double sink_l = settle * (o.tilt == 0 ? 0.5 : 1.0) * 0.5 * li.mass * g / o.block_law.k_normal;
    c0.x = -xc;
    c1.x = xc;
    c0.y = c1.y = 0.5 * h;
    li.y = h + 0.5 * b;
    // The rocking mode of the frame: both columns turn about the same-side base corner and the
    // lintel translates with the supporting top corners (a four-bar mechanism).
    const Vec2 before{c0.x + s * 0.5 * b, h};
    const Vec2 pivot0{c0.x - s * 0.5 * b, 0};
    turn_about(c0, pivot0, o.tilt);
    turn_about(c1, {c1.x - s * 0.5 * b, 0}, o.tilt);
    const Vec2 after = pivot0 + BodyRotation::of(o.tilt).offset(s * b, h);
    li.x += after.x - before.x;
    li.y += after.y - before.y;
    c0.y -= sink_g;
    c1.y -= sink_g;
    li.y -= sink_g + sink_l;
    a.blocks = {c0, c1, li};
    a.interfaces = {{-1, 0, o.ground_law}, {-1, 1, o.ground_law}, {0, 2, o.block_law}, {1, 2, o.block_law}};
  } else if (name == "arch") {
    build_arch(a, o);
  } else {
    throw std::invalid_argument("preset = '" + name + "' must be block, trilith, column or arch");
  }
  return a;
}

namespace {

// No two blocks may interpenetrate at the start, with or without an interface between them (the
// contact laws act only across interfaces: others would pass through each other).
void check_overlaps(const Assembly& a, double min_size) {
  const int nb = int(a.blocks.size());
  std::vector<std::vector<Vec2>> outline(nb);
  std::vector<std::array<double, 4>> box(nb);
  for (int i = 0; i < nb; ++i) {
    outline[i] = initial_outline(a.blocks[i]);
    box[i] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (const Vec2& v : outline[i])
      box[i] = {std::fmin(box[i][0], v.x), std::fmax(box[i][1], v.x), std::fmin(box[i][2], v.y),
                std::fmax(box[i][3], v.y)};
  }
  const double deep = 0.02 * min_size;
  for (int i = 0; i < nb; ++i)
    for (int j = i + 1; j < nb; ++j) {
      if (box[i][0] >= box[j][1] - deep || box[j][0] >= box[i][1] - deep || box[i][2] >= box[j][3] - deep ||
          box[j][2] >= box[i][3] - deep)
        continue;
      const double d = penetration_depth(outline[i], outline[j]);
      if (d > deep)
        throw std::invalid_argument("block " + std::to_string(i) + " (" + a.blocks[i].name + ") and block " +
                                    std::to_string(j) + " (" + a.blocks[j].name + ") overlap by " + number_text(d, 6) +
                                    " m at the start (at most " + number_text(deep, 6) +
                                    " m, 2% of the smallest block size)");
    }
}

void check_law(const ContactLaw& l, const std::string& where, bool plastic) {
  if (!(l.k_normal >= 1.0 && l.k_normal <= 1e13))
    throw std::invalid_argument(where + ".k_normal = " + number_text(l.k_normal, 6) + " must be in [1, 1e13] N/m");
  if (!(l.k_tangential < 0 || (l.k_tangential >= 1.0 && l.k_tangential <= 1e13)))
    throw std::invalid_argument(where + ".k_tangential = " + number_text(l.k_tangential, 6) +
                                " must be in [1, 1e13] N/m");
  if (!(l.restitution >= (plastic ? 0.0 : 1e-3) && l.restitution <= 1.0))
    throw std::invalid_argument(where + ".restitution = " + number_text(l.restitution, 6) + " must be in [" +
                                (plastic ? "0" : "0.001") + ", 1]");
  if (!(l.damping < 0 || (std::isfinite(l.damping) && l.damping <= 1e12)))
    throw std::invalid_argument(where + ".damping = " + number_text(l.damping, 6) + " must be in [0, 1e12] N s/m");
  if (!(l.mu_s >= 0 && l.mu_k >= 0 && l.mu_k <= l.mu_s && std::isfinite(l.mu_s)))
    throw std::invalid_argument(where + ": friction mu_s = " + number_text(l.mu_s, 6) +
                                ", mu_k = " + number_text(l.mu_k, 6) + " must satisfy 0 <= mu_k <= mu_s (finite)");
}

// Each block's size, mass, initial pose and polygon; returns the smallest block size.
double check_blocks(const Assembly& a) {
  const int nb = int(a.blocks.size());
  double min_size = INFINITY;
  for (int i = 0; i < nb; ++i) {
    const AssemblyBlock& k = a.blocks[i];
    const std::string w = "block " + std::to_string(i);
    if (!(k.width >= kMinBlockSize && k.width <= 1e3))
      throw std::invalid_argument(w + ".width = " + number_text(k.width, 6) + " must be in [1e-3, 1000] m" +
                                  (k.width < kMinBlockSize ? kMinBlockSizeWhy : ""));
    if (!(k.height >= kMinBlockSize && k.height <= 1e3))
      throw std::invalid_argument(w + ".height = " + number_text(k.height, 6) + " must be in [1e-3, 1000] m" +
                                  (k.height < kMinBlockSize ? kMinBlockSizeWhy : ""));
    if (!(k.mass > 0 && k.mass <= 1e12))
      throw std::invalid_argument(w + ".mass = " + number_text(k.mass, 6) + " must be in (0, 1e12] kg");
    for (double v : {k.x, k.y, k.theta, k.vx, k.vy, k.omega})
      if (!(std::isfinite(v) && std::fabs(v) <= 1e6))
        throw std::invalid_argument(w + ": initial pose and rates must be finite");
    if (!(std::fabs(k.theta) < 1.5))
      throw std::invalid_argument(w + ".theta = " + number_text(k.theta, 6) + " must be in (-1.5, 1.5) rad");
    if (!k.vertices.empty()) {
      if (const std::string why = polygon_problem(k.vertices); !why.empty())
        throw std::invalid_argument(w + " (" + k.name + ").vertices: the polygon " + why);
      if (!(k.gyration_sq > 0)) throw std::invalid_argument(w + ": a polygon needs its radius of gyration");
    }
    min_size = std::fmin(min_size, std::fmin(k.width, k.height));
  }
  return min_size;
}

// Each interface's blocks, its law, and no joint twice; every block stands on one.
void check_interfaces(const Assembly& a) {
  const int nb = int(a.blocks.size());
  std::vector<int> supports(nb, 0);
  for (std::size_t j = 0; j < a.interfaces.size(); ++j) {
    const AssemblyInterface& f = a.interfaces[j];
    const std::string w = "interface " + std::to_string(j);
    if (f.upper < 0 || f.upper >= nb)
      throw std::invalid_argument(w + ".upper = " + std::to_string(f.upper) + " is not a block");
    if (f.lower < -1 || f.lower >= nb || f.lower == f.upper)
      throw std::invalid_argument(w + ".lower = " + std::to_string(f.lower) + " must be -1 (ground) or another block");
    for (std::size_t k = 0; k < j; ++k) {
      const AssemblyInterface& o = a.interfaces[k];
      // Two ground interfaces of one block on different named edges are two abutments (a single
      // voussoir between its springings), not one joint twice.
      const bool same_edges = o.upper_edge == f.upper_edge && o.lower_edge == f.lower_edge;
      if (o.lower == f.lower && o.upper == f.upper && same_edges)
        throw std::invalid_argument(w + " repeats interface " + std::to_string(k));
      if (o.lower == f.upper && o.upper == f.lower && o.upper_edge == f.lower_edge && o.lower_edge == f.upper_edge)
        throw std::invalid_argument(w + " (lower = " + std::to_string(f.lower) +
                                    ", upper = " + std::to_string(f.upper) + ") repeats interface " +
                                    std::to_string(k) + " the other way round: one joint is one interface");
    }
    check_law(f.law, w, info(a.contact).plastic_impacts);
    ++supports[f.upper];
  }
  for (int i = 0; i < nb; ++i)
    if (supports[i] == 0)
      throw std::invalid_argument("block " + std::to_string(i) + " stands on nothing (no interface has it as upper)");
}

// Every block is carried at the start by an interface whose push on it has an upward part.
void check_carried(const Assembly& a) {
  const int nb = int(a.blocks.size());
  auto pose_of = [&](int i) { return initial_pose(a, i); };
  // A block is carried by an interface whose push on it has an upward part: as the upper block, a
  // support face whose normal points up; as the lower block, one whose normal points down (an
  // arch's voussoirs past the crown). A block carried by none falls at the start.
  std::vector<bool> carried(std::size_t(nb), false);
  std::vector<std::string> sideways(static_cast<std::size_t>(nb), std::string());
  constexpr double kCarries = 1e-3;  // the normal's vertical component that carries
  for (std::size_t j = 0; j < a.interfaces.size(); ++j) {
    const AssemblyInterface& f = a.interfaces[j];
    const Face lf = face_at(pose_of(f.lower), interface_faces(a, int(j)).lower);
    if (lf.n.y > kCarries) carried[std::size_t(f.upper)] = true;
    if (f.lower >= 0 && lf.n.y < -kCarries) carried[std::size_t(f.lower)] = true;
    if (!(lf.n.y > kCarries))
      sideways[std::size_t(f.upper)] = "interface " + std::to_string(j) + "'s support faces " +
                                       (lf.n.y < -kCarries ? "downwards" : "sideways") + " (normal " +
                                       number_text(lf.n.x, 6) + ", " + number_text(lf.n.y, 6) + ")";
  }
  for (int i = 0; i < nb; ++i)
    if (!carried[std::size_t(i)])
      throw std::invalid_argument("block " + std::to_string(i) + " (" + a.blocks[i].name +
                                  ") is carried by none of its interfaces at the start" +
                                  (sideways[std::size_t(i)].empty() ? std::string() : ": " + sideways[std::size_t(i)]) +
                                  "; name the edge it stands on (upper_edge), or a support below it");
}

// The initial configuration: every interface bears, touches (a block floating above its support
// is an input error, not a drop test) and does not interpenetrate.
void check_initial_contacts(const Assembly& a, double min_size) {
  auto pose_of = [&](int i) { return initial_pose(a, i); };
  const double touch = 1e-3 * min_size, deep = 0.02 * min_size;
  for (std::size_t j = 0; j < a.interfaces.size(); ++j) {
    const AssemblyInterface& f = a.interfaces[j];
    const BodyPose lp = pose_of(f.lower), up = pose_of(f.upper);
    const InterfaceFaces faces = interface_faces(a, int(j));
    const Face lf = face_at(lp, faces.lower);  // the ground's pose is the identity
    const Face uf = face_at(up, faces.upper);
    const std::string w = "interface " + std::to_string(j) + " (block " + std::to_string(f.upper) + " on " +
                          (f.lower < 0 ? std::string("the ground") : "block " + std::to_string(f.lower)) + ")";
    if (!(overlap(lf, uf) > 0)) throw std::invalid_argument(w + ": the faces do not overlap at the start");
    double min_gap = INFINITY;
    for (int end = 0; end < 2; ++end) {
      const int owner = owner_margin(lf, uf, end, 0) >= 0 ? 0 : 1;
      const FaceContact c = contact_point(lp, lf, up, uf, end, owner);
      min_gap = std::fmin(min_gap, c.gap);
      if (-c.gap > deep)
        throw std::invalid_argument(w + ": the blocks overlap by " + number_text(-c.gap, 6) +
                                    " m at the start (at most " + number_text(deep, 6) +
                                    " m, 2% of the smallest block size)");
    }
    if (min_gap > touch)
      throw std::invalid_argument(w + ": block " + std::to_string(f.upper) + " floats " + number_text(min_gap, 6) +
                                  " m above its support at the start (it must touch, within " + number_text(touch, 6) +
                                  " m)");
  }
}

}  // namespace

void validate(const Assembly& a, int max_blocks) {
  const int nb = int(a.blocks.size());
  if (nb < 1 || nb > max_blocks)
    throw std::invalid_argument(
        "blocks: " + std::to_string(nb) + " given, 1 to " + std::to_string(max_blocks) + " allowed" +
        (max_blocks < kMaxStaticBlocks
             ? std::string(" in the dynamics (limit-analysis takes ") + std::to_string(kMaxStaticBlocks) + ")"
             : std::string()));
  if (a.interfaces.empty() || a.interfaces.size() > std::size_t(nb + 1))
    throw std::invalid_argument("interfaces: " + std::to_string(a.interfaces.size()) + " given, 1 to " +
                                std::to_string(nb + 1) + " allowed for " + std::to_string(nb) + " blocks");
  if (a.rock_only_on_ground && !info(a.contact).rock_only_restriction)
    throw std::invalid_argument("columns-rock-only (seed 001's 5-DOF restriction) needs the rigid contact law");
  if (!(a.g > 0 && a.g <= 1e3))
    throw std::invalid_argument("g = " + number_text(a.g, 6) + " must be in (0, 1000] m/s^2");
  if (!(a.collapse_rotation > 0 && a.collapse_rotation <= 10))
    throw std::invalid_argument("collapse_rotation = " + number_text(a.collapse_rotation, 6) + " must be in (0, 10]");
  if (!(a.min_bearing >= 0 && std::isfinite(a.min_bearing)))
    throw std::invalid_argument("min_bearing = " + number_text(a.min_bearing, 6) + " must be >= 0 m");
  const double min_size = check_blocks(a);
  check_interfaces(a);
  check_overlaps(a, min_size);
  check_carried(a);
  check_initial_contacts(a, min_size);
}

void restrict_to_rocking_on_ground(Assembly& a) {
  if (!info(a.contact).rock_only_restriction)
    throw std::invalid_argument("`columns-rock-only` (seed 001's 5-DOF restriction) needs `contact` rigid");
  a.rock_only_on_ground = true;
  for (AssemblyInterface& i : a.interfaces)
    if (i.lower < 0) {
      i.law.mu_s = i.law.mu_k = kNoSlipFriction;
      i.law.restitution = 0.0;
    }
}

}  // namespace blockdyn
