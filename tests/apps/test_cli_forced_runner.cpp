// SPDX-License-Identifier: Apache-2.0
// spectrum, survival and response-curve on the sweep runner, end to end: the same bytes for 1 and
// 2 threads and under MPI (also for a refined survival map, which runs in stages), a killed run
// resumed without losing a point and to identical bytes, the friction-angle curve on a case with
// a known answer, and bad input (exit 2 naming the field).
#include <gtest/gtest.h>
#include <signal.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <thread>

#include "blockdyn/analysis/forced/fragility_study.hpp"
#include "blockdyn/analysis/forced/rocking_spectrum.hpp"
#include "blockdyn/analysis/sweep/point_table.hpp"
#include "blockdyn/simulation/rigid_ground_model.hpp"
#include "test_sweep_util.hpp"

using nlohmann::json;
using namespace sweep_test;

namespace {

const std::string kMpirun =
    "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 "
    "mpirun --oversubscribe --allow-run-as-root -np ";

std::vector<std::string> runner_with(std::vector<std::string> a, const std::vector<std::string>& more) {
  a.insert(a.end(), more.begin(), more.end());
  return a;
}

const std::vector<std::string> kBlock{"--model", "housner", "--width", "0.3", "--height", "1.5"};

// A Housner survival map refined twice near class changes: 3 stages.
std::vector<std::string> refined_survival(const std::string& out, const std::string& periods = "20") {
  return runner_with(runner_with({"survival"}, kBlock),
                     {"--beta-min", "0.5", "--beta-max", "6", "--beta-points", "5", "--omega-min", "1", "--omega-max",
                      "20", "--omega-points", "5", "--periods", periods, "--refine", "2", "--out", out});
}

std::vector<std::string> one_sine_spectrum(const std::string& csv) {
  return runner_with(runner_with({"spectrum"}, kBlock),
                     {"--pulse", "one-sine", "--duration-min", "0.15", "--duration-max", "3", "--duration-points", "12",
                      "--scan-points", "60", "--rel-tol", "1e-8", "--csv", csv});
}

std::size_t journal_rows(const std::string& path) {
  const std::size_t n = count_lines(slurp(path));
  return n >= 2 ? n - 2 : 0;
}

// Starts a run and SIGKILLs it once its journal holds `rows` rows; returns the rows kept.
std::size_t start_and_kill(const std::vector<std::string>& args, const std::string& dir, const std::string& csv,
                           std::size_t rows) {
  const pid_t pid = spawn_cli(args, dir);
  const std::string journal = dir + "/" + csv + ".journal";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int st = 0;
  bool ended = false;
  while (std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &st, WNOHANG) != 0) {
      ended = true;
      break;
    }
    if (journal_rows(journal) >= rows) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (!ended) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &st, 0);
  }
  EXPECT_TRUE(WIFSIGNALED(st)) << "the run ended before it could be interrupted: " << slurp(dir + "/spawn.err");
  EXPECT_FALSE(exists(dir + "/" + csv));
  return journal_rows(journal);
}

bool have_mpi(const std::string& dir) {
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) return false;
  const CliResult r = run_cli({"survival", "--model", "housner", "--width", "0.3", "--height", "1.5", "--beta-points",
                               "1", "--omega-points", "1", "--quiet", "--out", "probe.csv"},
                              dir, kMpirun + "2");
  return r.err.find("built without MPI") == std::string::npos && r.code == 0;
}

}  // namespace

