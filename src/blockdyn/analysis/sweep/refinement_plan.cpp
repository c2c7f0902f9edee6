// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/refinement_plan.hpp"

#include <algorithm>
#include <stdexcept>

namespace blockdyn {

RefinementPlan::RefinementPlan(std::size_t nx, std::size_t ny, int levels, Classify classify)
    : nxf_(fine_count(nx, levels)), nyf_(fine_count(ny, levels)), levels_(levels), classify_(std::move(classify)) {
  if (nx == 0 || ny == 0) throw std::invalid_argument("refinement: the grid has no point");
  if (levels < 0 || levels > 16) throw std::invalid_argument("refine: levels must be in [0, 16]");
}

int RefinementPlan::level_of(std::size_t index) const {
  const std::size_t ix = index % nxf_, iy = index / nxf_;
  for (int l = 0; l < levels_; ++l) {
    const std::size_t s = std::size_t(1) << (levels_ - l);
    if ((nxf_ == 1 || ix % s == 0) && (nyf_ == 1 || iy % s == 0)) return l;
  }
  return levels_;
}

std::string RefinementPlan::stage_label() const {
  return levels_ == 0 ? "" : "level " + std::to_string(stage_) + "/" + std::to_string(levels_);
}

std::vector<std::size_t> RefinementPlan::next_stage(const FinishedRow& row) {
  const std::size_t s0 = std::size_t(1) << levels_;
  // Cell extents along x and y at step s (0 along an axis of one point).
  auto span = [](std::size_t nf, std::size_t s) { return nf == 1 ? std::size_t(0) : s; };
  if (stage_ < 0) {
    stage_ = 0;
    std::vector<std::size_t> pts;
    for (std::size_t iy = 0; iy < nyf_; iy += s0)
      for (std::size_t ix = 0; ix < nxf_; ix += s0) pts.push_back(ix + nxf_ * iy);
    const std::size_t sx = span(nxf_, s0), sy = span(nyf_, s0);
    // Lower-left corners along an axis: every cell start, or just 0 along an axis of one point.
    auto starts = [](std::size_t nf, std::size_t step) {
      std::vector<std::size_t> v;
      if (step == 0) v.push_back(0);
      for (std::size_t i = 0; step > 0 && i + step < nf; i += step) v.push_back(i);
      return v;
    };
    cells_.clear();
    if (sx + sy > 0)
      for (std::size_t iy : starts(nyf_, sy))
        for (std::size_t ix : starts(nxf_, sx)) cells_.emplace_back(ix, iy);
    return pts;
  }
  if (stage_ >= levels_) return {};
  const std::size_t s = std::size_t(1) << (levels_ - stage_);  // this level's cell size
  const std::size_t sx = span(nxf_, s), sy = span(nyf_, s);
  auto cls = [&](std::size_t ix, std::size_t iy) {
    const CellRow* r = row(ix + nxf_ * iy);
    if (!r) throw std::logic_error("refinement: a corner of a cell has no row");
    return classify_(*r);
  };
  std::vector<std::pair<std::size_t, std::size_t>> next;
  const std::size_t h = s / 2, hx = span(nxf_, h), hy = span(nyf_, h);
  for (const auto& [ix, iy] : cells_) {
    const std::string c = cls(ix, iy);
    if (cls(ix + sx, iy) == c && cls(ix, iy + sy) == c && cls(ix + sx, iy + sy) == c) continue;
    for (std::size_t b = 0; b <= (hy ? 1u : 0u); ++b)
      for (std::size_t a = 0; a <= (hx ? 1u : 0u); ++a) next.emplace_back(ix + a * hx, iy + b * hy);
  }
  ++stage_;
  cells_ = std::move(next);
  std::vector<std::size_t> pts;
  for (const auto& [ix, iy] : cells_)
    for (std::size_t b = 0; b <= (hy ? 1u : 0u); ++b)
      for (std::size_t a = 0; a <= (hx ? 1u : 0u); ++a) pts.push_back(ix + a * hx + nxf_ * (iy + b * hy));
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  return pts;
}

}  // namespace blockdyn
