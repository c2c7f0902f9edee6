// SPDX-License-Identifier: Apache-2.0
// Issue 40's comparison with Bullet (Debian's libbullet-dev): the rigid3d box under the 60 s
// synthetic record along x, in blockdyn (event-driven, exact contact events) and in Bullet
// (time-stepping with soft contacts: a box on a static plane, the ground's acceleration applied
// as the inertial force -m a_g(t), friction 0.7, restitution 0), at Bullet's default 240 Hz step
// and at finer steps, side by side in one run: wall time, the largest tilt, whether it overturns,
// and the largest tilt's agreement with blockdyn's. Not a test: a table for docs/performance.md.
#include <btBulletDynamicsCommon.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "blockdyn/simulation/rigid3d_simulation.hpp"

using namespace blockdyn;

namespace {

constexpr double kWidth = 0.3, kHeight = 1.2, kMass = 500, kMu = 0.7, kG = 9.81, kTEnd = 60;

struct Outcome {
  double seconds = 0, max_tilt = 0;
  bool overturned = false;
  long steps = 0;
};

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

Outcome run_blockdyn(const std::shared_ptr<const Accelerogram>& rec, double scale) {
  GroundMotion3d g;
  g.h.record = rec;
  g.h.scale = scale;
  BodyOnGroundOptions o;
  o.mu_s = o.mu_k = kMu;
  const BodyOnGround m(box_body(kWidth, kWidth, kHeight, kMass), g, o);
  Body3dRunOptions ro;
  ro.t_end = kTEnd;
  ro.output_interval = 0;
  // The largest tilt is tracked with the balance (located inside the steps): on, as users run it.
  struct Ignore final : EventSink<Body3dEventRecord> {
    void on_event(const Body3dEventRecord&) override {}
  } ignore;  // counted in the result (the largest tilt with them), not kept
  ro.events = &ignore;
  Outcome out;
  const int repeat = 5;
  double best = INFINITY;
  Body3dResult r;
  for (int k = 0; k < repeat; ++k) {
    const double t0 = now();
    r = simulate_body3d(m, initial_state(m.body(), {}), ro);
    best = std::fmin(best, now() - t0);
  }
  out.seconds = best;
  out.max_tilt = r.max_tilt;
  out.overturned = r.status == SimStatus::Overturned;
  out.steps = r.stats.accepted;
  return out;
}

Outcome run_bullet(const std::shared_ptr<const Accelerogram>& rec, double scale, double dt) {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, 0, -kG));
  btStaticPlaneShape plane(btVector3(0, 0, 1), 0);
  btRigidBody::btRigidBodyConstructionInfo gi(0, nullptr, &plane);
  gi.m_friction = 1.0;  // Bullet multiplies the two frictions: the box's is the contact's
  gi.m_restitution = 0;
  btRigidBody ground(gi);
  world.addRigidBody(&ground);
  btBoxShape box(btVector3(kWidth / 2, kWidth / 2, kHeight / 2));
  btVector3 inertia;
  box.calculateLocalInertia(kMass, inertia);
  btDefaultMotionState motion(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, kHeight / 2)));
  btRigidBody::btRigidBodyConstructionInfo bi(kMass, &motion, &box, inertia);
  bi.m_friction = kMu;
  bi.m_restitution = 0;
  btRigidBody body(bi);
  body.setActivationState(DISABLE_DEACTIVATION);
  world.addRigidBody(&body);
  Outcome out;
  const double t0 = now();
  const long n = long(std::llround(kTEnd / dt));
  for (long k = 0; k < n; ++k) {
    const double t = k * dt;
    const double a = rec->at(t) * scale;  // g, along x
    body.applyCentralForce(btVector3(-kMass * a * kG, 0, 0));
    world.stepSimulation(dt, 0);
    const btMatrix3x3& r = body.getWorldTransform().getBasis();
    const double tilt = std::acos(std::fmax(-1.0, std::fmin(1.0, r[2][2])));
    out.max_tilt = std::fmax(out.max_tilt, tilt);
    ++out.steps;
    if (tilt > 0.5 * M_PI) {
      out.overturned = true;
      break;
    }
  }
  out.seconds = now() - t0;
  world.removeRigidBody(&body);
  world.removeRigidBody(&ground);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const auto rec = std::make_shared<const Accelerogram>(
      load_accelerogram(std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2", "record"));
  std::printf("box %.2f x %.2f x %.2f m, %g kg, mu %.1f, the 60 s synthetic record along x\n", kWidth, kWidth, kHeight,
              kMass, kMu);
  std::printf("%-7s %-22s %12s %14s %11s %10s %14s\n", "scale", "simulator", "time [ms]", "max tilt [rad]",
              "overturned", "steps", "tilt vs blockdyn");
  std::vector<double> scales;
  for (int i = 1; i < argc; ++i) scales.push_back(std::stod(argv[i]));
  if (scales.empty()) scales = {1.0, 1.2, 1.4, 1.5};
  for (double scale : scales) {
    const Outcome b = run_blockdyn(rec, scale);
    std::printf("%-7.1f %-22s %12.3f %14.6g %11s %10ld %14s\n", scale, "blockdyn (events)", 1e3 * b.seconds, b.max_tilt,
                b.overturned ? "yes" : "no", b.steps, "-");
    for (double hz : {240.0, 1000.0, 4000.0, 16000.0}) {
      const Outcome u = run_bullet(rec, scale, 1.0 / hz);
      char label[32], agree[32];
      std::snprintf(label, sizeof label, "bullet %.0f Hz", hz);
      if (b.max_tilt > 0)
        std::snprintf(agree, sizeof agree, "%+.1f %%", 100 * (u.max_tilt - b.max_tilt) / b.max_tilt);
      else
        std::snprintf(agree, sizeof agree, "-");
      std::printf("%-7.1f %-22s %12.3f %14.6g %11s %10ld %14s\n", scale, label, 1e3 * u.seconds, u.max_tilt,
                  u.overturned ? "yes" : "no", u.steps, agree);
    }
  }
  return 0;
}
