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

#include "blockdyn/io/table_cell.hpp"

namespace blockdyn {

struct SweepRow {
  CellRow cells;      // one per column, the index first
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

}  // namespace blockdyn
