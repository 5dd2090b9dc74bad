#include "core/solver/fluid_solver.h"

#include <algorithm>
#include <cmath>

#include "core/field/gradient_noise.h"
#include "core/obstacles/obstacle_physics.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

glm::ivec3 unit(int axis) {
  glm::ivec3 e(0);
  e[axis] = 1;
  return e;
}

}  // namespace

FluidSolver::FluidSolver(const Box& bounds, glm::ivec3 dims, const VectorField* initial,
                         unsigned threads)
    : bounds_(bounds), n_(dims), pool_(std::make_unique<ParallelFor>(threads)) {
  if (glm::any(glm::lessThan(dims, glm::ivec3(2))))
    throw Error(concat("FluidSolver: a ", dims.x, "x", dims.y, "x", dims.z,
                       " grid; expected at least 2 points along every axis"));
  if (std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z) > (std::size_t{1} << 26))
    throw Error(concat("FluidSolver: ", dims.x, "x", dims.y, "x", dims.z,
                       " cells are more than 2^26; resample the field coarser"));
  h_ = (bounds.max - bounds.min) / glm::vec3(dims - 1);
  if (!glm::all(glm::greaterThan(h_, glm::vec3(0.0f))))
    throw Error("FluidSolver: the field's bounds are empty along an axis");
  const std::size_t cells = std::size_t(n_.x) * std::size_t(n_.y) * std::size_t(n_.z);
  u_.assign(std::size_t(n_.x + 1) * std::size_t(n_.y) * std::size_t(n_.z), 0.0f);
  v_.assign(std::size_t(n_.x) * std::size_t(n_.y + 1) * std::size_t(n_.z), 0.0f);
  w_.assign(std::size_t(n_.x) * std::size_t(n_.y) * std::size_t(n_.z + 1), 0.0f);
  p_.assign(cells, 0.0f);
  divergence_.assign(cells, 0.0f);
  solid_.assign(cells, 0);
  solidVelocity_.assign(cells, glm::vec3(0.0f));
  neighbours_.assign(cells, 0);
  diag_.assign(cells, 0.0f);
  for (int axis = 0; axis < 3; ++axis)
    fixed_[axis].assign(faces(axis).size(), 0);
  for (auto& axis : sides_)
    axis[0] = axis[1] = Side::Open;
  sides_[2][0] = Side::Wall;
  if (initial && initial->dims() == dims) {
    // Each face the mean of the two points beside it (the one at the domain's edge).
    const auto at = [&](glm::ivec3 c) { return initial->at(c.x, c.y, c.z); };
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<float>& faces = axis == 0 ? u_ : axis == 1 ? v_ : w_;
      const glm::ivec3 d = n_ + unit(axis);
      for (int k = 0; k < d.z; ++k)
        for (int j = 0; j < d.y; ++j)
          for (int i = 0; i < d.x; ++i) {
            const glm::ivec3 f(i, j, k);
            const glm::ivec3 lo = glm::max(f - unit(axis), glm::ivec3(0));
            const glm::ivec3 hi = glm::min(f, n_ - 1);
            faces[std::size_t(i) +
                  std::size_t(d.x) * (std::size_t(j) + std::size_t(d.y) * std::size_t(k))] =
                0.5f * (at(lo)[axis] + at(hi)[axis]);
          }
    }
  }
}

FluidSolver::~FluidSolver() = default;

void FluidSolver::slabs(int count, const std::function<void(int, int)>& body) const {
  pool_->run(std::size_t(count),
             [&](std::size_t begin, std::size_t end) { body(int(begin), int(end)); });
}

