// SPDX-License-Identifier: Apache-2.0
// The streamed event list (issue 10, flat memory): a summary printed around spooled events is
// byte for byte the summary built in memory, with none, one or many events, non-finite numbers
// as null.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "blockdyn/io/json_event_spool.hpp"
#include "blockdyn/io/json_io.hpp"

using namespace blockdyn;
using json = nlohmann::ordered_json;

TEST(JsonEventSpool, SameTextAsTheSummaryBuiltInMemory) {
  for (int n : {0, 1, 7}) {
    json doc;
    doc["schema"] = "x";
    doc["status"] = "t_end";
    doc["events"] = json::array();
    doc["after"] = {{"a", 1.5}, {"b", nullptr}};
    JsonEventSpool spool;
    json in_memory = doc;
    for (int i = 0; i < n; ++i) {
      const json e = {
          {"t", 0.1 * i + 1e-17}, {"kind", "takeoff"}, {"state", {{"x", 1.0 / 3}, {"w", i == 3 ? INFINITY : -2e-300}}}};
      spool.add(e);
      in_memory["events"].push_back(e);
    }
    EXPECT_EQ(spool.size(), n);
    std::ostringstream streamed;
    spool.write_document(doc, streamed);
    EXPECT_EQ(streamed.str(), dump_json(in_memory)) << n;
    std::ostringstream again;  // the spool can be written twice (--json and --json-out)
    spool.write_document(doc, again);
    EXPECT_EQ(again.str(), streamed.str());
  }
}
