#include "contexts/solver/gpu_fluid_solver.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

#include "contexts/particles/record_readback.h"
#include "core/obstacles/obstacle_physics.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

struct alignas(16) FluidBlock {
  glm::ivec4 dims;
  glm::vec4 spacing, inverse, inverse2, minimum;
  glm::ivec4 lowSide, highSide;
  glm::vec4 wind, rotor, rotorMore, viscosity;
  glm::vec4 eddies;  // the subgrid eddies: x intensity, y size, z the solver's time
};

enum FacePass { kFix = 0, kRotor, kAdvect, kDiffuse, kGradient, kConfine };
enum CellPass { kStencil = 0, kDivergence, kRelax, kPoints, kVorticity, kConfinement };
constexpr GLuint kGroup = 256;

gl::Buffer storage(std::size_t bytes, const void* data = nullptr) {
  gl::Buffer b = gl::createBuffer();
  // Whole vec4s, so the float buffers read back as records (readRecords).
  const std::size_t rounded = std::max<std::size_t>((bytes + 15) / 16 * 16, 16);
  glNamedBufferStorage(b.id(), GLsizeiptr(rounded), nullptr, GL_DYNAMIC_STORAGE_BIT);
  if (data) glNamedBufferSubData(b.id(), 0, GLsizeiptr(bytes), data);
  return b;
}

std::vector<float> readFloats(std::uint32_t buffer, std::size_t count) {
  const std::vector<glm::vec4> words = readRecords(buffer, (count + 3) / 4);
  std::vector<float> out(count);
  for (std::size_t i = 0; i < count; ++i)
    out[i] = words[i / 4][int(i % 4)];
  return out;
}

}  // namespace

GpuFluidSolver::GpuFluidSolver(const Box& bounds, glm::ivec3 dims, const VectorField* initial)
    : bounds_(bounds),
      n_(dims),
      facesProgram_(std::vector<std::string>{"fluid_faces.comp"}),
      cellsProgram_(std::vector<std::string>{"fluid_cells.comp"}) {
  // The CPU solver checks the grid and makes the starting faces the same way.
  const FluidSolver start(bounds, dims, initial, 1);
  h_ = start.spacing();
  const std::size_t cells = std::size_t(n_.x) * std::size_t(n_.y) * std::size_t(n_.z);
  for (int axis = 0; axis < 3; ++axis) {
    glm::ivec3 d = n_;
    d[axis] += 1;
    std::vector<float> values(std::size_t(d.x) * std::size_t(d.y) * std::size_t(d.z));
    for (int k = 0; k < d.z; ++k)
      for (int j = 0; j < d.y; ++j)
        for (int i = 0; i < d.x; ++i)
          values[std::size_t(i) +
                 std::size_t(d.x) * (std::size_t(j) + std::size_t(d.y) * std::size_t(k))] =
              axis == 0   ? start.u(i, j, k)
              : axis == 1 ? start.v(i, j, k)
                          : start.w(i, j, k);
    face_[axis] = storage(values.size() * 4, values.data());
    out_[axis] = storage(values.size() * 4);
  }
  const std::vector<float> zeros(cells, 0.0f);
  pressure_ = storage(cells * 4, zeros.data());
  divergence_ = storage(cells * 4, zeros.data());
  const std::vector<glm::vec4> open(cells, glm::vec4(0.0f));
  solid_ = storage(cells * 16, open.data());
  stencil_ = storage(cells * 4);
  diagonal_ = storage(cells * 4);
  points_ = storage(cells * 16);
  vorticity_ = storage(cells * 16);
  confinement_ = storage(cells * 16);
  block_ = storage(sizeof(FluidBlock));
}

void GpuFluidSolver::setSolids(const HeightMap* terrain, const std::vector<Obstacle>& obstacles,
                               const FieldPlacement& placement) {
  // The same solids as last time (the usual case: nothing moved): nothing to do.
  if (!solidsKey_.changed(terrain, obstacles, placement)) return;
  // Cell by cell as FluidSolver::setSolids decides (w 1: solid).
  std::vector<glm::vec4> solid(std::size_t(n_.x) * std::size_t(n_.y) * std::size_t(n_.z),
                               glm::vec4(0.0f));
  for (int k = 0; k < n_.z; ++k)
    for (int j = 0; j < n_.y; ++j)
      for (int i = 0; i < n_.x; ++i) {
        const glm::vec3 c = placement.toRoom(bounds_.min + glm::vec3(i, j, k) * h_);
        glm::vec4& s =
            solid[std::size_t(i) +
                  std::size_t(n_.x) * (std::size_t(j) + std::size_t(n_.y) * std::size_t(k))];
        if (terrain && c.z < terrain->heightAt(glm::vec2(c))) {
          s = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
          continue;
        }
        for (const Obstacle& o : obstacles)
          if (o.enabled && obstacleSurface(o, c).distance < 0.0f) {
            s = glm::vec4(placement.vectorToLocal(o.velocity), 1.0f);
            break;
          }
      }
  glNamedBufferSubData(solid_.id(), 0, GLsizeiptr(solid.size() * sizeof(glm::vec4)), solid.data());
}

