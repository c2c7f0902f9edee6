// SPDX-License-Identifier: Apache-2.0
// Ground motions (issue 7, sec. 2): pulse shapes, PEER .AT2 and CSV records, breakpoints that the
// integrator lands on, time-unit conversion.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"

#include "test_support.hpp"

using namespace blockdyn;
using blockdyn::test::error_of;

namespace {

double integral(PulseShape p, double tp) {
  const double end = pulse_support(p) * tp;
  return boost::math::quadrature::gauss_kronrod<double, 61>::integrate([&](double s) { return pulse_value(p, s, tp); },
                                                                       0.0, end, 15, 1e-13);
}

}  // namespace

TEST(Pulses, ShapesAndTheirVelocityChange) {
  const double tp = 0.8;
  EXPECT_DOUBLE_EQ(pulse_value(PulseShape::Rect, 0.3, tp), 1.0);
  EXPECT_NEAR(pulse_value(PulseShape::HalfSine, 0.4, tp), 1.0, 1e-15);
  EXPECT_NEAR(pulse_value(PulseShape::HalfCosine, 0.0, tp), 1.0, 1e-15);
  EXPECT_NEAR(pulse_value(PulseShape::HalfCosine, tp, tp), -1.0, 1e-15);  // seed 002: changes sign
  EXPECT_NEAR(pulse_value(PulseShape::OneSine, 0.2, tp), 1.0, 1e-15);
  EXPECT_NEAR(pulse_value(PulseShape::Cycloidal, 0.4, tp), -1.0, 1e-15);
  EXPECT_NEAR(pulse_value(PulseShape::Ricker, 1.5 * tp, tp), 1.0, 1e-15);  // peak at the centre
  EXPECT_LT(std::fabs(pulse_value(PulseShape::Ricker, 0.0, tp)), 1.1e-8);
  EXPECT_EQ(pulse_value(PulseShape::Rect, tp * 1.0001, tp), 0.0);
  // Ground velocity change over the pulse: t_p (rect), 2 t_p / pi (half-sine), zero for the
  // full-cycle pulses and the Ricker wavelet (the ground comes back to rest).
  EXPECT_NEAR(integral(PulseShape::Rect, tp), tp, 1e-12);
  EXPECT_NEAR(integral(PulseShape::HalfSine, tp), 2.0 * tp / M_PI, 1e-12);
  EXPECT_NEAR(integral(PulseShape::HalfCosine, tp), 0.0, 1e-12);
  EXPECT_NEAR(integral(PulseShape::OneSine, tp), 0.0, 1e-12);
  EXPECT_NEAR(integral(PulseShape::Cycloidal, tp), 0.0, 1e-12);
  EXPECT_NEAR(integral(PulseShape::Ricker, tp), 0.0, 1e-8);
  for (const char* n : {"rect", "half-sine", "half-cosine", "one-sine", "ricker", "cycloidal"})
    EXPECT_STREQ(to_string(*pulse_from_string(n)), n);
  EXPECT_FALSE(pulse_from_string("sine"));
}

TEST(Accelerogram, At2HeaderVariants) {
  const std::string body = "  0.1  0.2\n -0.3 4.0E-01 0.5D+00\n";
  const Accelerogram a = parse_at2("h1\nh2\nh3\nNPTS=  5, DT=   .01000 SEC\n" + body, "a.AT2");
  EXPECT_EQ(a.size(), 5u);
  EXPECT_DOUBLE_EQ(a.dt(), 0.01);
  EXPECT_NEAR(a.at(0.005), 0.15, 1e-15);  // linear between samples
  EXPECT_NEAR(a.at(0.015), -0.05, 1e-15);
  EXPECT_DOUBLE_EQ(a.at(0.04), 0.5);
  EXPECT_EQ(a.at(0.0401), 0.0);  // zero after the record
  const Accelerogram b = parse_at2("h1\nh2\nh3\n5   0.01000   NPTS, DT\n" + body, "b.AT2");
  EXPECT_EQ(b.values(), a.values());
  const Accelerogram c = parse_at2("h1\nh2\nh3\nDT= 0.01 NPTS= 5\n" + body, "c.AT2");
  EXPECT_EQ(c.values(), a.values());
  EXPECT_NEAR(a.next_sample_after(0.02), 0.03, 1e-15);
  EXPECT_GT(a.next_sample_after(0.02), 0.02);
  EXPECT_TRUE(std::isinf(a.next_sample_after(0.04)));
}

TEST(Accelerogram, MalformedFilesNameTheProblem) {
  const std::string hdr = "h1\nh2\nh3\nNPTS=  5, DT=   .01000 SEC\n";
  EXPECT_NE(error_of([&] { parse_at2(hdr + "0.1 0.2 0.3\n", "t.AT2"); }).find("truncated"), std::string::npos);
  EXPECT_NE(error_of([&] { parse_at2(hdr + "0.1 0.2 x 0.4 0.5\n", "t.AT2"); }).find("not a number"), std::string::npos);
  EXPECT_NE(error_of([&] { parse_at2(hdr + "0.1 0.2 0.3 0.4 0.5 0.6\n", "t.AT2"); }).find("more values"),
            std::string::npos);
  EXPECT_NE(error_of([&] { parse_at2("h1\nh2\nh3\nno counts here\n0.1\n", "t.AT2"); }).find("NPTS"), std::string::npos);
  EXPECT_NE(error_of([&] { parse_at2("h1\nh2\n", "t.AT2"); }).find("truncated"), std::string::npos);
  EXPECT_NE(error_of([&] { parse_at2("h1\nh2\nh3\nNPTS= 2, DT= -0.1\n0 1\n", "t.AT2"); }).find("DT"),
            std::string::npos);
  EXPECT_NE(error_of([&] { parse_at2(hdr + "0.1 0.2 nan 0.4 0.5\n", "t.AT2"); }).find("t.AT2:5: 'nan' is not a number"),
            std::string::npos);
  EXPECT_NE(error_of([&] { parse_at2(hdr + "0.1 0.2 200 0.4 0.5\n", "t.AT2"); }).find("sample 3 = 200"),
            std::string::npos);
}

