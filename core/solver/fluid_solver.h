// FluidSolver: an incompressible flow on the field's grid, stable fluids
// (Stam 1999) on a staggered (MAC) grid: the field's points are the cells'
// centres, velocities live on the faces between them. One step:
//   1. forces: a momentum source pushing air down through the rotor's disc
//      (FluidForces::rotor*), as its thrust does;
//      vorticity confinement (Fedkiw, Stam & Jensen 2001; settings.vorticity
//      = epsilon): each cell's vorticity w = curl u (central differences of
//      the cells' velocities), N = grad|w| / |grad|w||, a force
//      epsilon h (N x w) on the cell, each face the mean of its two cells';
//      it puts back the small swirls the coarse grid's advection smears out;
//   2. advection: each face's velocity is what the flow brings to it from
//      where it was dt ago (semi-Lagrangian: a straight backtrace with the
//      face's velocity, a trilinear sample), unconditionally stable;
//   3. viscosity (if any): an explicit diffusion, sub-stepped to stay stable;
//   4. boundaries: faces of solid cells (terrain, obstacles: setSolids) take
//      the solid's velocity, the domain's floor is a wall, the sides the wind
//      blows in through take the wind, the other sides and the top are open
//      (pressure 0 outside); with `closed` every side is a wall;
//   5. projection: the pressure that makes the flow divergence-free, by
//      red-black successive over-relaxation (deterministic: each colour's cells
//      are independent), warm-started from the last step's; the face
//      velocities lose its gradient. maxDivergence() says what is left.
// The velocity at the field's points (the average of each cell's faces) is
// the field particles move through (velocityField()), with subgrid eddies
// (settings.turbulence = I, eddySize = L): each point's velocity u gains
// I |u| times eddyPattern() there, fluctuations of about I |u| the particles
// feel, which the flow itself does not (so they cannot feed on themselves):
// the turbulence of a wall jet, too fine for the grid, which lifts the dust. The work is split over
// the machine's threads (ParallelFor) in a way that gives the same result
// whatever their number or timing.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/field/box.h"
#include "core/field/field_placement.h"
#include "core/field/height_map.h"
#include "core/field/vector_field.h"
#include "core/obstacles/obstacle.h"
#include "core/solver/fluid_settings.h"
#include "core/solver/solids_key.h"
#include "core/util/parallel_for.h"

namespace sandstorm {

struct FluidForces {
  // The rotor as an actuator disc: centre, radius, and the pressure jump
  // across it over the air's density (m^2/s^2; momentum theory: thrust /
  // (disc area * density)). The solver spreads it over the cell layer at
  // the disc as a downward acceleration.
  glm::vec3 rotorCentre{0.0f};
  float rotorRadius = 0.0f;
  float rotorPressure = 0.0f;
};

// The subgrid eddies' pattern at x and time t: the curl of three gradient
// noises (CurlNoiseField's, seed kEddySeed) at x / size + t * kEddyDrift, so
// the pattern renews about once a second; its GLSL twin is fluid_cells.comp's.
glm::vec3 eddyPattern(const glm::vec3& x, float size, float time);
inline constexpr std::uint32_t kEddySeed = 11;
inline constexpr glm::vec3 kEddyDrift{0.6f, 0.4f, 0.7f};  // noise cells a second

class FluidSolver {
 public:
  // Cells centred on the points of a grid of `dims` over `bounds` (every
  // axis at least 2 points); velocities start at `initial` (may be null: rest).
  FluidSolver(const Box& bounds, glm::ivec3 dims, const VectorField* initial = nullptr,
              unsigned threads = 0);
  ~FluidSolver();

  // Cells whose centre lies under the terrain or inside an obstacle are solid
  // (their faces move with the obstacle). Call when either moves.
  // `placement` carries the solver's (the field's) coordinates into the room,
  // where the terrain and the obstacles are.
  void setSolids(const HeightMap* terrain, const std::vector<Obstacle>& obstacles,
                 const FieldPlacement& placement = {});

  void step(float dt, const FluidSettings& settings, const FluidForces& forces = {});

  // The velocity at the cells' centres (the field's points); a solid cell
  // under a fluid one has that one's horizontal velocity (the free-slip
  // ground's, so dust on the terrain feels the flow over it), others 0.
  VectorField velocityField() const;
  // After the last projection: the largest |div u| over fluid cells (1/s).
  double maxDivergence() const;
  // Sum over fluid cells of |u|^2 / 2 times the cell's volume (m^5/s^2, density 1).
  double kineticEnergy() const;

