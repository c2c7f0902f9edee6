// SPDX-License-Identifier: Apache-2.0
// `blockdyn limit-analysis (--preset ... | FILE.toml)`: the horizontal load multiplier of rigid
// no-tension blocks with Coulomb friction, its mechanism and line of thrust, and (--min-thickness)
// the thinnest arch that stands (blockdyn/commands/limit_analysis_command.hpp). Parse, call the
// library, write.
#include <unistd.h>

#include <cstdio>
#include <memory>

#include "blockdyn/commands/limit_analysis_command.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
// Each command's own names (add, Flags, ...) in its own namespace: the files build as one unity.
namespace cmd_limit_analysis {
namespace {

struct Flags {
  bool json = false;
  std::string json_out, plot;
};

void add(CLI::App& app) {
  auto f = std::make_shared<Flags>();
  CLI::App* s = app.add_subcommand(
      "limit-analysis",
      "static limit analysis (Heyman's masonry: rigid no-tension blocks, Coulomb friction): the horizontal "
      "load multiplier lambda = a_H / g at which the assembly becomes a mechanism, the mechanism, the line of "
      "thrust, and (--min-thickness) the thinnest arch that stands");
  s->add_option("file", "assembly file (TOML: [[block]] with width/height or vertices, [[interface]])");
  add_spec_options(*s, limit_analysis_options());
  s->add_flag("--json", f->json, "print the JSON document (instead of the text)");
  s->add_option("--json-out", f->json_out, "write the JSON document to this file");
  s->add_option("--plot", f->plot, "a figure: the blocks, the line of thrust and the mechanism (PNG + SVG)");
  s->callback([s, f] {
    const nlohmann::ordered_json j = limit_analysis_run(settings_of(*s, {"--json", "--json-out", "--plot"}));
    if (!f->json_out.empty()) emit_json(j, f->json_out);
    if (!f->plot.empty()) {
      char path[] = "/tmp/blockdyn-limit-XXXXXX";
      const int fd = ::mkstemp(path);
      if (fd < 0) throw std::runtime_error("cannot create a temporary file for the figure");
      ::close(fd);
      const RemoveOnSignal guard(path);
      try {
        emit_json(j, path);
        run_python("plot_limit_analysis.py", {path, f->plot});
      } catch (...) {
        std::remove(path);
        throw;
      }
      std::remove(path);
    }
    if (f->json)
      emit_json(j, "-");
    else
      std::fputs(limit_analysis_text(j).c_str(), stdout);
  });
}

RegisterCommand reg(16, add);

}  // namespace
}  // namespace cmd_limit_analysis
}  // namespace blockdyn::cli
