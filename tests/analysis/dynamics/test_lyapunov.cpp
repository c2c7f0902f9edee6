// SPDX-License-Identifier: Apache-2.0
// Largest Lyapunov exponent: the two-trajectory estimator on hybrid toy systems with known
// exponents, then sign expectations on the block (thesis sec. 5.3: > 1 in rock to vertical,
// > 2 with mu = 0, ~0 in steady rocking and settle down).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

#include "blockdyn/analysis/winkler/lyapunov_block.hpp"
#include "blockdyn/model/winkler/initial_conditions.hpp"

using namespace blockdyn;

namespace {

struct SideMode {
  int side = 1;
};

// Common adapter for the toys: Euclidean metric on the whole state, mode = side of the
// switching surface, section = that surface.
template <std::size_t N, int SwitchIndex, int CrossIndex>
struct ToyAdapter {
  using State = Vec<N>;
  double distance(const SideMode&, const State& a, const SideMode&, const State& b) const {
    double s = 0;
    for (std::size_t i = 0; i < N; ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(s);
  }
  bool compatible(const SideMode& a, const SideMode& b) const { return a.side == b.side; }
  void rescale(const SideMode&, const State& zr, SideMode&, State& zp, double s) const {
    for (std::size_t i = 0; i < N; ++i) zp[i] = zr[i] + s * (zp[i] - zr[i]);
  }
  void perturb(const SideMode& mr, const State& zr, double d, SideMode& mp, State& zp) const {
    mp = mr;
    zp = zr;
    for (std::size_t i = 0; i < N; ++i) zp[i] += d / std::sqrt(double(N));
    zp[SwitchIndex] = zr[SwitchIndex] + mr.side * d / std::sqrt(double(N));  // stay on the side
  }
  bool is_section_event(int e) const { return e == 0; }
  int crossing_sign(const State& z) const { return z[CrossIndex] > 0 ? 1 : -1; }
};

// Base for one-switching-surface toys: event 0 is side * z[S] >= 0, crossing flips the side.
template <std::size_t N, int S>
struct ToyBase {
  static constexpr std::size_t kDim = N;
  static constexpr std::size_t kNumEvents = 1;
  using Mode = SideMode;
  void events(double, const Mode& m, const Vec<N>& z, std::array<double, 1>& g) const { g[0] = m.side * z[S]; }
  void complete(const Mode&, Vec<N>&) const {}
  Transition<Mode> transition(double, const Mode& m, const Vec<N>&, int) const { return {Mode{-m.side}, false, 0}; }
  std::optional<Transition<Mode>> resolve_chatter(double, const Mode&, const Vec<N>&) const { return std::nullopt; }
  double step_hint(const Mode&) const { return 0.1; }
  Vec<N> abs_tol_scale() const {
    Vec<N> s;
    s.fill(1.0);
    return s;
  }
};

// Oscillator with a different stiffness on each side of x = 0: isochronous, exponent 0.
struct SplitOscillator : ToyBase<2, 0> {
  double w_pos = 1.0, w_neg = 2.0;
  void rhs(double, const Mode& m, const Vec<2>& z, Vec<2>& dz) const {
    const double w = m.side > 0 ? w_pos : w_neg;
    dz = {z[1], -w * w * z[0]};
  }
};

// Inverted pendulum (theta'' = g sin theta; the reference sits on its unstable equilibrium,
// eigenvalue sqrt(g)) next to an oscillator in a V-shaped potential (x'' = -sign(x)) whose
// switching at x = 0 the reference passes through every half period.
struct SaddleAndRelay : ToyBase<4, 2> {
  double g = 2.25;
  void rhs(double, const Mode& m, const Vec<4>& z, Vec<4>& dz) const {
    dz = {z[1], g * std::sin(z[0]), z[3], -double(m.side)};
  }
};

// Spiral with growth sigma_+ for y > 0 and sigma_- for y < 0; each half turn takes pi, so both
// exponents equal (sigma_+ + sigma_-) / 2. The vector field jumps across y = 0 (non-trivial
// saltation).
struct SplitSpiral : ToyBase<2, 1> {
  double s_pos = 0.35, s_neg = -0.15;
  void rhs(double, const Mode& m, const Vec<2>& z, Vec<2>& dz) const {
    const double s = m.side > 0 ? s_pos : s_neg;
    dz = {s * z[0] - z[1], z[0] + s * z[1]};
  }
};

template <class M, class A>
LyapunovResult estimate(const M& m, const A& a, SideMode m0, Vec<M::kDim> z0, LyapunovMethod method, double t_end,
                        double d0 = 1e-8) {
  LyapunovOptions o;
  o.method = method;
  o.t_end = t_end;
  o.d0 = d0;
  const LyapunovEstimator<M, A> est(m, a, o);
  return est.run(m0, z0);
}

LyapunovResult block(const WinklerParams& p, const WinklerState& z0, double t_end,
                     LyapunovMethod method = LyapunovMethod::Time, double d0 = 1e-8) {
  LyapunovOptions o;
  o.t_end = t_end;
  o.method = method;
  o.d0 = d0;
  return block_lyapunov(p, z0, o);
}

int lyapunov_cli(const std::string& args) {
  const int rc = std::system((std::string(BLOCKDYN_CLI) + " " + args + " >/dev/null 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

}  // namespace

TEST(LyapunovToy, SplitOscillatorHasZeroExponent) {
  const SplitOscillator m;
  const ToyAdapter<2, 0, 1> a;
  for (auto method : {LyapunovMethod::Time, LyapunovMethod::Section}) {
    const auto r = estimate(m, a, SideMode{1}, Vec<2>{1.0, 0.0}, method, 500);
    EXPECT_EQ(r.status, LyapunovStatus::Completed);
    EXPECT_LT(std::fabs(r.exponent), 0.01) << to_string(method);
    EXPECT_GT(r.renormalisations, 100);
  }
}

TEST(LyapunovToy, OrbitOnAnUnstableEquilibriumGivesItsEigenvalue) {
  const SaddleAndRelay m;
  const ToyAdapter<4, 2, 3> a;
  for (auto method : {LyapunovMethod::Time, LyapunovMethod::Section}) {
    const auto r = estimate(m, a, SideMode{1}, Vec<4>{0.0, 0.0, 1.0, 0.0}, method, 200);
    EXPECT_EQ(r.status, LyapunovStatus::Completed);
    EXPECT_NEAR(r.exponent, std::sqrt(m.g), 0.015) << to_string(method);
  }
}

TEST(LyapunovToy, SwitchedSpiralGivesTheMeanGrowthRate) {
  SplitSpiral m;
  const ToyAdapter<2, 1, 0> a;
  for (auto method : {LyapunovMethod::Time, LyapunovMethod::Section}) {
    const auto r = estimate(m, a, SideMode{1}, Vec<2>{1.0, 0.0}, method, 100, 1e-4);
    EXPECT_NEAR(r.exponent, 0.5 * (m.s_pos + m.s_neg), 0.01) << to_string(method);
  }
  m.s_pos = 0.3;
  m.s_neg = -0.3;  // a closed orbit although each half expands or contracts
  const auto r = estimate(m, a, SideMode{1}, Vec<2>{1.0, 0.0}, LyapunovMethod::Time, 200, 1e-6);
  EXPECT_LT(std::fabs(r.exponent), 0.01);
}

TEST(LyapunovBlock, RockToVerticalIsChaotic) {
  const WinklerParams p{0.1, 0.2, 1e6};
  const auto r = block(p, ic1(p), 100);
  EXPECT_EQ(r.status, LyapunovStatus::Completed);
  EXPECT_GT(r.exponent, 1.0);  // thesis: larger than 1
  EXPECT_GT(tail_exponent(r, 50), 0.8);
}

TEST(LyapunovBlock, ZeroFrictionExponentsExceedTwoOrNearly) {
  const WinklerParams tall{0.1, 0.0, 1e6};               // rock to vertical with mu = 0
  EXPECT_GT(block(tall, ic1(tall), 100).exponent, 2.0);  // thesis: larger than 2 for mu = 0
  const WinklerParams wide{0.5, 0.0, 1e4};               // zero-friction rock-flight
  const auto t = block(wide, ic1(wide), 150);
  const auto s = block(wide, ic1(wide), 150, LyapunovMethod::Section);
  EXPECT_GT(t.exponent, 1.5);
  EXPECT_NEAR(s.exponent, t.exponent, 0.15 * t.exponent);  // the two renormalisations agree
}

TEST(LyapunovBlock, SteadyRockingAndSettleDownAreNotChaotic) {
  const WinklerParams rock{0.5, 0.0, 100};
  const auto a = block(rock, ic1(rock), 300);
  EXPECT_LT(std::fabs(tail_exponent(a, 150)), 0.01);
  EXPECT_LT(std::fabs(a.exponent), 0.03);
  const WinklerParams settle{0.5, 0.1, 1e5};
  const auto b = block(settle, ic1(settle), 100);
  EXPECT_LT(std::fabs(tail_exponent(b, 50)), 0.05);  // after the transient the orbit is regular
}

TEST(LyapunovBlock, PairedIntegrationMakesTheEstimateIndependentOfD0) {
  // Integration errors common to both copies cancel; with independent integrations they would
  // bias a zero exponent upwards the more, the smaller d0.
  const WinklerParams p{0.5, 0.0, 100};
  const double e7 = block(p, ic1(p), 200, LyapunovMethod::Time, 1e-7).exponent;
  const double e10 = block(p, ic1(p), 200, LyapunovMethod::Time, 1e-10).exponent;
  EXPECT_NEAR(e7, e10, 1e-3);
}

TEST(LyapunovBlock, InvalidOptionsAreRejected) {
  const WinklerParams p{0.5, 0.0, 100};
  EXPECT_THROW(block(p, ic1(p), -1), std::invalid_argument);
  EXPECT_THROW(block(p, ic1(p), 10, LyapunovMethod::Time, 1.0), std::invalid_argument);
  EXPECT_EQ(lyapunov_cli("lyapunov --d0 1 --t-end 1"), 2);
  EXPECT_NE(lyapunov_cli("lyapunov --method bogus --t-end 1"), 0);  // CLI11 usage error
  EXPECT_EQ(lyapunov_cli("lyapunov --interval 0 --t-end 1"), 2);
  EXPECT_EQ(lyapunov_cli("lyapunov --mu 0 --r 0.5 --k 100 --t-end 5"), 0);
}
