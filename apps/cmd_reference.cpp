// SPDX-License-Identifier: Apache-2.0
// `blockdyn reference` (hidden): every subcommand and option as the parser holds them, as JSON:
// the documentation site's option reference is generated from it (scripts/gen_reference.py), so it
// says what the program accepts, not what a page once said.
#include <cstdio>
#include <iostream>

#include "cli_common.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
// Each command's own names (add, Flags, ...) in its own namespace: the files build as one unity.
namespace cmd_reference {
namespace {

nlohmann::ordered_json option_json(const CLI::Option& o) {
  nlohmann::ordered_json j;
  nlohmann::ordered_json names = nlohmann::ordered_json::array();
  for (const std::string& n : o.get_snames()) names.push_back("-" + n);
  for (const std::string& n : o.get_lnames()) names.push_back("--" + n);
  if (o.get_positional()) names.push_back(o.get_name());
  j["names"] = names;
  j["help"] = o.get_description();
  j["default"] = o.get_default_str();
  j["kind"] = o.get_positional()          ? "positional"
              : o.get_expected_min() == 0 ? "flag"
              : o.get_expected_max() > 1  ? "list"
                                          : "value";
  j["required"] = o.get_required();
  j["group"] = o.get_group();
  return j;
}

nlohmann::ordered_json command_json(const CLI::App& app) {
  nlohmann::ordered_json j;
  j["name"] = app.get_name();
  j["description"] = app.get_description();
  nlohmann::ordered_json opts = nlohmann::ordered_json::array();
  for (const CLI::Option* o : app.get_options())
    if (o->get_lnames().empty() || o->get_lnames().front() != "help") opts.push_back(option_json(*o));
  j["options"] = opts;
  nlohmann::ordered_json subs = nlohmann::ordered_json::array();
  for (const CLI::App* s : app.get_subcommands({}))
    if (!s->get_group().empty()) subs.push_back(command_json(*s));
  if (!subs.empty()) j["subcommands"] = subs;
  return j;
}

void add(CLI::App& app) {
  CLI::App* s = app.add_subcommand("reference", "every subcommand and option as JSON (for the documentation)");
  s->group("");  // hidden from --help
  CLI::App* root = &app;
  s->callback([root] {
    nlohmann::ordered_json j;
    j["schema"] = "blockdyn.reference/1";
    nlohmann::ordered_json cmds = nlohmann::ordered_json::array();
    for (const CLI::App* c : root->get_subcommands({}))
      if (!c->get_group().empty()) cmds.push_back(command_json(*c));
    j["commands"] = cmds;
    std::cout << j.dump(1) << "\n";
  });
}

RegisterCommand reg(1000, add);

}  // namespace
}  // namespace cmd_reference
}  // namespace blockdyn::cli
