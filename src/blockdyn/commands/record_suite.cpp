// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/record_suite.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "blockdyn/analysis/sweep/sweep_axis.hpp"
#include "blockdyn/base/range_check.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

SuiteRecords suite_records(const std::string& dir) {
  json j;
  std::ifstream file(dir + "/motions.json");
  try {
    if (!file) throw std::runtime_error("cannot open it");
    j = json::parse(file);
  } catch (const std::exception& e) {
    throw std::invalid_argument("suite = '" + dir + "': no readable motions.json (" + e.what() + ")");
  }
  if (!j.contains("records") || !j["records"].is_array() || j["records"].empty())
    throw std::invalid_argument("suite = '" + dir + "': its motions.json lists no records");
  SuiteRecords s;
  for (const json& r : j["records"]) {
    if (!r.contains("components")) {
      s.h1.push_back(dir + "/" + r.at("file").get<std::string>());
      continue;
    }
    const json& c = r["components"];
    s.h1.push_back(dir + "/" + c.at("h1").at("file").get<std::string>());
    if (c.contains("h2")) s.h2.push_back(dir + "/" + c["h2"].at("file").get<std::string>());
    if (c.contains("v")) s.v.push_back(dir + "/" + c["v"].at("file").get<std::string>());
  }
  if ((!s.h2.empty() && s.h2.size() != s.h1.size()) || (!s.v.empty() && s.v.size() != s.h1.size()))
    throw std::invalid_argument("suite = '" + dir + "': its records do not all have the same components");
  return s;
}

std::vector<double> incidences_of(const Settings& given) {
  if (!given.has("incidence")) return {0.0};
  const std::vector<double> v = parse_axis("incidence", given.text("incidence"), AxisSpacing::Linear).values;
  for (double a : v) require_in_range("incidence", a, -360, 360);
  return v;
}

}  // namespace blockdyn