TEST(ForcedRunner, SameBytesForOneAndTwoThreads) {
  TmpDir d("forced-threads");
  for (const char* t : {"1", "2"}) {
    const CliResult r =
        run_cli(runner_with(refined_survival(std::string("s") + t + ".csv"),
                            {"--threads", t, "--json-out", std::string("s") + t + "_summary.json", "--quiet"}),
                d.path);
    ASSERT_EQ(r.code, 0) << r.err;
    const CliResult q =
        run_cli(runner_with(one_sine_spectrum(std::string("p") + t + ".csv"), {"--threads", t, "--quiet"}), d.path);
    ASSERT_EQ(q.code, 0) << q.err;
    const CliResult c =
        run_cli(runner_with(runner_with({"response-curve"}, kBlock),
                            {"--betas", "1.5,3", "--omega-min", "2", "--omega-max", "12", "--omega-points", "6",
                             "--t-end", "8", "--threads", t, "--quiet", "--out", std::string("c") + t + ".csv"}),
                d.path);
    ASSERT_EQ(c.code, 0) << c.err;
  }
  for (const char* f : {"s", "p", "c"})
    EXPECT_EQ(slurp(d.path + "/" + f + "1.csv"), slurp(d.path + "/" + f + "2.csv")) << f;
  const json a = json::parse(slurp(d.path + "/s1_summary.json")), b = json::parse(slurp(d.path + "/s2_summary.json"));
  EXPECT_EQ(a["points"], b["points"]);
  // The refined map holds the coarse grid and points of levels 1 and 2, not the whole lattice.
  const json side = json::parse(slurp(d.path + "/s1.json"));
  EXPECT_EQ(side["schema"], "blockdyn.survival.sidecar/1");
  EXPECT_EQ(side["point_count"], 17 * 17);
  EXPECT_LT(a["points"].size(), 17u * 17u);
  EXPECT_GT(a["points"].size(), 25u);
  EXPECT_TRUE(side.contains("tolerances"));
  EXPECT_EQ(side["definition"]["options"]["refine"], 2);
}

TEST(ForcedRunner, MpiRanksMatchOneProcess) {
  TmpDir d("forced-mpi");
  if (!have_mpi(d.path)) GTEST_SKIP() << "mpirun or an MPI build not available";
  ASSERT_EQ(run_cli(runner_with(refined_survival("one.csv"), {"--quiet", "--threads", "1"}), d.path).code, 0);
  const CliResult two = run_cli(runner_with(refined_survival("two.csv"), {"--progress", "none", "--threads", "1"}),
                                d.path, kMpirun + "2");
  ASSERT_EQ(two.code, 0) << two.err;
  EXPECT_NE(two.out.find("2 rank(s)"), std::string::npos) << two.out;
  EXPECT_EQ(slurp(d.path + "/two.csv"), slurp(d.path + "/one.csv"));
  ASSERT_EQ(run_cli(runner_with(one_sine_spectrum("p1.csv"), {"--quiet", "--threads", "2"}), d.path).code, 0);
  const CliResult three =
      run_cli(runner_with(one_sine_spectrum("p3.csv"), {"--quiet", "--threads", "1"}), d.path, kMpirun + "3");
  ASSERT_EQ(three.code, 0) << three.err;
  EXPECT_EQ(slurp(d.path + "/p3.csv"), slurp(d.path + "/p1.csv"));
  EXPECT_NE(slurp(d.path + "/p3.json").find("\"mpi_ranks\": 3"), std::string::npos);
}

TEST(ForcedRunner, KilledRefinedSurvivalResumesToIdenticalBytes) {
  TmpDir d("forced-kill");
  // Long runs (1500 forcing periods) so that the run is interrupted inside a refinement level.
  ASSERT_EQ(run_cli(runner_with(refined_survival("ref.csv", "1500"), {"--quiet", "--threads", "2"}), d.path).code, 0);
  const std::size_t total = count_lines(slurp(d.path + "/ref.csv")) - 1;
  const std::size_t kept =
      start_and_kill(runner_with(refined_survival("s.csv", "1500"), {"--threads", "1"}), d.path, "s.csv", 30);
  if (HasFailure()) return;
  EXPECT_LT(kept, total);
  const CliResult refused = run_cli(runner_with(refined_survival("s.csv", "1500"), {"--quiet"}), d.path);
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("--resume"), std::string::npos) << refused.err;
  const CliResult res =
      run_cli(runner_with(refined_survival("s.csv", "1500"), {"--resume", "--progress", "none"}), d.path);
  ASSERT_EQ(res.code, 0) << res.err;
  EXPECT_NE(res.out.find("(" + std::to_string(total - kept) + " computed, " + std::to_string(kept) + " resumed"),
            std::string::npos)
      << res.out;
  EXPECT_EQ(slurp(d.path + "/s.csv"), slurp(d.path + "/ref.csv"));
  EXPECT_FALSE(exists(d.path + "/s.csv.journal"));
}

