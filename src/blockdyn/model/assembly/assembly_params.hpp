// SPDX-License-Identifier: Apache-2.0
#pragma once
// An assembly of rigid blocks on the moving ground (spec block-assemblies.md): the blocks
// (rectangles or convex polygons: size, mass, initial pose), the interfaces between facing faces,
// and each interface's contact law. Presets build seed 002's trilith, a single block, a column of
// drums and a circular arch of voussoirs. Units are SI; angles in radians.
#include <string>
#include <vector>

#include "blockdyn/model/assembly/contact_kind.hpp"
#include "blockdyn/model/common/block_kinematics.hpp"

namespace blockdyn {

// Friction coefficient standing for a 90 degree friction angle: no sliding at all.
inline constexpr double kNoSlipFriction = 1e12;

// The per-point deformable law of an interface (deformable_contact.hpp).
struct ContactLaw {
  double k_normal = 1e7;                                  // N/m per contact point (seed 002: k_C = 1e4 kN/m)
  double k_tangential = -1;                               // N/m per point; < 0: k_normal / 3 (seed 002's k_E)
  double restitution = 0.5;                               // normal restitution of a flat drop of the upper block
  double mu_s = kNoSlipFriction, mu_k = kNoSlipFriction;  // static and kinetic friction
  double damping = -1;                                    // N s/m per point; < 0: calibrated from restitution
};

struct AssemblyBlock {
  std::string name;
  double width = 0, height = 0, mass = 0;  // m, m, kg (a polygon: its bounding box at rest)
  double x = 0, y = 0, theta = 0;          // initial centre of mass and rotation (counter-clockwise)
  double vx = 0, vy = 0, omega = 0;        // initial rates
  // A convex polygon: its vertices, counter-clockwise, relative to the centre of mass with the
  // block unturned (empty: the width x height rectangle), and its squared radius of gyration.
  std::vector<Vec2> vertices;
  double gyration_sq = 0;
  double inertia() const {
    return vertices.empty() ? mass * (width * width + height * height) / 12.0 : mass * gyration_sq;
  }
};

// Block `upper` standing on block `lower` (-1: the ground): a rectangle's base on the top face
// below, or the facing edges of polygons (interface_faces.hpp). Edges may be named (edge k runs
// from vertex k to k + 1; -1: found from the geometry at the start).
struct AssemblyInterface {
  int lower = -1, upper = 0;
  ContactLaw law;
  int lower_edge = -1, upper_edge = -1;
};

// Blocks an assembly's dynamics takes (the state's capacity); the static analysis takes more.
inline constexpr int kMaxDynamicBlocks = 24;
inline constexpr int kMaxStaticBlocks = 2000;
// Above this many blocks the rigid law runs by time-stepping unless told otherwise.
inline constexpr int kEventDrivenMaxBlocks = 8;

struct Assembly {
  std::string preset = "custom";  // block | trilith | column | arch | custom
  ContactKind contact = ContactKind::Deformable;
  std::vector<AssemblyBlock> blocks;
  std::vector<AssemblyInterface> interfaces;
  double g = 9.81;
  double collapse_rotation = 1.0;  // mode 1: |theta| >= this fraction of the block's atan(b/h)
  double min_bearing = 0.0;        // mode 2: an interface's overlap falls to this length (m)
  // Seed 001's 5-DOF restriction (rigid law): blocks on the ground only rock on it (no sliding,
  // no plastic-impact bounce); a block leaving the ground is outside the model and is reported.
  bool rock_only_on_ground = false;
};

// Preset geometry (seed 002: b = 0.12 m, thickness 0.06 m, density 2700 kg/m^3).
struct PresetOptions {
  double slenderness = 4;                         // column height / width
  double block_width = 0.12;                      // m
  double thickness = 0.06;                        // m, out of plane
  double density = 2700;                          // kg/m^3
  int drums = 4;                                  // column preset
  double lintel_length = -1;                      // trilith: < 0 means the column height (seed 002's layout)
  double overhang = 0;                            // trilith: lintel beyond each column's outer face (m; < 0 inset)
  double tilt = 0;                                // initial rotation of the assembly's rocking mode (rad)
  int voussoirs = 9;                              // arch: number of equal voussoirs
  double thickness_ratio = 0.15;                  // arch: ring thickness / centreline radius
  double radius = 1.0;                            // arch: centreline radius (m)
  double embrace = 180;                           // arch: angle the arch spans (degrees)
  ContactKind contact = ContactKind::Deformable;  // the rigid law: no settlement into the contacts
  ContactLaw ground_law, block_law;
};

Assembly make_preset(const std::string& name, const PresetOptions& o);

// Seed 001's 5-DOF restriction (rigid law only): the blocks standing on the ground only rock (no
// sliding, plastic impacts on the ground); a block leaving the ground is reported, not integrated.
// Throws std::invalid_argument for an assembly with deformable contacts.
void restrict_to_rocking_on_ground(Assembly& a);

// Checks sizes, masses, polygons, friction, indices and the initial configuration (overlapping
// blocks, a block floating above its support, interfaces whose faces do not face each other);
// throws std::invalid_argument naming the field. max_blocks: the dynamics' capacity, or the
// static analysis' larger one.
void validate(const Assembly& a, int max_blocks = kMaxDynamicBlocks);

// A convex polygonal block from its vertices at rest (counter-clockwise, ground frame) and its
// mass (kg) or, with mass <= 0, density (kg/m^3) times thickness (m) times area. Throws
// std::invalid_argument naming `what` for a polygon that is not convex and counter-clockwise.
AssemblyBlock polygon_block(const std::string& what, const std::vector<Vec2>& vertices, double mass, double density,
                            double thickness);

// Damping per point that gives restitution e to a flat drop of mass m on two points of
// stiffness k each, with the force released when it vanishes (max(0, k d + c d')).
double damping_for_restitution(double e, double m, double k);
// The restitution such a drop realises (closed form), the inverse of the above.
double restitution_of_damping(double c, double m, double k);

}  // namespace blockdyn