void FluidSolver::setSolids(const HeightMap* terrain, const std::vector<Obstacle>& obstacles,
                            const FieldPlacement& placement) {
  // The same solids as last time (the usual case: nothing moved): nothing to do.
  if (!solidsKey_.changed(terrain, obstacles, placement)) return;
  for (int k = 0; k < n_.z; ++k)
    for (int j = 0; j < n_.y; ++j)
      for (int i = 0; i < n_.x; ++i) {
        const glm::vec3 c = placement.toRoom(bounds_.min + glm::vec3(i, j, k) * h_);
        const std::size_t at = cell(i, j, k);
        solid_[at] = 0;
        solidVelocity_[at] = glm::vec3(0.0f);
        if (terrain && c.z < terrain->heightAt(glm::vec2(c))) {
          solid_[at] = 1;
          continue;
        }
        for (const Obstacle& o : obstacles) {
          if (o.enabled && obstacleSurface(o, c).distance < 0.0f) {
            solid_[at] = 1;
            solidVelocity_[at] = placement.vectorToLocal(o.velocity);
            break;
          }
        }
      }
}

float FluidSolver::sampleFaces(const std::vector<float>& faces, int axis,
                               const glm::vec3& p) const {
  const glm::ivec3 d = n_ + unit(axis);
  glm::vec3 q = (p - bounds_.min) / h_;
  q[axis] += 0.5f;
  q = glm::clamp(q, glm::vec3(0.0f), glm::vec3(d - 1));
  const glm::ivec3 i0 = glm::min(glm::ivec3(glm::floor(q)), d - 2);
  const glm::vec3 f = q - glm::vec3(i0);
  const auto at = [&](int i, int j, int k) {
    return faces[std::size_t(i) +
                 std::size_t(d.x) * (std::size_t(j) + std::size_t(d.y) * std::size_t(k))];
  };
  const float c00 = at(i0.x, i0.y, i0.z) + (at(i0.x + 1, i0.y, i0.z) - at(i0.x, i0.y, i0.z)) * f.x;
  const float c10 =
      at(i0.x, i0.y + 1, i0.z) + (at(i0.x + 1, i0.y + 1, i0.z) - at(i0.x, i0.y + 1, i0.z)) * f.x;
  const float c01 =
      at(i0.x, i0.y, i0.z + 1) + (at(i0.x + 1, i0.y, i0.z + 1) - at(i0.x, i0.y, i0.z + 1)) * f.x;
  const float c11 = at(i0.x, i0.y + 1, i0.z + 1) +
                    (at(i0.x + 1, i0.y + 1, i0.z + 1) - at(i0.x, i0.y + 1, i0.z + 1)) * f.x;
  const float c0 = c00 + (c10 - c00) * f.y, c1 = c01 + (c11 - c01) * f.y;
  return c0 + (c1 - c0) * f.z;
}

glm::vec3 FluidSolver::velocityAt(const glm::vec3& p) const {
  return {sampleFaces(u_, 0, p), sampleFaces(v_, 1, p), sampleFaces(w_, 2, p)};
}

bool FluidSolver::fixedFace(int axis, int i, int j, int k, float* velocity) const {
  const glm::ivec3 f(i, j, k);
  const int along = f[axis];
  Side side = Side::Open;
  if (along == 0 || along == n_[axis]) {
    side = sides_[axis][along == 0 ? 0 : 1];
    if (side == Side::Open) return false;
    *velocity = side == Side::Inflow ? wind_[axis] : 0.0f;
    return true;
  }
  const glm::ivec3 lo = f - unit(axis);
  const std::size_t a = cell(lo.x, lo.y, lo.z), b = cell(i, j, k);
  if (!solid_[a] && !solid_[b]) return false;
  const glm::vec3 moving = solid_[a] ? solidVelocity_[a] : solidVelocity_[b];
  *velocity = moving[axis];
  return true;
}

