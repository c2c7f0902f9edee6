// SPDX-License-Identifier: Apache-2.0
#pragma once
// Options by name, as a user gives them: the command line's flags (without the dashes) or Python's
// keyword arguments (underscores read as dashes). One vocabulary: every front end hands its options
// to the library as Settings, and the library alone turns them into model parameters, ground
// motions and run options, with one validation. Values are kept as the user wrote them and parsed
// on use, with errors naming the option (`--t-end`); a record may also be given as arrays.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "blockdyn/commands/option_spec.hpp"
#include "blockdyn/excitation/accelerogram.hpp"
#include "blockdyn/integrate/integrator_options.hpp"

namespace blockdyn {

class Settings {
 public:
  // Appends a value to option `name` (a repeated option keeps every value in order).
  void add(std::string_view name, std::string value);
  // Replaces every value of option `name` by this one.
  void set(std::string_view name, std::string value);
  // A record given as samples (t in s, a in g) instead of a file.
  void add_record(std::string_view name, std::shared_ptr<const Accelerogram> record);

  bool has(std::string_view name) const;
  // The option's last value, parsed; throws std::invalid_argument naming `--name` when it does not
  // parse completely. Absent: the fallback.
  double number(std::string_view name, double fallback) const;
  std::optional<double> number(std::string_view name) const;
  long integer(std::string_view name, long fallback) const;
  // The same for a count held in an int: a value beyond an int's range is refused naming it.
  int small_integer(std::string_view name, int fallback) const;
  std::string text(std::string_view name, const std::string& fallback = "") const;
  bool flag(std::string_view name) const;  // given without a value, or true/1
  std::vector<std::string> values(std::string_view name) const;
  std::shared_ptr<const Accelerogram> record(std::string_view name) const;

  // The options given, in name order.
  std::vector<std::string> names() const;
  // Throws std::invalid_argument naming the first option that is not in `known`.
  void require_known(const std::vector<std::string>& known, const std::string& what) const;
  // The same for the options `specs` describes and the names `extra`.
  void require_known(const std::vector<StudyOption>& specs, const std::vector<std::string>& extra,
                     const std::string& what) const;

  // A number as a value that reads back to the same double (the shortest such decimal).
  static std::string exact(double v);
  // "t_end" -> "t-end": Python's keyword names to the command line's.
  static std::string canonical(std::string_view name);

 private:
  struct Entry {
    std::vector<std::string> values;
    std::shared_ptr<const Accelerogram> record;
  };
  const Entry* find(std::string_view name) const;
  std::map<std::string, Entry, std::less<>> entries_;
};

// The settings with every alias an option's description gives renamed to the option's name
// (--d595 -> d5-95); both given is an error naming them.
Settings with_canonical_names(const Settings& s, const std::vector<StudyOption>& specs);

// --rtol, --atol and --method (auto, dopri5, dop853) where given; std::invalid_argument naming
// the option. Their ranges are checked with the run's options (simulation/run_options.hpp).
void apply_integrator_settings(const Settings& s, IntegratorOptions& o);

}  // namespace blockdyn
