// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/rigid3d_run.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/ground_settings.hpp"
#include "blockdyn/commands/simulate_run.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/model/rigid_ground/rigid_params.hpp"
#include "blockdyn/simulation/rigid3d_simulation.hpp"
#include "blockdyn/simulation/run_options.hpp"

namespace blockdyn {

namespace {

using json = nlohmann::ordered_json;
constexpr double kDeg = M_PI / 180;

struct Rigid3dSetup {
  Body3d body;
  GroundMotion3d ground;
  BodyOnGroundOptions model;
  Body3dStart start;
  Body3dRunOptions run;
};

Vec3 vec3_option(const Settings& s, const char* name) {
  std::string all;
  for (const std::string& v : s.values(name)) all += (all.empty() ? "" : ",") + v;
  std::stringstream in(all);
  std::vector<double> xs;
  for (std::string cell; std::getline(in, cell, ',');) {
    char* end = nullptr;
    const double x = std::strtod(cell.c_str(), &end);
    if (cell.empty() || *end != '\0' || !std::isfinite(x) || std::fabs(x) > 1e3)
      throw std::invalid_argument(std::string("`") + name + "` = '" + all +
                                  "': three finite numbers X,Y,Z are needed, each within [-1000, 1000]");
    xs.push_back(x);
  }
  if (xs.size() != 3)
    throw std::invalid_argument(std::string("`") + name + "` = '" + all + "': three numbers X,Y,Z are needed");
  return {xs[0], xs[1], xs[2]};
}

}  // namespace

Body3d body3d_from(const Settings& s) {
  Body3d b;
  const std::string shape = s.text("shape", "box");
  if (shape != "box" && shape != "cylinder")
    throw std::invalid_argument("`shape` = '" + shape + "' is not one of: box, cylinder");
  b.shape = shape == "box" ? BodyShape3d::Box : BodyShape3d::Cylinder;
  for (const char* n :
       b.shape == BodyShape3d::Box ? std::vector<const char*>{"radius"} : std::vector<const char*>{"width", "depth"})
    if (s.has(n)) throw std::invalid_argument(std::string("`") + n + "` does not belong to `shape` " + shape);
  b.height = s.number("height", 1.2);
  b.width = s.number("width", 0.4);
  b.depth = s.number("depth", b.width);
  b.radius = s.number("radius", 0.2);
  b.g = s.number("g", 9.81);
  if (s.has("mass") && s.has("density")) throw std::invalid_argument("`mass` and `density`: give one of them");
  if (s.has("density")) {
    const double rho = s.number("density", 0);
    require_in_range("density", rho, 0, 1e5, false);
    const double base = b.shape == BodyShape3d::Box ? b.width * b.depth : M_PI * b.radius * b.radius;
    b.mass = rho * base * b.height;
  } else {
    b.mass = s.number("mass", 100);
  }
  validate(b);
  return b;
}

BodyOnGroundOptions body3d_friction_from(const Settings& s) {
  BodyOnGroundOptions f;
  f.mu_s = s.number("mu-s", 0.7);
  require_in_range("mu-s", f.mu_s, 0, 1e6);
  f.mu_k = s.number("mu-k", f.mu_s);
  require_in_range("mu-k", f.mu_k, 0, 1e6);
  if (s.has("impact")) {
    // The impact laws' names are the planar block's (one vocabulary).
    const auto law = impact_law_from_string(s.text("impact"));
    if (!law) throw std::invalid_argument("`impact` = '" + s.text("impact") + "' is not one of: newton, housner");
    f.impact = *law == ImpactLaw::Housner ? Body3dImpactLaw::Housner : Body3dImpactLaw::Newton;
  }
  if (s.has("restitution")) {
    if (f.impact == Body3dImpactLaw::Housner)
      throw std::invalid_argument("`restitution` is Newton's e: Housner's law in 3D has none (give `impact` newton)");
    f.restitution = s.number("restitution", 0);
    require_in_range("restitution", f.restitution, 0, 1);
  }
  return f;
}

namespace {

Body3dStart start_from(const Settings& s) {
  Body3dStart st;
  st.yaw = s.number("yaw", 0) * kDeg;
  st.tilt = s.number("tilt", 0);
  st.tilt_azimuth = s.number("tilt-azimuth", 0) * kDeg;
  st.lift = s.number("lift", 0);
  require_in_range("yaw", st.yaw / kDeg, -360, 360);
  require_in_range("tilt", st.tilt, 0, 0.5 * M_PI, true, false);
  require_in_range("tilt-azimuth", st.tilt_azimuth / kDeg, -360, 360);
  require_in_range("lift", st.lift, 0, 1e3);
  // In contact: a corner moving into the ground starts with Newton's impact; points moving along it
  // slip (BodyOnGround::start, Body3dRunOptions::slip_start).
  if (s.has("velocity")) st.velocity = vec3_option(s, "velocity");
  if (s.has("angular-velocity")) st.angular_velocity = vec3_option(s, "angular-velocity");
  return st;
}

Rigid3dSetup rigid3d_from(const Settings& s) {
  Rigid3dSetup r;
  r.body = body3d_from(s);
  r.start = start_from(s);
  apply_ground_settings(s, r.ground);
  validate(r.ground);
  r.model = body3d_friction_from(s);
  r.model.rest_yaw = r.start.yaw;
  r.run.t_end = s.number("t-end", 10);
  r.run.output_interval = s.number("output-interval", 0.01);
  apply_integrator_settings(s, r.run.integ);
  RunOptions check;
  check.t_end = r.run.t_end;
  check.integrator = r.run.integ;
  validate(check);
  require_in_range("output-interval", r.run.output_interval, 0, r.run.t_end);
  r.run.rows_every_step = r.run.output_interval == 0;  // 0: every step, as the planar families
  // A velocity given is the body's own: contact points it moves along the ground slip from t = 0
  // (as the planar families' vx0); without one the contact takes the velocities it allows.
  r.run.slip_start = s.has("velocity");
  if (s.has("painleve")) {
    const std::string p = s.text("painleve");
    if (p != "step" && p != "stop") throw std::invalid_argument("`painleve` = '" + p + "' is not one of: step, stop");
    r.run.painleve_steps = p == "step";
  }
  r.run.painleve_step = s.number("painleve-step", 0);
  if (s.has("painleve-step")) require_in_range("painleve-step", r.run.painleve_step, 0, 1e-2, false);
  if (s.has("painleve-step") && !r.run.painleve_steps)
    throw std::invalid_argument("`painleve-step` is the Moreau-Jean step of `painleve` step, not of stop");
  return r;
}

const char* mode_name(const Body3d& b, const BodyOnGroundMode& m) {
  switch (m.contact) {
    case BodyContact::Rest:
      return "rest";
    case BodyContact::Flight:
      return "flight";
    case BodyContact::Point:
      return m.slips() ? "corner_slip" : "corner";
    case BodyContact::Line:
      // A slipping edge: both ends slip, or one sticks and the edge turns about it.
      if (m.slipping == 3) return "edge_slip";
      if (m.slips()) return "edge_turn";
      return b.shape == BodyShape3d::Box ? "edge" : "rim";
    case BodyContact::Slide:
      return "slide";
    case BodyContact::Roll:
      return m.slips() ? "rim_slip" : "roll";
  }
  return "?";
}

// One trajectory row (rigid3d_columns()).
void fill_row(RowBuffer& row, const BodyOnGround& m, double e0, const Body3dSample& smp) {
  const BodyOnGround::State& z = smp.z;
  row.clear();
  row.number(smp.t);
  for (std::size_t i = BodyOnGround::kX; i <= BodyOnGround::kQz; ++i) row.number(z[i]);
  row.number(m.tilt(z));
  row.number(tilt_azimuth_deg(z));
  for (std::size_t i = BodyOnGround::kVx; i <= BodyOnGround::kWz; ++i) row.number(z[i]);
  row.text(mode_name(m.body(), smp.mode));
  const Vec3 contact = m.contact_point(smp.mode, z);
  row.number(contact[0]);
  row.number(contact[1]);
  const std::array<Vec3, 2> f = m.contact_forces(smp.t, smp.mode, z);
  row.number(f[0][2] + f[1][2]);
  const double pot = m.body().mass * m.body().g * z[BodyOnGround::kZ];
  row.number(m.energy(z) - pot);
  row.number(pot);
  row.number(z[BodyOnGround::kWorkGround]);
  row.number(z[BodyOnGround::kWorkImpact]);
  row.number(z[BodyOnGround::kWorkFriction]);
  row.number(m.balance(z) - e0);
  row.text(smp.event ? smp.event : "");
}

BodyOnGroundMode mode_of_record(BodyContact c, unsigned char slipping) {
  BodyOnGroundMode m;
  m.contact = c;
  m.slipping = slipping;
  return m;
}

json event_json(const BodyOnGround& m, const Body3dEventRecord& e) {
  return {{"t", e.t},
          {"kind", to_string(e.kind)},
          {"from", mode_name(m.body(), mode_of_record(e.from, e.from_slipping))},
          {"to", mode_name(m.body(), mode_of_record(e.to, e.to_slipping))},
          {"x", e.z[BodyOnGround::kX]},
          {"y", e.z[BodyOnGround::kY]},
          {"z", e.z[BodyOnGround::kZ]},
          {"tilt", m.tilt(e.z)},
          {"tilt_azimuth", tilt_azimuth_deg(e.z)}};
}

std::string body_phrase(const Body3d& b) {
  if (b.shape == BodyShape3d::Box)
    return "box " + number_text(b.width, 4) + " x " + number_text(b.depth, 4) + " x " + number_text(b.height, 4) + " m";
  return "cylinder r " + number_text(b.radius, 4) + " m, h " + number_text(b.height, 4) + " m";
}

// " under <h> at 30 deg, <h2> across, <v> vertical" or " in free motion", for figure titles.
std::string motion_phrase(const GroundMotion3d& g) {
  if (g.is_zero()) return " in free motion";
  auto one = [](const GroundComponent& c) {
    GroundMotion m;
    m.horizontal = c;
    return describe(m, "Hz", "s");
  };
  std::string p = " under";
  if (!g.h.is_zero()) p += " " + one(g.h) + " at " + number_text(g.azimuth, 4) + " deg";
  if (!g.h2.is_zero()) p += std::string(g.h.is_zero() ? "" : ",") + " " + one(g.h2) + " across";
  if (!g.v.is_zero()) p += std::string(p == " under" ? "" : ",") + " " + one(g.v) + " vertical";
  return p;
}

json optional_time(double t) { return t >= 0 ? json(t) : json(nullptr); }

json summary_json(const Rigid3dSetup& s, const BodyOnGround& m, const Body3dResult& r) {
  const Body3d& b = s.body;
  const Vec3 in = b.inertia();
  json body = {{"shape", b.shape == BodyShape3d::Box ? "box" : "cylinder"}};
  if (b.shape == BodyShape3d::Box) {
    body["width"] = b.width;
    body["depth"] = b.depth;
  } else {
    body["radius"] = b.radius;
  }
  body["height"] = b.height;
  body["mass"] = b.mass;
  body["g"] = b.g;
  body["inertia"] = {in[0], in[1], in[2]};
  const BodyOnGround::State& z = r.z;
  return {{"model", "rigid3d"},
          {"status", to_string(r.status)},
          {"stop_reason", r.note},
          {"t_final", r.t_final},
          {"overturn_time", optional_time(r.overturn_time)},
          {"first_uplift_time", optional_time(r.first_uplift_time)},
          {"impacts", r.impacts},
          {"max_tilt", r.max_tilt},
          {"max_tilt_azimuth", r.max_tilt_azimuth},
          {"overturn_azimuth", r.overturn_time >= 0 ? json(r.overturn_azimuth) : json(nullptr)},
          {"first_slide_time", optional_time(r.first_slide_time)},
          {"max_slide", r.max_slide},
          {"final_mode", mode_name(b, r.mode)},
          {"final_state", std::vector<double>(z.begin(), z.begin() + BodyOnGround::kWorkGround)},
          {"max_abs_energy_error", r.max_abs_energy_error},
          {"energy",
           {{"initial", r.initial_energy},
            {"final", m.energy(z)},
            {"work_ground", z[BodyOnGround::kWorkGround]},
            {"work_impact", z[BodyOnGround::kWorkImpact]},
            {"work_friction", z[BodyOnGround::kWorkFriction]}}},
          {"body", body},
          {"initial_state",
           {{"yaw_deg", s.start.yaw / kDeg},
            {"tilt", s.start.tilt},
            {"tilt_azimuth_deg", s.start.tilt_azimuth / kDeg},
            {"lift", s.start.lift},
            {"velocity", s.start.velocity},
            {"angular_velocity", s.start.angular_velocity}}},
          {"friction",
           {{"mu_s", s.model.mu_s},
            {"mu_k", s.model.mu_k < 0 ? s.model.mu_s : s.model.mu_k},
            {"contacts",
             "a box's base slides on its four corners (Coulomb, mu_k, each against its own slip: twisting "
             "included), a cylinder's on its disc (uniform pressure, the tilting moment's share on one rim point); "
             "edges, corners and the rim stick within mu_s and slip against mu_k"}}},
          {"impact_law",
           s.model.impact == Body3dImpactLaw::Newton && s.body.shape == BodyShape3d::Box
               ? "newton: the touching corners' velocity-level problem, normal velocity -e times the one before, "
                 "Coulomb's cone on the impulses (a corner friction cannot hold leaves slipping; Housner's where no "
                 "impulses in the cones solve it)"
               : "housner: angular momentum about the new contact conserved (Housner's law in 3D)"},
          {"restitution", s.model.impact == Body3dImpactLaw::Newton ? nlohmann::ordered_json(s.model.restitution)
                                                                    : nlohmann::ordered_json(nullptr)},
          {"ground",
           {{"azimuth_deg", s.ground.azimuth},
            {"h", to_json(s.ground.h)},
            {"h2", to_json(s.ground.h2)},
            {"v", to_json(s.ground.v)}}},
          {"t_end", s.run.t_end},
          {"output_interval", s.run.output_interval},
          {"integrator", to_json(s.run.integ)},
          {"steps", r.stats.accepted},
          {"painleve",
           {{"treatment", s.run.painleve_steps ? "step" : "stop"},
            {"step", s.run.painleve_steps ? json(s.run.painleve_step > 0 ? s.run.painleve_step
                                                                         : kPainleveStep * std::sqrt(m.size() / b.g))
                                          : json(nullptr)},
            {"spans", r.painleve_spans},
            {"time", r.painleve_time},
            {"steps", r.painleve_steps}}},
          {"events", json::array()},
          {"run", run_info()}};
}

std::string summary_text(const Body3dResult& r) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "rigid3d: %s at t = %.6g s%s%s\n  impacts %ld, max tilt %.6g rad, first uplift %s, energy balance "
                "error %.3g J\n",
                to_string(r.status), r.t_final, r.note.empty() ? "" : ": ", r.note.c_str(), r.impacts, r.max_tilt,
                r.first_uplift_time >= 0 ? (number_text(r.first_uplift_time, 6) + " s").c_str() : "none",
                r.max_abs_energy_error);
  return buf;
}