void FluidSolver::applyForces(float dt, const FluidForces& forces) {
  if (!(forces.rotorRadius > 0.0f) || forces.rotorPressure == 0.0f) return;
  const float half = 0.5f * std::max(h_.z, 0.5f);
  // The jump spread over the layer's thickness.
  const float acceleration = forces.rotorPressure / (2.0f * half);
  for (int k = 0; k <= n_.z; ++k)
    for (int j = 0; j < n_.y; ++j)
      for (int i = 0; i < n_.x; ++i) {
        const glm::vec3 x = bounds_.min + glm::vec3(float(i), float(j), float(k) - 0.5f) * h_;
        const glm::vec2 r = glm::vec2(x) - glm::vec2(forces.rotorCentre);
        if (glm::dot(r, r) <= forces.rotorRadius * forces.rotorRadius &&
            std::abs(x.z - forces.rotorCentre.z) <= half)
          w_[wIndex(i, j, k)] -= acceleration * dt;
      }
}

glm::vec3 FluidSolver::cellVelocity(glm::ivec3 c) const {
  if (solid_[cell(c.x, c.y, c.z)]) return glm::vec3(0.0f);
  return 0.5f * glm::vec3(u_[uIndex(c.x, c.y, c.z)] + u_[uIndex(c.x + 1, c.y, c.z)],
                          v_[vIndex(c.x, c.y, c.z)] + v_[vIndex(c.x, c.y + 1, c.z)],
                          w_[wIndex(c.x, c.y, c.z)] + w_[wIndex(c.x, c.y, c.z + 1)]);
}

glm::vec3 eddyPattern(const glm::vec3& x, float size, float time) {
  static const GradientNoise n1(kEddySeed * 3u), n2(kEddySeed * 3u + 1u), n3(kEddySeed * 3u + 2u);
  const glm::vec3 q = x / size + time * kEddyDrift;
  const glm::vec3 g1(n1.valueAndGradient(q)), g2(n2.valueAndGradient(q)),
      g3(n3.valueAndGradient(q));
  return glm::vec3(g3.y - g2.z, g1.z - g3.x, g2.x - g1.y);
}

void FluidSolver::confineVorticity(float dt, float epsilon) {
  if (!(epsilon > 0.0f)) return;
  const std::size_t cells = std::size_t(n_.x) * std::size_t(n_.y) * std::size_t(n_.z);
  vorticity_.resize(cells);
  confinement_.resize(cells);
  // Central differences between the neighbours along `axis` (one-sided at the domain's edges).
  const auto across = [&](glm::ivec3 c, int axis, auto&& value) {
    glm::ivec3 lo = c, hi = c;
    lo[axis] = std::max(c[axis] - 1, 0);
    hi[axis] = std::min(c[axis] + 1, n_[axis] - 1);
    return (value(hi) - value(lo)) / (float(hi[axis] - lo[axis]) * h_[axis]);
  };
  slabs(n_.z, [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < n_.y; ++j)
        for (int i = 0; i < n_.x; ++i) {
          const glm::ivec3 c(i, j, k);
          const auto velocity = [&](glm::ivec3 at) { return cellVelocity(at); };
          const glm::vec3 dx = across(c, 0, velocity), dy = across(c, 1, velocity),
                          dz = across(c, 2, velocity);
          const glm::vec3 w(dy.z - dz.y, dz.x - dx.z, dx.y - dy.x);
          vorticity_[cell(i, j, k)] = glm::vec4(w, glm::length(w));
        }
  });
  const float h = std::min({h_.x, h_.y, h_.z});
  slabs(n_.z, [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < n_.y; ++j)
        for (int i = 0; i < n_.x; ++i) {
          const glm::ivec3 c(i, j, k);
          const std::size_t at = cell(i, j, k);
          confinement_[at] = glm::vec4(0.0f);
          if (solid_[at]) continue;
          const auto magnitude = [&](glm::ivec3 q) { return vorticity_[cell(q.x, q.y, q.z)].w; };
          const glm::vec3 eta(across(c, 0, magnitude), across(c, 1, magnitude),
                              across(c, 2, magnitude));
          const float length = glm::length(eta);
          if (!(length > 1e-20f)) continue;
          confinement_[at] =
              glm::vec4(epsilon * h * glm::cross(eta / length, glm::vec3(vorticity_[at])), 0.0f);
        }
  });
  // Each free face between two cells gains dt times the mean of their forces.
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<float>& f = faces(axis);
    const glm::ivec3 d = n_ + unit(axis);
    slabs(d.z, [&](int k0, int k1) {
      for (int k = k0; k < k1; ++k)
        for (int j = 0; j < d.y; ++j)
          for (int i = 0; i < d.x; ++i) {
            const glm::ivec3 face(i, j, k), lo = face - unit(axis);
            if (face[axis] == 0 || face[axis] == n_[axis]) continue;
            const std::size_t at = faceIndex(axis, i, j, k);
            if (fixed_[axis][at]) continue;
            f[at] += dt * 0.5f *
                     (confinement_[cell(lo.x, lo.y, lo.z)][axis] +
                      confinement_[cell(face.x, face.y, face.z)][axis]);
          }
    });
  }
}

