// SPDX-License-Identifier: Apache-2.0
#include "figure_script.hpp"

namespace blockdyn::cli {

std::string plot_script(const FigureSpec& f) { return "plot_" + f.kind + ".py"; }

std::string animation_script(const FigureSpec& f) { return "animate_" + f.kind + ".py"; }

std::vector<std::string> figure_arguments(const FigureSpec& f) {
  std::vector<std::string> args = f.inputs;
  for (const FigureSpec::Option& o : f.options) {
    args.push_back("--" + o.name);
    args.insert(args.end(), o.values.begin(), o.values.end());
  }
  return args;
}

}  // namespace blockdyn::cli
