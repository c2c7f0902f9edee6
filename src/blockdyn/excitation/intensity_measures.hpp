// SPDX-License-Identifier: Apache-2.0
#pragma once
// Intensity measures of a ground-motion record, computed exactly for its piecewise-linear
// acceleration (the record's own definition, accelerogram.hpp): velocity and displacement are
// piecewise quadratic and cubic, so their peaks and the Husid plot's crossings are solved inside
// the segments, not read at the samples. The record is taken as given (no baseline correction).
#include <vector>

#include "blockdyn/excitation/accelerogram.hpp"

namespace blockdyn {

struct IntensityMeasures {
  double pga = 0;          // max |a| (g)
  double pgv = 0;          // max |v| (m/s), v(t_first) = 0
  double pgd = 0;          // max |d| (m), d(t_first) = 0
  double arias = 0;        // Arias intensity pi / (2 g) int a^2 dt (m/s)
  double t5 = 0, t95 = 0;  // times at 5 % and 95 % of the Arias intensity (s)
  double d5_95 = 0;        // significant duration t95 - t5 (s)
  double t_mid = 0;        // time at 45 % of the Arias intensity (s)
  double mean_period = 0;  // Rathje et al. (1998): sum C^2 / f over sum C^2, 0.25 <= f <= 20 Hz (s)
  double duration = 0;     // t_last - t_first (s)
  double final_velocity = 0, final_displacement = 0;  // at the last sample (m/s, m)
};

// g: the acceleration of gravity converting the record's units (m/s^2).
IntensityMeasures intensity_measures(const Accelerogram& rec, double g = 9.81);

// The time at which the Arias intensity reaches `fraction` (in [0, 1]) of its total, solved in
// the segment (the Husid plot is a cubic there). NaN for a record without energy.
double husid_time(const Accelerogram& rec, double fraction);

}  // namespace blockdyn