TEST(ForcedRunner, KilledSpectrumResumesToIdenticalBytes) {
  TmpDir d("forced-kill-spectrum");
  ASSERT_EQ(run_cli(runner_with(one_sine_spectrum("ref.csv"), {"--quiet", "--threads", "2"}), d.path).code, 0);
  const std::size_t kept =
      start_and_kill(runner_with(one_sine_spectrum("s.csv"), {"--threads", "1"}), d.path, "s.csv", 3);
  if (HasFailure()) return;
  const CliResult res = run_cli(runner_with(one_sine_spectrum("s.csv"), {"--resume", "--json"}), d.path);
  ASSERT_EQ(res.code, 0) << res.err;
  EXPECT_EQ(slurp(d.path + "/s.csv"), slurp(d.path + "/ref.csv"));
  EXPECT_EQ(json::parse(res.out)["rows"].size(), 12u);
  EXPECT_LT(kept, 12u);
}

TEST(ForcedRunner, FrictionAngleCurveOfTheRigidTrilith) {
  // A half-cosine pulse of peak beta alpha g = 0.147 g, below the columns' uplift (tan alpha =
  // 0.25): nothing rocks, the columns stick to the ground (phi_s = 90) and move with it, and the
  // lintel follows them as long as friction can accelerate it: it slides exactly when
  // tan(phi_l) < 0.147, i.e. phi_l < 8.36 deg.
  TmpDir d("forced-phi");
  const std::vector<std::string> base{
      "response-curve", "--model", "assembly", "--preset", "trilith", "--contact", "rigid", "--excitation",
      "half-cosine",    "--betas", "0.6",      "--omega",  "2",       "--t-end",   "1.5",   "--json",
      "--quiet"};
  const CliResult r = run_cli(runner_with(base, {"--phi-l-values", "5,8,9,20,90"}), d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_EQ(j["points"].size(), 5u);
  const double b = j["width"];
  for (const auto& p : j["points"]) {
    const double phi = p["phi_l"], slip = p["max_sliding_over_b"].get<double>() * b;
    if (phi < 8.36)
      EXPECT_GT(slip, 1e-6) << phi;
    else
      EXPECT_LT(slip, 1e-12) << phi;  // no sliding at all, phi = 90 included
    EXPECT_LT(p["theta_max_over_alpha"].get<double>(), 1e-12) << phi;
    EXPECT_EQ(p["phi_s"], 90.0);
  }
  // The phi_l = 90 point of the curve is the run with the default (no-slip) friction, bit for bit.
  const CliResult ref = run_cli(base, d.path);
  ASSERT_EQ(ref.code, 0) << ref.err;
  const json k = json::parse(ref.out);
  EXPECT_EQ(k["points"][0]["phi_l"], 90.0);
  EXPECT_EQ(k["points"][0]["max_sliding_over_b"], j["points"][4]["max_sliding_over_b"]);
  EXPECT_EQ(k["points"][0]["theta_max_over_alpha"], j["points"][4]["theta_max_over_alpha"]);
}

TEST(ForcedRunner, BadInputIsAUsageError) {
  TmpDir d("forced-bad");
  const auto survival = runner_with({"survival"}, kBlock);
  const auto curve = runner_with(runner_with({"response-curve"}, kBlock), {"--betas", "2"});
  const std::vector<std::string> trilith{"response-curve", "--model", "assembly", "--preset",
                                         "trilith",        "--betas", "2"};
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {runner_with(survival, {"--resume"}), "resume: needs --out"},
      {runner_with(survival, {"--out", "x.csv", "--resume", "--overwrite"}), "--resume and --overwrite"},
      {runner_with(survival, {"--refine", "9"}), "refine"},
      {runner_with(survival, {"--beta-points", "400", "--omega-points", "400", "--refine", "4"}), "refine"},
      {runner_with(survival, {"--out", "x.csv", "--json-out", "x.json"}), "json-out"},
      {runner_with(survival, {"--out", "x.csv", "--progress-interval", "0"}), "progress-interval"},
      {runner_with(runner_with({"spectrum"}, kBlock), {"--durations", "1", "--resume"}), "resume: needs --csv"},
      {runner_with(curve, {"--phi-l-values", "5,10"}), "assembly"},
      {runner_with(trilith, {"--phi-l-values", "0,45"}), "phi-l-values"},
      {runner_with(trilith, {"--phi-l-values", "5:95:4"}), "phi-l-values"},
      {runner_with(trilith, {"--phi-l-values", "5,10", "--omega-points", "3"}), "omega"},
      {runner_with(trilith, {"--phi-l-values", "5,10", "--phi-l", "20", "--omega", "3"}), "--phi-l"},
      {runner_with(curve, {"--omega", "3", "--omega-min", "2"}), "--omega"},
      {runner_with(curve, {"--omega", "-1"}), "omega"},
  };
  expect_usage_errors(cases, d.path, true);
  // An existing table is never replaced silently.
  ASSERT_EQ(
      run_cli(runner_with(survival, {"--beta-points", "2", "--omega-points", "2", "--out", "t.csv", "--quiet"}), d.path)
          .code,
      0);
  const CliResult again =
      run_cli(runner_with(survival, {"--beta-points", "2", "--omega-points", "2", "--out", "t.csv"}), d.path);
  EXPECT_EQ(again.code, 2);
  EXPECT_NE(again.err.find("--overwrite"), std::string::npos) << again.err;
}