class PreparedRigid3d final : public PreparedRun {
 public:
  explicit PreparedRigid3d(Rigid3dSetup s) : s_(std::move(s)), model_(s_.body, s_.ground, s_.model) {}
  SimulateReport run(const SimulateOutputs& out) const override {
    Body3dRunOptions o = s_.run;
    RowBuffer row;
    const BodyOnGround::State z0 = initial_state(s_.body, s_.start);
    double e0 = 0;
    if (out.trajectory) {
      require_sample_count("output-interval", o.output_interval, o.t_end, out.max_output_rows);
      out.trajectory->columns(rigid3d_columns());
      row.resize(rigid3d_columns().size());
      o.on_sample = [&](const Body3dSample& smp) {
        if (smp.t == 0 && !smp.event) e0 = model_.balance(smp.z);
        fill_row(row, model_, e0, smp);
        row.write_to(*out.trajectory);
      };
    }
    auto forward = [&](const Body3dEventRecord& e) {
      if (out.on_event) out.on_event(event_json(model_, e));
    };
    EventCallback<Body3dEventRecord, decltype(forward)> sink(forward);
    o.events = &sink;
    const RunClock clock;
    const Body3dResult r = simulate_body3d(model_, z0, o);
    SimulateReport rep;
    rep.timing = clock.elapsed();
    rep.summary = summary_json(s_, model_, r);
    rep.text = summary_text(r);
    const std::string title = body_phrase(s_.body) + motion_phrase(s_.ground) + ": " + to_string(r.status) +
                              " at t = " + number_text(r.t_final, 6) + " s";
    SimulateFigure fig;
    fig.plot = FigureSpec{"rigid3d",
                          {},
                          {{"title", {title}},
                           {"weight", {number_text(s_.body.mass * s_.body.g)}},
                           {"height", {number_text(s_.body.height)}}}};
    fig.animation = FigureSpec{"rigid3d",
                               {},
                               {{"title", {title}},
                                {"shape", {s_.body.shape == BodyShape3d::Box ? "box" : "cylinder"}},
                                {"size",
                                 {number_text(s_.body.width) + "," + number_text(s_.body.depth) + "," +
                                  number_text(s_.body.height) + "," + number_text(s_.body.radius)}}}};
    rep.figure = std::move(fig);
    return rep;
  }

