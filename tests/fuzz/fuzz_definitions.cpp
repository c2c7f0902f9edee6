// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the TOML definitions (a scenario, an assembly file with its start checks, a
// sweep file of either family) on arbitrary text. Each is read or refused with
// std::invalid_argument naming the key; none crashes or hangs.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "blockdyn/analysis/sweep/rigid_sweep.hpp"
#include "blockdyn/analysis/sweep/sweep_toml.hpp"
#include "blockdyn/io/assembly_file.hpp"
#include "blockdyn/io/scenario.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"

namespace {
template <class F>
void refused_or_read(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument&) {
  } catch (const std::out_of_range&) {
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;  // a definition is small; longer inputs only slow the search
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string nowhere = "/nonexistent-blockdyn-fuzz";  // relative record paths read nothing
  refused_or_read([&] { blockdyn::parse_scenario(text, "fuzz.toml", nowhere); });
  refused_or_read([&] {
    blockdyn::Assembly a = blockdyn::parse_assembly(text, "fuzz.toml");
    a.contact = blockdyn::ContactKind::Rigid;
    blockdyn::validate(a, 64);
  });
  refused_or_read([&] { blockdyn::parse_sweep(text, "fuzz.toml"); });
  refused_or_read(
      [&] { blockdyn::parse_rigid_sweep(text, "fuzz.toml", blockdyn::three_dof_on_rigid_ground(), nowhere); });
  return 0;
}
