// SPDX-License-Identifier: Apache-2.0
// Record files: the AT2 writer's text reads back to the very samples written (extremes included),
// the readers refuse what is not a decimal number, not an acceleration in g, or a CSV header that
// names other columns, and honour a header that swaps the columns.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/excitation/accelerogram.hpp"
#include "blockdyn/io/at2_writer.hpp"

using namespace blockdyn;

namespace {

std::string error_of(const std::string& text, bool at2) {
  try {
    if (at2)
      parse_at2(text, "r.AT2");
    else
      parse_record_csv(text, "r.csv");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

std::string at2_with_line3(const std::string& line3) {
  return "title\nevent\n" + line3 + "\nNPTS= 3, DT= 0.01 SEC\n 0.1 0.2 0.3\n";
}

}  // namespace

TEST(RecordFiles, At2TextReadsBackBitForBit) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  std::vector<double> a = {0.0,
                           -0.0,
                           tiny,
                           -tiny,
                           DBL_MIN,
                           -DBL_MIN,
                           1e-300,
                           -1e-300,
                           1e-219,
                           -7.786353410e-219,
                           100.0,
                           -100.0,
                           std::nextafter(100.0, 0.0),
                           0.1,
                           -1.0 / 3.0};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> mant(-1.0, 1.0);
  std::uniform_int_distribution<int> expo(-320, 1);
  for (int i = 0; i < 2000; ++i) a.push_back(std::ldexp(mant(rng), expo(rng) * 3));
  const std::string text = at2_text(a, 1.0 / 3.0 * 0.01, "round trip");
  const Accelerogram r = parse_at2(text, "round-trip.AT2");
  ASSERT_EQ(r.size(), a.size());
  EXPECT_EQ(r.dt(), 1.0 / 3.0 * 0.01);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(r.values()[i], a[i]) << i;
    EXPECT_EQ(std::signbit(r.values()[i]), std::signbit(a[i])) << i;
  }
}

TEST(RecordFiles, At2FieldsNeverTouchEvenForTheLargestDouble) {
  // The widest numbers the writer can meet fit its 25-character field with a space to spare.
  for (double v : {-DBL_MAX, -DBL_MIN, -std::numeric_limits<double>::denorm_min(), -2.2250738585072014e-308}) {
    const std::string s = scientific_text(v);
    EXPECT_LE(s.size(), 24u) << s;
    double back = 0;
    ASSERT_TRUE(parse_decimal(s, back)) << s;
    EXPECT_EQ(back, v);
  }
  const std::string text = at2_text({-DBL_MIN, -DBL_MIN, -DBL_MIN}, 0.01, "t");
  const std::string line = text.substr(text.rfind("SEC\n") + 4);
  EXPECT_EQ(line.size(), 3u * 25u + 1u);
  EXPECT_EQ(line[0], ' ');
}

TEST(RecordFiles, NumbersAreDecimalOnly) {
  double v = 0;
  for (const char* ok : {"1", "-2.5", "+.5", "5.", "1e-3", "1.5D+02", "4.9406564584124654E-324", "1e-400"})
    EXPECT_TRUE(parse_decimal(ok, v)) << ok;
  EXPECT_TRUE(parse_decimal("1.5D+02", v) && v == 150.0);
  for (const char* bad : {"", "0x10", "0x1p-7", "inf", "-inf", "nan", "1e400", ".", "e5", "1e", "1.2.3", "1,5", " 1"})
    EXPECT_FALSE(parse_decimal(bad, v)) << bad;
  EXPECT_NE(
      error_of("a\nb\nACCELERATION IN UNITS OF G\nNPTS= 3, DT= 0.01\n 0x10 0 0\n", true).find("'0x10' is not a number"),
      std::string::npos);
  EXPECT_NE(error_of("a\nb\nACCELERATION IN UNITS OF G\nNPTS= 3, DT= 0x1p-7\n 0 0 0\n", true).find("line 4"),
            std::string::npos);
  EXPECT_NE(error_of("t,a\n0,0\n0.01,inf\n", false).find("r.csv:3"), std::string::npos);
}

TEST(RecordFiles, At2UnitsLineIsRead) {
  EXPECT_EQ(error_of(at2_with_line3("ACCELERATION TIME SERIES IN UNITS OF G"), true), "(no error)");
  EXPECT_EQ(error_of(at2_with_line3("ACCELERATION TIME HISTORY IN UNITS OF G."), true), "(no error)");
  const std::string cm = error_of(at2_with_line3("ACCELERATION TIME SERIES IN UNITS OF CM/S/S"), true);
  EXPECT_NE(cm.find("r.AT2:3"), std::string::npos) << cm;
  EXPECT_NE(cm.find("CM/S/S"), std::string::npos) << cm;
  const std::string vel = error_of(at2_with_line3("VELOCITY TIME SERIES IN UNITS OF CM/S"), true);
  EXPECT_NE(vel.find("velocity"), std::string::npos) << vel;
  EXPECT_NE(error_of(at2_with_line3("DISPLACEMENT TIME SERIES IN UNITS OF CM"), true).find("displacement"),
            std::string::npos);
  EXPECT_NE(error_of(at2_with_line3("ACCELERATION (GAL)"), true).find("GAL"), std::string::npos);
}

TEST(RecordFiles, CsvHeaderNamesTheColumns) {
  const Accelerogram ta = parse_record_csv("t,a\n0,0.1\n0.5,0.2\n1.5,0.3\n", "ta.csv");
  const Accelerogram at = parse_record_csv("a,t\n0.1,0\n0.2,0.5\n0.3,1.5\n", "at.csv");
  ASSERT_EQ(at.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(at.time(i), ta.time(i));
    EXPECT_EQ(at.values()[i], ta.values()[i]);
  }
  EXPECT_EQ(at.time(2), 1.5);
  EXPECT_EQ(error_of("time (s), acceleration (g)\n0,0\n1,0.1\n", false), "(no error)");
  EXPECT_EQ(error_of("0,0\n1,0.1\n", false), "(no error)");  // no header: t, a
  EXPECT_NE(error_of("foo,bar\n0,0\n1,0.1\n", false).find("must name the columns"), std::string::npos);
  EXPECT_NE(error_of("t,a_ms2 (m/s^2)\n0,0\n1,0.1\n", false).find("not in g"), std::string::npos);
  EXPECT_NE(error_of("t,v\n0,0\n1,0.1\n", false).find("must name the columns"), std::string::npos);
}

TEST(RecordFiles, MessagesNameTheValueGiven) {
  const std::string small = error_of("a\nb\nUNITS OF G\nNPTS= 3, DT= 1e-200\n 0 0 0\n", true);
  EXPECT_NE(small.find("DT = 1e-200"), std::string::npos) << small;
  const std::string big = error_of("a\nb\nUNITS OF G\nNPTS= 3, DT= 1e300\n 0 0 0\n", true);
  EXPECT_NE(big.find("DT = 1e+300"), std::string::npos) << big;
  EXPECT_EQ(number_text(-5.0), "-5");
  EXPECT_EQ(number_text(0.1), "0.1");
  EXPECT_EQ(number_text(1e-200), "1e-200");
}
