// SPDX-License-Identifier: Apache-2.0
#pragma once
// The five mechanisms of a rigid block on rigid ground (seed 001, sec. 4.2) and the event kinds
// that the rigid-ground models report.
namespace blockdyn {

enum class Mechanism { Rest, Slide, Rock, SlideRock, Flight };

inline const char* to_string(Mechanism m) {
  switch (m) {
    case Mechanism::Rest:
      return "rest";
    case Mechanism::Slide:
      return "slide";
    case Mechanism::Rock:
      return "rock";
    case Mechanism::SlideRock:
      return "slide_rock";
    case Mechanism::Flight:
      return "flight";
  }
  return "?";
}

enum class RigidEventKind : int {
  Impact,         // a corner hits the ground (state jump)
  Mode,           // the mechanism changes without an impact
  BeyondAlpha,    // |theta| passes alpha outwards (the static overturning limit)
  WithinAlpha,    // |theta| comes back below alpha
  Overturn,       // |theta| reaches pi/2: the block lies on its side (the run stops)
  Invalid,        // the state leaves the model (e.g. the ground pulls away faster than gravity)
  Painleve,       // no or several consistent mechanisms (Painleve's paradox): reported, the run stops
  GroundBreak,    // a breakpoint of the ground motion (not reported)
  WZero,          // theta passes 0 without an impact (flight)
  AmbiguousOnset  // a switch at which more than one mechanism is consistent (reported; the
                  // rule's choice is taken: docs/rigid-ground.md)
};

inline const char* to_string(RigidEventKind k) {
  switch (k) {
    case RigidEventKind::Impact:
      return "impact";
    case RigidEventKind::Mode:
      return "mode";
    case RigidEventKind::BeyondAlpha:
      return "beyond_alpha";
    case RigidEventKind::WithinAlpha:
      return "within_alpha";
    case RigidEventKind::Overturn:
      return "overturn";
    case RigidEventKind::Invalid:
      return "invalid";
    case RigidEventKind::Painleve:
      return "painleve";
    case RigidEventKind::GroundBreak:
      return "ground_break";
    case RigidEventKind::WZero:
      return "w_zero";
    case RigidEventKind::AmbiguousOnset:
      return "ambiguous_onset";
  }
  return "?";
}

// A set of mechanisms as bits.
inline constexpr unsigned mechanism_bit(Mechanism m) { return 1u << unsigned(m); }
inline constexpr Mechanism kMechanisms[] = {Mechanism::Rest, Mechanism::Slide, Mechanism::Rock, Mechanism::SlideRock,
                                            Mechanism::Flight};

// Name of a base corner: side +1 is the left corner A, -1 the right corner B.
inline const char* corner_name(int side) { return side > 0 ? "A" : "B"; }

}  // namespace blockdyn