 private:
  Rigid3dSetup s_;
  BodyOnGround model_;
};

}  // namespace

const std::vector<StudyOption>& rigid3d_options() {
  static const std::vector<StudyOption> o = [] {
    std::vector<StudyOption> v{
        {"shape", "rigid3d: box (`width` along x, `depth` along y, `height`) or cylinder (`radius`, `height`)", "box"},
        {"depth", "rigid3d: the box's depth along its e2 axis [m] (default: `width`)"},
        {"tilt-azimuth", "rigid3d: the side the body leans to at `tilt`, degrees from x towards y (default 0)"},
        {"yaw", "rigid3d: the body's e1 axis from x towards y [deg] (default 0)"},
        {"velocity",
         "rigid3d: initial velocity VX,VY,VZ of the centroid [m/s], its own (in contact: points it moves along the "
         "ground slip; without it the contact takes the velocities it allows)"},
        {"angular-velocity", "rigid3d: initial angular velocity WX,WY,WZ [rad/s] (world frame)"},
        {"lift", "rigid3d: start in flight this high above the ground [m] (default 0)"},
        {"painleve",
         "rigid3d: where no contact state is consistent (Painleve, an edge and a corner taking turns at one instant, "
         "a cylinder's flat base tipping onto a roll) or the events' steps underflow: step (Moreau-Jean steps across "
         "the span, then the events again) or stop (the run ends there, invalid)",
         "step"},
        {"painleve-step", "rigid3d: the Moreau-Jean step across a Painleve span [s] (default 1e-6 sqrt(size / g))"},
    };
    for (const StudyOption& g : ground_3d_options()) v.push_back(g);
    return v;
  }();
  return o;
}