  glm::ivec3 cells() const { return n_; }
  glm::vec3 spacing() const { return h_; }
  bool solid(int i, int j, int k) const { return solid_[cell(i, j, k)] != 0; }
  // Face velocities: u at the x-face left of cell (i, j, k) (i = 0..nx), v, w alike.
  float u(int i, int j, int k) const { return u_[uIndex(i, j, k)]; }
  float v(int i, int j, int k) const { return v_[vIndex(i, j, k)]; }
  float w(int i, int j, int k) const { return w_[wIndex(i, j, k)]; }
  // The flow's velocity at a point (each component sampled on its own faces).
  glm::vec3 velocityAt(const glm::vec3& p) const;

  // Simulated seconds stepped since the start (the subgrid eddies' clock).
  double time() const { return time_; }

 private:
  SolidsKey solidsKey_;  // what the solids were last made from
  double time_ = 0.0;
  float eddyIntensity_ = 0.0f, eddySize_ = 1.0f;  // the last step's subgrid eddies
  enum class Side : std::uint8_t { Wall, Open, Inflow };

  std::size_t cell(int i, int j, int k) const {
    return std::size_t(i) +
           std::size_t(n_.x) * (std::size_t(j) + std::size_t(n_.y) * std::size_t(k));
  }
  std::size_t uIndex(int i, int j, int k) const {
    return std::size_t(i) +
           std::size_t(n_.x + 1) * (std::size_t(j) + std::size_t(n_.y) * std::size_t(k));
  }
  std::size_t vIndex(int i, int j, int k) const {
    return std::size_t(i) +
           std::size_t(n_.x) * (std::size_t(j) + std::size_t(n_.y + 1) * std::size_t(k));
  }
  std::size_t wIndex(int i, int j, int k) const {
    return std::size_t(i) +
           std::size_t(n_.x) * (std::size_t(j) + std::size_t(n_.y) * std::size_t(k));
  }
  float sampleFaces(const std::vector<float>& faces, int axis, const glm::vec3& p) const;
  void applyForces(float dt, const FluidForces& forces);
  // Vorticity confinement, per cell, then onto the faces.
  void confineVorticity(float dt, float epsilon);
  // The velocity at cell c's centre (the mean of its faces), 0 in a solid cell.
  glm::vec3 cellVelocity(glm::ivec3 c) const;
  void advect(float dt);
  void diffuse(float dt, float viscosity);
  void setBoundaries(const FluidSettings& settings);
  void project(const FluidSettings& settings);
  // Whether the face on `axis` at the low side of cell (i, j, k) is fixed
  // (a wall, an inflow, or next to a solid cell), and if so its velocity.
  bool fixedFace(int axis, int i, int j, int k, float* velocity) const;
  // Fixes the faces (fixed_, their values) and each cell's pressure stencil.
  void classify();
  std::vector<float>& faces(int axis) { return axis == 0 ? u_ : axis == 1 ? v_ : w_; }
  const std::vector<float>& faces(int axis) const { return axis == 0 ? u_ : axis == 1 ? v_ : w_; }
  std::size_t faceIndex(int axis, int i, int j, int k) const {
    return axis == 0 ? uIndex(i, j, k) : axis == 1 ? vIndex(i, j, k) : wIndex(i, j, k);
  }
  // body(k0, k1) over the z-slabs [0, slabs), split over the threads.
  void slabs(int count, const std::function<void(int, int)>& body) const;

  Box bounds_;
  glm::ivec3 n_;
  glm::vec3 h_;
  std::vector<float> u_, v_, w_, scratch_;
  std::vector<float> p_, divergence_;
  std::vector<glm::vec4> vorticity_, confinement_;  // per cell: curl u and |curl u|; the force
  std::vector<std::uint8_t> solid_;
  std::vector<std::uint8_t> fixed_[3];  // per face: its velocity is given
  std::vector<std::uint8_t>
      neighbours_;           // per cell: bit 2a+s, the face is free and a fluid cell is beyond
  std::vector<float> diag_;  // per cell: the pressure stencil's centre
  std::unique_ptr<ParallelFor> pool_;
  std::vector<glm::vec3> solidVelocity_;
  Side sides_[3][2];  // per axis, low and high side
  glm::vec3 wind_{0.0f};
  double maxDivergence_ = 0.0;
};

}  // namespace sandstorm