namespace {

// A small generated suite (6 records of 12 s) and a fragility over it: 6 x 8 runs.
std::vector<std::string> fragility_args(const std::string& out) {
  return {"fragility", "--model",     "housner", "--width", "0.4",      "--height",    "1.7",
          "--records", "suite/*.AT2", "--im",    "pga",     "--levels", "0.15:0.85:8", "--t-after",
          "2",         "--bootstrap", "50",      "--out",   out};
}

void make_suite(const std::string& dir) {
  const CliResult r = run_cli({"motion", "generate", "--arias", "0.6", "--d5-95", "6", "--t-mid", "4", "--f-mid", "3",
                               "--t-end", "12", "--count", "6", "--seed", "3", "--out", "suite", "--quiet"},
                              dir);
  ASSERT_EQ(r.code, 0) << r.err;
}

}  // namespace

TEST(ForcedRunner, FragilityRunsAreSimulateRunsAndResumeToIdenticalBytes) {
  TmpDir d("forced-fragility");
  make_suite(d.path);
  const CliResult ref =
      run_cli(runner_with(fragility_args("ref.csv"), {"--json", "--quiet", "--threads", "2"}), d.path);
  ASSERT_EQ(ref.code, 0) << ref.err;
  const json j = json::parse(ref.out);
  EXPECT_EQ(j["schema"], "blockdyn.fragility.summary/1");
  ASSERT_EQ(j["runs"].size(), 48u);
  ASSERT_EQ(j["levels"].size(), 8u);
  std::size_t over = 0;
  for (const auto& l : j["levels"]) {
    EXPECT_EQ(l["n"], 6);
    over += l["n_overturned"].get<std::size_t>();
  }
  std::size_t counted = 0;
  for (const auto& r : j["runs"]) counted += r["overturned"].get<bool>();
  EXPECT_EQ(over, counted);
  EXPECT_TRUE(j["fit"].contains("status"));
  // Two runs against `simulate` with the record scaled as the table says (17 digits).
  const std::string csv = slurp(d.path + "/ref.csv");
  for (const std::size_t row : {9u, 46u}) {
    std::size_t at = 0;
    for (std::size_t k = 0; k <= row; ++k) at = csv.find('\n', at) + 1;
    const std::string line = csv.substr(at, csv.find('\n', at) - at);
    std::vector<std::string> c;
    for (std::size_t a = 0, b; a <= line.size(); a = b + 1) {
      b = line.find(',', a);
      if (b == std::string::npos) b = line.size();
      c.push_back(line.substr(a, b - a));
    }
    const CliResult s =
        run_cli({"simulate", "--model", "housner", "--width", "0.4", "--height", "1.7", "--ground-h-record", c[1],
                 "--ground-h-scale", c[4], "--t-end", "14", "--json", "--quiet"},
                d.path);
    ASSERT_EQ(s.code, 0) << s.err;
    const json sj = json::parse(s.out);
    EXPECT_EQ(j["runs"][row]["max_abs_rotation"], sj["max_abs_rotation"]) << line;
    EXPECT_EQ(j["runs"][row]["overturned"].get<bool>(), sj["status"] == "overturned") << line;
  }
  // Killed and resumed: the same bytes as the uninterrupted run.
  const std::size_t kept = start_and_kill(runner_with(fragility_args("s.csv"), {"--threads", "1"}), d.path, "s.csv", 5);
  if (HasFailure()) return;
  const CliResult res = run_cli(runner_with(fragility_args("s.csv"), {"--resume", "--json"}), d.path);
  ASSERT_EQ(res.code, 0) << res.err;
  EXPECT_EQ(slurp(d.path + "/s.csv"), slurp(d.path + "/ref.csv"));
  EXPECT_EQ(json::parse(res.out)["fit"], j["fit"]);
  EXPECT_LT(kept, 48u);
}

