// SPDX-License-Identifier: Apache-2.0
#pragma once
// Which points of a PointTable a run computes, stage by stage. A plain grid computes every point
// in one stage (AllPoints). An adaptive analysis - refinement near class changes, a boundary
// search - chooses each stage from the rows finished so far. The runner (single process or MPI
// rank 0) asks for stage after stage, computes the points not yet in the journal, and stops at
// an empty stage.
//
// next_stage() must be a pure function of the finished rows (never of timing, thread or rank
// count, or completion order): a resumed run then replays the same stages, skips what its
// journal holds, and writes the same bytes.
#include <cstddef>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include "blockdyn/io/table_cell.hpp"

namespace blockdyn {

// The finished row of an index (its cells), or nullptr.
using FinishedRow = std::function<const CellRow*(std::size_t index)>;

class PointPlan {
 public:
  virtual ~PointPlan() = default;
  // Indices of the next stage (ascending; finished ones are skipped by the runner), or an empty
  // list when the analysis is complete.
  virtual std::vector<std::size_t> next_stage(const FinishedRow& row) = 0;
  // Progress label of the stage just returned (e.g. "level 2"); empty for a one-stage plan.
  virtual std::string stage_label() const { return ""; }
  // True when the final table may hold fewer rows than the table has points.
  virtual bool sparse() const = 0;
};

// Every point, in one stage.
class AllPoints final : public PointPlan {
 public:
  explicit AllPoints(std::size_t n) : n_(n) {}
  std::vector<std::size_t> next_stage(const FinishedRow&) override {
    if (done_) return {};
    done_ = true;
    std::vector<std::size_t> all(n_);
    std::iota(all.begin(), all.end(), std::size_t(0));
    return all;
  }
  bool sparse() const override { return false; }

 private:
  std::size_t n_;
  bool done_ = false;
};

}  // namespace blockdyn
