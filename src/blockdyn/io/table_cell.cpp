// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/table_cell.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace blockdyn {

double Cell::number() const {
  if (kind_ == Kind::real) return real_;
  if (kind_ == Kind::integer) return double(integer_);
  throw std::runtime_error(kind_ == Kind::empty ? "table: an empty cell where a number is needed"
                                                : "table: '" + label_ + "' is not a number");
}

std::optional<double> Cell::optional_number() const {
  if (kind_ == Kind::empty) return std::nullopt;
  return number();
}

long long Cell::integer() const {
  if (kind_ == Kind::integer) return integer_;
  if (kind_ == Kind::real && std::isfinite(real_) && real_ == std::floor(real_)) return static_cast<long long>(real_);
  throw std::runtime_error("table: '" + csv_cell(*this) + "' is not an integer");
}

const std::string& Cell::label() const {
  if (kind_ != Kind::label) throw std::runtime_error("table: '" + csv_cell(*this) + "' is not a label");
  return label_;
}

std::string Cell::text() const {
  if (kind_ == Kind::label) return label_;
  if (kind_ == Kind::empty) return {};
  return csv_cell(*this);
}

std::size_t CellTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  throw std::invalid_argument("table has no column '" + name + "'");
}

std::string format_double(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string csv_escape(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

namespace {

std::string shortest_text(double v) {
  if (std::isnan(v)) return "nan";
  char b[32];
  std::snprintf(b, sizeof b, "%.15g", v);
  if (std::strtod(b, nullptr) != v) std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

}  // namespace

std::string csv_cell(const Cell& c) {
  switch (c.kind()) {
    case Cell::Kind::real:
      return c.shortest_digits() ? shortest_text(c.number()) : format_double(c.number());
    case Cell::Kind::integer:
      return std::to_string(c.integer());
    case Cell::Kind::label:
      return c.always_quoted() && c.label().find_first_of(",\"\n\r") == std::string::npos ? '"' + c.label() + '"'
                                                                                          : csv_escape(c.label());
    case Cell::Kind::empty:
      break;
  }
  return {};
}

void append_csv_row(std::string& to, const CellRow& row) {
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (i > 0) to += ',';
    to += csv_cell(row[i]);
  }
  to += '\n';
}

std::string csv_line(const CellRow& row) {
  std::string s;
  append_csv_row(s, row);
  return s;
}

std::string csv_header(const std::vector<std::string>& columns) {
  std::string h;
  for (const auto& c : columns) {
    if (!h.empty()) h += ',';
    h += csv_escape(c);
  }
  return h + '\n';
}

void write_csv(std::ostream& os, const CellTable& t) {
  std::string text = csv_header(t.columns);
  for (const CellRow& r : t.rows) append_csv_row(text, r);
  os << text;
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        out.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

Cell parse_cell(const std::string& f) {
  if (f.empty()) return {};
  const char* s = f.c_str();
  const char* end = s + f.size();
  // Neither std::to_string nor %.17g writes a leading zero before a digit ("0012" is a label).
  const std::size_t d0 = f[0] == '-' ? 1 : 0;
  if (f.size() > d0 + 1 && f[d0] == '0' && f[d0 + 1] >= '0' && f[d0 + 1] <= '9') return Cell(f);
  // An integer as std::to_string writes it ("-0" is the real -0.0 that %.17g writes).
  const bool digits = f.size() > d0 && f.find_first_not_of("0123456789", d0) == std::string::npos && f != "-0";
  if (digits) {
    errno = 0;
    char* e = nullptr;
    const long long v = std::strtoll(s, &e, 10);
    if (e == end && errno == 0) return Cell(v);
  }
  // A number as %.17g writes it: no hexadecimal, no leading '+' or blank.
  const char c0 = f[0] == '-' ? (f.size() > 1 ? f[1] : '\0') : f[0];
  const bool numeric_start = (c0 >= '0' && c0 <= '9') || c0 == '.' || c0 == 'n' || c0 == 'i';
  if (numeric_start && f.find_first_of("xX") == std::string::npos) {
    char* e = nullptr;
    const double v = std::strtod(s, &e);
    if (e == end) return Cell(v);
  }
  return Cell(f);
}

CellRow parse_csv_row(const std::string& line) {
  CellRow row;
  for (const std::string& f : split_csv_line(line)) row.push_back(parse_cell(f));
  return row;
}

}  // namespace blockdyn
