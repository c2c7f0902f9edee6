// SPDX-License-Identifier: Apache-2.0
#include "mpi_sweep.hpp"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/commands/option_spec.hpp"
#include "cli_common.hpp"

#ifdef BLOCKDYN_HAVE_MPI
#include <mpi.h>
#endif

namespace blockdyn::cli {

namespace {
const char* const kLauncherVars[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"};
}

bool launched_by_mpi() {
  for (const char* v : kLauncherVars)
    if (std::getenv(v)) return true;
  return false;
}

int launcher_world_size() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* s = std::getenv(v)) return std::max(1, std::atoi(s));
  return 1;
}

#ifndef BLOCKDYN_HAVE_MPI

bool mpi_built() { return false; }

MpiSweepResult run_sweep_mpi(const PointTable&, SweepRunOptions, PointPlan*) {
  throw UsageError("this blockdyn was built without MPI: run it without mpirun, or rebuild with Open MPI");
}

#else

bool mpi_built() { return true; }

namespace {

enum Tag : int { kTagRow = 1, kTagDone = 2 };

// Rows finished by this rank's worker threads, waiting for the main (MPI) thread.
struct RowQueue {
  std::mutex mu;
  std::condition_variable cv;
  std::deque<std::pair<std::size_t, SweepRow> > rows;
  bool finished = false;
  std::exception_ptr error;
};

// A row travels as the CSV writer's line (its reader gives back cells that write the same bytes),
// length-prefixed so that the line (which may hold quoted newlines) and its error travel together.
std::string encode(const SweepRow& r) {
  const std::string line = csv_line(r.cells);
  return std::to_string(line.size()) + "\n" + line + r.error;
}

SweepRow decode(const std::string& s) {
  const std::size_t nl = s.find('\n');
  const std::size_t n = std::stoul(s.substr(0, nl));
  const std::string line = s.substr(nl + 1, n);
  if (line.empty() || line.back() != '\n') throw std::invalid_argument("a row without its end of line");
  return SweepRow{parse_csv_row(line.substr(0, line.size() - 1)), s.substr(nl + 1 + n)};
}

[[noreturn]] void abort_all(const std::string& what_raw) {
  const std::string what = spell_options(what_raw, "--", false);
  std::fprintf(stderr, "error: %s\n", what.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::abort();
}

// One stage: this rank's points on its threads; rows go to rank 0 (which records them and also
// those of the other ranks) until every rank has reported the end of its share.
void run_stage(const PointTable& ev, const std::vector<std::size_t>& mine, int threads, int rank, int size,
               SweepSession* session) {
  RowQueue q;
  std::thread worker([&] {
    try {
      compute_rows(ev, mine, threads, [&](std::size_t i, const SweepRow& r) {
        std::lock_guard<std::mutex> lock(q.mu);
        q.rows.emplace_back(i, r);
        q.cv.notify_one();
      });
    } catch (...) {
      std::lock_guard<std::mutex> lock(q.mu);
      q.error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(q.mu);
    q.finished = true;
    q.cv.notify_one();
  });

  // Main thread: the only one talking MPI (MPI_THREAD_FUNNELED).
  int remote_done = 0;
  bool local_done = false;
  std::string buf;
  while (true) {
    std::deque<std::pair<std::size_t, SweepRow> > batch;
    {
      std::unique_lock<std::mutex> lock(q.mu);
      q.cv.wait_for(lock, std::chrono::milliseconds(rank == 0 ? 2 : 50), [&] { return !q.rows.empty() || q.finished; });
      batch.swap(q.rows);
      if (q.error) {
        try {
          std::rethrow_exception(q.error);
        } catch (const std::exception& e) {
          lock.unlock();
          abort_all(std::string("rank ") + std::to_string(rank) + ": " + e.what());
        }
      }
      local_done = q.finished && q.rows.empty();
    }
    for (auto& [i, r] : batch) {
      if (rank == 0) {
        session->record(i, r);
      } else {
        const std::string msg = encode(r);
        MPI_Send(msg.data(), int(msg.size()), MPI_CHAR, 0, kTagRow, MPI_COMM_WORLD);
      }
    }
    if (rank != 0) {
      if (local_done) {
        MPI_Send(nullptr, 0, MPI_CHAR, 0, kTagDone, MPI_COMM_WORLD);
        break;
      }
      continue;
    }
    // Rank 0: take in whatever the other ranks have sent.
    for (;;) {
      int flag = 0;
      MPI_Status st;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
      if (!flag) break;
      int count = 0;
      MPI_Get_count(&st, MPI_CHAR, &count);
      buf.resize(std::size_t(count));
      MPI_Recv(buf.data(), count, MPI_CHAR, st.MPI_SOURCE, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (st.MPI_TAG == kTagDone) {
        ++remote_done;
        continue;
      }
      try {
        const SweepRow r = decode(buf);
        session->record(std::size_t(r.cells.at(0).integer()), r);
      } catch (const std::exception& e) {
        abort_all(std::string("rank 0: bad row from rank ") + std::to_string(st.MPI_SOURCE) + ": " + e.what());
      }
    }
    if (local_done && remote_done == size - 1) break;
  }
  worker.join();
}

}  // namespace

MpiSweepResult run_sweep_mpi(const PointTable& ev, SweepRunOptions o, PointPlan* plan) {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  o.ranks = size;
  if (o.threads <= 0) {
    // Share the node's cores among the ranks placed on it.
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node);
    int local = 1;
    MPI_Comm_size(node, &local);
    MPI_Comm_free(&node);
    o.threads = std::max(1, resolve_threads(0) / std::max(1, local));
  }
  if (rank != 0) o.progress = ProgressMode::None;

  // Rank 0 opens the outputs; a usage error there must stop every rank cleanly.
  std::unique_ptr<SweepSession> session;
  int status = 0;
  std::string message;
  if (rank == 0) {
    try {
      session = std::make_unique<SweepSession>(ev, o);
    } catch (const std::invalid_argument& e) {
      status = 2;
      message = spell_options(e.what(), "--", false);
    } catch (const std::exception& e) {
      status = 1;
      message = spell_options(e.what(), "--", false);
    }
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (status != 0) {
    MPI_Finalize();
    if (rank == 0) {
      if (status == 2) throw UsageError(message);
      throw std::runtime_error(message);
    }
    std::exit(status);
  }

  AllPoints all(ev.size());
  PointPlan& stages = plan ? *plan : all;
  // Stage by stage (one for a plain grid): rank 0 picks the stage's unfinished points from the
  // plan and its journal, everyone learns them, each rank computes its share.
  for (;;) {
    std::vector<std::uint64_t> pending;
    if (rank == 0) {
      try {
        for (std::size_t i : session->next_stage(stages)) pending.push_back(i);
      } catch (const std::exception& e) {
        abort_all(std::string("rank 0: ") + e.what());
      }
    }
    std::uint64_t npending = pending.size();
    MPI_Bcast(&npending, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    if (npending == 0) break;  // the plan is complete
    pending.resize(npending);
    MPI_Bcast(pending.data(), int(npending), MPI_UINT64_T, 0, MPI_COMM_WORLD);
    std::vector<std::size_t> mine;
    for (std::size_t j = std::size_t(rank); j < pending.size(); j += std::size_t(size)) mine.push_back(pending[j]);
    run_stage(ev, mine, o.threads, rank, size, session.get());
  }

  MpiSweepResult res;
  res.root = rank == 0;
  res.ranks = size;
  if (rank == 0) {
    try {
      res.outcome = session->finish(o.threads, stages.sparse());
    } catch (const std::exception& e) {
      abort_all(e.what());
    }
  }
  MPI_Barrier(MPI_COMM_WORLD);
  MPI_Finalize();
  return res;
}

#endif

}  // namespace blockdyn::cli
