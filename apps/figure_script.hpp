// SPDX-License-Identifier: Apache-2.0
#pragma once
// A figure of the library's (FigureSpec: its kind, inputs and named options) as the command line
// draws it: the script python/plot_<kind>.py or animate_<kind>.py and its argument list, each
// option spelled --<name> followed by its values.
#include <string>
#include <vector>

#include "blockdyn/commands/figure_spec.hpp"

namespace blockdyn::cli {

std::string plot_script(const FigureSpec& f);
std::string animation_script(const FigureSpec& f);
// The inputs, then the options.
std::vector<std::string> figure_arguments(const FigureSpec& f);

}  // namespace blockdyn::cli
