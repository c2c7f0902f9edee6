// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/sweep_journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "blockdyn/io/atomic_file.hpp"

namespace blockdyn {

namespace {

void write_all(int fd, const std::string& s, const std::string& path) {
  const char* p = s.data();
  std::size_t left = s.size();
  while (left > 0) {
    const ssize_t w = ::write(fd, p, left);
    if (w < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot write to '" + path + "': " + std::strerror(errno));
    }
    p += w;
    left -= std::size_t(w);
  }
}

// Number of fields of one CSV line (RFC 4180 quoting).
std::size_t field_count(const std::string& line) {
  std::size_t n = 1;
  bool quoted = false;
  for (char c : line) {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      ++n;
  }
  return n;
}

// Each journal line is a row followed by ",@" and the 16 hex digits of a checksum of the
// definition's fingerprint and the row: a row altered after it was written (a cell edited,
// truncated, a line from another file) is never copied into the final CSV.
constexpr const char* kChecksumMark = ",@";
constexpr std::size_t kChecksumDigits = 16;

std::string row_checksum(const std::string& fingerprint, const std::string& row) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64
  for (const std::string* s : {&fingerprint, &row})
    for (unsigned char c : *s) {
      h ^= c;
      h *= 1099511628211ull;
    }
  char buf[kChecksumDigits + 1];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace

std::size_t row_index(const std::string& row) {
  std::size_t v = 0;
  const char* end = row.data() + row.size();
  auto [p, ec] = std::from_chars(row.data(), end, v);
  if (ec != std::errc() || p == row.data() || p == end || *p != ',')
    throw std::invalid_argument("malformed row (no index): '" + row.substr(0, 40) + "'");
  return v;
}

std::string SweepJournal::first_line(const std::string& fingerprint, std::size_t points) {
  return "# blockdyn sweep journal v2 fingerprint=" + fingerprint + " points=" + std::to_string(points) + "\n";
}

SweepJournal::SweepJournal(std::string path, std::string fingerprint, std::string header, std::size_t points,
                           bool resume)
    : path_(std::move(path)), fingerprint_(std::move(fingerprint)), header_(std::move(header)), rows_(points) {
  const bool exists = ::access(path_.c_str(), F_OK) == 0;
  if (resume && exists) {
    load();
  } else {
    // The first two lines appear atomically, so a journal never lacks its identification.
    write_file_atomically(path_, first_line(fingerprint_, points) + header_);
  }
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) throw std::runtime_error("cannot open '" + path_ + "' for appending: " + std::strerror(errno));
}

SweepJournal::~SweepJournal() {
  if (fd_ >= 0) ::close(fd_);
}

void SweepJournal::load() {
  std::ifstream in(path_, std::ios::binary);
  if (!in) throw std::invalid_argument("journal '" + path_ + "' cannot be read");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const std::string expect = first_line(fingerprint_, rows_.size());
  std::size_t line_no = 2;
  auto fail = [&](const std::string& why) {
    throw std::invalid_argument("journal '" + path_ + "' " + why +
                                "; use `overwrite` to discard it, or a different output path");
  };
  if (text.compare(0, expect.size(), expect) != 0) {
    if (text.rfind("# blockdyn sweep journal v1 ", 0) == 0)
      fail("was written by an earlier blockdyn (journal format v1, rows without checksums)");
    if (text.rfind("# blockdyn sweep journal", 0) == 0)
      fail("was written for a different sweep definition (its first line: '" + text.substr(0, text.find('\n')) +
           "', expected fingerprint " + fingerprint_ + ")");
    fail("is not a blockdyn sweep journal");
  }
  std::size_t pos = expect.size();
  if (text.compare(pos, header_.size(), header_) != 0) fail("has different columns");
  pos += header_.size();
  std::size_t complete_end = pos;  // end of the last complete line
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) break;  // partial row written when the sweep was killed
    const std::string line = text.substr(pos, nl - pos);
    ++line_no;
    // A line whose checksum does not match is not this sweep's row as written (a cell edited,
    // a line from another file): never copied into the CSV.
    const std::size_t mark = line.rfind(kChecksumMark);
    std::string row = mark == std::string::npos ? std::string() : line.substr(0, mark) + "\n";
    if (mark == std::string::npos || line.size() - mark != 2 + kChecksumDigits ||
        line.compare(mark + 2, kChecksumDigits, row_checksum(fingerprint_, row)) != 0)
      fail("is corrupt: line " + std::to_string(line_no) +
           " fails its checksum (altered after it was written; delete that line to compute its point again)");
    std::size_t idx = 0;
    try {
      idx = row_index(row);
    } catch (const std::invalid_argument& e) {
      fail(std::string("is corrupt: ") + e.what());
    }
    if (idx >= rows_.size()) fail("is corrupt: row index " + std::to_string(idx) + " out of range");
    if (field_count(row) != field_count(header_))
      fail("is corrupt: row " + std::to_string(idx) + " has " + std::to_string(field_count(row)) +
           " fields, the header " + std::to_string(field_count(header_)));
    if (rows_[idx].empty()) {
      CellRow cells = parse_csv_row(row.substr(0, row.size() - 1));
      // The index as the writer writes it ("01" is not how index 1 is written).
      if (cells.empty() || cells[0].kind() != Cell::Kind::integer || cells[0].integer() != static_cast<long long>(idx))
        fail("is corrupt: row " + std::to_string(idx) + " does not start with its index");
      rows_[idx] = std::move(cells);
      ++done_;
    } else if (csv_line(rows_[idx]) != row) {
      fail("is corrupt: two different rows for index " + std::to_string(idx));
    }
    pos = nl + 1;
    complete_end = pos;
  }
  if (complete_end < text.size() && ::truncate(path_.c_str(), off_t(complete_end)) != 0)
    throw std::runtime_error("cannot truncate '" + path_ + "': " + std::strerror(errno));
  resumed_ = done_;
}

std::vector<std::size_t> SweepJournal::pending() const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < rows_.size(); ++i)
    if (rows_[i].empty()) out.push_back(i);
  return out;
}

void SweepJournal::append(std::size_t index, CellRow row) {
  if (index >= rows_.size()) throw std::out_of_range("sweep row index out of range");
  if (row.empty() || !row[0].is_number() || row[0].number() != double(index))
    throw std::logic_error("sweep row does not match its index");
  if (!rows_[index].empty()) return;  // already recorded (identical by construction)
  const std::string text = csv_line(row);
  write_all(fd_, text.substr(0, text.size() - 1) + kChecksumMark + row_checksum(fingerprint_, text) + "\n", path_);
  rows_[index] = std::move(row);
  ++done_;
}

void SweepJournal::write_csv(const std::string& csv_path, bool sparse) const {
  if (!sparse && done_ != rows_.size()) throw std::logic_error("sweep CSV written before all rows were done");
  AtomicFile f(csv_path);
  f.stream() << header_;
  std::string line;
  for (const CellRow& r : rows_) {
    if (r.empty()) continue;
    line.clear();
    append_csv_row(line, r);
    f.stream() << line;
  }
  f.commit();
}

void SweepJournal::remove_file() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::remove(path_.c_str());
}

}  // namespace blockdyn