void GpuFluidSolver::faces(int pass, int axis) const {
  glm::ivec3 d = n_;
  d[axis] += 1;
  const GLuint count = GLuint(d.x * d.y * d.z);
  facesProgram_.use();
  glProgramUniform1i(facesProgram_.id(), 0, axis);
  glProgramUniform1i(facesProgram_.id(), 1, pass);
  glDispatchCompute((count + kGroup - 1) / kGroup, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuFluidSolver::cells(int pass, int colour) const {
  const GLuint count = GLuint(n_.x * n_.y * n_.z);
  cellsProgram_.use();
  glProgramUniform1i(cellsProgram_.id(), 1, pass);
  glProgramUniform1i(cellsProgram_.id(), 2, colour);
  glDispatchCompute((count + kGroup - 1) / kGroup, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuFluidSolver::swapFaces() {
  for (int axis = 0; axis < 3; ++axis) {
    std::swap(face_[axis], out_[axis]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(axis), face_[axis].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(3 + axis), out_[axis].id());
  }
}

void GpuFluidSolver::step(float dt, const FluidSettings& s, const FluidForces& forces) {
  if (!(dt > 0.0f)) return;
  FluidBlock b{};
  b.dims = glm::ivec4(n_, 0);
  b.spacing = glm::vec4(h_, dt);
  b.inverse = glm::vec4(1.0f / h_, 0.0f);
  b.inverse2 = glm::vec4(1.0f / (h_ * h_), 0.0f);
  b.minimum = glm::vec4(bounds_.min, std::clamp(s.relaxation, 1.0f, 1.95f));
  for (int axis = 0; axis < 3; ++axis) {
    b.lowSide[axis] = s.wind[axis] > 0.0f ? 2 : 0;
    b.highSide[axis] = s.wind[axis] < 0.0f ? 2 : 0;
  }
  b.lowSide.z = 1;  // the floor
  if (s.closed) b.lowSide = b.highSide = glm::ivec4(1);
  b.wind = glm::vec4(s.wind, 0.0f);
  b.rotor = glm::vec4(forces.rotorCentre, forces.rotorRadius);
  const bool rotor = forces.rotorRadius > 0.0f && forces.rotorPressure != 0.0f;
  const float half = 0.5f * std::max(h_.z, 0.5f);  // as FluidSolver::applyForces
  b.rotorMore = glm::vec4(forces.rotorPressure / (2.0f * half), half, 0.0f, 0.0f);
  // Viscosity's substeps as FluidSolver::diffuse counts them.
  int substeps = 0;
  if (s.viscosity > 0.0f) {
    const glm::vec3 inv2 = 1.0f / (h_ * h_);
    const float limit = 1.0f / (6.0f * std::max({inv2.x, inv2.y, inv2.z}));
    substeps = std::max(1, int(std::ceil(s.viscosity * dt / limit)));
    b.viscosity.x = s.viscosity * dt / float(substeps);
  }
  const bool confine = s.vorticity > 0.0f;
  b.viscosity.y = s.vorticity * std::min({h_.x, h_.y, h_.z});
  // The subgrid eddies of the points pass, at the time after this step (as FluidSolver's).
  b.eddies = glm::vec4(s.turbulence, std::max(s.eddySize, 1e-3f), float(time_ + dt), 0.0f);
  glNamedBufferSubData(block_.id(), 0, sizeof(b), &b);
  glBindBufferBase(GL_UNIFORM_BUFFER, 6, block_.id());
  for (int axis = 0; axis < 3; ++axis) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(axis), face_[axis].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(3 + axis), out_[axis].id());
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, pressure_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, divergence_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, solid_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, stencil_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 10, diagonal_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 11, points_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 12, vorticity_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 13, confinement_.id());

  // FluidSolver::step, pass for pass.
  for (int axis = 0; axis < 3; ++axis)
    faces(kFix, axis);
  if (rotor) faces(kRotor, 2);
  if (confine) {
    cells(kVorticity);
    cells(kConfinement);
    for (int axis = 0; axis < 3; ++axis)
      faces(kConfine, axis);
  }
  for (int axis = 0; axis < 3; ++axis)
    faces(kAdvect, axis);
  swapFaces();
  for (int k = 0; k < substeps; ++k) {
    for (int axis = 0; axis < 3; ++axis)
      faces(kDiffuse, axis);
    swapFaces();
  }
  for (int axis = 0; axis < 3; ++axis)
    faces(kFix, axis);
  cells(kStencil);
  cells(kDivergence);
  for (int it = 0; it < std::max(s.iterations, 0); ++it) {
    cells(kRelax, 0);
    cells(kRelax, 1);
  }
  for (int axis = 0; axis < 3; ++axis)
    faces(kGradient, axis);
  cells(kDivergence);
  cells(kPoints);
  time_ += dt;
}

VectorField GpuFluidSolver::readVelocityField() const {
  const std::vector<glm::vec4> points =
      readRecords(points_.id(), std::size_t(n_.x) * std::size_t(n_.y) * std::size_t(n_.z));
  VectorField out(bounds_, n_);
  for (std::size_t i = 0; i < points.size(); ++i)
    out.values()[i] = glm::vec3(points[i]);
  return out;
}

double GpuFluidSolver::maxDivergence() const {
  double most = 0.0;
  for (float d :
       readFloats(divergence_.id(), std::size_t(n_.x) * std::size_t(n_.y) * std::size_t(n_.z)))
    most = std::max(most, double(std::abs(d)));
  return most;
}

}  // namespace sandstorm
