// SPDX-License-Identifier: Apache-2.0
#pragma once
// Adaptive refinement of a 2-D grid near class changes: fine resolution only where the outcome
// changes (the fractal survival boundaries of the rocking literature), coarse elsewhere.
//
// With nx x ny coarse points and L levels the table's points are the fine lattice of
//   nx_f = (nx - 1) 2^L + 1  by  ny_f = (ny - 1) 2^L + 1  points,  index = ix + nx_f * iy
// (x fastest; an axis with one point stays one point). Stage 0 computes the coarse grid (every
// 2^L-th lattice point). Stage l = 1..L splits every cell of level l-1 whose corners do not all
// have the same class into four and computes the new corners (edge midpoints and centre). The
// class of a point comes from its finished row, so each stage is a pure function of the rows
// before it (PointPlan's rule): threads, MPI ranks and resumed runs refine identically.
#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "blockdyn/analysis/sweep/point_plan.hpp"

namespace blockdyn {

class RefinementPlan final : public PointPlan {
 public:
  // The class of a finished row (e.g. "collapse 1"); equal strings are the same class.
  using Classify = std::function<std::string(const CellRow& row)>;

  RefinementPlan(std::size_t nx, std::size_t ny, int levels, Classify classify);

  // Lattice points along an axis of n coarse points refined `levels` times.
  static std::size_t fine_count(std::size_t n, int levels) { return n <= 1 ? n : ((n - 1) << levels) + 1; }
  std::size_t nx_fine() const { return nxf_; }
  std::size_t ny_fine() const { return nyf_; }
  std::size_t size() const { return nxf_ * nyf_; }
  // The stage that computes lattice point `index` (0: the coarse grid).
  int level_of(std::size_t index) const;

  std::vector<std::size_t> next_stage(const FinishedRow& row) override;
  std::string stage_label() const override;
  bool sparse() const override { return levels_ > 0; }

 private:
  std::size_t nxf_, nyf_;
  int levels_;
  Classify classify_;
  int stage_ = -1;                                          // the stage last handed out
  std::vector<std::pair<std::size_t, std::size_t>> cells_;  // lower-left corners of this level's cells
};

}  // namespace blockdyn
