// ParticleGeoUpdate: the thesis's particle update (5.1.1-5.1.2) on the GPU,
// through transform feedback and geometry shaders.
//
// Two sets of buffers (position + remaining life, velocity + kind) take turns:
// each update reads one set and writes the other, then they swap. An update
// writes, in one pass after the other:
//   1. the emission pass: emitters' newborn particles at the start of the
//      buffer (shaders/particle_emit.*); their number is known before the pass
//      (Reeves' counts from the main context, capped by the EmissionBudget);
//   2. the particle pass: every particle of the other set ages and moves; the
//      geometry stage drops the dead, and survivors follow the newborn
//      (shaders/particle_update.*).
// The buffer's capacity is the hard limit; Maximum is the soft one. The update
// never waits for the GPU: the budget uses counts two updates old, read back
// from transform-feedback queries. The CPU twin is ReferenceSimulator.
//
// All calls need this object's GL context current.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/particles/expression_programs.h"
#include "contexts/particles/particle_backend.h"
#include "contexts/particles/particle_environment.h"
#include "contexts/particles/particle_trails.h"
#include "core/field/field_placement.h"
#include "core/field/height_map.h"
#include "core/sim/emission_budget.h"
#include "core/sim/particle.h"
#include "core/sim/particle_state.h"
#include "core/sim/sim_step.h"

namespace sandstorm {

class ParticleGeoUpdate final : public ParticleBackend {
 public:
  explicit ParticleGeoUpdate(std::size_t capacity, UploadThread* uploads = nullptr);

  void setField(std::shared_ptr<const VectorField> field, const FieldPlacement& placement,
                std::shared_ptr<const VectorField> next = nullptr) override;
  void prefetchField(std::shared_ptr<const VectorField> upcoming) override {
    environment_.prefetch(std::move(upcoming));
  }
  void setEquation(std::shared_ptr<const FieldEquation> equation) override {
    environment_.setEquation(std::move(equation));
  }
  void setSparse(std::shared_ptr<const SparseField> sparse) override {
    environment_.setSparse(std::move(sparse));
  }
  void setTerrain(std::shared_ptr<const HeightMap> terrain) override;
  void step(const SimStep& step, const ParticleState& state) override;
  void clear() override;
  void grow(std::size_t capacity) override;
  void draw() const override;
  Records records() const override;

  std::size_t capacity() const override { return capacity_; }
  std::size_t liveCount() const override;
  std::size_t lateCount() const override { return lateCount_; }
  std::vector<Particle> readBack() const override;
  double lastFieldUploadMs() const override { return environment_.lastUploadMs(); }
  const char* name() const override { return "tf-gs"; }

 private:
  struct BufferSet {
    gl::Buffer positionLife, velocityKind;
    gl::VertexArray all;        // from the start: the newborn
    gl::VertexArray survivors;  // from the first survivor, drawn through `update`'s count
    gl::TransformFeedback emit, update;
    std::uint32_t born = 0;
    bool hasSurvivors = false;
  };

  static constexpr int kHistory = 3;

  void allocate(BufferSet& set, std::size_t capacity);
  // `sourceProgram`: the update program numbering survivors' sources, or null.
  void drawSet(const BufferSet& set, const gl::Program* sourceProgram = nullptr) const;
  std::size_t countAfter(std::uint64_t update) const;

  std::size_t capacity_;
  std::array<BufferSet, 2> sets_;
  int current_ = 0;
  gl::VertexArray emptyVao_;
  gl::Buffer simBlock_;
  gl::Buffer
      survivorCounts_;  // per set: its survivors, written by the GPU from the query (records())
  gl::Framebuffer dummyTarget_;  // drawing needs a framebuffer, even with rasterizer discard
  gl::Renderbuffer dummyColor_;
  gl::Program emitProgram_;
  // The update: [field equation?  + 2 * trails?], each made on first use.
  std::array<std::unique_ptr<gl::Program>, 12> updatePrograms_;  // FieldRead, trails, obstacles
  std::unique_ptr<gl::Program> emitObstacleProgram_;             // OBSTACLES, on first use
  ExpressionPrograms expressionPrograms_;                        // field.mode = expression
  std::unique_ptr<ParticleTrails> trails_;                       // while render.trail_length > 0

  ParticleEnvironment environment_;

  EmissionBudget budget_;
  std::uint64_t updates_ = 0;
  std::array<gl::Query, kHistory> survivorQueries_;
  std::array<std::uint32_t, kHistory> bornHistory_{};
  std::array<bool, kHistory> queried_{};
  std::size_t lateCount_ = 0;  // count(u - 2), read by the last step
};

}  // namespace sandstorm
