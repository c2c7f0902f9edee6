// SPDX-License-Identifier: Apache-2.0
// Swings, swing-averaged energies, phase sampling and the long-term response classification
// (thesis sec. 4.4, Table 4.1).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "blockdyn/analysis/winkler/response_type.hpp"
#include "blockdyn/model/winkler/initial_conditions.hpp"

using namespace blockdyn;

namespace {

ResponseRun run(const WinklerParams& p, const WinklerState& z0, double t_end, double phase_dt = 0.0) {
  ResponseOptions o;
  o.t_end = t_end;
  o.phase_dt = phase_dt;
  return run_response(p, {}, z0, o);
}

// Evaluates w' on the dense output at given times, in a second identical run.
class RateProbe : public WinklerSink {
 public:
  explicit RateProbe(std::vector<double> times) : times_(std::move(times)), vw_(times_.size(), NAN) {}
  void on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double t0, double t1,
                  const WinklerMode& mode) override {
    for (std::size_t i = 0; i < times_.size(); ++i) {
      if (times_[i] < t0 || times_[i] > t1) continue;
      WinklerState z;
      seg.eval(times_[i], z);
      m.complete(mode, z);
      vw_[i] = z[kVW];
    }
  }
  const std::vector<double>& vw() const { return vw_; }

 private:
  std::vector<double> times_, vw_;
};

