// SPDX-License-Identifier: Apache-2.0
#pragma once
// A table as values: each cell a number, an integer, a label or nothing. Analyses build tables of
// cells and read them by column; only the CSV writer below turns a cell into text (numbers with
// enough digits to read back to the same double) and only its reader turns text back into cells
// (a journal resumed, a finished table read from disk). Nothing formats a row to parse it again.
#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace blockdyn {

class Cell {
 public:
  enum class Kind : unsigned char { empty, real, integer, label };

  Cell() = default;
  Cell(double v) : kind_(Kind::real), real_(v) {}
  template <class I>
  requires(std::is_integral_v<I> && !std::is_same_v<I, bool> && !std::is_same_v<I, char>) Cell(I v)
      : kind_(Kind::integer), integer_(static_cast<long long>(v)) {}
  // A label; an empty text is an empty cell (what an empty field reads back as).
  Cell(std::string s) : kind_(s.empty() ? Kind::empty : Kind::label), label_(std::move(s)) {}
  Cell(const char* s) : Cell(std::string(s)) {}
  Cell(bool) = delete;  // a flag is an integer 0 or 1: say so
  // A number written with the fewest of 15 or 17 significant digits that read back exactly ("nan"
  // for any NaN): the studies' tables, kept short for people reading them.
  static Cell shortest(double v) {
    Cell c(v);
    c.shortest_ = true;
    return c;
  }
  // A label always written in quotes (the cycles' "(m,n)" column keeps one look whatever the label).
  static Cell quoted(std::string s) {
    Cell c(std::move(s));
    c.quoted_ = c.kind_ == Kind::label;
    return c;
  }
  // An absent value: the cell is empty.
  static Cell maybe(const std::optional<double>& v) { return v ? Cell(*v) : Cell(); }

  Kind kind() const { return kind_; }
  bool empty() const { return kind_ == Kind::empty; }
  bool is_number() const { return kind_ == Kind::real || kind_ == Kind::integer; }
  // The value of a real or integer cell; std::runtime_error for an empty cell or a label.
  double number() const;
  std::optional<double> optional_number() const;  // empty: nullopt
  long long integer() const;                      // an integer cell (or a real with an integral value)
  const std::string& label() const;               // a label cell
  // A column of labels read back: the label, "" for an empty cell, and for a label that reads as
  // a number ("2", a cycle's period) the digits it was written with.
  std::string text() const;
  bool shortest_digits() const { return shortest_; }
  bool always_quoted() const { return quoted_; }

 private:
  Kind kind_ = Kind::empty;
  bool shortest_ = false;
  bool quoted_ = false;
  double real_ = 0.0;
  long long integer_ = 0;
  std::string label_;
};

using CellRow = std::vector<Cell>;

struct CellTable {
  std::vector<std::string> columns;
  std::vector<CellRow> rows;
  std::size_t column(const std::string& name) const;  // std::invalid_argument if absent
};

// The writer: a cell as CSV text (%.17g or the shortest exact digits; integers; labels quoted
// per RFC 4180 where they need it), a row as one line with its '\n', a table with its header.
std::string format_double(double v);  // %.17g
std::string csv_escape(const std::string& s);
std::string csv_cell(const Cell& c);
void append_csv_row(std::string& to, const CellRow& row);
std::string csv_line(const CellRow& row);
std::string csv_header(const std::vector<std::string>& columns);
void write_csv(std::ostream& os, const CellTable& t);

// The reader: one CSV line (no '\n') split per RFC 4180, each field typed: an integer, else a
// number (what %.17g writes, "nan" and "inf" included), else a label; an empty field is empty.
// What the writer wrote reads back to cells that write the same bytes.
std::vector<std::string> split_csv_line(const std::string& line);
Cell parse_cell(const std::string& field);
CellRow parse_csv_row(const std::string& line);

}  // namespace blockdyn
