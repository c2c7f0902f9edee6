// SPDX-License-Identifier: Apache-2.0
// `blockdyn motion info FILE`: a record's intensity measures and its response spectrum
// (blockdyn/api/motion_info.hpp). Parse, call the library, write.
#include <cstdio>
#include <memory>

#include "blockdyn/api/motion_info.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
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

void add(CLI::App& app) {
  CLI::App* m = app.add_subcommand("motion", "ground motions: measure a record (info)");
  m->require_subcommand(1);
  add_info(*m);
}

RegisterCommand reg(14, add);

}  // namespace
}  // namespace blockdyn::cli