void FluidSolver::advect(float dt) {
  std::vector<float> next[3] = {u_, v_, w_};
  for (int axis = 0; axis < 3; ++axis) {
    const glm::ivec3 d = n_ + unit(axis);
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    slabs(d.z, [&](int k0, int k1) {
      for (int k = k0; k < k1; ++k)
        for (int j = 0; j < d.y; ++j)
          for (int i = 0; i < d.x; ++i) {
            const glm::ivec3 f(i, j, k);
            // The face's velocity: its own component, and the other two the
            // mean of the four faces around it (cells clamped at the edges).
            glm::vec3 velocity;
            velocity[axis] = faces(axis)[faceIndex(axis, i, j, k)];
            for (const int other : {a1, a2}) {
              float sum = 0.0f;
              for (int lo = 0; lo < 2; ++lo)
                for (int hi = 0; hi < 2; ++hi) {
                  glm::ivec3 c = f;
                  c[axis] = std::clamp(f[axis] - 1 + lo, 0, n_[axis] - 1);
                  c[other] = f[other] + hi;
                  sum += faces(other)[faceIndex(other, c.x, c.y, c.z)];
                }
              velocity[other] = 0.25f * sum;
            }
            glm::vec3 x = bounds_.min + glm::vec3(f) * h_;
            x[axis] -= 0.5f * h_[axis];
            next[axis][faceIndex(axis, i, j, k)] =
                sampleFaces(faces(axis), axis, x - dt * velocity);
          }
    });
  }
  u_.swap(next[0]);
  v_.swap(next[1]);
  w_.swap(next[2]);
}

void FluidSolver::diffuse(float dt, float viscosity) {
  if (!(viscosity > 0.0f)) return;
  const glm::vec3 inv2 = 1.0f / (h_ * h_);
  const float limit = 1.0f / (6.0f * std::max({inv2.x, inv2.y, inv2.z}));  // stable step
  const int steps = std::max(1, int(std::ceil(viscosity * dt / limit)));
  const float nudt = viscosity * dt / float(steps);
  for (int s = 0; s < steps; ++s)
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<float>& faces = axis == 0 ? u_ : axis == 1 ? v_ : w_;
      const std::vector<float> from = faces;
      const glm::ivec3 d = n_ + unit(axis);
      const auto at = [&](glm::ivec3 c) {
        c = glm::clamp(c, glm::ivec3(0), d - 1);
        return from[std::size_t(c.x) +
                    std::size_t(d.x) * (std::size_t(c.y) + std::size_t(d.y) * std::size_t(c.z))];
      };
      for (int k = 0; k < d.z; ++k)
        for (int j = 0; j < d.y; ++j)
          for (int i = 0; i < d.x; ++i) {
            const glm::ivec3 c(i, j, k);
            const float here = at(c);
            float lap = 0.0f;
            for (int a = 0; a < 3; ++a)
              lap += (at(c + unit(a)) - 2.0f * here + at(c - unit(a))) * inv2[a];
            faces[std::size_t(i) +
                  std::size_t(d.x) * (std::size_t(j) + std::size_t(d.y) * std::size_t(k))] =
                here + nudt * lap;
          }
    }
}

