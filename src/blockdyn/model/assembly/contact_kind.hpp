// SPDX-License-Identifier: Apache-2.0
#pragma once
// The contact laws an assembly's interfaces may follow, registered once (contact_kinds()): the
// deformable law (spring-dashpot contact points, event-driven) and the rigid law (unilateral
// contact with Newton impacts and Coulomb friction: event-driven or Moreau-Jean time-stepping).
// Everything that depends on the law asks its traits here; nothing compares its name.
#include <string>
#include <vector>

namespace blockdyn {

enum class ContactKind { Deformable, Rigid };

struct ContactKindInfo {
  ContactKind kind;
  const char* name;         // the --contact value and the outputs' "contact"
  const char* description;  // for --help and the reference
  // The contact points are springs and dashpots (stiffness, damping; they settle under the weight).
  bool springs;
  // Impacts may be plastic (restitution 0, the default); the deformable law's dashpots need a
  // restitution of at least 0.001.
  bool plastic_impacts;
  // Each orbit is event-located and smooth between events: it has a variational equation (the
  // Lyapunov exponent). Time-stepping has none.
  bool linearisable;
  // Seed 001's 5-DOF restriction (columns only rock on the ground) is defined for this law.
  bool rock_only_restriction;
  // It runs event-driven or by Moreau-Jean time-stepping (--scheme, --step).
  bool schemes;
};

// Every registered law, in the order --help lists them.
const std::vector<ContactKindInfo>& contact_kinds();
const ContactKindInfo& info(ContactKind k);
const char* to_string(ContactKind k);
// The law named; throws std::invalid_argument "<field> = '<text>' is not one of: deformable, rigid".
ContactKind contact_kind_from(const std::string& field, const std::string& text);
// "deformable, rigid"
std::string contact_kind_names();

}  // namespace blockdyn
