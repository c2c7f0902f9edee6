// SPDX-License-Identifier: Apache-2.0
#pragma once
// What draws a result, as data: the figure's kind and what it is drawn from. The front ends turn
// it into a script and its arguments (the command line: apps/figure_script.cpp, python/plot_<kind>.py
// for a plot and python/animate_<kind>.py for an animation; Python the same through the module):
// this layer names no script and spells no command-line option.
#include <string>
#include <vector>

namespace blockdyn {

struct FigureSpec {
  // A named input of the figure, with its values (none: a switch).
  struct Option {
    std::string name;
    std::vector<std::string> values;
  };
  std::string kind;  // e.g. "fragility": what the figure shows
  // Its inputs in order: "@csv:<series>" a table's path, "@plot" the figure's path, else a value.
  std::vector<std::string> inputs;
  std::vector<Option> options;

  bool empty() const { return kind.empty(); }
};

}  // namespace blockdyn
