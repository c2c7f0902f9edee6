// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/at2_writer.hpp"

#include <stdexcept>

#include "blockdyn/base/number_text.hpp"

namespace blockdyn {

std::string at2_text(const std::vector<double>& a, double dt, const std::string& title) {
  std::string t = "PEER-format record written by blockdyn\n" + title +
                  "\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= " + std::to_string(a.size()) +
                  ", DT= " + scientific_text(dt) + " SEC\n";
  t.reserve(t.size() + 26 * a.size() + a.size() / 5 + 2);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string v = scientific_text(a[i]);
    if (v.size() > 24) throw std::logic_error("at2_text: a sample wider than its field");
    t.append(25 - v.size(), ' ');
    t += v;
    if (i % 5 == 4 || i + 1 == a.size()) t += '\n';
  }
  return t;
}

}  // namespace blockdyn
