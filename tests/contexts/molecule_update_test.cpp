// Molecules on the GPU (MoleculeUpdate) against the CPU reference
// (MoleculeReference), record for record, through births, deaths and mid-run
// changes; with obstacles, the push tool, repulsion, a terrain, every motion
// model and integrator, a field expression and both paths of the look-back
// scan. Counts are equal every frame; positions and velocities bit for bit
// where the GPU rounds sqrt and division correctly (llvmpipe); elsewhere in
// lockstep, each update within the bound of tests/contexts/gpu_arithmetic.h
// (the springs amplify any difference frame after frame). What would break
// it: any operation of shaders/molecule_*.glsl that differs from
// core/molecules/molecule_physics.cpp, or a compaction that reorders molecules.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include <epoxy/gl.h>

#include <cstring>

#include "contexts/molecules/molecule_update.h"
#include "core/field/vortex_field.h"
#include "core/molecules/molecule_reference.h"
#include "core/sim/main_context.h"
#include "tests/contexts/gl_test.h"
#include "tests/contexts/gpu_arithmetic.h"

namespace sandstorm {
namespace {

class MoleculeUpdateTest : public GlTest {};

std::shared_ptr<const VectorField> vortex() {
  VortexParams vp;
  vp.range = 3.0f;
  vp.up = 1.5f;
  return std::make_shared<VectorField>(
      bake(VortexField(vp), Box{{-3, -3, 0}, {3, 3, 4}}, {16, 16, 12}));
}

ParticleState moleculeState(int complexity) {
  ParticleState s;
  s.molecules.maximum = 1500;
  s.molecules.complexity = complexity;
  s.sim.motion = MotionModel::Drag;
  Emitter& e = s.emitters[0];
  e.kind = EmitterKind::Molecules;
  e.shape = EmitterShape::Disc;
  e.position = {0.0f, 0.0f, 0.3f};
  e.radius = 2.0f;
  e.rate = 2000.0f;
  e.lifetime = 0.8f;
  e.lifetimeVariance = 0.5f;
  e.spread = 0.5f;
  // And a particle emitter beside it, which the molecules leave alone.
  Emitter particles = e;
  particles.kind = EmitterKind::Particles;
  s.emitters.push_back(particles);
  return s;
}

struct MoleculeRun {
  ParticleState state;
  int frames = 60;
  std::uint32_t spin = 64;
  // Changes made on the main context at a frame.
  std::function<void(MainContext&, int frame)> changes = [](MainContext&, int) {};
};

using test::exactArithmetic;

// Frames whose records all matched (counts exactly; bit for bit with exact
// arithmetic, else one update at a time within its bound); stops at the
// first that differs.
int matchingFrames(const MoleculeRun& run, std::size_t* most = nullptr) {
  MoleculeUpdate gpu(1024, 1 << 16, GpuTuning{.scanSpin = run.spin});
  MoleculeReference cpu(1024, 1 << 16);
  auto terrain =
      std::make_shared<const HeightMap>(glm::vec2(-4, -4), glm::vec2(4, 4), glm::ivec2(9, 9), [] {
        std::vector<float> h(81);
        for (int i = 0; i < 81; ++i)
          h[std::size_t(i)] = 0.05f * float((i * 7) % 5);
        return h;
      }());
  gpu.setTerrain(terrain);
  cpu.world().setTerrain(terrain);
  MainContext::Options options;
  options.fixedDt = 1.0f / 60.0f;
  options.seed = 99;
  MainContext main(run.state, FieldUpdate{.field = vortex()}, options);
  ParticleState state = main.initialState();
  int matching = 0;
  float worstUlps = 0.0f;
  for (int f = 0; f < run.frames; ++f) {
    run.changes(main, f);
    const FramePacket packet = main.next();
    for (const StateChange& c : packet.changes)
      applyChange(state, c);
    if (packet.fieldUpdate) {
      gpu.setField(packet.fieldUpdate->field, {});
      gpu.setEquation(packet.fieldUpdate->equation);
      cpu.world().setField(packet.fieldUpdate->field, {});
    }
    gpu.step(packet.step(), state);
    cpu.step(packet.step(), state);
    const std::vector<Particle> g = gpu.readBack();
    const auto c = cpu.records();
    if (g.size() != c.size()) {
      ADD_FAILURE() << "frame " << f << ": " << g.size() << " records on the GPU, " << c.size()
                    << " on the CPU";
      break;
    }
    float worst = 0.0f, scale = 0.0f;
    for (std::size_t i = 0; i < g.size(); ++i) {
      worst = std::max({worst, glm::length(g[i].positionLife - c[i].positionLife),
                        glm::length(g[i].velocityKind - c[i].velocityKind)});
      const glm::vec4 p = glm::abs(c[i].positionLife), v = glm::abs(c[i].velocityKind);
      scale = std::max({scale, p.x, p.y, p.z, p.w, v.x, v.y, v.z});
    }
    const bool exact = exactArithmetic();
    if (worst > (exact ? 0.0f : test::oneUpdateBound(scale))) {
      ADD_FAILURE() << "frame " << f << ": max |gpu - cpu| = " << worst << " ("
                    << worst / test::ulpAt(scale) << " ulp of the largest value " << scale << ")";
      break;
    }
    if (!exact) {
      worstUlps = std::max(worstUlps, worst / test::ulpAt(scale));
      cpu.adopt(g);
    }
    if (most) *most = std::max(*most, cpu.count());
    ++matching;
  }
  if (!exactArithmetic())
    std::printf("lockstep: one update differs by at most %.1f ulp (bound %.0f)\n", worstUlps,
                test::kOneUpdateUlps);
  return matching;
}

TEST_F(MoleculeUpdateTest, MoleculesMoveAsTheReferenceSaysForEveryShape) {
  for (int n : {2, 4, 7}) {  // a rod, a solid, a chain (each shape a program to compile)
    SCOPED_TRACE(n);
    MoleculeRun run{.state = moleculeState(n)};
    std::size_t most = 0;
    EXPECT_EQ(matchingFrames(run, &most), run.frames);
    EXPECT_GT(most, 500u);
  }
}

TEST_F(MoleculeUpdateTest, MidRunChangesObstaclesPushAndRepulsionStayTheReferences) {
  MoleculeRun run{.state = moleculeState(4), .frames = 70};
  Obstacle sphere;
  sphere.shape = ObstacleShape::Sphere;
  sphere.position = {0.5f, 0.0f, 1.0f};
  sphere.radius = 0.6f;
  run.state.obstacles = {sphere};
  run.state.molecules.repulsion = true;
  run.state.molecules.repulsionRadius = 0.15f;
  run.state.molecules.push = true;
  run.state.molecules.pushPosition = {-1.0f, 0.0f, 0.8f};
  run.changes = [](MainContext& main, int f) {
    if (f == 20) main.set("molecules.stiffness", 0.4f);
    if (f == 25) main.set("obstacle.0.position", glm::vec3(-0.5f, 0.5f, 1.0f));
    if (f == 30) main.set("molecules.complexity", 5);  // starts afresh
    if (f == 40) main.set("sim.integrator", std::string("rk4"));
    if (f == 50) main.set("molecules.maximum", 2000);
  };
  std::size_t most = 0;
  EXPECT_EQ(matchingFrames(run, &most), run.frames);
  EXPECT_GT(most, 500u);
}

TEST_F(MoleculeUpdateTest, EveryMotionModelBoundaryAndBothScanPaths) {
  struct Case {
    MotionModel motion;
    Integrator integrator;
    BoundaryMode boundary;
    std::uint32_t spin;
  };
  for (const Case c : {Case{MotionModel::Tracer, Integrator::RK4, BoundaryMode::Wrap, 0},
                       Case{MotionModel::Force, Integrator::Euler, BoundaryMode::Clamp, 200},
                       Case{MotionModel::Drag, Integrator::RK2, BoundaryMode::Kill, 0}}) {
    SCOPED_TRACE(int(c.motion));
    MoleculeRun run{.state = moleculeState(3), .frames = 40, .spin = c.spin};
    run.state.sim.motion = c.motion;
    run.state.sim.integrator = c.integrator;
    run.state.sim.boundary = c.boundary;
    run.state.sim.gravity = glm::vec3(0.0f, 0.0f, -2.0f);
    std::size_t most = 0;
    EXPECT_EQ(matchingFrames(run, &most), run.frames);
    EXPECT_GT(most, 300u);
  }
}

TEST_F(MoleculeUpdateTest, AFieldWrittenAsAnExpressionMovesThemAlike) {
  MoleculeRun run{.state = moleculeState(4), .frames = 40};
  run.state.field.mode = FieldMode::Expression;
  run.state.field.expression = {"-y + 0.1*vx", "x", "0.2 + 0.1*sin(t)"};
  run.state.sim.motion = MotionModel::Tracer;
  std::size_t most = 0;
  // muParser on the CPU evaluates in double: not bit for bit, so compare
  // within the expression tests' tolerance instead.
  MoleculeUpdate gpu(1024, 1 << 16);
  MoleculeReference cpu(1024, 1 << 16);
  MainContext::Options options;
  options.fixedDt = 1.0f / 60.0f;
  MainContext main(run.state, FieldUpdate{.field = vortex()}, options);
  ParticleState state = main.initialState();
  float worst = 0.0f;
  for (int f = 0; f < run.frames; ++f) {
    const FramePacket packet = main.next();
    for (const StateChange& c : packet.changes)
      applyChange(state, c);
    if (packet.fieldUpdate) {
      gpu.setField(packet.fieldUpdate->field, {});
      cpu.world().setField(packet.fieldUpdate->field, {});
    }
    gpu.step(packet.step(), state);
    cpu.step(packet.step(), state);
    const std::vector<Particle> g = gpu.readBack();
    ASSERT_EQ(g.size(), cpu.records().size()) << f;
    for (std::size_t i = 0; i < g.size(); ++i)
      worst = std::max(worst, glm::distance(g[i].position(), cpu.records()[i].position()));
    most = std::max(most, cpu.count());
  }
  EXPECT_LT(worst, 1e-3f);
  EXPECT_GT(most, 500u);
}

}  // namespace
}  // namespace sandstorm