void FluidSolver::setBoundaries(const FluidSettings& settings) {
  wind_ = settings.wind;
  for (int axis = 0; axis < 3; ++axis) {
    sides_[axis][0] = settings.wind[axis] > 0.0f ? Side::Inflow : Side::Open;
    sides_[axis][1] = settings.wind[axis] < 0.0f ? Side::Inflow : Side::Open;
  }
  sides_[2][0] = Side::Wall;  // the floor
  if (settings.closed)
    for (auto& axis : sides_)
      axis[0] = axis[1] = Side::Wall;
  classify();
}

void FluidSolver::classify() {
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<float>& f = faces(axis);
    const glm::ivec3 d = n_ + unit(axis);
    slabs(d.z, [&](int k0, int k1) {
      for (int k = k0; k < k1; ++k)
        for (int j = 0; j < d.y; ++j)
          for (int i = 0; i < d.x; ++i) {
            float velocity = 0.0f;
            const std::size_t at = faceIndex(axis, i, j, k);
            fixed_[axis][at] = fixedFace(axis, i, j, k, &velocity) ? 1 : 0;
            if (fixed_[axis][at]) f[at] = velocity;
          }
    });
  }
  const glm::vec3 inv2 = 1.0f / (h_ * h_);
  slabs(n_.z, [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < n_.y; ++j)
        for (int i = 0; i < n_.x; ++i) {
          const std::size_t c = cell(i, j, k);
          std::uint8_t bits = 0;
          float diag = 0.0f;
          const glm::ivec3 here(i, j, k);
          for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) {
              const glm::ivec3 face = here + (side ? unit(axis) : glm::ivec3(0));
              if (fixed_[axis][faceIndex(axis, face.x, face.y, face.z)]) continue;
              diag += inv2[axis];  // a free face: to a fluid cell, or open (pressure 0 beyond)
              const int beyond = here[axis] + (side ? 1 : -1);
              if (beyond >= 0 && beyond < n_[axis]) bits |= std::uint8_t(1u << (2 * axis + side));
            }
          neighbours_[c] = solid_[c] ? 0 : bits;
          diag_[c] = solid_[c] ? 0.0f : diag;
        }
  });
}

