// The GPU particle updates (transform feedback + geometry shaders, and compute
// shaders) against the CPU reference simulator: the same frame packets, ~10^4
// particles, 120 frames with emission, death and a field that carries
// particles out of its bounds. Every test runs for each backend.
#include "contexts/particles/particle_geo_update.h"
#include "contexts/particles/particle_system.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>

#include "core/field/field_timeline.h"
#include "core/field/vortex_field.h"
#include "core/obstacles/obstacle_physics.h"
#include "core/sim/main_context.h"
#include "core/sim/reference_simulator.h"
#include "core/util/error.h"
#include "tests/contexts/gl_test.h"
#include "tests/contexts/gpu_arithmetic.h"
#include "tests/core/sparse_grid_builder.h"

namespace sandstorm {
namespace {

class ParticleBackendTest : public GlTest, public ::testing::WithParamInterface<const char*> {};

struct Scenario {
  ParticleState state;
  std::shared_ptr<const VectorField> field;
  std::optional<FieldTimeline> timeline;
  std::shared_ptr<const HeightMap> terrain;
  FieldPlacement placement;
  std::shared_ptr<const SparseField> sparse;  // read in place of `field`, its overview
};

Scenario tornado(MotionModel motion, Integrator integrator, BoundaryMode boundary) {
  Scenario s;
  VortexParams vp;
  vp.range = 3.0f;
  vp.height = 5.0f;
  s.field = std::make_shared<VectorField>(
      bake(VortexField(vp), Box{{-3, -3, 0}, {3, 3, 4}}, {24, 24, 16}));
  s.terrain = std::make_shared<HeightMap>(HeightMap::flat(0.05f));
  s.state.sim.motion = motion;
  s.state.sim.integrator = integrator;
  s.state.sim.boundary = boundary;
  s.state.sim.maximum = 12000;
  Emitter& e = s.state.emitters[0];
  e.shape = EmitterShape::Disc;
  e.position = {0.5f, 0.0f, 0.3f};
  e.radius = 2.5f;
  e.rate = 6000.0f;
  e.rateVariance = 2000.0f;
  e.lifetime = 1.5f;
  e.lifetimeVariance = 0.5f;
  e.velocity = {0, 0, 1.0f};
  e.spread = 0.5f;
  Emitter box = e;
  box.shape = EmitterShape::Box;
  box.position = {-1, 1, 1};
  box.width = 1.0f;
  box.depth = 0.5f;
  box.height = 0.2f;
  box.rate = 3000.0f;
  s.state.emitters.push_back(box);
  return s;
}

struct Agreement {
  std::size_t frames = 0;
  float maxError = 0.0f;             // over the run, or one update's in lockstep
  float worstUlps = 0.0f;            // one update's, in ulps of the frame's largest coordinate
  std::size_t updates = 0;           // particle updates compared
  std::size_t surfaceDecisions = 0;  // lockstep: pushed out on one side only (see compare)
  std::size_t peak = 0;
  std::vector<Particle> last;  // the GPU's particles after the last frame
  ParticleState state;         // and the state then
};

// `script`: requests made before each frame's packet (beyond the rate change at 50).
// On a GPU without IEEE sqrt and division, in lockstep (tests/contexts/gpu_arithmetic.h).
Agreement compare(const std::string& backend, Scenario s, int frames, std::size_t capacity,
                  const GpuTuning& tuning = {},
                  const std::function<void(MainContext&, int)>& script = {}) {
  MainContext::Options options;
  options.fixedDt = 1.0f / 60.0f;
  options.seed = 0xC0FFEEull;
  MainContext main(s.state,
                   FieldUpdate{.field = s.field, .placement = s.placement, .sparse = s.sparse},
                   options);
  if (s.timeline) main.setFieldTimeline(*s.timeline, s.placement);
  std::unique_ptr<ParticleBackend> backendPtr = makeParticleBackend(backend, capacity, tuning);
  ParticleBackend& gpu = *backendPtr;
  EXPECT_STREQ(gpu.name(), backend.c_str());
  ReferenceSimulator cpu(capacity);
  gpu.setTerrain(s.terrain);
  cpu.setTerrain(s.terrain);
  ParticleState state = main.initialState();
  Agreement a;
  for (int f = 0; f < frames; ++f) {
    if (f == 50) main.set("emitter.0.rate", 12000.0f);  // a mid-run change
    if (script) script(main, f);
    const FramePacket packet = main.next();
    for (const StateChange& c : packet.changes)
      applyChange(state, c);
    if (const auto& u = packet.fieldUpdate) {
      gpu.setField(u->field, u->placement, u->next);
      cpu.setField(u->field, u->placement, u->next);
      gpu.setSparse(u->sparse);
      cpu.setSparse(u->sparse);
    }
    gpu.prefetchField(packet.upcomingField);  // as the walls do: the coming frame ahead of need
    // A pair blended point by point (the compute backend's FieldPairBlend) on both sides.
    cpu.setPointwiseBlend(gpu.blendsPairPointwise(state));
    gpu.step(packet.step(), state);
    cpu.step(packet.step(), state);
    const std::vector<Particle> g = gpu.readBack();
    const auto c = cpu.particles();
    EXPECT_EQ(g.size(), c.size()) << "alive count at frame " << f;
    if (g.size() != c.size()) return a;
    float scale = 0.0f;
    for (std::size_t i = 0; i < g.size(); ++i) {
      const glm::vec3 p = glm::abs(c[i].position());
      scale = std::max({scale, p.x, p.y, p.z, std::abs(c[i].life())});
    }
    const bool lockstep = !test::exactArithmetic();
    const float bound = test::oneUpdateBound(scale);
    // Whether x lies on an obstacle's surface, within the push's margin.
    const auto onSurface = [&](const glm::vec3& x) {
      for (const Obstacle& o : state.obstacles)
        if (std::abs(obstacleSurface(o, x).distance) <= kObstacleMargin + bound) return true;
      return false;
    };
    float worst = 0.0f;
    for (std::size_t i = 0; i < g.size(); ++i) {
      const float d = std::max(glm::length(g[i].position() - c[i].position()),
                               std::abs(g[i].life() - c[i].life()));
      // In lockstep, a particle that ended a step a few ulps inside an
      // obstacle on one side and a few outside on the other is pushed out by
      // kObstacleMargin on one side only: a decision at the surface, which no
      // bound on rounding can remove. Allowed there, up to the margin, and counted.
      if (lockstep && d > bound && d <= kObstacleMargin + bound && onSurface(c[i].position()) &&
          onSurface(g[i].position())) {
        ++a.surfaceDecisions;
        continue;
      }
      worst = std::max(worst, d);
    }
    a.maxError = std::max(a.maxError, worst);
    a.updates += g.size();
    if (lockstep) {
      a.worstUlps = std::max(a.worstUlps, worst / test::ulpAt(scale));
      EXPECT_LE(worst, bound) << "frame " << f << ", largest coordinate " << scale;
      cpu.adopt(g);
    }
    a.peak = std::max(a.peak, g.size());
    ++a.frames;
    a.last = g;
    a.state = state;
  }
  if (!test::exactArithmetic()) {
    std::printf(
        "lockstep: one update differs by at most %.1f ulp (bound %.0f); %zu of %zu "
        "updates decided differently at an obstacle's surface\n",
        a.worstUlps, test::kOneUpdateUlps, a.surfaceDecisions, a.updates);
    // Rare: a particle must end a step within ulps of a surface.
    EXPECT_LE(a.surfaceDecisions * 10000, a.updates) << "more than 1 in 10^4";
  }
  return a;
}

TEST_P(ParticleBackendTest, MatchesTheCpuReferenceWithEmissionAndDeath) {
  for (auto [motion, integrator, boundary] :
       {std::tuple{MotionModel::Tracer, Integrator::RK2, BoundaryMode::Kill},
        std::tuple{MotionModel::Drag, Integrator::RK4, BoundaryMode::Clamp},
        std::tuple{MotionModel::Force, Integrator::Euler, BoundaryMode::Wrap}}) {
    SCOPED_TRACE(::testing::Message() << "motion " << int(motion) << " integrator "
                                      << int(integrator) << " boundary " << int(boundary));
    const Agreement a = compare(GetParam(), tornado(motion, integrator, boundary), 120, 16384);
    EXPECT_EQ(a.frames, 120u);
    // Positions agree to rounding: the shaders mirror the C++ operation by operation.
    EXPECT_LT(a.maxError, 1e-4f);
    std::printf("max |gpu - cpu| = %g over %zu frames, peak %zu particles\n", a.maxError, a.frames,
                a.peak);
    EXPECT_GT(a.peak, 8000u);  // ~10^4 particles
  }
}

TEST_P(ParticleBackendTest, APlacedFieldMovesParticlesTheSameOnBothSides) {
  // The field turned (a y-up data set stood up), scaled and moved in the room.
  Scenario s = tornado(MotionModel::Drag, Integrator::RK2, BoundaryMode::Clamp);
  const float c = std::cos(glm::radians(90.0f)), si = std::sin(glm::radians(90.0f));
  s.placement.rotation = glm::mat3(1, 0, 0, 0, c, si, 0, -si, c);
  s.placement.offset = {0.3f, 2.0f, 0.1f};
  s.placement.scale = 1.5f;
  const Agreement a = compare(GetParam(), s, 90, 16384);
  EXPECT_EQ(a.frames, 90u);
  // Matrix products may round differently on the GPU: agreement to a tenth of a millimetre.
  EXPECT_LT(a.maxError, 1e-4f);
  std::printf("placed field: max |gpu - cpu| = %g\n", a.maxError);
}

TEST_P(ParticleBackendTest, ObstaclesTurnTheFlowAndHoldParticlesOutTheSameOnBothSides) {
  // A sphere, a box and a cylinder in the tornado; the sphere moves mid-run.
  // Last, none turns the flow (the compute backend then only puts particles out).
  for (const auto& [motion, flow] :
       {std::pair{MotionModel::Tracer, true}, std::pair{MotionModel::Force, true},
        std::pair{MotionModel::Drag, false}}) {
    SCOPED_TRACE(::testing::Message() << int(motion) << (flow ? "" : ", no flow"));
    Scenario s = tornado(motion, Integrator::RK2, BoundaryMode::Clamp);
    Obstacle sphere;
    sphere.position = {0.8f, 0.6f, 1.0f};
    sphere.radius = 0.6f;
    sphere.velocity = {0.0f, -0.5f, 0.0f};
    Obstacle box;
    box.shape = ObstacleShape::Box;
    box.position = {-1.0f, -0.8f, 0.5f};
    box.size = {0.8f, 0.6f, 1.0f};
    box.restitution = 0.8f;
    Obstacle pillar;
    pillar.shape = ObstacleShape::Cylinder;
    pillar.position = {0.0f, 1.5f, 1.0f};
    pillar.radius = 0.3f;
    pillar.height = 2.0f;
    pillar.flow = false;
    s.state.obstacles = {sphere, box, pillar};
    if (!flow)
      for (Obstacle& o : s.state.obstacles)
        o.flow = false;
    const Agreement a = compare(GetParam(), s, 90, 16384, {}, [](MainContext& main, int f) {
      if (f >= 30) main.set("obstacle.0.position", glm::vec3(0.8f, 0.6f - 0.01f * float(f), 1.0f));
    });
    EXPECT_EQ(a.frames, 90u);
    EXPECT_LT(a.maxError, 1e-4f);
    std::printf("obstacles: max |gpu - cpu| = %g, peak %zu\n", a.maxError, a.peak);
    EXPECT_GT(a.peak, 8000u);
    // None inside, and many held on a surface (the obstacles did act).
    std::size_t onSurface = 0;
    for (const Particle& p : a.last)
      for (const Obstacle& o : a.state.obstacles) {
        const float d = obstacleSurface(o, p.position()).distance;
        EXPECT_GE(d, 0.0f);
        if (d < 1e-3f) ++onSurface;
      }
    EXPECT_GT(onSurface, 50u);
    std::printf("obstacles: %zu particles on a surface\n", onSurface);
  }
}

TEST_P(ParticleBackendTest, FieldExpressionsMoveParticlesTheSameOnBothSides) {
  // Fields written at run time, evaluated by muParser (double) on the CPU and
  // as translated GLSL (float) on the GPU: the same particles to float
  // rounding. Each reads other variables; the last is changed mid-run.
  const std::array<std::string, 3> fields[] = {
      {"-y", "x", "0.3 + 0.05*x"},
      {"-y + 0.2*sin(t)", "x - 0.1*vy", "(age < 0.5 ? 1 : 0.2) + z^2/20"},
      {"max(-1, min(1, -y*2))", "atan2(x, 1) + abs(z - 2)", "sqrt(x^2 + y^2) > 2 ? -0.5 : 0.8"},
  };
  const Agreement plain = compare(
      GetParam(), tornado(MotionModel::Drag, Integrator::RK2, BoundaryMode::Kill), 90, 16384);
  for (const auto& text : fields) {
    SCOPED_TRACE(text[0] + " | " + text[1] + " | " + text[2]);
    Scenario s = tornado(MotionModel::Drag, Integrator::RK2, BoundaryMode::Kill);
    s.state.field.mode = FieldMode::Expression;
    s.state.field.expression = text;
    const Agreement a = compare(GetParam(), s, 90, 16384, {}, [](MainContext& main, int f) {
      if (f == 60) main.set("field.expression_z", std::string("0.5 - 0.1*y"));
    });
    EXPECT_EQ(a.frames, 90u);
    EXPECT_LT(a.maxError, 1e-3f);
    std::printf("expression: max |gpu - cpu| = %g, peak %zu\n", a.maxError, a.peak);
    EXPECT_GT(a.peak, 5000u);
    // The expression moved them, not the tornado's grid.
    ASSERT_FALSE(a.last.empty());
    ASSERT_FALSE(plain.last.empty());
    EXPECT_GT(glm::length(a.last.back().position() - plain.last.back().position()), 0.01f);
  }
}

// Three frames of a vortex that turns one way, then the other (in halves:
// a series read with field.precision = "half").
std::vector<std::shared_ptr<const VectorField>> turningVortex(bool halves) {
  std::vector<std::shared_ptr<const VectorField>> frames;
  for (float spin : {6.0f, -4.0f, 8.0f}) {
    VortexParams vp;
    vp.range = 3.0f;
    vp.spin = spin;
    VectorField f = bake(VortexField(vp), Box{{-3, -3, 0}, {3, 3, 4}}, {20, 20, 12});
    if (halves) f.roundToHalf();
    frames.push_back(std::make_shared<VectorField>(std::move(f)));
  }
  return frames;
}

TEST_P(ParticleBackendTest, TimeVaryingFieldsBlendTheSameOnBothSides) {
  // Three frames of a vortex that turns one way, then the other: the walls
  // blend frames themselves, and must match the CPU doing the same.
  Scenario s = tornado(MotionModel::Tracer, Integrator::RK4, BoundaryMode::Clamp);
  s.timeline = FieldTimeline({0.0, 0.5, 1.2}, turningVortex(false));
  s.state.field.loop = true;
  // Forwards and backwards: each frame is uploaded ahead of need in the
  // order it comes (FramePacket::upcomingField) and swapped in.
  for (const float speed : {1.5f, -1.5f}) {
    s.state.field.speed = speed;
    const Agreement a = compare(GetParam(), s, 90, 16384);
    EXPECT_EQ(a.frames, 90u);
    EXPECT_LT(a.maxError, 1e-4f);
    // With IEEE arithmetic (llvmpipe) the twin is exact, blend included.
    if (test::exactArithmetic()) {
      EXPECT_EQ(a.maxError, 0.0f);
    }
    std::printf("time-varying at speed %g: max |gpu - cpu| = %g over %zu frames\n", speed,
                a.maxError, a.frames);
  }
}

TEST_P(ParticleBackendTest, HalfTimeVaryingFieldsBlendTheSameOnBothSides) {
  // Three frames in halves (a streamed series' field.precision = "half"):
  // the compute backend blends each pair into one grid, rounded to halves
  // (FieldPairBlend), and the CPU twin samples that grid; transform feedback
  // samples both frames. Either way the same as the CPU.
  Scenario s = tornado(MotionModel::Drag, Integrator::RK2, BoundaryMode::Kill);
  const std::vector<std::shared_ptr<const VectorField>> frames = turningVortex(true);
  s.timeline = FieldTimeline({0.0, 0.5, 1.2}, frames);
  s.state.field.loop = true;
  s.state.field.speed = 1.5f;
  // Which way the backend blends, asked as compare() asks it.
  {
    std::unique_ptr<ParticleBackend> probe = makeParticleBackend(GetParam(), 1024, {});
    probe->setField(frames[0], {}, frames[1]);
    EXPECT_EQ(probe->blendsPairPointwise(s.state), std::string(GetParam()) == "compute");
    std::unique_ptr<ParticleBackend> textures = makeParticleBackend(
        GetParam(), 1024, GpuTuning{.fieldStorage = GpuTuning::FieldStorage::Texture});
    textures->setField(frames[0], {}, frames[1]);
    EXPECT_FALSE(textures->blendsPairPointwise(s.state));
  }
  const Agreement a = compare(GetParam(), s, 90, 16384);
  EXPECT_EQ(a.frames, 90u);
  EXPECT_LT(a.maxError, 1e-4f);
  EXPECT_GT(a.peak, 4000u);
  if (test::exactArithmetic()) {
    EXPECT_EQ(a.maxError, 0.0f);
  }
  std::printf("half time-varying: max |gpu - cpu| = %g over %zu frames\n", a.maxError, a.frames);
}

TEST_P(ParticleBackendTest, GridsKeptAsTexturesMoveParticlesTheSame) {
  // The compute backend's texture fallback for grids beyond the
  // storage-buffer limit (GpuField), forced; transform feedback keeps its
  // texture either way.
  const Agreement a =
      compare(GetParam(), tornado(MotionModel::Tracer, Integrator::RK4, BoundaryMode::Clamp), 60,
              16384, GpuTuning{.fieldStorage = GpuTuning::FieldStorage::Texture});
  EXPECT_EQ(a.frames, 60u);
  EXPECT_LT(a.maxError, 1e-4f);
  EXPECT_GT(a.peak, 4000u);
}

// A sparse grid (NanoVDB, read with PNanoVDB.h on both sides): the tornado's
// voxels within 2.2 m of its axis only, 0.2 m apart, the rest the background;
// particles move through it as through the CPU twin, and a coarse overview in
// `field` (only the bounds) changes nothing: they leave the active voxels and stop.
TEST_P(ParticleBackendTest, ASparseGridMovesParticlesAsTheCpuTwin) {
  Scenario s = tornado(MotionModel::Tracer, Integrator::RK4, BoundaryMode::Kill);
  VortexParams vp;
  vp.range = 3.0f;
  vp.height = 5.0f;
  const VortexField vortex(vp);
  const glm::vec3 origin(-3.0f, -3.0f, 0.0f);
  auto sparse = std::make_shared<SparseField>(test::buildSparseGrid(
                                                  [&](const auto& set) {
                                                    for (int k = 0; k <= 20; ++k)
                                                      for (int j = 0; j <= 30; ++j)
                                                        for (int i = 0; i <= 30; ++i) {
                                                          const glm::vec3 p =
                                                              origin + 0.2f * glm::vec3(i, j, k);
                                                          if (glm::length(glm::vec2(p)) < 2.2f)
                                                            set({i, j, k}, vortex.evaluate(p));
                                                        }
                                                  },
                                                  0.2, glm::dvec3(origin)),
                                              "tornado.nvdb");
  s.sparse = sparse;
  s.field = std::make_shared<VectorField>(sparse->overview(4));
  const Agreement a = compare(GetParam(), s, 60, 16384);
  EXPECT_EQ(a.frames, 60u);
  EXPECT_LT(a.maxError, 1e-4f);
  EXPECT_GT(a.peak, 2000u);
  std::printf("sparse grid of %llu voxels (%zu bytes): max |gpu - cpu| = %g, peak %zu\n",
              static_cast<unsigned long long>(sparse->activeVoxelCount()), sparse->byteSize(),
              a.maxError, a.peak);
  // The particles felt the sparse grid, not the 4^3 overview: the GPU's
  // against the CPU twin reading the overview differ.
  Scenario coarse = s;
  coarse.sparse = nullptr;
  const Agreement b = compare(GetParam(), coarse, 60, 16384);
  ASSERT_EQ(a.last.size() > 0, true);
  bool differ = a.last.size() != b.last.size();
  for (std::size_t i = 0; !differ && i < a.last.size(); ++i)
    differ = a.last[i].position() != b.last[i].position();
  EXPECT_TRUE(differ);
}

// Marks the points with x > 0.5 and z > 1 as without data (a corner of the box).
void maskCorner(VectorField& field) {
  std::vector<std::uint8_t> valid(field.pointCount(), 1);
  const glm::ivec3 d = field.dims();
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i) {
        const glm::vec3 p = field.pointPosition(i, j, k);
        if (p.x > 0.5f && p.z > 1.0f) valid[field.index(i, j, k)] = 0;
      }
  field.setValidity(valid);
}

// The scenario's particles on the GPU against the CPU twin for 60 frames,
// the grid kept in the backend's buffer and as a texture.
void expectAgreementEitherStorage(const std::string& backend, const Scenario& s) {
  for (const bool texture : {false, true}) {
    SCOPED_TRACE(texture ? "texture" : "buffer");
    GpuTuning tuning;
    if (texture) tuning.fieldStorage = GpuTuning::FieldStorage::Texture;
    const Agreement a = compare(backend, s, 60, 16384, tuning);
    EXPECT_EQ(a.frames, 60u);
    EXPECT_LT(a.maxError, 1e-4f);
    EXPECT_GT(a.peak, 2000u);
  }
}

// field.precision = "half": the grid on the GPU as 16-bit floats (the
// compute backend's buffer of halves, or a texture), the CPU twin sampling
// the same rounded values: the same particles to rounding, with and without
// a validity mask.
TEST_P(ParticleBackendTest, AHalfPrecisionFieldMovesParticlesAsTheCpuTwin) {
  for (const bool masked : {false, true}) {
    SCOPED_TRACE(masked ? "masked" : "unmasked");
    Scenario s = tornado(MotionModel::Tracer, Integrator::RK4, BoundaryMode::Kill);
    auto half = std::make_shared<VectorField>(*s.field);
    if (masked) maskCorner(*half);
    half->roundToHalf();
    s.field = half;
    expectAgreementEitherStorage(GetParam(), s);
  }
}

// A field with a validity mask (points a resampled file had no data for):
// the same particles die (kill) or stop (clamp) on the GPU as on the CPU,
// whether the grid is a storage buffer (w) or a texture (alpha).
TEST_P(ParticleBackendTest, CellsOutsideTheDataAreOutsideTheFieldOnBothSides) {
  for (const BoundaryMode mode : {BoundaryMode::Kill, BoundaryMode::Clamp}) {
    SCOPED_TRACE(mode == BoundaryMode::Kill ? "kill" : "clamp");
    Scenario s = tornado(MotionModel::Tracer, Integrator::RK4, mode);
    auto masked = std::make_shared<VectorField>(*s.field);
    maskCorner(*masked);
    s.field = masked;
    expectAgreementEitherStorage(GetParam(), s);
  }
}

TEST_P(ParticleBackendTest, MaximumCapsTheLiveCountAndCapacityTheBuffer) {
  Scenario s = tornado(MotionModel::Tracer, Integrator::Euler, BoundaryMode::Clamp);
  s.state.emitters[0].lifetime = 100.0f;
  s.state.sim.maximum = 3000;
  const Agreement a = compare(GetParam(), s, 40, 4096);
  EXPECT_EQ(a.frames, 40u);
  EXPECT_LE(a.peak, 3000u);
  EXPECT_GE(a.peak, 2900u);
}

TEST_P(ParticleBackendTest, RaisingMaximumGrowsTheBuffersWithoutLosingParticles) {
  Scenario s = tornado(MotionModel::Drag, Integrator::RK2, BoundaryMode::Kill);
  s.state.sim.maximum = 4000;
  s.state.emitters[0].lifetime = 30.0f;
  MainContext::Options options;
  options.fixedDt = 1.0f / 60.0f;
  MainContext main(s.state,
                   FieldUpdate{.field = s.field, .placement = s.placement, .sparse = s.sparse},
                   options);
  ParticleSystem gpu(
      main.initialState(),
      ParticleSystem::Options{.capacity = 4096, .capacityLimit = 1 << 16, .backend = GetParam()});
  gpu.setTerrain(s.terrain);
  ReferenceSimulator cpu(4096, 1 << 16);
  cpu.setField(s.field, s.placement);
  cpu.setTerrain(s.terrain);
  ParticleState state = main.initialState();
  std::vector<Particle> before;
  for (int f = 0; f < 60; ++f) {
    if (f == 30) {
      before = gpu.update().readBack();
      main.set("sim.maximum", 20000.0f);  // above the 4096 the buffers hold
    }
    const FramePacket packet = main.next();
    for (const StateChange& c : packet.changes)
      applyChange(state, c);
    gpu.advance(packet);
    cpu.step(packet.step(), state);
    const std::vector<Particle> g = gpu.update().readBack();
    ASSERT_EQ(g.size(), cpu.particles().size()) << "frame " << f;
    for (std::size_t i = 0; i < g.size(); ++i)
      ASSERT_EQ(g[i].positionLife, cpu.particles()[i].positionLife)
          << "frame " << f << " particle " << i;
    if (f == 30) {
      // Every particle alive before the growth is still there, moved one step, after the newborn.
      const std::size_t born = g.size() - before.size();
      EXPECT_GE(g.size(), before.size());
      for (std::size_t i = 0; i < before.size(); i += 97)
        EXPECT_NEAR(g[born + i].life(), before[i].life() - 1.0f / 60.0f, 1e-5f);
    }
  }
  EXPECT_GE(gpu.update().capacity(), 20000u);
  EXPECT_GT(gpu.update().liveCount(), 8000u);
}

INSTANTIATE_TEST_SUITE_P(Backends, ParticleBackendTest, ::testing::Values("tf-gs", "compute"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param) == "tf-gs"
                                      ? std::string("TransformFeedback")
                                      : std::string("Compute");
                         });

}  // namespace
}  // namespace sandstorm
