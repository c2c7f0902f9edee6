// SPDX-License-Identifier: Apache-2.0
#pragma once
// The model of the forced analyses from Settings: --model housner|rigid (--width --height --mass
// --g --mu-s --mu-k --impact --restitution) or --model assembly (--preset --contact --slenderness
// --block-width --drums --phi-s --phi-l --columns-rock-only --restitution). Options of the other
// family are refused; a value given is checked, never read as "not given".
#include <string>
#include <vector>

#include "blockdyn/analysis/forced/forced_model.hpp"
#include "blockdyn/commands/settings.hpp"
#include "blockdyn/family/family.hpp"

namespace blockdyn {

const std::vector<std::string>& forced_model_option_names();

// What names the model in titles and decides the analyses' variants: the options as given, with
// their defaults (model housner, contact deformable, friction angles 90 deg).
struct ForcedModelChoice {
  std::string model = "housner", preset, contact = "deformable";
  double phi_s = 90, phi_l = 90;
  bool columns_rock_only = false;
  const Family* family = nullptr;
  // Friction by angles per interface (an assembly's --phi-s/--phi-l).
  bool friction_angles() const { return family && family->forced->friction_angles; }
  std::string label() const { return model + (preset.empty() ? "" : " " + preset); }  // "assembly trilith"
};
// Throws std::invalid_argument unless `model` names a family of the forced analyses.
ForcedModelChoice forced_model_choice(const Settings& s);
const Family& forced_family(const std::string& name);
// The families' entries (family_registry.cpp).
const ForcedFamily& housner_forced();
const ForcedFamily& rigid_forced();
const ForcedFamily& assembly_forced();
const ForcedFamily& rigid3d_forced();
// Throws std::invalid_argument naming the option.
ForcedModel forced_model_from(const Settings& s);

}  // namespace blockdyn
