#include "app/bench/bench_scene.h"

#include <cmath>
#include <numbers>

#include "core/field/vortex_field.h"
#include "core/util/error.h"

namespace sandstorm::bench {

ParticleState benchState(const SceneChoice& c) {
  ParticleState s;
  s.sim.maximum = int(c.particles);
  s.sim.motion = MotionModel::Tracer;
  s.sim.integrator = c.integrator == "euler" ? Integrator::Euler
                     : c.integrator == "rk4" ? Integrator::RK4
                                             : Integrator::RK2;
  s.sim.boundary = BoundaryMode::Clamp;
  Emitter& e = s.emitters[0];
  e.shape = EmitterShape::Disc;
  e.position = {0.0f, 0.0f, 0.5f};
  e.radius = 3.5f;
  e.velocity = {0.0f, 0.0f, 1.0f};
  e.spread = 0.5f;
  e.lifetime = 1000.0f;  // no particle dies during a run
  e.lifetimeVariance = 0.0f;
  e.rate = 0.0f;  // the packets carry the counts
  if (c.renderer == "points")
    s.render.mode = RenderMode::Points;
  else if (c.renderer == "splat" || c.renderer == "splat-atomic")
    s.render.mode = RenderMode::Splat;
  else if (c.renderer == "billboards")
    s.render.mode = RenderMode::Billboards;
  else
    throw Error(concat("sandstorm-bench: unknown renderer '", c.renderer, "'"));
  s.render.size = c.particleSize;
  s.render.trailLength = c.trailLength;
  s.render.shadows = c.shadows;
  s.field.mode = c.field == "equation" ? FieldMode::Equation : FieldMode::Texture;
  if (c.obstacles > 0) {
    Obstacle sphere;
    sphere.position = {1.5f, 0.0f, 3.0f};
    sphere.radius = 1.0f;
    Obstacle box;
    box.shape = ObstacleShape::Box;
    box.position = {-1.5f, 1.0f, 2.0f};
    box.size = {1.0f, 1.0f, 1.5f};
    s.obstacles = {sphere};
    if (c.obstacles > 1) s.obstacles.push_back(box);
  }
  if (c.molecules > 0) {
    e.kind = EmitterKind::Molecules;
    s.molecules.complexity = c.molecules;
    s.molecules.maximum = int(c.particles) / c.molecules;
  }
  if (c.turnover) {
    s.sim.boundary = BoundaryMode::Kill;
    e.lifetime = 0.3f;
    e.lifetimeVariance = 0.2f;
  }
  return s;
}

std::shared_ptr<const FieldUpdate> benchField(const std::string& mode) {
  VortexParams vp;
  vp.range = 5.0f;
  vp.height = 9.0f;
  const Box box{{-6.0f, -6.0f, 0.0f}, {6.0f, 6.0f, 10.0f}};
  auto update = std::make_shared<FieldUpdate>();
  update->field = std::make_shared<VectorField>(bake(VortexField(vp), box, {64, 64, 48}));
  if (mode == "equation") {
    update->equation = std::make_shared<FieldEquation>(*fieldEquation(VortexField(vp)));
  } else if (mode != "texture") {
    throw Error(concat("sandstorm-bench: unknown field mode '", mode, "'"));
  }
  return update;
}

FramePacket benchPacket(std::uint32_t frame, const SceneChoice& c,
                        const std::shared_ptr<const FieldUpdate>& field) {
  FramePacket p;
  p.frame = frame;
  p.dt = p.simDt = 1.0f / 60.0f;
  p.time = frame / 60.0;
  p.seed = 0x5A4D5700ull;
  const std::size_t units = c.molecules > 0 ? c.particles / std::size_t(c.molecules) : c.particles;
  p.emission = {frame == 0 ? std::uint32_t(units) : c.turnover ? std::uint32_t(units / 8) : 0u};
  if (frame == 0) p.fieldUpdate = field;
  return p;
}

View benchView(int index, int count, glm::ivec2 size) {
  const float a = 2.0f * std::numbers::pi_v<float> * float(index) / float(std::max(count, 1)) -
                  0.5f * std::numbers::pi_v<float>;
  const glm::vec3 eye(14.0f * std::cos(a), 14.0f * std::sin(a), 3.5f);
  return perspectiveView(eye, {0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, 1.0f}, glm::radians(60.0f),
                         float(size.x) / float(size.y), 0.1f, 200.0f);
}

}  // namespace sandstorm::bench
