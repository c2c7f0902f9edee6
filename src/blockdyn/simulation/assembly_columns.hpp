// SPDX-License-Identifier: Apache-2.0
#pragma once
// The assembly's trajectory columns, the same for both contact laws: per block its pose and
// velocity, the ground acceleration, per contact end its point, forces and state, the energies.
#include <string>
#include <vector>

namespace blockdyn {

inline std::vector<std::string> assembly_columns(int blocks, int interfaces) {
  std::vector<std::string> n{"t", "event"};
  for (int b = 0; b < blocks; ++b)
    for (const char* c : {"x", "y", "theta", "vx", "vy", "omega"})
      n.push_back(std::string(c) + '_' + std::to_string(b));
  n.emplace_back("a_h");
  n.emplace_back("a_v");
  for (int p = 0; p < 2 * interfaces; ++p)
    for (const char* c : {"px", "py", "fn", "ft", "state"})
      n.push_back(std::string(c) + '_' + std::to_string(p / 2) + '_' + std::to_string(p % 2));
  for (const char* c : {"E_kin", "E_grav", "E_spring_n", "E_spring_t", "E_total", "W_ground", "W_normal", "W_friction",
                        "W_switch", "energy_balance"})
    n.emplace_back(c);
  return n;
}

// A contact end's state as a table text: open (O), stick (K), slip + (P), slip - (N).
inline const char* end_state_text(char c) { return c == 'K' ? "K" : c == 'P' ? "P" : c == 'N' ? "N" : "O"; }

}  // namespace blockdyn
