// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/winkler/ic_choice.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "blockdyn/model/winkler/initial_conditions.hpp"

namespace blockdyn {

WinklerState IcChoice::state(const WinklerParams& p) const {
  if (set == Set::Ic2) return ic2(p);
  return ic1(p, w0_fraction * p.alpha());
}

std::string IcChoice::name() const {
  if (set == Set::Ic2) return "ic2";
  if (w0_fraction == 0.5) return "ic1";
  std::ostringstream os;
  os.precision(17);
  os << "ic1:" << w0_fraction;
  return os.str();
}

IcChoice parse_ic_choice(const std::string& s) {
  const std::string msg = "ic = '" + s + "' is not one of: ic1, ic2, ic1:F (w0 = F alpha, 0 < F <= 1)";
  if (s == "ic1") return {IcChoice::Set::Ic1, 0.5};
  if (s == "ic2") return {IcChoice::Set::Ic2, 0.5};
  if (s.rfind("ic1:", 0) != 0) throw std::invalid_argument(msg);
  std::size_t used = 0;
  double f = 0;
  try {
    f = std::stod(s.substr(4), &used);
  } catch (const std::exception&) {
    throw std::invalid_argument(msg);
  }
  if (used != s.size() - 4 || !std::isfinite(f) || !(f > 0) || f > 1) throw std::invalid_argument(msg);
  return {IcChoice::Set::Ic1, f};
}

}  // namespace blockdyn
