// SPDX-License-Identifier: Apache-2.0
// Sweep runs through the library: determinism across thread counts, metrics, journal/resume.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "blockdyn/analysis/sweep/sweep_evaluator.hpp"
#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/io/progress.hpp"
#include "test_sweep_util.hpp"

using namespace blockdyn;
using sweep_test::slurp;

namespace {

// Small but varied: flight, no flight and overturning points, two ic sets.
SweepSpec small_spec(const std::string& out) {
  SweepSpec s;
  s.k = axis_range("k", 1e2, 1e5, 4, AxisSpacing::Log);
  s.r = axis_list("inv_r", {2, 5});
  s.mu = axis_list("mu", {0.2});
  s.initial.sets = {"ic2", "ic1"};
  s.options.t_end = 4;
  s.options.integrator.max_steps = 2'000'000;
  s.output = out;
  return s;
}

SweepRunOptions quiet(int threads) {
  SweepRunOptions o;
  o.threads = threads;
  o.progress = ProgressMode::None;
  return o;
}

// A computed row as the CSV writer writes it.
std::string row_text(const SweepRow& r) { return csv_line(r.cells); }

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',')
      out.emplace_back();
    else if (c != '\n')
      out.back() += c;
  }
  return out;
}

}  // namespace

TEST(SweepRun, BitIdenticalForOneAndTwoThreads) {
  const sweep_test::TmpDir tmp("sweep-threads");
  const std::string& dir = tmp.path;
  const SweepEvaluator e1(small_spec(dir + "/t1.csv")), e2(small_spec(dir + "/t2.csv"));
  const SweepOutcome o1 = run_sweep(e1, quiet(1));
  const SweepOutcome o2 = run_sweep(e2, quiet(2));
  EXPECT_EQ(o1.computed, 16u);
  EXPECT_EQ(o2.computed, 16u);
  const std::string a = slurp(dir + "/t1.csv"), b = slurp(dir + "/t2.csv");
  EXPECT_EQ(sweep_test::count_lines(a), 17u);
  EXPECT_EQ(a, b);
  EXPECT_FALSE(sweep_test::exists(dir + "/t1.csv.journal"));  // removed once the CSV is written
  // The sidecar describes the run; the CSV row equals a directly computed row.
  const std::string side = slurp(dir + "/t1.json");
  EXPECT_NE(side.find("\"status\": \"complete\""), std::string::npos);
  EXPECT_NE(side.find("\"rtol\": 1e-10"), std::string::npos);
  EXPECT_NE(side.find("\"point_count\": 16"), std::string::npos);
  EXPECT_NE(a.find(row_text(e1.row(5))), std::string::npos);
  // The outcomes seen in the sweep are varied (the test would be weak otherwise).
  EXPECT_NE(a.find(",overturned,"), std::string::npos);
  EXPECT_NE(a.find(",t_end,"), std::string::npos);
}

TEST(SweepRun, RowFieldsMatchSimulate) {
  SweepSpec s = small_spec("/dev/null");
  const SweepEvaluator ev(s);
  const std::size_t idx = 2;  // k = 1e4, inv_r = 2, ic2
  const auto cells = cells_of(row_text(ev.row(idx)));
  ASSERT_EQ(cells.size(), ev.columns().size());
  const SweepPoint p = sweep_point(s, idx);
  const WinklerResult r = simulate(p.params, {}, sweep_initial_state(s, p), ev.options());
  auto col = [&](const std::string& name) {
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (ev.columns()[i] == name) return cells[i];
    return std::string("?");
  };
  EXPECT_EQ(col("index"), "2");
  EXPECT_EQ(col("k"), "10000");
  EXPECT_EQ(col("r"), "0.5");
  EXPECT_EQ(col("ic"), "ic2");
  EXPECT_EQ(col("status"), to_string(r.status));
  ASSERT_TRUE(r.first_flight_time.has_value());
  EXPECT_EQ(std::stod(col("first_flight_time")), *r.first_flight_time);  // %.17g round-trips
  EXPECT_EQ(std::stol(col("ihor_final")), r.upright_passages);
  EXPECT_EQ(std::stod(col("energy_lost")), -r.work_friction());
  EXPECT_EQ(std::stol(col("steps")), r.stats.accepted);
  EXPECT_EQ(col("overturned"), r.overturn_time ? "1" : "0");
}

namespace {
// A metric observing the trajectory: counts segments and sums their durations.
struct CountingSink : WinklerSink {
  long segments = 0;
  double time = 0;
  void on_segment(const WinklerBlock&, const DenseSegment<kStateDim>&, double t0, double t1,
                  const WinklerMode&) override {
    ++segments;
    time += t1 - t0;
  }
};
struct CountingMetric : PointMetric {
  std::vector<std::string> columns() const override { return {"segments", "segment_time", "label"}; }
  bool needs_events() const override { return true; }
  std::unique_ptr<WinklerSink> make_sink(const PointContext&) const override {
    return std::make_unique<CountingSink>();
  }
  void compute(const PointContext& ctx, const WinklerResult& r, const WinklerSink* sink,
               std::vector<MetricValue>& out) const override {
    const auto& s = static_cast<const CountingSink&>(*sink);
    out.emplace_back((long long)s.segments);
    out.emplace_back(s.time - (r.t_final - ctx.options.t_start));
    out.emplace_back(std::string("n,\"") + std::to_string(r.events.size()) + "\"");
  }
};
}  // namespace

