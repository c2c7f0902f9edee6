// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/sweep/sweep_runner.hpp"

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

// The machine is often shared: the load when the sweep started qualifies its timing.
json load_average() {
  std::ifstream in("/proc/loadavg");
  double a = 0, b = 0, c = 0;
  if (in >> a >> b >> c) return json::array({a, b, c});
  return nullptr;
}

bool exists(const std::string& p) { return ::access(p.c_str(), F_OK) == 0; }

}  // namespace

SweepPaths sweep_paths(const std::string& csv) {
  SweepPaths p;
  p.csv = csv;
  p.journal = csv + ".journal";
  const std::string ext = ".csv";
  if (csv.size() > ext.size() && csv.compare(csv.size() - ext.size(), ext.size(), ext) == 0)
    p.sidecar = csv.substr(0, csv.size() - ext.size()) + ".json";
  else
    p.sidecar = csv + ".json";
  return p;
}

std::string complete_sidecar_fingerprint(const std::string& path) {
  std::ifstream in(path);
  if (!in) return "";
  try {
    const json j = json::parse(in);
    if (j.value("status", "") != "complete") return "";
    return j.value("fingerprint", "");
  } catch (const std::exception&) {
    return "";
  }
}

void compute_rows(const PointTable& ev, const std::vector<std::size_t>& indices, int threads,
                  const std::function<void(std::size_t, const SweepRow&)>& on_row) {
  // Rows are handed from the worker to the lock-protected callback through a per-index slot.
  std::vector<SweepRow> slot(indices.size());
  parallel_for(
      indices.size(), threads, [&](std::size_t j) { slot[j] = ev.row(indices[j]); },
      [&](std::size_t j) {
        on_row(indices[j], slot[j]);
        slot[j] = SweepRow{};  // keep memory flat on big sweeps
      });
}

