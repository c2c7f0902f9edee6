// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/assembly/contact_kind.hpp"

#include <stdexcept>

namespace blockdyn {

const std::vector<ContactKindInfo>& contact_kinds() {
  static const std::vector<ContactKindInfo> kinds{
      {ContactKind::Deformable, "deformable", "spring-dashpot contact points (seed 002), event-driven", true, false,
       true, false, false},
      {ContactKind::Rigid, "rigid",
       "unilateral contact, Newton impacts, Coulomb friction (event-driven, or Moreau-Jean time-stepping)", false, true,
       false, true, true},
  };
  return kinds;
}

const ContactKindInfo& info(ContactKind k) {
  for (const ContactKindInfo& i : contact_kinds())
    if (i.kind == k) return i;
  throw std::logic_error("contact kind not registered");
}

const char* to_string(ContactKind k) { return info(k).name; }

std::string contact_kind_names() {
  std::string names;
  for (const ContactKindInfo& i : contact_kinds()) names += (names.empty() ? "" : ", ") + std::string(i.name);
  return names;
}

ContactKind contact_kind_from(const std::string& field, const std::string& text) {
  for (const ContactKindInfo& i : contact_kinds())
    if (text == i.name) return i.kind;
  throw std::invalid_argument(field + " = '" + text + "' is not one of: " + contact_kind_names());
}

}  // namespace blockdyn