void FluidSolver::project(const FluidSettings& settings) {
  const glm::vec3 inv = 1.0f / h_, inv2 = inv * inv;
  const std::ptrdiff_t stride[3] = {1, n_.x, std::ptrdiff_t(n_.x) * n_.y};
  const auto computeDivergence = [&] {
    std::vector<double> most(std::size_t(n_.z), 0.0);
    slabs(n_.z, [&](int k0, int k1) {
      for (int k = k0; k < k1; ++k)
        for (int j = 0; j < n_.y; ++j)
          for (int i = 0; i < n_.x; ++i) {
            const std::size_t c = cell(i, j, k);
            if (solid_[c]) {
              divergence_[c] = 0.0f;
              continue;
            }
            const float div = (u_[uIndex(i + 1, j, k)] - u_[uIndex(i, j, k)]) * inv.x +
                              (v_[vIndex(i, j + 1, k)] - v_[vIndex(i, j, k)]) * inv.y +
                              (w_[wIndex(i, j, k + 1)] - w_[wIndex(i, j, k)]) * inv.z;
            divergence_[c] = div;
            most[std::size_t(k)] = std::max(most[std::size_t(k)], double(std::abs(div)));
          }
    });
    return *std::max_element(most.begin(), most.end());
  };
  computeDivergence();
  const float omega = std::clamp(settings.relaxation, 1.0f, 1.95f);
  for (int it = 0; it < std::max(settings.iterations, 0); ++it)
    for (int colour = 0; colour < 2; ++colour)
      slabs(n_.z, [&](int k0, int k1) {
        for (int k = k0; k < k1; ++k)
          for (int j = 0; j < n_.y; ++j)
            for (int i = (j + k + colour) % 2; i < n_.x; i += 2) {
              const std::size_t c = cell(i, j, k);
              if (diag_[c] == 0.0f) continue;
              const std::uint8_t bits = neighbours_[c];
              float sum = 0.0f;
              for (int axis = 0; axis < 3; ++axis) {
                if (bits & (1u << (2 * axis)))
                  sum += p_[std::size_t(std::ptrdiff_t(c) - stride[axis])] * inv2[axis];
                if (bits & (1u << (2 * axis + 1)))
                  sum += p_[std::size_t(std::ptrdiff_t(c) + stride[axis])] * inv2[axis];
              }
              p_[c] += omega * ((sum - divergence_[c]) / diag_[c] - p_[c]);
            }
      });
  // The faces lose the pressure's gradient (0 outside an open side).
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<float>& f = faces(axis);
    const glm::ivec3 d = n_ + unit(axis);
    slabs(d.z, [&](int k0, int k1) {
      for (int k = k0; k < k1; ++k)
        for (int j = 0; j < d.y; ++j)
          for (int i = 0; i < d.x; ++i) {
            const std::size_t at = faceIndex(axis, i, j, k);
            if (fixed_[axis][at]) continue;
            const glm::ivec3 face(i, j, k), lo = face - unit(axis);
            const float right = face[axis] < n_[axis] ? p_[cell(face.x, face.y, face.z)] : 0.0f;
            const float left = lo[axis] >= 0 ? p_[cell(lo.x, lo.y, lo.z)] : 0.0f;
            f[at] -= (right - left) * inv[axis];
          }
    });
  }
  maxDivergence_ = computeDivergence();
}

void FluidSolver::step(float dt, const FluidSettings& settings, const FluidForces& forces) {
  if (!(dt > 0.0f)) return;
  setBoundaries(settings);
  applyForces(dt, forces);
  confineVorticity(dt, settings.vorticity);
  time_ += dt;
  eddyIntensity_ = settings.turbulence;
  eddySize_ = std::max(settings.eddySize, 1e-3f);
  advect(dt);
  diffuse(dt, settings.viscosity);
  setBoundaries(settings);
  project(settings);
}

VectorField FluidSolver::velocityField() const {
  VectorField out(bounds_, n_);
  slabs(n_.z, [&](int k0, int k1) {
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < n_.y; ++j)
        for (int i = 0; i < n_.x; ++i) {
          // A solid cell under a fluid one takes its horizontal velocity (the
          // free-slip ground's), so dust resting on the terrain, which lies
          // between the two cells' centres, feels the flow over it.
          const bool ground = solid_[cell(i, j, k)] && k + 1 < n_.z && !solid_[cell(i, j, k + 1)];
          glm::vec3 v = cellVelocity({i, j, ground ? k + 1 : k});
          if (eddyIntensity_ > 0.0f) {
            const glm::vec3 x = bounds_.min + glm::vec3(float(i), float(j), float(k)) * h_;
            v += (eddyIntensity_ * glm::length(v)) * eddyPattern(x, eddySize_, float(time_));
          }
          out.at(i, j, k) = ground ? glm::vec3(v.x, v.y, 0.0f) : v;
        }
  });
  return out;
}

double FluidSolver::maxDivergence() const {
  return maxDivergence_;
}

double FluidSolver::kineticEnergy() const {
  double e = 0.0;
  const VectorField f = velocityField();
  for (const glm::vec3& v : f.values())
    e += 0.5 * double(glm::dot(v, v));
  return e * double(h_.x) * double(h_.y) * double(h_.z);
}

}  // namespace sandstorm
