// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/forced_body3d.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/simulation/rigid3d_simulation.hpp"

namespace blockdyn {

namespace {

// The frequency parameter of the rocking the rest threshold in direction phi starts: a box about
// the edge across the nearer axis (R its section's half diagonal, p^2 = 3 g / (4 R)), a cylinder
// about a rim point (p^2 = g R / (5 a^2 / 4 + 4 c^2 / 3), R = sqrt(a^2 + c^2): docs/3d.md).
double frequency_parameter(const Body3d& b, double phi) {
  const double c = b.half_height();
  if (b.shape == BodyShape3d::Cylinder) {
    const double a = b.radius, R = std::hypot(a, c);
    return std::sqrt(b.g * R / (1.25 * a * a + 4.0 * c * c / 3.0));
  }
  const bool along_e1 = b.width / std::fabs(std::cos(phi)) <= b.depth / std::fabs(std::sin(phi));
  const double R = 0.5 * std::hypot(along_e1 ? b.width : b.depth, b.height);
  return std::sqrt(0.75 * b.g / R);
}

}  // namespace

ForcedModel forced_body3d_model(const Body3d& body, const BodyOnGroundOptions& friction, double incidence_deg) {
  validate(body);
  if (!(std::isfinite(incidence_deg) && std::fabs(incidence_deg) <= 360))
    throw std::invalid_argument("incidence = " + number_text(incidence_deg) + " is out of range: [-360, 360] degrees");
  (void)BodyOnGround(body, {}, friction);  // the friction checked once, before any run
  const double phi = incidence_deg * M_PI / 180;
  ForcedModel fm;
  fm.alpha = std::atan(rest_threshold(body, phi));
  fm.p = frequency_parameter(body, phi);
  fm.width = body.shape == BodyShape3d::Box ? body.width : 2 * body.radius;
  const double mu_k = friction.mu_k < 0 ? friction.mu_s : friction.mu_k;
  fm.description = {{"model", "rigid3d"},
                    {"shape", body.shape == BodyShape3d::Box ? "box" : "cylinder"},
                    {"width", body.shape == BodyShape3d::Box ? body.width : 2 * body.radius},
                    {"height", body.height},
                    {"mass", body.mass},
                    {"g", body.g},
                    {"mu_s", friction.mu_s},
                    {"mu_k", mu_k},
                    {"impact", to_string(friction.impact)},
                    {"painleve", "step"},
                    {"incidence_deg", incidence_deg},
                    {"alpha", fm.alpha},
                    {"p", fm.p}};
  if (body.shape == BodyShape3d::Box) fm.description["depth"] = body.depth;
  fm.overturn_rule = "the base vertical (tilt pi/2), in any direction";
  const Body3dRunOptions defaults;
  fm.tolerances = to_json(defaults.integ);
  fm.block_names = {"body"};
  fm.impact_definition = "a base point hitting the ground";
  fm.run3 = [body, friction](const GroundMotion3d& g3, double t_end) {
    const BodyOnGround m(body, g3, friction);
    Body3dRunOptions o;
    o.t_end = t_end;
    o.output_interval = 0;
    struct Ignore final : EventSink<Body3dEventRecord> {
      void on_event(const Body3dEventRecord&) override {}
    } ignore;  // counted in the result, not kept
    o.events = &ignore;
    const Body3dResult r = simulate_body3d(m, initial_state(body, {}), o);
    SurvivalOutcome out;
    out.moved = r.first_uplift_time >= 0 || r.first_slide_time >= 0;
    out.max_abs_rotation = r.max_tilt;
    out.max_sliding = r.max_slide;
    classify_block_end(out, r.status, r.overturn_time);
    return out;
  };
  fm.run = [run3 = fm.run3, incidence_deg](const GroundMotion& g, double t_end) {
    GroundMotion3d g3;
    g3.h = g.horizontal;
    g3.v = g.vertical;
    g3.azimuth = incidence_deg;
    return run3(g3, t_end);
  };
  return fm;
}

}  // namespace blockdyn