TEST(ForcedRunner, FragilityBadInputIsAUsageError) {
  TmpDir d("forced-fragility-bad");
  make_suite(d.path);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"fragility", "--records", "none/*.AT2", "--levels", "0.1:1:3", "--width", "0.4", "--height", "1.7"}, "records"},
      {{"fragility", "--records", "suite/*.AT2", "--levels", "0:1:3", "--width", "0.4", "--height", "1.7"}, "levels"},
      {{"fragility", "--records", "suite/*.AT2", "--levels", "-0.1,0.2", "--width", "0.4", "--height", "1.7"},
       "levels"},
      {{"fragility", "--records", "suite/*.AT2", "--width", "0.4", "--height", "1.7"}, "levels"},
      {{"fragility", "--records", "suite/*.AT2", "--levels", "0.1:1:3", "--im", "pgd", "--width", "0.4", "--height",
        "1.7"},
       "im"},
      {{"fragility", "--records", "suite/*.AT2", "--levels", "0.1:1:3", "--im", "sa:0", "--width", "0.4", "--height",
        "1.7"},
       "im"},
      {{"fragility", "--records", "suite/*.AT2", "--levels", "0.1:1:3", "--bootstrap", "-1", "--width", "0.4",
        "--height", "1.7"},
       "bootstrap"},
  };
  expect_usage_errors(cases, d.path);
}

