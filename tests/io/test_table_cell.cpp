// SPDX-License-Identifier: Apache-2.0
// Table cells: the CSV writer and its reader. Whatever the writer writes reads back to cells that
// write the same bytes (a resumed sweep's CSV equals an uninterrupted one), numbers to the same
// bits, and a label never turns into a number on the way.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "blockdyn/io/table_cell.hpp"

namespace blockdyn::table_cell_test {

TEST(TableCell, WriterAndReaderRoundTripToTheSameBytesAndBits) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const CellRow row{std::size_t(7),
                    0.1 + 0.2,
                    -0.0,
                    1e16,
                    -1234567890123456789LL,
                    1e-300,
                    std::numeric_limits<double>::infinity(),
                    nan,
                    -nan,
                    Cell(),
                    "collapse",
                    "0012",
                    "a,b \"quoted\"",
                    "nan-like-label",
                    "1e5x",
                    "0x10",
                    Cell::maybe(std::nullopt),
                    Cell::maybe(2.5)};
  const std::string line = csv_line(row);
  ASSERT_EQ(line.back(), '\n');
  const CellRow back = parse_csv_row(line.substr(0, line.size() - 1));
  ASSERT_EQ(back.size(), row.size());
  EXPECT_EQ(csv_line(back), line);
  for (std::size_t i = 0; i < row.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(back[i].empty(), row[i].empty());
    if (row[i].is_number() && !std::isnan(row[i].number())) {
      EXPECT_EQ(back[i].number(), row[i].number());
      EXPECT_EQ(std::signbit(back[i].number()), std::signbit(row[i].number()));
    }
    if (row[i].kind() == Cell::Kind::label) {
      EXPECT_EQ(back[i].kind(), Cell::Kind::label) << row[i].label();
      EXPECT_EQ(back[i].text(), row[i].label());
    }
  }
  EXPECT_TRUE(std::isnan(back[7].number()));
  EXPECT_EQ(back[4].integer(), -1234567890123456789LL);
  EXPECT_EQ(csv_cell(row[1]), "0.30000000000000004");
  EXPECT_EQ(csv_cell(row[12]), "\"a,b \"\"quoted\"\"\"");
}

TEST(TableCell, ShortestDigitsAndQuotedLabels) {
  EXPECT_EQ(csv_cell(Cell::shortest(0.1)), "0.1");
  EXPECT_EQ(csv_cell(Cell(0.1)), "0.10000000000000001");
  EXPECT_EQ(csv_cell(Cell::shortest(0.1 + 0.2)), "0.30000000000000004");
  EXPECT_EQ(csv_cell(Cell::shortest(-std::numeric_limits<double>::quiet_NaN())), "nan");
  EXPECT_EQ(csv_cell(Cell::quoted("(1,3)")), "\"(1,3)\"");
  EXPECT_EQ(csv_cell(Cell::quoted("non-periodic")), "\"non-periodic\"");
  EXPECT_EQ(csv_cell(Cell("non-periodic")), "non-periodic");
  EXPECT_TRUE(Cell(std::string()).empty());
}

TEST(TableCell, AccessorsRefuseWhatACellIsNot) {
  EXPECT_THROW(Cell().number(), std::runtime_error);
  EXPECT_THROW(Cell("rest").number(), std::runtime_error);
  EXPECT_THROW(Cell(0.5).integer(), std::runtime_error);
  EXPECT_THROW(Cell(2.0).label(), std::runtime_error);
  EXPECT_EQ(Cell(2.0).integer(), 2);
  EXPECT_FALSE(Cell().optional_number());
  EXPECT_EQ(Cell(3).text(), "3");
  EXPECT_EQ(Cell().text(), "");
}

TEST(TableCell, ATableWritesItsHeaderThenItsRows) {
  CellTable t;
  t.columns = {"t", "mode"};
  t.rows.push_back({0.5, "rock"});
  t.rows.push_back({1.0, Cell()});
  std::ostringstream os;
  write_csv(os, t);
  EXPECT_EQ(os.str(), "t,mode\n0.5,rock\n1,\n");
  EXPECT_EQ(t.column("mode"), 1u);
  EXPECT_THROW(t.column("x"), std::invalid_argument);
}

}  // namespace blockdyn::table_cell_test
