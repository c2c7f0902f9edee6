// SPDX-License-Identifier: Apache-2.0
// `blockdyn motion generate` (a suite of synthetic records: blockdyn/commands/motion_generate.hpp) and
// `blockdyn motion info FILE` (a record's intensity measures and its response spectrum:
// blockdyn/commands/motion_info.hpp). Parse, call the library, write.
#include <cstdio>
#include <memory>

#include "blockdyn/commands/motion_generate.hpp"
#include "blockdyn/commands/motion_info.hpp"
#include "blockdyn/io/progress.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
// Each command's own names (add, Flags, ...) in its own namespace: the files build as one unity.
namespace cmd_motion {
namespace {

struct InfoFlags {
  bool json = false;
  std::string json_out;
};

void add_info(CLI::App& motion) {
  auto f = std::make_shared<InfoFlags>();
  CLI::App* s = motion.add_subcommand(
      "info", "a record's pga, pgv, pgd, Arias intensity, D5-95, t_mid, mean period and (--spectrum) Sa(T)");
  s->add_option("record", "the record: PEER .AT2 (g) or CSV 't, a' (s, g)")->required();
  add_spec_options(*s, motion_info_options());
  s->add_flag("--json", f->json, "print the JSON document (instead of the text)");
  s->add_option("--json-out", f->json_out, "write the JSON document to this file");
  s->callback([s, f] {
    const nlohmann::ordered_json j = motion_info(settings_of(*s, {"--json", "--json-out"}));
    if (!f->json_out.empty()) emit_json(j, f->json_out);
    if (f->json)
      emit_json(j, "-");
    else
      std::fputs(motion_info_text(j).c_str(), stdout);
  });
}

struct GenerateFlags {
  bool json = false, quiet = false, overwrite = false;
  std::string json_out, plot;
};

const char* const kGenerateHelp =
    "a suite of synthetic records as PEER .AT2 files (g): the Rezaeian & Der Kiureghian site model, or a near-fault "
    "pulse (Mavroeidis & Papageorgiou), optionally on a stochastic background";

void add_generate(CLI::App& motion) {
  auto f = std::make_shared<GenerateFlags>();
  CLI::App* s = motion.add_subcommand("generate", kGenerateHelp);
  add_spec_options(*s, motion_generate_options());
  s->get_option("--out")->group(kDirectoryOutputs);  // a directory, checked by the library
  s->add_option("--threads", "worker threads (0: all cores); the files are the same for any count")->default_str("0");
  s->add_flag("--overwrite", f->overwrite, "replace the suite already in --out");
  s->add_flag("--json", f->json, "print motions.json's document");
  s->add_option("--json-out", f->json_out, "also write the document to this file");
  s->add_option("--plot", f->plot, "a figure: a few records and the suite's measures against the targets (PNG + SVG)");
  s->add_flag("--quiet", f->quiet, "no summary line");
  s->callback([s, f] {
    const Settings given = settings_of(*s, {"--json", "--json-out", "--plot", "--quiet"});
    std::unique_ptr<Progress> bar;
    const nlohmann::ordered_json j = motion_generate(given, [&](std::size_t done, std::size_t total) {
      if (f->quiet || f->json) return;
      if (!bar)
        bar = std::make_unique<Progress>("motion generate", total, 0, ProgressMode::Auto, stderr, 10.0, "records");
      bar->advance();
      if (done == total) bar->finish();
    });
    if (!f->plot.empty()) run_python("plot_motions.py", {given.text("out") + "/motions.json", f->plot});
    if (!f->json_out.empty()) emit_json(j, f->json_out);
    if (f->json) emit_json(j, "-");
    if (!f->json && !f->quiet) {
      const auto& m = j["median"];
      std::printf(
          "motion generate: %zu %s records in %s; medians: arias %.4g m/s, d5_95 %.4g s, t_mid %.4g s, pga %.4g g\n",
          j["records"].size(), j["model"].get<std::string>().c_str(), given.text("out").c_str(),
          m["arias"].get<double>(), m["d5_95"].get<double>(), m["t_mid"].get<double>(), m["pga"].get<double>());
    }
  });
}

void add(CLI::App& app) {
  CLI::App* m = app.add_subcommand("motion", "ground motions: generate a suite (generate), measure a record (info)");
  m->require_subcommand(1);
  add_generate(*m);
  add_info(*m);
}

RegisterCommand reg(14, add);

}  // namespace
}  // namespace cmd_motion
}  // namespace blockdyn::cli
