// The molecules' rules (the molecules paper: particles moved by the flow,
// then springs restoring the shape), shared operation for operation with
// shaders/molecule_physics.glsl; MoleculeReference calls these, the GPU runs
// the twins, and the GPU/CPU agreement tests compare them.
//
// One step of a molecule of n members (records m[0..n-1]; all share the
// molecule's life and lifetime):
//   1. it ages; at the end of its life it dies whole;
//   2. each member moves through the field with the simulation's motion model
//      and integrator (integrate()), with the push tool's wind; its step is
//      then scaled by its vane factor (below);
//   3. the molecule is displaced by its repulsion from its neighbours (if on);
//   4. `iterations` passes over the springs move each pair of members along
//      their spring towards its rest length, by their inverse masses
//      (position-based: unconditionally stable), a share k of the stretch
//      a pass such that the passes together remove `stiffness` of it;
//   5. under the force and drag models the members' velocities take up what
//      steps 3-4 moved them (PBD's velocity update), then `damping` of each
//      member's velocity relative to the molecule's (mass-weighted) is
//      removed: stretching and spin die away, the molecule's momentum stays;
//      a tracer's velocity is the flow's;
//   6. bounds: a member leaving the field kills the molecule (kill), is held
//      at the bounds (clamp), or, when the head leaves, the whole molecule
//      moves with the head's wrap (wrap); cells without data as for particles;
//      then the ground and the obstacles put each member out, as a particle.
// Why it points along the flow: a free body carried by uniform air has no
// direction of its own to take (in the air's frame nothing is special), so a
// molecule is built like a wind vane: each step member j goes
// s_j = 1 + vane (d_j - d) of the way its motion takes it, d_j its rest
// distance from the head (member 0) in edges and d their mass-weighted mean,
// so each member runs ahead of the head by `vane` times the step per edge
// between them (a long chain turns as fast as a rod) while the molecule as a
// whole (the mass-weighted mean) moves exactly as a particle would; the
// springs turn it until its tail trails along its path: downstream, for a
// tracer or settled dust. The scaled steps do not enter the velocities.
// With vane = 0 molecules only stretch and turn with the flow's strain, as
// in the paper.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "core/molecules/molecule_settings.h"
#include "core/molecules/molecule_shape.h"
#include "core/sim/counter_rng.h"
#include "core/sim/emitter.h"
#include "core/sim/particle.h"
#include "core/sim/particle_physics.h"

namespace sandstorm {

// The numbers a step uses, derived once from the settings (on the CPU, so
// the GPU's block holds the very same floats).
struct MoleculeParams {
  int members = 0;
  int iterations = 1;
  float headMass = 1.0f;
  float invHeadMass = 1.0f;
  float invTotalMass = 1.0f;
  float invMembers = 1.0f, invTailMembers = 1.0f;                   // 1 / n, 1 / (n - 1)
  std::array<float, MoleculeSettings::kMaxComplexity> vaneReach{};  // vane * d_j, per member
  bool solid = false;          // a shape with faces: the vane turns it about its axis
  float passStiffness = 0.0f;  // k: 1 - (1 - stiffness)^(1 / iterations)
  float damping = 0.0f;
  float invDt = 0.0f;
  std::array<float, MoleculeShape::kMaxSprings> springLength{};  // m
  // k / (w_a + w_b): the share of a spring's stretch a pass moves, over its ends' inverse masses.
  std::array<float, MoleculeShape::kMaxSprings> springFactor{};
  Forcing push;  // push, pushCentre, pushRadius, pushSpeed (fieldScale unused)
  bool repulsion = false;
  float repulsionRadius = 0.0f;
  float repulsionShare = 0.0f;  // each of a close pair moves this share of the overlap
};

MoleculeParams moleculeParams(const MoleculeSettings& settings, float dt);

// Molecule number `index` of emitter `emitterIndex` born in frame `frame`:
// its centre, velocity and life as birth() gives a particle's, turned by a
// random rotation (a uniform unit quaternion: the first of 32 candidates in
// the 4-ball, normalised), its members `size` apart.
void birthMolecule(const Emitter& emitter, Seed seed, std::uint32_t frame,
                   std::uint32_t emitterIndex, std::uint32_t index, const MoleculeShape& shape,
                   float size, std::span<Particle> members);

// A newborn molecule's members put out of the terrain (when particles
// collide with it) and the obstacles, so none is born below the ground.
void settleNewbornMolecule(std::span<Particle> members, const PhysicsInputs& in);

// The mean of the members' positions (the repulsion's centre).
glm::vec3 moleculeCentre(std::span<const Particle> members);

// One step (above). `repulsion`: the molecule's displacement from its
// neighbours this step (MoleculeGrid). Returns false when it dies.
bool advanceMolecule(std::span<Particle> members, const PhysicsInputs& in,
                     const MoleculeParams& params, const glm::vec3& repulsion);

}  // namespace sandstorm