TEST(SweepRun, MetricsAddColumnsAndSeeTheTrajectory) {
  SweepSpec s = small_spec("/dev/null");
  s.metrics = {"event_counts", "regime_time"};
  std::vector<std::unique_ptr<PointMetric>> extra;
  extra.push_back(std::make_unique<CountingMetric>());
  const SweepEvaluator ev(s, std::move(extra));
  EXPECT_TRUE(ev.options().record_events);  // asked for by CountingMetric
  const auto& c = ev.columns();
  EXPECT_EQ(c.back(), "label");
  EXPECT_NE(ev.header().find(",n_takeoff,"), std::string::npos);
  EXPECT_NE(ev.header().find(",time_contact,time_slide,time_flight,segments,"), std::string::npos);
  const SweepPoint p = sweep_point(s, 3);
  const WinklerResult r = simulate(p.params, {}, sweep_initial_state(s, p), ev.options());
  const std::string row = row_text(ev.row(3));
  // Quoted text cell (it contains a comma and quotes), last in the row.
  EXPECT_NE(row.find(",\"n,\"\"" + std::to_string(r.events.size()) + "\"\"\"\n"), std::string::npos) << row;
  // Regime times add up to the run time; the counting sink saw the whole run.
  std::vector<std::string> cells;
  std::string cur;
  for (std::size_t i = 0; i < row.size() && row[i] != '"'; ++i) {
    if (row[i] == ',') {
      cells.push_back(cur);
      cur.clear();
    } else {
      cur += row[i];
    }
  }
  auto at = [&](const std::string& name) {
    for (std::size_t i = 0; i < c.size(); ++i)
      if (c[i] == name) return std::stod(cells.at(i));
    return double(NAN);
  };
  EXPECT_NEAR(at("time_contact") + at("time_slide") + at("time_flight"), r.t_final, 1e-12);
  EXPECT_GT(at("time_flight"), 0.0);
  EXPECT_EQ(at("n_takeoff"), double(r.event_counts[int(WinklerEventKind::Takeoff)]));
  EXPECT_GT(at("segments"), 10.0);
  EXPECT_NEAR(at("segment_time"), 0.0, 1e-12);
}

TEST(SweepRun, ResumeKeepsJournalRowsAndRecomputesTheRest) {
  const sweep_test::TmpDir tmp("sweep-resume");
  const std::string& dir = tmp.path;
  const SweepEvaluator full(small_spec(dir + "/full.csv"));
  run_sweep(full, quiet(2));
  const std::string reference = slurp(dir + "/full.csv");

  // An interrupted sweep: three finished rows, the last one half-written.
  const SweepEvaluator ev(small_spec(dir + "/part.csv"));
  {
    SweepJournal j(dir + "/part.csv.journal", ev.fingerprint(), ev.header(), ev.size(), false);
    j.append(7, ev.row(7).cells);
    j.append(0, ev.row(0).cells);
  }
  {
    std::ofstream app(dir + "/part.csv.journal", std::ios::app);
    const std::string r = row_text(ev.row(12));
    app << r.substr(0, r.size() / 2);  // killed mid-write
  }
  // Without --resume or --overwrite the journal is protected.
  EXPECT_THROW(run_sweep(ev, quiet(2)), std::invalid_argument);
  SweepRunOptions o = quiet(2);
  o.resume = true;
  const SweepOutcome out = run_sweep(ev, o);
  EXPECT_EQ(out.resumed, 2u);
  EXPECT_EQ(out.computed, 14u);
  EXPECT_EQ(slurp(dir + "/part.csv"), reference);
  // Resuming a finished sweep recomputes nothing.
  const SweepOutcome again = run_sweep(ev, o);
  EXPECT_TRUE(again.was_complete);
  EXPECT_EQ(again.computed, 0u);
  EXPECT_THROW(run_sweep(ev, quiet(2)), std::invalid_argument);  // existing CSV needs --overwrite
}

TEST(SweepRun, ResumeTrustsFinishedRows) {
  // A row in the journal is taken as is: tamper with one and it reaches the CSV unchanged.
  const sweep_test::TmpDir tmp("sweep-trust");
  const std::string& dir = tmp.path;
  const SweepEvaluator ev(small_spec(dir + "/s.csv"));
  std::string row = row_text(ev.row(4));
  const std::string tampered = row.substr(0, row.size() - 1) + "0\n";  // rhs_evals * 10
  {
    SweepJournal j(dir + "/s.csv.journal", ev.fingerprint(), ev.header(), ev.size(), false);
    j.append(4, parse_csv_row(tampered.substr(0, tampered.size() - 1)));
  }
  SweepRunOptions o = quiet(1);
  o.resume = true;
  EXPECT_EQ(run_sweep(ev, o).computed, 15u);
  EXPECT_NE(slurp(dir + "/s.csv").find(tampered), std::string::npos);
}