TEST(Accelerogram, TwoColumnCsv) {
  const Accelerogram a = parse_record_csv("t,a\n0,0\n0.02,0.1\n# comment\n0.04,-0.1\n0.06,0\n", "r.csv");
  EXPECT_TRUE(a.uniform());
  EXPECT_NEAR(a.at(0.03), 0.0, 1e-15);
  const Accelerogram b = parse_record_csv("0.0 0.0\n0.1 0.2\n0.15 0.1\n", "r.csv");  // uneven steps
  EXPECT_FALSE(b.uniform());
  EXPECT_NEAR(b.at(0.125), 0.15, 1e-15);
  EXPECT_DOUBLE_EQ(b.next_sample_after(0.1), 0.15);
  EXPECT_NE(error_of([] { parse_record_csv("0 0\n0.1 0.2\n0.1 0.3\n", "r.csv"); }).find("increasing"),
            std::string::npos);
  EXPECT_NE(error_of([] { parse_record_csv("0 0\n", "r.csv"); }).find("at least 2"), std::string::npos);
  EXPECT_NE(error_of([] { parse_record_csv("0 0\n0.1 zz\n", "r.csv"); }).find("r.csv:2"), std::string::npos);
}

TEST(GroundMotion, BreakpointsAndWindows) {
  GroundComponent c;
  c.pulse = PulseShape::HalfSine;
  c.amplitude = 0.3;
  c.duration = 0.5;
  c.t_start = 1.0;
  EXPECT_EQ(c.next_break(0.0), 1.0);
  EXPECT_EQ(c.next_break(1.0), 1.5);
  EXPECT_TRUE(std::isinf(c.next_break(1.5)));
  EXPECT_NEAR(c.at(1.25), 0.3, 1e-15);
  EXPECT_EQ(c.at(1.6), 0.0);
  GroundMotion g;
  g.horizontal.record = std::make_shared<const Accelerogram>(std::vector<double>{0, 1, 0, -1}, 0.1, "r");
  g.horizontal.t_start = 2.0;
  g.horizontal.scale = 2.0;
  EXPECT_NEAR(g.ah(2.15), 2.0 * 0.5, 4e-15);
  EXPECT_NEAR(g.next_break(2.05), 2.1, 1e-15);
  EXPECT_NEAR(g.next_break(2.1), 2.2, 1e-15);
  // Seconds -> a model time unit of 0.5 s: times halve, frequencies and the record's clock double.
  GroundMotion h;
  h.horizontal.amplitude = 0.2;
  h.horizontal.frequency = 1.0;
  h.horizontal.t_start = 1.0;
  h.horizontal.record = g.horizontal.record;
  const GroundMotion u = in_time_unit(h, 0.5);
  EXPECT_DOUBLE_EQ(u.horizontal.t_start, 2.0);
  EXPECT_DOUBLE_EQ(u.horizontal.frequency, 0.5);
  EXPECT_NEAR(u.ah(2.0 + 0.3), h.ah(1.0 + 0.15), 1e-15);
}

TEST(GroundMotion, InvalidInputIsRejected) {
  GroundMotion g;
  g.horizontal.pulse = PulseShape::Rect;
  g.horizontal.amplitude = 0.3;
  EXPECT_NE(error_of([&] { validate(g); }).find("ground.horizontal.duration"), std::string::npos);
  g.horizontal.duration = 0.5;
  g.horizontal.frequency = 2.0;
  EXPECT_NE(error_of([&] { validate(g); }).find("ground.horizontal.frequency"), std::string::npos);
  GroundMotion v;
  v.vertical.amplitude = 0.1;
  EXPECT_NE(error_of([&] { validate(v); }).find("ground.vertical.frequency"), std::string::npos);
}

// The integrator never steps across a record sample while the block moves: every sample time
// inside the run is the end of an accepted step (the input's kinks are breakpoints). A block
// that rocks without losses (e = 1) keeps moving through the whole record.
TEST(GroundMotion, IntegratorLandsOnEverySample) {
  struct Ends : Observer<HousnerBlock> {
    std::vector<double> t;
    bool on_segment(const HousnerBlock&, const Segment&, double, double t1, const Mode&) override {
      t.push_back(t1);
      return true;
    }
  } ends;
  std::vector<double> a;
  for (int i = 0; i < 200; ++i) a.push_back(0.5 * std::sin(0.37 * i) * (i % 3 == 0 ? 1.0 : -0.5));
  GroundMotion g;
  g.horizontal.record = std::make_shared<const Accelerogram>(a, 0.013, "r");
  BlockShape s;
  s.width = 0.3;
  s.height = 1.0;
  RigidRunOptions o;
  o.t_end = 2.0;
  RigidInitial in;
  in.w0 = 0.1;
  const RigidResult r = simulate_housner(s, 1.0, g, in, o, &ends);
  ASSERT_EQ(r.status, SimStatus::TEnd);
  ASSERT_EQ(r.event_counts[int(RigidEventKind::Mode)], 0);  // never at rest
  std::size_t found = 0;
  for (int i = 1; i < 153; ++i) {
    const double ti = 0.013 * i;
    for (double e : ends.t)
      if (std::fabs(e - ti) <= 4e-16 * ti) {
        ++found;
        break;
      }
  }
  EXPECT_EQ(found, 152u);
}