const std::vector<std::string>& rigid3d_option_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n{"model", "width", "height", "radius", "mass",           "density",
                               "g",     "tilt",  "mu-s",   "mu-k",   "impact",         "restitution",
                               "t-end", "rtol",  "atol",   "method", "output-interval"};
    for (const StudyOption& o : rigid3d_options()) n.push_back(o.name);
    for (const std::string& g : ground_option_names()) n.push_back(g);
    return n;
  }();
  return names;
}

const std::vector<std::string>& rigid3d_columns() {
  static const std::vector<std::string> c{"t",
                                          "x",
                                          "y",
                                          "z",
                                          "qw",
                                          "qx",
                                          "qy",
                                          "qz",
                                          "tilt",
                                          "tilt_azimuth",
                                          "vx",
                                          "vy",
                                          "vz",
                                          "wx",
                                          "wy",
                                          "wz",
                                          "mode",
                                          "contact_x",
                                          "contact_y",
                                          "normal_force",
                                          "kinetic",
                                          "potential",
                                          "work_ground",
                                          "work_impact",
                                          "work_friction",
                                          "energy_error",
                                          "event"};
  return c;
}

const std::vector<std::string>& rigid3d_result_keys() {
  static const std::vector<std::string> k{"status",
                                          "t_final",
                                          "max_tilt",
                                          "max_tilt_azimuth",
                                          "overturn_time",
                                          "overturn_azimuth",
                                          "first_uplift_time",
                                          "first_slide_time",
                                          "max_slide",
                                          "impacts",
                                          "max_abs_energy_error",
                                          "stop_reason"};
  return k;
}

