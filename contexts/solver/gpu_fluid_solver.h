// GpuFluidSolver: FluidSolver's step (core/solver/fluid_solver.h) in compute
// shaders (shaders/fluid_faces.comp, fluid_cells.comp), pass for pass: the
// boundaries, the rotor, advection, viscosity, the stencil and divergence,
// red-black over-relaxation sweeps (deterministic: no atomics, each colour's
// cells independent), the gradient, and the velocity at the field's points in
// the layout the particle updates read a field grid (vec4 a point, x fastest:
// pointBuffer()). The solid cells come from the CPU (setSolids). It agrees
// with FluidSolver within float rounding (tests/contexts/gpu_fluid_solver_test.cpp).
// Needs its GL context current for every call.
#pragma once

#include <cstdint>
#include <vector>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "core/field/field_placement.h"
#include "core/field/height_map.h"
#include "core/field/vector_field.h"
#include "core/obstacles/obstacle.h"
#include "core/solver/fluid_solver.h"
#include "core/solver/solids_key.h"

namespace sandstorm {

class GpuFluidSolver {
 public:
  GpuFluidSolver(const Box& bounds, glm::ivec3 dims, const VectorField* initial = nullptr);

  void setSolids(const HeightMap* terrain, const std::vector<Obstacle>& obstacles,
                 const FieldPlacement& placement = {});
  void step(float dt, const FluidSettings& settings, const FluidForces& forces = {});

  // The velocity at the field's points, vec4 each (w 1), x fastest.
  std::uint32_t pointBuffer() const { return points_.id(); }
  // These wait for the GPU (tests).
  VectorField readVelocityField() const;
  double maxDivergence() const;

 private:
  void faces(int pass, int axis) const;
  void cells(int pass, int colour = 0) const;
  void swapFaces();

  Box bounds_;
  glm::ivec3 n_;
  glm::vec3 h_;
  double time_ = 0.0;    // simulated seconds stepped (the subgrid eddies' clock, as FluidSolver's)
  SolidsKey solidsKey_;  // what the solids were last made from
  gl::Program facesProgram_, cellsProgram_;
  gl::Buffer block_, face_[3], out_[3], pressure_, divergence_, solid_, stencil_, diagonal_,
      vorticity_, confinement_, points_;
};

}  // namespace sandstorm