SweepSession::SweepSession(const PointTable& ev, const SweepRunOptions& o)
    : ev_(ev), opt_(o), paths_(sweep_paths(ev.output())) {
  t_start_ = now_seconds();
  started_utc_ = utc_now();
  load_at_start_ = load_average();
  // The outputs must be writable before anything is computed (not after hours of work).
  if (paths_.csv.empty()) throw std::invalid_argument("output: the CSV path is empty");
  struct stat st {};
  if (::stat(paths_.csv.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw std::invalid_argument("output: '" + paths_.csv + "' is a directory");
  const auto slash = paths_.csv.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : paths_.csv.substr(0, slash));
  if (::access(dir.c_str(), W_OK) != 0)
    throw std::invalid_argument("output: cannot write in '" + dir + "': " + std::strerror(errno));
  const bool have_journal = exists(paths_.journal), have_csv = exists(paths_.csv);
  if (!o.resume && !o.overwrite) {
    if (have_journal)
      throw std::invalid_argument(
          "output: '" + paths_.journal +
          "' holds an unfinished sweep: pass `resume` to continue it or `overwrite` to start over");
    if (have_csv) throw std::invalid_argument("output: '" + paths_.csv + "' exists: pass `overwrite` to replace it");
  }
  if (o.resume && !have_journal && have_csv) {
    if (complete_sidecar_fingerprint(paths_.sidecar) != ev.fingerprint())
      throw std::invalid_argument(
          "output: '" + paths_.csv + "' exists but '" + paths_.sidecar +
          "' does not record a finished sweep of this definition; pass `overwrite` to replace it");
    was_complete_ = true;
    return;
  }
  journal_ = std::make_unique<SweepJournal>(paths_.journal, ev.fingerprint(), ev.header(), ev.size(), o.resume);
  // A table streamed into a FIFO or a device has no sidecar beside it (/dev/null.json): the
  // command's JSON summary holds the definition.
  stream_output_ = ::stat(paths_.csv.c_str(), &st) == 0 && !S_ISREG(st.st_mode);
  if (!stream_output_)
    write_file_atomically(paths_.sidecar, dump_json(sidecar("running", resolve_threads(o.threads))) + "\n");
}

SweepSession::~SweepSession() = default;

std::vector<std::size_t> SweepSession::pending() const {
  return journal_ ? journal_->pending() : std::vector<std::size_t>{};
}

const CellRow* SweepSession::row(std::size_t index) const {
  return journal_ && index < journal_->points() ? journal_->row(index) : nullptr;
}

std::vector<std::size_t> SweepSession::next_stage(PointPlan& plan) {
  if (!journal_) return {};
  if (progress_) progress_->finish();
  const FinishedRow finished = [this](std::size_t i) { return row(i); };
  for (;;) {
    const std::vector<std::size_t> stage = plan.next_stage(finished);
    if (stage.empty()) return {};
    std::vector<std::size_t> todo;
    for (std::size_t i : stage) {
      if (i >= ev_.size()) throw std::logic_error("point plan: index out of range");
      if (!journal_->has(i)) todo.push_back(i);
    }
    if (todo.empty()) continue;
    const std::string label = plan.stage_label();
    progress_ = std::make_unique<Progress>(label.empty() ? ev_.kind() : ev_.kind() + " " + label, stage.size(),
                                           stage.size() - todo.size(), opt_.progress, stderr, opt_.progress_interval);
    return todo;
  }
}

void SweepSession::record(std::size_t index, const SweepRow& row) {
  journal_->append(index, row.cells);
  if (!row.error.empty()) {
    ++errors_;
    std::fprintf(stderr, "%swarning: sweep point %zu: %s\n",
                 progress_ && progress_->mode() == ProgressMode::Bar ? "\n" : "", index, row.error.c_str());
  }
  if (progress_) progress_->advance();
}

json table_sidecar(const PointTable& t, const std::string& status) {
  json j;
  j["schema"] = schema_name(t.kind(), "sidecar");
  j["run"] = run_info();
  j["status"] = status;
  j["fingerprint"] = t.fingerprint();
  j["point_count"] = t.size();
  j["columns"] = t.columns();
  j["definition"] = t.definition();
  j["tolerances"] = t.tolerances();
  return j;
}

json SweepSession::sidecar(const std::string& status, int threads) const {
  json j;
  const json base = table_sidecar(ev_, status);
  for (auto it = base.begin(); it != base.end(); ++it) {
    j[it.key()] = it.value();
    if (it.key() == "fingerprint") j["csv"] = paths_.csv;
  }
  json t;
  t["started_utc"] = started_utc_;
  t["threads_per_rank"] = threads;
  t["mpi_ranks"] = opt_.ranks;
  char host[256] = {0};
  if (::gethostname(host, sizeof host - 1) == 0) t["host"] = host;
  t["load_average_at_start"] = load_at_start_;
  j["timing"] = t;
  return j;
}

SweepOutcome SweepSession::finish(int threads, bool sparse) {
  SweepOutcome out;
  out.paths = paths_;
  out.points = ev_.size();
  out.was_complete = was_complete_;
  if (was_complete_) {
    out.resumed = out.points;
    // The finished table is the input of this run: read back only from a regular file.
    struct stat st {};
    if (::stat(paths_.csv.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
      throw std::invalid_argument("output: '" + paths_.csv +
                                  "' is not a regular file: a finished sweep resumes from its CSV");
    out.table = read_table(paths_.csv, ev_.header());
    return out;
  }
  if (progress_) progress_->finish();
  journal_->write_csv(paths_.csv, sparse);
  out.table.columns = ev_.columns();
  for (std::size_t i = 0; i < journal_->points(); ++i)
    if (const CellRow* r = journal_->row(i)) out.table.rows.push_back(TableRow{i, *r});
  out.resumed = journal_->resumed();
  out.computed = journal_->done() - journal_->resumed();
  out.errors = errors_;
  out.wall_seconds = now_seconds() - t_start_;
  json j = sidecar("complete", threads);
  json& t = j["timing"];
  t["finished_utc"] = utc_now();
  t["wall_seconds"] = out.wall_seconds;
  t["points_computed"] = out.computed;
  t["points_resumed"] = out.resumed;
  if (sparse) j["rows_in_table"] = journal_->done();
  t["points_per_second"] = out.wall_seconds > 0 ? double(out.computed) / out.wall_seconds : 0.0;
  rusage ru{};
  if (::getrusage(RUSAGE_SELF, &ru) == 0)
    t["cpu_seconds_this_process"] = double(ru.ru_utime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec) +
                                    double(ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_stime.tv_usec);
  t["load_average_at_end"] = load_average();
  j["errors"] = errors_;
  if (!stream_output_) write_file_atomically(paths_.sidecar, dump_json(j) + "\n");
  journal_->remove_file();
  return out;
}

SweepOutcome run_sweep(const PointTable& ev, const SweepRunOptions& o, PointPlan* plan) {
  AllPoints all(ev.size());
  PointPlan& p = plan ? *plan : all;
  SweepSession session(ev, o);
  const int threads = resolve_threads(o.threads);
  for (;;) {
    const std::vector<std::size_t> todo = session.next_stage(p);
    if (todo.empty()) break;
    compute_rows(ev, todo, threads, [&](std::size_t i, const SweepRow& row) { session.record(i, row); });
  }
  return session.finish(threads, p.sparse());
}

}  // namespace blockdyn