std::vector<std::pair<std::string, std::string>> rigid3d_sweep_axes() {
  std::vector<std::pair<std::string, std::string>> a = {{"width", "box width along e1 [m]"},
                                                        {"depth", "box depth along e2 [m]"},
                                                        {"height", "height [m]"},
                                                        {"radius", "cylinder radius [m]"},
                                                        {"mass", "mass [kg]"},
                                                        {"mu_s", "static friction"},
                                                        {"mu_k", "kinetic friction"},
                                                        {"restitution", "Newton's restitution e"},
                                                        {"tilt", "initial tilt [rad]"},
                                                        {"tilt_azimuth", "the side it leans to [deg]"},
                                                        {"yaw", "the body's e1 from x [deg]"},
                                                        {"lift", "start in flight this high [m]"}};
  // The ground's numbers (not its kinds or record files).
  for (const StudyOption& g : ground_3d_options())
    for (const char* part : {"constant", "amplitude", "frequency", "phase", "duration", "start", "scale", "azimuth"})
      if (g.name.find(part) != std::string::npos) {
        std::string n = g.name;
        std::replace(n.begin(), n.end(), '-', '_');
        a.emplace_back(n, g.help);
        break;
      }
  return a;
}

std::unique_ptr<PreparedRun> prepare_rigid3d(const Settings& s) {
  return std::make_unique<PreparedRigid3d>(rigid3d_from(s));
}

}  // namespace blockdyn
