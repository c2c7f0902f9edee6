// SPDX-License-Identifier: Apache-2.0
#pragma once
// The event list of a JSON summary, written out as the run goes: each event is appended to an
// anonymous temporary file (std::tmpfile: gone when closed or when the process dies), and the
// summary is printed around the spooled events at the end. A run of any length thus holds O(1)
// memory for its JSON output, and the text is the same as a summary built in memory.
#include <cstdio>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

namespace blockdyn {

class JsonEventSpool {
 public:
  JsonEventSpool();
  ~JsonEventSpool();
  JsonEventSpool(const JsonEventSpool&) = delete;
  JsonEventSpool& operator=(const JsonEventSpool&) = delete;

  // Appends one event (non-finite numbers become null, as in dump_json).
  void add(const nlohmann::ordered_json& event);
  long size() const { return count_; }

  // Writes dump_json(doc) with the value of doc's "events" member replaced by the spooled events,
  // formatted as dump_json would have formatted them in place (doc must have an "events" member
  // at the top level). Throws std::runtime_error on an I/O error.
  void write_document(const nlohmann::ordered_json& doc, std::ostream& out) const;

 private:
  std::FILE* file_ = nullptr;
  long count_ = 0;
};

}  // namespace blockdyn
