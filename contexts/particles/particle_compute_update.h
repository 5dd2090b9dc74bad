// ParticleComputeUpdate: the particle update of ParticleGeoUpdate with compute
// shaders, record for record the same (ReferenceSimulator is the
// specification).
//
// Two sets of shader-storage buffers (position + remaining life, velocity +
// kind) take turns, as in the transform-feedback path. One update:
//   1. prepare (one invocation, shaders/particle_prepare.comp): reads the input
//      set's live count, which only the GPU knows, and writes the update's
//      indirect dispatch size, the output's provisional count (the newborn)
//      and its indirect draw command;
//   2. emit (shaders/particle_emit.comp): thread g writes newborn g at record g;
//   3. update (shaders/particle_update.comp, indirect): tiles of 256 x items input
//      records advance their particles; survivors are compacted IN ORDER after
//      the newborn by a prefix sum over the tiles (a single-pass scan with
//      decoupled look-back: tiles take their index from an atomic ticket, so a
//      tile only ever waits for tiles that are already running; one that
//      waits too long counts the slow tile's survivors itself, so no schedule
//      changes the result). The last tile writes the output's live count and
//      draw command.
// Nothing is read back in the frame loop: draw() uses glDrawArraysIndirect, and
// the EmissionBudget gets count(u-2) from a persistently mapped ring that each
// update copies its count into, behind a fence.
//
// All calls need this object's GL context current.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/particles/expression_programs.h"
#include "contexts/particles/particle_backend.h"
#include "contexts/particles/particle_environment.h"
#include "contexts/particles/particle_trails.h"
#include "contexts/particles/scan_spin.h"
#include "contexts/particles/update_control.h"
#include "core/config/gpu_tuning.h"
#include "core/sim/emission_budget.h"

namespace sandstorm {

class ParticleComputeUpdate final : public ParticleBackend {
 public:
  // `tuning`: the records an invocation of the update pass advances (a tile is
  // 256 invocations), the scan's patience, where the field's grid is kept.
  explicit ParticleComputeUpdate(std::size_t capacity, const GpuTuning& tuning = {},
                                 UploadThread* uploads = nullptr);

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
  bool setFieldBuffer(std::uint32_t buffer) override {
    const bool can = environment_.readsBuffers();
    environment_.setFieldBuffer(can ? buffer : 0);
    return can || buffer == 0;
  }
  void step(const SimStep& step, const ParticleState& state) override;
  void clear() override;
  void grow(std::size_t capacity) override;
  void draw() const override;
  Records records() const override;

  std::size_t capacity() const override { return capacity_; }
  std::size_t liveCount() const override;
  std::size_t lateCount() const override { return lateCount_; }
  std::vector<Particle> readBack() const override;
  // The trails of the records readBack() returns, newest first (tests); empty without trails.
  std::vector<std::vector<glm::vec3>> readBackTrails() const;
  double lastFieldUploadMs() const override { return environment_.lastUploadMs(); }
  const char* name() const override { return "compute"; }
  bool blendsPairPointwise(const ParticleState& state) const override {
    return environment_.blendsPair(state);
  }

 private:
  struct BufferSet {
    gl::Buffer positionLife, velocityKind;
    gl::VertexArray vao;
  };

  void allocate(BufferSet& set, std::size_t capacity);
  void allocateTiles(std::size_t capacity);
  void setCount(int set, std::uint32_t count);

  std::size_t capacity_;
  std::array<BufferSet, 2> sets_;
  int current_ = 0;
  gl::Buffer control_;     // counts, ticket, dispatch and draw commands (particle_prepare.comp)
  gl::Buffer tileStatus_;  // the scan's per-tile status words
  gl::Buffer simBlock_;
  gl::Buffer collideList_;  // with obstacles: the records the update found not clear of one
  std::ptrdiff_t collideListBytes_ = 0;
  UpdateCounts counts_;  // the counts updates left, read late
  ScanWait scanWait_;    // how the update's tiles wait for a predecessor
  gl::Program prepareProgram_, emitProgram_, updateProgram_;
  std::unique_ptr<gl::Program> narrowPrepare_;  // for a sparse grid's fewer records an invocation
  // Programs other than the plain update, by their defines (FIELD_EQUATION,
  // grids too large for a buffer, OBSTACLES), made on first use.
  std::map<std::string, std::unique_ptr<gl::Program>> variants_;
  const gl::Program& variant(
      const std::vector<std::string>& defines,
      const std::function<gl::Program(const std::vector<std::string>&)>& make);
  ExpressionPrograms expressionPrograms_;  // field.mode = expression
  int items_;                              // records an invocation

  ParticleEnvironment environment_;
  std::unique_ptr<ParticleTrails> trails_;  // while render.trail_length > 0

  EmissionBudget budget_;
  std::uint64_t updates_ = 0;
  std::size_t lateCount_ = 0;  // count(u - 2), read by the last step
};

}  // namespace sandstorm
