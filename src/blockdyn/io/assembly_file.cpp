// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/assembly_file.hpp"

#include <cmath>
#include <set>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/io/toml_read.hpp"
#include "blockdyn/model/assembly/interface_faces.hpp"

namespace blockdyn {

namespace {

using namespace toml_read;

const std::set<std::string> kLawKeys{"k_normal", "k_tangential", "restitution", "damping",
                                     "phi",      "phi_kinetic",  "mu_s",        "mu_k"};

// Friction from an angle in degrees (90: no sliding) or from coefficients.
void read_law(const toml::table& t, const std::string& where, ContactLaw& l) {
  if (auto v = opt_number(t, where, "k_normal")) l.k_normal = *v;
  if (auto v = opt_number(t, where, "k_tangential")) l.k_tangential = *v;
  if (auto v = opt_number(t, where, "restitution")) {
    if (*v == kUnsetRestitution) fail(where + ".restitution", "= -1 must be in [0, 1]");
    l.restitution = *v;
  }
  if (auto v = opt_number(t, where, "damping")) l.damping = *v;
  const auto phi = opt_number(t, where, "phi"), phik = opt_number(t, where, "phi_kinetic");
  const auto mus = opt_number(t, where, "mu_s"), muk = opt_number(t, where, "mu_k");
  if ((phi || phik) && (mus || muk)) fail(where, "give the friction as phi (degrees) or as mu_s/mu_k, not both");
  if (phi) {
    l.mu_s = l.mu_k = friction_of_angle(*phi, where + ".phi");
    if (phik) l.mu_k = friction_of_angle(*phik, where + ".phi_kinetic");
  } else if (phik) {
    fail(where + ".phi_kinetic", "needs phi");
  }
  if (mus) l.mu_s = l.mu_k = *mus;
  if (muk) l.mu_k = *muk;
}

// [[x, y], ...] at rest, counter-clockwise.
std::vector<Vec2> read_vertices(const toml::table& t, const std::string& w) {
  const toml::array* arr = t["vertices"].as_array();
  if (!arr) fail(w + ".vertices", "must be an array of [x, y] pairs (m, counter-clockwise)");
  std::vector<Vec2> v;
  for (std::size_t k = 0; k < arr->size(); ++k) {
    const std::string f = w + ".vertices[" + std::to_string(k) + "]";
    const toml::array* xy = (*arr)[k].as_array();
    if (!xy || xy->size() != 2) fail(f, "must be a pair [x, y] of numbers (m)");
    v.push_back({number(*xy->get(0), f + "[0]"), number(*xy->get(1), f + "[1]")});
  }
  return v;
}

AssemblyBlock read_block(const toml::table& t, const std::string& w, std::size_t i) {
  const auto mass = opt_number(t, w, "mass"), rho = opt_number(t, w, "density"), depth = opt_number(t, w, "thickness");
  if (mass && rho) fail(w, "give mass or density (with thickness), not both");
  // Each as given, before any is combined into a mass.
  auto check = [&](const std::optional<double>& v, const char* key, double hi, const char* unit) {
    if (v && !(*v > 0 && *v <= hi))
      throw std::invalid_argument(w + "." + key + " = " + number_text(*v) + " is out of range: must be in (0, " +
                                  number_text(hi) + "] " + unit);
  };
  check(mass, "mass", 1e12, "kg");
  check(rho, "density", 1e5, "kg/m^3");
  check(depth, "thickness", 1e3, "m");
  if (!mass && !(rho && depth)) fail(w + ".mass", "is missing (or give density and thickness)");
  const std::string name = opt_string(t, w, "name").value_or("block " + std::to_string(i));
  AssemblyBlock b;
  if (t.contains("vertices")) {
    for (const char* k : {"width", "height", "x", "y"})
      if (t.contains(k))
        fail(w + "." + k, "belongs to a rectangular block (a polygon's vertices give its size and place)");
    b = polygon_block(w, read_vertices(t, w), mass ? *mass : 0.0, rho ? *rho : 0.0, depth ? *depth : 0.0);
  } else {
    const auto width = opt_number(t, w, "width"), height = opt_number(t, w, "height");
    if (!width) fail(w + ".width", "is missing (or give vertices)");
    if (!height) fail(w + ".height", "is missing (or give vertices)");
    b.width = *width;
    b.height = *height;
    b.mass = mass ? *mass : *rho * b.width * b.height * *depth;
    b.x = opt_number(t, w, "x").value_or(0.0);
    const auto y = opt_number(t, w, "y");
    if (!y) fail(w + ".y", "is missing (the height of the block's centre)");
    b.y = *y;
  }
  b.name = name;
  b.theta = opt_number(t, w, "theta").value_or(0.0);
  b.vx = opt_number(t, w, "vx").value_or(0.0);
  b.vy = opt_number(t, w, "vy").value_or(0.0);
  b.omega = opt_number(t, w, "omega").value_or(0.0);
  return b;
}

// A polygon's theta turns it about the end of its base on which it then stands (the end the other
// rises from), not about its centroid (which would sink a corner into the ground): the block
// touches the ground exactly at the start, as a tilted rectangle of a preset does.
void stand_tilted_polygons(Assembly& a) {
  for (std::size_t j = 0; j < a.interfaces.size(); ++j) {
    const AssemblyInterface& f = a.interfaces[j];
    if (f.lower >= 0 || f.upper_edge >= 0) continue;
    AssemblyBlock& b = a.blocks[std::size_t(f.upper)];
    if (b.vertices.empty() || b.theta == 0.0) continue;
    const LocalFace base = interface_faces(a, int(j)).upper;  // relative to the centroid, at rest
    const BodyRotation q = BodyRotation::of(b.theta);
    const Vec2 c{b.x, b.y};
    const Vec2 ends[2] = {c + base.c + base.half * base.t, c + base.c - base.half * base.t};
    for (int e = 0; e < 2; ++e) {
      const Vec2 pivot = ends[e], other = ends[1 - e] - pivot;
      if (q.offset(other.x, other.y).y < 0.0) continue;  // this end would sink the other
      const Vec2 arm = c - pivot;
      const Vec2 turned = q.offset(arm.x, arm.y);
      b.x = pivot.x + turned.x;
      b.y = pivot.y + turned.y;
      break;
    }
  }
}

}  // namespace

void apply_default_restitution(Assembly& a, bool plastic) {
  for (AssemblyInterface& i : a.interfaces)
    if (i.law.restitution == kUnsetRestitution) i.law.restitution = plastic ? 0.0 : 0.5;
}

double friction_of_angle(double deg, const std::string& field) {
  if (!(deg >= 0 && deg <= 90)) fail(field, "= " + number_text(deg) + " must be in [0, 90] degrees");
  // 90 degrees: no sliding; a coefficient so large that the static cone is never left, kept
  // finite so that mu N stays a number at N = 0.
  if (deg >= 90) return kNoSlip;
  return std::tan(deg * M_PI / 180.0);
}

Assembly read_assembly_file(const std::string& path) { return parse_assembly(read_file(path, "assembly file"), path); }

Assembly parse_assembly(const std::string& text, const std::string& source) {
  const toml::table root = parse(text, source);
  if (auto k = first_unknown_key(root, {"assembly", "contact", "block", "interface"}); !k.empty())
    fail(k, "unknown table (allowed: assembly, contact, [[block]], [[interface]])");
  Assembly a;
  ContactLaw base;
  base.restitution = kUnsetRestitution;  // the contact law's own default, once the law is known
  if (const toml::table* t = sub_table(root, "assembly", "assembly")) {
    if (auto k = first_unknown_key(*t, {"g", "collapse_rotation", "min_bearing"}); !k.empty())
      fail("assembly." + k, "unknown key (allowed: g, collapse_rotation, min_bearing)");
    if (auto v = opt_number(*t, "assembly", "g")) a.g = *v;
    if (auto v = opt_number(*t, "assembly", "collapse_rotation")) a.collapse_rotation = *v;
    if (auto v = opt_number(*t, "assembly", "min_bearing")) a.min_bearing = *v;
  }
  if (const toml::table* t = sub_table(root, "contact", "contact")) {
    if (auto k = first_unknown_key(*t, kLawKeys); !k.empty())
      fail("contact." + k, "unknown key (allowed: " + joined(kLawKeys) + ")");
    read_law(*t, "contact", base);
  }
  const toml::array* blocks = root["block"].as_array();
  if (!blocks || blocks->empty()) fail("block", "at least one [[block]] is needed");
  const std::set<std::string> block_keys{"name", "width", "height", "mass", "density", "thickness", "x",
                                         "y",    "theta", "vx",     "vy",   "omega",   "vertices"};
  for (std::size_t i = 0; i < blocks->size(); ++i) {
    const std::string w = "block[" + std::to_string(i) + "]";
    const toml::table* t = (*blocks)[i].as_table();
    if (!t) fail(w, "must be a table");
    if (auto k = first_unknown_key(*t, block_keys); !k.empty())
      fail(w + "." + k, "unknown key (allowed: " + joined(block_keys) + ")");
    a.blocks.push_back(read_block(*t, w, i));
  }
  const toml::array* faces = root["interface"].as_array();
  if (!faces || faces->empty()) fail("interface", "at least one [[interface]] is needed (lower, upper)");
  std::set<std::string> iface_keys = kLawKeys;
  iface_keys.insert({"lower", "upper", "lower_edge", "upper_edge"});
  const long long nb = static_cast<long long>(a.blocks.size());
  for (std::size_t i = 0; i < faces->size(); ++i) {
    const std::string w = "interface[" + std::to_string(i) + "]";
    const toml::table* t = (*faces)[i].as_table();
    if (!t) fail(w, "must be a table");
    if (auto k = first_unknown_key(*t, iface_keys); !k.empty())
      fail(w + "." + k, "unknown key (allowed: " + joined(iface_keys) + ")");
    AssemblyInterface f;
    f.law = base;
    const auto upper = opt_integer(*t, w, "upper", 0, nb - 1);
    if (!upper) fail(w + ".upper", "is missing (the index of the block standing on this face)");
    f.upper = int(*upper);
    if (const auto s = (*t)["lower"].as_string()) {
      if (s->get() != "ground") fail(w + ".lower", "must be \"ground\" or a block index");
      f.lower = -1;
    } else {
      const auto lower = opt_integer(*t, w, "lower", -1, nb - 1);
      if (!lower) fail(w + ".lower", "is missing (\"ground\" or a block index)");
      f.lower = int(*lower);
    }
    read_law(*t, w, f.law);
    if (auto e = opt_integer(*t, w, "upper_edge", 0, 63)) f.upper_edge = int(*e);
    if (auto e = opt_integer(*t, w, "lower_edge", 0, 63)) f.lower_edge = int(*e);
    if (f.lower < 0 && f.lower_edge >= 0) fail(w + ".lower_edge", "belongs to a block (the ground has no edges)");
    a.interfaces.push_back(f);
  }
  stand_tilted_polygons(a);
  return a;
}

}  // namespace blockdyn
