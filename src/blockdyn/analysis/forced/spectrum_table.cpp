// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/spectrum_table.hpp"

#include <algorithm>
#include <stdexcept>

namespace blockdyn {

using json = nlohmann::ordered_json;

const std::vector<std::string>& spectrum_columns() {
  static const std::vector<std::string> c{
      "duration", "min_overturning_amplitude", "linearised_rect", "safe_islands", "at_scan_floor", "islands", "runs",
      "scan",     "bisection_outside_model"};
  return c;
}

void add_spectrum_cells(const SpectrumRow& r, std::optional<double> linearised_rect, CellRow& row) {
  row.emplace_back(r.duration);
  if (r.min_overturning_amplitude)
    row.emplace_back(*r.min_overturning_amplitude);
  else
    row.emplace_back();
  if (linearised_rect)
    row.emplace_back(*linearised_rect);
  else
    row.emplace_back();
  row.emplace_back(r.safe_islands.size());
  row.emplace_back(static_cast<long long>(r.at_scan_floor));
  std::string isl;
  for (const SpectrumIsland& i : r.safe_islands) {
    if (!isl.empty()) isl.push_back(';');
    isl.append(format_double(i.from)).push_back(':');
    isl.append(format_double(i.to));
  }
  row.emplace_back(isl);
  row.emplace_back(static_cast<long long>(r.runs));
  std::string scan;
  for (char c : r.scan) scan += char('0' + c);
  row.emplace_back(scan);
  row.emplace_back(static_cast<long long>(r.bisection_outside_model));
}

SpectrumRow spectrum_row_from(const Table& t, const TableRow& r) {
  auto cell = [&](const char* name) -> const Cell& { return r.cells[t.column(name)]; };
  SpectrumRow s;
  s.duration = cell("duration").number();
  s.min_overturning_amplitude = cell("min_overturning_amplitude").optional_number();
  s.at_scan_floor = cell("at_scan_floor").integer() != 0;
  const std::string isl = cell("islands").text();
  std::size_t pos = 0;
  while (pos < isl.size()) {
    std::size_t end = isl.find(';', pos);
    if (end == std::string::npos) end = isl.size();
    const std::string one = isl.substr(pos, end - pos);
    const std::size_t colon = one.find(':');
    if (colon == std::string::npos) throw std::runtime_error("table: island '" + one + "' is not from:to");
    s.safe_islands.push_back({parse_cell(one.substr(0, colon)).number(), parse_cell(one.substr(colon + 1)).number()});
    pos = end + 1;
  }
  s.runs = long(cell("runs").integer());
  for (char c : cell("scan").text()) {
    s.scan.push_back(c == '1' ? kOverturns : c == '2' ? kOutsideModel : kSurvives);
    s.outside_model += c == '2';
  }
  s.bisection_outside_model = long(cell("bisection_outside_model").integer());
  s.outside_model += s.bisection_outside_model;
  s.upper_bound = s.bisection_outside_model > 0;
  for (std::size_t j = 0; j < s.scan.size() && s.scan[j] != kOverturns; ++j)
    s.upper_bound = s.upper_bound || s.scan[j] == kOutsideModel;
  return s;
}

SpectrumPoints spectrum_points(const Table& t, PulseShape pulse, double alpha, double p) {
  SpectrumPoints out;
  for (const TableRow& tr : t.rows) {
    const SpectrumRow r = spectrum_row_from(t, tr);
    json x;
    x["duration"] = r.duration;
    x["min_overturning_amplitude"] = r.min_overturning_amplitude ? json(*r.min_overturning_amplitude) : json(nullptr);
    x["at_scan_floor"] = r.at_scan_floor;
    // true: a run below it left the model's validity, so the minimum may lie lower.
    x["min_overturning_upper_bound"] = r.upper_bound;
    if (pulse == PulseShape::Rect) x["linearised_rect"] = rect_pulse_overturning_linear(alpha, p, r.duration);
    json isl = json::array();
    for (const SpectrumIsland& i : r.safe_islands) isl.push_back({i.from, i.to});
    x["safe_islands"] = isl;
    x["runs"] = r.runs;
    json scan = json::array();
    for (char c : r.scan) scan.push_back(c == kOutsideModel ? json(nullptr) : json(c == kOverturns));
    x["scan_overturned"] = scan;  // null: the run left the model's validity
    x["scan_outside_model"] = std::count(r.scan.begin(), r.scan.end(), char(kOutsideModel));
    out.runs += r.runs;
    out.json.push_back(x);
    out.rows.push_back(r);
  }
  return out;
}

}  // namespace blockdyn