int response_cli(const std::string& args) {
  const int rc = std::system((std::string(BLOCKDYN_CLI) + " " + args + " >/dev/null 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

}  // namespace

TEST(ResponseSwings, TurningPointsAreRootsOfAngularVelocity) {
  const WinklerParams p{0.5, 0.0, 100};  // steady rocking, no flight
  const auto r = run(p, ic1(p), 30);
  ASSERT_GT(r.swings.size(), 10u);
  EXPECT_EQ(r.swings.front().t_start, 0.0);  // ic1 is released from rest: a turning point
  std::vector<double> ends;
  for (const auto& s : r.swings) ends.push_back(s.t_end);
  RateProbe probe(ends);
  WinklerRunOptions o;
  o.t_end = 30;
  o.record_events = false;
  simulate(p, {}, ic1(p), o, &probe);
  double max_vw = 0;  // scale of w', from a sampled run
  for (const auto& s : run(p, ic1(p), 30, 0.01).phase) max_vw = std::max(max_vw, std::fabs(s.s.vw));
  ASSERT_GT(max_vw, 0.1);
  for (std::size_t i = 0; i < ends.size(); ++i) EXPECT_LT(std::fabs(probe.vw()[i]), 1e-12 * max_vw) << "swing " << i;
  // Consecutive swings share their turning point.
  for (std::size_t i = 1; i < r.swings.size(); ++i) EXPECT_EQ(r.swings[i].t_start, r.swings[i - 1].t_end);
}

TEST(ResponseSwings, AveragedTotalEnergyLiesInTheRangeOfTheEnergy) {
  // The swing average of E(t) must lie within [E0 - max|E - E0|, E0 + max|E - E0|].
  const WinklerParams p{0.5, 0.0, 1e4};  // zero-friction rock-flight: E changes only by W_nonpotential
  const auto r = run(p, ic1(p), 40);
  const double e0 = r.result.initial_energy.total(), spread = r.result.max_abs_energy_change;
  ASSERT_GT(r.swings.size(), 20u);
  for (const auto& s : r.swings) EXPECT_LE(std::fabs(s.average.total() - e0), spread + 1e-12);
  // Components are averages of non-negative quantities where they must be.
  for (const auto& s : r.swings) {
    EXPECT_GE(s.average.rotation, 0.0);
    EXPECT_GE(s.average.kinetic_y, 0.0);
    EXPECT_GE(s.average.springs, 0.0);
  }
}

// The swing averages integrate the energy components over the step ends with the trapezoidal
// end corrections (their rates): against the same run sampled every 5e-6 (about 200 samples a
// step), every component of every swing agrees to 5e-5 of the swing's energy scale (measured
// 7e-6; the plain trapezoidal rule at two samples a step was off by 1e-3, in kinetic_y and
// springs, which exchange energy at the vertical frequency).
TEST(ResponseSwings, AveragesMatchAFinelySampledRun) {
  const WinklerParams p{0.5, 0.1, 1e5};
  ResponseOptions o;
  o.t_end = 20;
  const ResponseRun coarse = run_response(p, {}, ic1(p), o);
  o.quadrature_dt = 5e-6;
  const ResponseRun fine = run_response(p, {}, ic1(p), o);
  ASSERT_GT(coarse.swings.size(), 100u);
  ASSERT_EQ(coarse.swings.size(), fine.swings.size());
  for (std::size_t i = 0; i < fine.swings.size(); ++i) {
    const Energy& a = coarse.swings[i].average;
    const Energy& b = fine.swings[i].average;
    EXPECT_NEAR(coarse.swings[i].t_end, fine.swings[i].t_end, 1e-12);
    const double scale = std::fabs(b.rotation) + std::fabs(b.springs) + std::fabs(b.kinetic_y);
    const double da[5] = {a.kinetic_x - b.kinetic_x, a.kinetic_y - b.kinetic_y, a.rotation - b.rotation,
                          a.gravity - b.gravity, a.springs - b.springs};
    for (int c = 0; c < 5; ++c) EXPECT_LT(std::fabs(da[c]), 5e-5 * scale) << "swing " << i << ", component " << c;
  }
}

TEST(ResponseSwings, DissipationMakesAveragedEnergyDecrease) {
  const WinklerParams p{0.5, 0.1, 1e5};  // settle down
  const auto r = run(p, ic1(p), 20);
  ASSERT_GT(r.swings.size(), 10u);
  const double tol = 2.0 * std::fabs(r.result.work_nonpotential()) + 1e-9;
  for (std::size_t i = 1; i < r.swings.size(); ++i)
    EXPECT_LE(r.swings[i].average.total(), r.swings[i - 1].average.total() + tol) << "swing " << i;
}

TEST(ResponseSwings, PhaseSamplesAtConstantIntervals) {
  const WinklerParams p{0.2, 0.2, 1e3};
  const double dt = 0.05, t_end = 20;
  const auto r = run(p, ic1(p), t_end, dt);
  ASSERT_EQ(r.phase.size(), std::size_t(std::floor(t_end / dt + 1e-9)) + 1);
  for (std::size_t i = 0; i < r.phase.size(); ++i) EXPECT_NEAR(r.phase[i].t, i * dt, 1e-12);
}

TEST(ResponseSwings, SwingLengthsFollowTheThesisFigure457) {
  // Steady rocking: nearly constant swing length; settle down: swings shrink to almost nothing.
  const WinklerParams rock{0.5, 0.0, 100};
  const auto a = run(rock, ic1(rock), 100);
  EXPECT_LT(a.report.metrics.late_swing_length_cv, 0.05);
  const WinklerParams settle{0.5, 0.1, 1e5};
  const auto b = run(settle, ic1(settle), 60);
  EXPECT_LT(b.report.metrics.late_swing_length, 0.2 * b.report.metrics.early_swing_length);
}

// One Table 4.1 point per type. The OCR garbles the k exponents; these k values reproduce the
// tabulated types (see docs/response.md).
struct TablePoint {
  const char* fig;
  double mu, r, k;
  bool ic2;
  double t_end;
  ResponseType expected;
};

class ResponseTable41 : public ::testing::TestWithParam<TablePoint> {};

TEST_P(ResponseTable41, ClassifiesAsInTheThesis) {
  const TablePoint& tp = GetParam();
  const WinklerParams p{tp.r, tp.mu, tp.k};
  ResponseOptions o;
  o.t_end = tp.t_end;
  const auto rep = classify_response(p, {}, tp.ic2 ? ic2(p) : ic1(p), o);
  EXPECT_EQ(rep.type, tp.expected) << "Fig. " << tp.fig << ": got " << to_string(rep.type) << " (" << rep.reason << ")";
}

INSTANTIATE_TEST_SUITE_P(
    ResponseTable, ResponseTable41,
    ::testing::Values(TablePoint{"4.41", 0.0, 0.5, 1e2, false, 100, ResponseType::SteadyRocking},
                      TablePoint{"4.42", 0.0, 0.5, 1e4, false, 100, ResponseType::ZeroFrictionRockFlight},
                      // Frictionless and chaotic: over t = 100 the late rotational share is not
                      // converged in the tolerance (0.70 at rtol 1e-9, 0.23-0.36 at 1e-10..1e-12,
                      // 0.70-0.78 with another step sequence of the same model); over t = 200 it
                      // is rock-to-vertical in all of these runs.
                      TablePoint{"4.43", 0.0, 0.1, 1e6, false, 200, ResponseType::RockToVertical},
                      TablePoint{"4.45", 0.0, 0.5, 1e4, true, 100, ResponseType::ZeroFrictionRockFlight},
                      TablePoint{"4.47", 0.2, 0.2, 1e3, false, 100, ResponseType::SteadyRocking},
                      TablePoint{"4.49", 0.1, 0.5, 1e5, false, 60, ResponseType::SettleDown},
                      TablePoint{"4.50", 0.3, 0.2, 1e5, false, 100, ResponseType::RockToVertical},
                      TablePoint{"4.51", 0.2, 0.1, 1e6, false, 100, ResponseType::RockToVertical},
                      TablePoint{"4.53", 0.2, 0.3, 1e4, true, 100, ResponseType::SteadyRocking},
                      TablePoint{"4.54", 0.1, 0.2, 1e4, true, 100, ResponseType::SettleDown},
                      // k = 1e5 of the OCR's "1e5 or 1e6": with k = 1e6 the late rotational
                      // share sits on the settle-down threshold 0.1 (0.03-0.5 over t = 100..1000
                      // as the step sequence changes, so settle down in some runs). With k = 1e5
                      // it is 0.36-0.60 and the late flight fraction 0.22-0.57 at rtol
                      // 1e-9..1e-12: rock to vertical by a wide margin, in every run.
                      TablePoint{"4.55", 0.2, 0.15, 1e5, true, 100, ResponseType::RockToVertical},
                      // Below k_uns(0.2) no stable equilibrium exists: the block falls over.
                      TablePoint{"(k<k_uns)", 0.2, 0.2, 1e2, false, 20, ResponseType::Overturned}),
    [](const ::testing::TestParamInfo<TablePoint>& point) {
      // "Fig4_41", ..., "BelowKuns": readable names in ctest's listing.
      std::string name = point.param.fig[0] == '(' ? "BelowKuns" : std::string("Fig") + point.param.fig;
      for (char& c : name)
        if (c == '.') c = '_';
      return name;
    });

// Blocks that flew and came to rest (issue 12): r = 1, mu = 0.2, t = 30 as in the response map.
// They used to be labelled steady rocking (no late flight). Settled needs E < 0 late (flight
// impossible) and at most 1e-2 of the available energy left above rest.
// The points are settled at rtol 1e-9 ... 1e-12. Not k = 1e7 with ic1 (here until 2026-11-26):
// whether the vertical energy left after its chaotic transient is above rest (it bounces on the
// undamped springs for ever: settle down) or below (settled) is a knife edge, +-1e-7, that the
// tolerance or an ulp-level change of the engine flips either way.
TEST(ResponseSettled, BlocksThatFlewAndCameToRestAreSettled) {
  ResponseOptions o;
  o.t_end = 30;
  for (const auto& [k, use_ic2] :
       {std::pair{1e6, true}, std::pair{1e4, true}, std::pair{1e6, false}, std::pair{5e6, true}}) {
    const WinklerParams p{1.0, 0.2, k};
    const auto rep = classify_response(p, {}, use_ic2 ? ic2(p) : ic1(p), o);
    const auto& m = rep.metrics;
    SCOPED_TRACE("k = " + std::to_string(k) + (use_ic2 ? " ic2" : " ic1") + ": " + rep.reason);
    EXPECT_EQ(rep.type, ResponseType::Settled);
    EXPECT_GT(m.takeoffs, 0);  // it flew first
    EXPECT_EQ(m.late_takeoffs, 0);
    EXPECT_LT(m.late_energy_max, 0.0);
    EXPECT_LE(m.late_energy_fraction, o.criteria.settled_energy);
    // The criterion decides: demanding less energy than what is left makes it something else.
    ResponseCriteria strict;
    strict.settled_energy = 0.5 * m.late_energy_fraction;
    EXPECT_NE(classify(p, m, strict).type, ResponseType::Settled);
  }
}

TEST(ResponseSettled, HoppingAndRockingBlocksAreNotSettled) {
  ResponseOptions o;
  o.t_end = 30;
  // k = 1e7, ic2: all the rocking gone but the block still hops (E >= 0): settle down.
  const WinklerParams hop{1.0, 0.2, 1e7};
  const auto a = classify_response(hop, {}, ic2(hop), o);
  EXPECT_EQ(a.type, ResponseType::SettleDown) << a.reason;
  EXPECT_GE(a.metrics.late_energy_max, 0.0);
  // k = 10, ic2: slides and loses 97 % of its energy but keeps rocking with 3 % of it on the soft
  // foundation; the swing length stays constant: steady rocking.
  const WinklerParams soft{1.0, 0.2, 10};
  const auto b = classify_response(soft, {}, ic2(soft), o);
  EXPECT_EQ(b.type, ResponseType::SteadyRocking) << b.reason;
  EXPECT_GT(b.metrics.late_energy_fraction, o.criteria.settled_energy);
  // Without friction nothing is lost (up to the two-corner non-potential work of the model, a
  // few 1e-6 here): never settled.
  const WinklerParams rock{0.5, 0.0, 100};
  const auto c = classify_response(rock, {}, ic1(rock), o);
  EXPECT_EQ(c.type, ResponseType::SteadyRocking) << c.reason;
  EXPECT_GT(c.metrics.late_energy_fraction, 0.99);
}

TEST(ResponseClassify, CriteriaAreReportedAndValidated) {
  const WinklerParams p{0.5, 0.1, 1e5};
  ResponseOptions o;
  o.t_end = 30;
  o.criteria.settle_dissipation = 1.5;
  EXPECT_THROW(classify_response(p, {}, ic1(p), o), std::invalid_argument);
  o.criteria = {};
  o.t_end = -1;
  EXPECT_THROW(classify_response(p, {}, ic1(p), o), std::invalid_argument);
  o.t_end = 30;
  const auto rep = classify_response(p, {}, ic1(p), o);
  EXPECT_EQ(rep.type, ResponseType::SettleDown);
  EXPECT_NE(rep.reason.find("dissipated"), std::string::npos);
  EXPECT_GT(rep.metrics.dissipated_fraction, 0.9);
}

TEST(ResponseCli, BadInputExitsWithStatus2) {
  EXPECT_EQ(response_cli("response --t-end -5"), 2);
  EXPECT_EQ(response_cli("response --settle-dissipation 2 --t-end 1"), 2);
  EXPECT_EQ(response_cli("response --settled-energy 0 --t-end 1"), 2);
  EXPECT_EQ(response_cli("response --energy-axis cubic --t-end 1"), 2);
  EXPECT_EQ(response_cli("response --r -1 --t-end 1"), 2);
  EXPECT_EQ(response_cli("response --ic ic1 --w0 5 --t-end 1"), 2);
  EXPECT_EQ(response_cli("response --mu 0 --r 0.5 --k 100 --t-end 5"), 0);
}

// --energy-axis log: the energy panel of the plot on a symmetric-log axis (issue 12: early rises
// of small components visible). matplotlib writes each text of the SVG as a comment.
TEST(ResponseCli, LogEnergyAxisReachesThePlot) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "matplotlib not available for /usr/bin/python3";
  const auto dir = std::filesystem::temp_directory_path() / ("blockdyn_resp_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto svg_text = [&](const std::string& axis) {
    const std::string png = (dir / (axis + ".png")).string();
    EXPECT_EQ(response_cli("response --mu 0 --r 0.5 --k 100 --t-end 20 --energy-axis " + axis + " --plot " + png), 0);
    std::ifstream in((dir / (axis + ".svg")).string());
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string log = svg_text("log"), lin = svg_text("lin");
  EXPECT_NE(log.find("swing-averaged energy (symmetric log)"), std::string::npos);
  EXPECT_EQ(lin.find("symmetric log"), std::string::npos);
  EXPECT_NE(lin.find("swing-averaged energy"), std::string::npos);
  std::filesystem::remove_all(dir);
}
