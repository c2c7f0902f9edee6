// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/io/json_event_spool.hpp"

#include <stdexcept>

#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

namespace {
// Stands for the events while the rest of the document is printed.
constexpr const char* kPlaceholder = "@blockdyn-spooled-events@";
}  // namespace

JsonEventSpool::JsonEventSpool() : file_(std::tmpfile()) {
  if (!file_) throw std::runtime_error("cannot create a temporary file for the event list");
}

JsonEventSpool::~JsonEventSpool() {
  if (file_) std::fclose(file_);
}

void JsonEventSpool::add(const nlohmann::ordered_json& event) {
  // One event per line, compact; re-indented when the document is written.
  const std::string line = dump_json(event, -1) + "\n";
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size())
    throw std::runtime_error("cannot write the event list to its temporary file");
  ++count_;
}

void JsonEventSpool::write_document(const nlohmann::ordered_json& doc, std::ostream& out) const {
  nlohmann::ordered_json d = doc;
  d["events"] = kPlaceholder;
  const std::string text = dump_json(d);
  const std::string quoted = std::string("\"") + kPlaceholder + "\"";
  const std::size_t at = text.find(quoted);
  if (at == std::string::npos) throw std::logic_error("JSON document without an events member");
  out << text.substr(0, at);
  if (count_ == 0) {
    out << "[]";
  } else {
    // The array sits at depth 1 (indent 2): its elements at depth 2, their members at depth 3.
    std::fflush(file_);
    std::rewind(file_);
    out << "[\n";
    std::string line;
    char buf[4096];
    long n = 0;
    while (std::fgets(buf, sizeof buf, file_)) {
      line += buf;
      if (line.empty() || line.back() != '\n') continue;
      line.pop_back();
      const std::string pretty = nlohmann::ordered_json::parse(line).dump(2);
      if (n++ > 0) out << ",\n";
      out << "    ";
      for (char c : pretty) {
        out << c;
        if (c == '\n') out << "    ";
      }
      line.clear();
    }
    if (std::ferror(file_)) throw std::runtime_error("cannot read the event list back from its temporary file");
    out << "\n  ]";
    std::fseek(file_, 0, SEEK_END);
  }
  out << text.substr(at + quoted.size());
  if (!out) throw std::runtime_error("cannot write the JSON summary");
}

}  // namespace blockdyn