TEST(ForcedRunner, FragilityOfASuiteInComponentsAtIncidences) {
  // Two-component records at three incidences on a 3D box: each run is `simulate` with both
  // components scaled alike along the incidence, the measure the geometric mean of the two pgas,
  // and the fits per incidence name the critical one.
  TmpDir d("forced-fragility-3d");
  ASSERT_EQ(run_cli({"motion",     "generate", "--arias", "1.2", "--d5-95", "5", "--t-mid",      "4",
                     "--f-mid",    "2.5",      "--t-end", "10",  "--count", "4", "--components", "2",
                     "--h2-arias", "0.8",      "--out",   "s3",  "--quiet"},
                    d.path)
                .code,
            0);
  const std::vector<std::string> args = {"fragility", "--model",  "rigid3d",   "--width", "0.4", "--height",
                                         "1.2",       "--mu-s",   "0.7",       "--suite", "s3",  "--incidence",
                                         "0:90:3",    "--levels", "0.1:0.4:3", "--t-end", "12",  "--bootstrap",
                                         "0",         "--json",   "--quiet"};
  const CliResult r = run_cli(args, d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["definition"]["components"], json::array({"h1", "h2"}));
  EXPECT_EQ(j["definition"]["incidences"], json::array({0.0, 45.0, 90.0}));
  ASSERT_EQ(j["runs"].size(), 36u);  // 4 records x 3 incidences x 3 levels
  ASSERT_EQ(j["incidences"].size(), 3u);
  const double critical = j["critical_incidence"].get<double>();
  EXPECT_TRUE(critical == 0.0 || critical == 45.0 || critical == 90.0);
  std::ifstream mf(d.path + "/s3/motions.json");
  const json motions = json::parse(mf);
  int compared = 0;
  for (const std::size_t i : {5u, 22u, 34u}) {
    const json& run = j["runs"][i];
    const std::size_t record = i / 9, incidence = (i / 3) % 3;
    const json& c = motions["records"][record]["components"];
    const double im = std::sqrt(c["h1"]["pga"].get<double>() * c["h2"]["pga"].get<double>());
    EXPECT_DOUBLE_EQ(run["scale"].get<double>(), run["level"].get<double>() / im) << i;
    const std::string scale = blockdyn::format_double(run["scale"].get<double>());
    const CliResult sim = run_cli({"simulate",
                                   "--model",
                                   "rigid3d",
                                   "--width",
                                   "0.4",
                                   "--depth",
                                   "0.4",
                                   "--height",
                                   "1.2",
                                   "--mass",
                                   "100",
                                   "--mu-s",
                                   "0.7",
                                   "--ground-h-record",
                                   "s3/" + c["h1"]["file"].get<std::string>(),
                                   "--ground-h2-record",
                                   "s3/" + c["h2"]["file"].get<std::string>(),
                                   "--ground-h-scale",
                                   scale,
                                   "--ground-h2-scale",
                                   scale,
                                   "--ground-azimuth",
                                   blockdyn::format_double(45.0 * double(incidence)),
                                   "--t-end",
                                   "12",
                                   "--json",
                                   "--quiet"},
                                  d.path);
    ASSERT_EQ(sim.code, 0) << sim.err;
    const json sj = json::parse(sim.out);
    if (sj["status"] == "invalid") {
      EXPECT_TRUE(run["overturned"].is_null()) << i;
      continue;
    }
    EXPECT_EQ(run["overturned"].get<bool>(), sj["status"] == "overturned") << i;
    EXPECT_EQ(run["max_abs_rotation"], sj["max_tilt"]) << i;
    ++compared;
  }
  EXPECT_GE(compared, 2);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"fragility", "--suite", "s3", "--levels", "0.1:1:3", "--width", "0.4", "--height", "1.7"}, "rigid3d"},
      {{"fragility", "--model", "rigid3d", "--suite", "s3", "--records", "s3/*.AT2", "--levels", "0.1:1:3", "--width",
        "0.4", "--height", "1.2"},
       "suite"},
      {{"fragility", "--model", "rigid3d", "--suite", "none", "--levels", "0.1:1:3", "--width", "0.4", "--height",
        "1.2"},
       "suite"},
      {{"fragility", "--model", "rigid3d", "--suite", "s3", "--incidence", "0:400:3", "--levels", "0.1:1:3", "--width",
        "0.4", "--height", "1.2"},
       "incidence"},
  };
  expect_usage_errors(cases, d.path);
}

TEST(ForcedRunner, FragilityOfAnAssemblyCountsCollapses) {
  TmpDir d("forced-fragility-assembly");
  make_suite(d.path);
  const CliResult r =
      run_cli({"fragility", "--model", "assembly", "--preset", "trilith", "--contact", "rigid", "--records",
               "suite/*.AT2", "--levels", "0.05,1.5", "--t-after", "1", "--json", "--quiet"},
              d.path);
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  // Far below the columns' uplift (tan alpha = 0.25 g) nothing collapses; at 1.5 g all do: the
  // runs are separated, which has no finite lognormal fit, and the summary says so.
  EXPECT_EQ(j["levels"][0]["n_overturned"], 0);
  EXPECT_EQ(j["levels"][1]["n_overturned"], 6);
  EXPECT_EQ(j["fit"]["status"], "no_fit");
  EXPECT_TRUE(j["fit"]["median"].is_null());
}

