// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the sweep runner (threads, MPI, journal, resume, sidecar) needs of a parameter study, for
// any model family: a fixed number of points, each row a pure function of the definition and
// the index (the same bytes on any thread, rank or rerun), a header, a fingerprint tying a journal
// to its definition, and the definition itself for the sidecar. SweepEvaluator (Winkler block)
// and RigidSweepEvaluator (housner, rigid) implement it; GridTable (grid_table.hpp) makes one from
// a per-point function for the other grid analyses (spectrum, survival, response-curve).
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace blockdyn {

struct SweepRow {
  std::string text;   // CSV line including the trailing '\n'
  std::string error;  // non-empty when status is "error" or "outside_model"
};

class PointTable {
 public:
  virtual ~PointTable() = default;
  virtual std::size_t size() const = 0;
  virtual const std::vector<std::string>& columns() const = 0;
  virtual const std::string& header() const = 0;  // with '\n'
  virtual const std::string& fingerprint() const = 0;
  virtual SweepRow row(std::size_t index) const = 0;  // thread-safe
  virtual nlohmann::ordered_json definition() const = 0;
  virtual nlohmann::ordered_json tolerances() const = 0;
  virtual const std::string& output() const = 0;  // the CSV path
  // The command the table belongs to: the sidecar's schema (blockdyn.<kind>.sidecar/1) and the
  // progress label.
  virtual std::string kind() const { return "sweep"; }
};

// Helpers for cell formatting (exposed for tests and metric authors).
std::string format_double(double v);           // %.17g
std::string csv_escape(const std::string& s);  // RFC 4180 quoting when needed

// One CSV line built cell by cell.
class RowBuilder {
 public:
  void add(const std::string& cell_text) {
    if (!first_) text_ += ',';
    first_ = false;
    text_ += cell_text;
  }
  void add(double v) { add(format_double(v)); }
  void add(long long v) { add(std::to_string(v)); }
  void add(long v) { add(static_cast<long long>(v)); }
  void add(std::size_t v) { add(std::to_string(v)); }
  void empty() { add(std::string()); }
  std::string finish() { return text_ + '\n'; }

 private:
  std::string text_;
  bool first_ = true;
};

// "a,b,c\n" from column names.
std::string csv_header(const std::vector<std::string>& columns);

}  // namespace blockdyn