TEST(SweepRun, JournalOfAnotherDefinitionIsRefused) {
  const sweep_test::TmpDir tmp("sweep-other");
  const std::string& dir = tmp.path;
  SweepSpec a = small_spec(dir + "/s.csv");
  const SweepEvaluator ea(a);
  { SweepJournal j(dir + "/s.csv.journal", ea.fingerprint(), ea.header(), ea.size(), false); }
  a.options.t_end = 5;
  const SweepEvaluator eb(a);
  SweepRunOptions o = quiet(1);
  o.resume = true;
  try {
    run_sweep(eb, o);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("different sweep definition"), std::string::npos) << e.what();
  }
  o.resume = false;
  o.overwrite = true;
  EXPECT_EQ(run_sweep(eb, o).computed, 16u);
}

TEST(SweepProgress, PlainLinesAndDurations) {
  EXPECT_EQ(Progress::format_duration(5.2), "5s");
  EXPECT_EQ(Progress::format_duration(185), "3m05s");
  EXPECT_EQ(Progress::format_duration(7620), "2h07m");
  EXPECT_EQ(Progress::format_duration(NAN), "?");
  std::FILE* f = std::tmpfile();
  {
    Progress p("sweep", 10, 4, ProgressMode::Plain, f, 1e9);
    p.advance(3);
    EXPECT_EQ(p.line(2.0, 0).substr(0, 33), "sweep: 7/10 (70.0%), 1.5 points/s");
    EXPECT_NE(p.line(2.0, 10).find("[#######   ]"), std::string::npos);
    EXPECT_NE(p.line(2.0, 0).find("ETA 2s"), std::string::npos);
  }
  std::rewind(f);
  char buf[512] = {0};
  const std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
  std::fclose(f);
  const std::string text(buf, n);
  // Start line, no periodic line (interval not reached), final line on destruction.
  EXPECT_EQ(sweep_test::count_lines(text), 2u) << text;
  EXPECT_NE(text.find("10 points, 4 already done"), std::string::npos);
}

// Issue 25 item 5: a journal row altered after it was written (a cell made nan or a word) is
// refused by its checksum, never copied into the CSV; the row as written resumes.
TEST(SweepRun, AlteredJournalCellsAreRefused) {
  const sweep_test::TmpDir tmp("sweep-altered");
  const std::string& dir = tmp.path;
  const SweepEvaluator ev(small_spec(dir + "/s.csv"));
  const std::string row = row_text(ev.row(4));
  const std::size_t cut = row.find(',', row.find(',') + 1);  // the second cell
  SweepRunOptions o = quiet(1);
  o.resume = true;
  for (const std::string cell : {"nan", "zzz"}) {
    SCOPED_TRACE(cell);
    {
      SweepJournal j(dir + "/s.csv.journal", ev.fingerprint(), ev.header(), ev.size(), false);
      j.append(4, parse_csv_row(row.substr(0, row.size() - 1)));
    }
    std::string text = slurp(dir + "/s.csv.journal");
    const std::size_t at = text.find(row.substr(0, cut));
    ASSERT_NE(at, std::string::npos);
    const std::size_t end = text.find(',', at + cut + 1);
    text.replace(at + cut + 1, end - (at + cut + 1), cell);
    std::ofstream(dir + "/s.csv.journal", std::ios::trunc) << text;
    try {
      run_sweep(ev, o);
      FAIL() << "expected an error";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(sweep_test::exists(dir + "/s.csv"));
  }
  {
    SweepJournal j(dir + "/s.csv.journal", ev.fingerprint(), ev.header(), ev.size(), false);
    j.append(4, parse_csv_row(row.substr(0, row.size() - 1)));
  }
  EXPECT_EQ(run_sweep(ev, o).resumed, 1u);
  EXPECT_NE(slurp(dir + "/s.csv").find(row), std::string::npos);
}

// A journal of the format before row checksums is named as such, not as another definition.
TEST(SweepRun, JournalOfTheEarlierFormatIsNamed) {
  const sweep_test::TmpDir tmp("sweep-v1");
  const SweepEvaluator ev(small_spec(tmp.path + "/s.csv"));
  std::ofstream(tmp.path + "/s.csv.journal")
      << "# blockdyn sweep journal v1 fingerprint=" << ev.fingerprint() << " points=" << ev.size() << "\n"
      << ev.header();
  SweepRunOptions o = quiet(1);
  o.resume = true;
  try {
    run_sweep(ev, o);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("format v1"), std::string::npos) << e.what();
  }
}