// The typed C++ study (analysis/forced/fragility_study.hpp) gives the command's numbers: the same
// runs, fit and band from the same records, levels and options.
TEST(ForcedRunner, TypedFragilityStudyEqualsTheCommand) {
  TmpDir d("forced-fragility-typed");
  make_suite(d.path);
  const CliResult ref = run_cli(runner_with(fragility_args("ref.csv"), {"--json", "--quiet"}), d.path);
  ASSERT_EQ(ref.code, 0) << ref.err;
  const json j = json::parse(ref.out);
  std::vector<std::string> names;
  std::vector<std::shared_ptr<const blockdyn::Accelerogram>> records;
  for (const auto& f : j["definition"]["records"]) {
    names.push_back(f.get<std::string>());
    records.push_back(std::make_shared<const blockdyn::Accelerogram>(
        blockdyn::load_accelerogram(d.path + "/" + names.back(), "records")));
  }
  blockdyn::RigidBlockParams p;
  p.shape.width = 0.4;
  p.shape.height = 1.7;
  const blockdyn::ForcedModel m = blockdyn::forced_block_model(p, blockdyn::housner_on_rigid_ground());
  const auto suite = blockdyn::fragility_suite(names, records, blockdyn::IntensityMeasure::pga(), 9.81, m.alpha);
  blockdyn::FragilityOptions o;
  o.levels = j["definition"]["levels"].get<std::vector<double>>();
  o.t_after = 2;
  o.bootstrap = 50;
  o.threads = 2;
  const blockdyn::FragilityResult r = blockdyn::run_fragility(m, suite, o);
  ASSERT_EQ(r.runs.size(), j["runs"].size());
  for (std::size_t i = 0; i < r.runs.size(); ++i) {
    EXPECT_EQ(r.runs[i].overturned, j["runs"][i]["overturned"].get<bool>()) << i;
    EXPECT_EQ(r.runs[i].max_abs_rotation, j["runs"][i]["max_abs_rotation"].get<double>()) << i;
    EXPECT_EQ(r.runs[i].scale, j["runs"][i]["scale"].get<double>()) << i;
  }
  ASSERT_TRUE(r.fit.ok);
  EXPECT_EQ(r.fit.median, j["fit"]["median"].get<double>());
  EXPECT_EQ(r.fit.beta, j["fit"]["beta"].get<double>());
  EXPECT_EQ(r.band.median_lo, j["fit"]["ci90"]["median"][0].get<double>());
  EXPECT_EQ(r.band.beta_hi, j["fit"]["ci90"]["beta"][1].get<double>());
  ASSERT_EQ(r.curve.size(), j["curve"].size());
  EXPECT_EQ(r.curve[40].p, j["curve"][40]["p"].get<double>());
}

// The typed rocking spectrum (analysis/forced/rocking_spectrum.hpp) gives the command's rows and
// overturning scales.
TEST(ForcedRunner, TypedRockingSpectrumEqualsTheCommand) {
  TmpDir d("forced-rocking-typed");
  make_suite(d.path);
  const CliResult ref =
      run_cli({"rocking-spectrum", "--record", "suite/rezaeian_0001.AT2", "--alpha", "0.2", "--p-min", "1", "--p-max",
               "4", "--p-points", "5", "--scales", "0.5,1,2", "--out", "rs.csv", "--json", "--quiet"},
              d.path);
  ASSERT_EQ(ref.code, 0) << ref.err;
  const json j = json::parse(ref.out);
  blockdyn::RockingSpectrumOptions o;
  o.alpha = 0.2;
  o.p = j["definition"]["p"].get<std::vector<double>>();
  o.scales = {0.5, 1, 2};
  o.t_end = j["definition"]["t_end"].get<double>();
  o.threads = 2;
  const auto record = std::make_shared<const blockdyn::Accelerogram>(
      blockdyn::load_accelerogram(d.path + "/suite/rezaeian_0001.AT2", "record"));
  blockdyn::RigidBlockParams base;
  const auto pts = blockdyn::rocking_spectrum(blockdyn::housner_on_rigid_ground(), base, o, record);
  ASSERT_EQ(pts.size(), j["rows"].size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_EQ(pts[i].p, j["rows"][i]["p"].get<double>());
    EXPECT_EQ(pts[i].max_abs_rotation_over_alpha, j["rows"][i]["max_abs_rotation_over_alpha"].get<double>()) << i;
    EXPECT_EQ(pts[i].overturned, j["rows"][i]["overturned"].get<bool>()) << i;
  }
  const auto s = blockdyn::overturning_scales(pts, o);
  ASSERT_EQ(s.size(), j["overturning_scales"].size());
  for (std::size_t i = 0; i < s.size(); ++i)
    EXPECT_EQ(s[i].scale.has_value(), !j["overturning_scales"][i]["min_overturning_scale"].is_null()) << i;
}
