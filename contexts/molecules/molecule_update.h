// MoleculeUpdate: one context's molecules on the GPU, record for record
// MoleculeReference's (core/molecules/molecule_reference.h is the
// specification). Molecules are kept as their members' records, member by
// member (member j of molecule i at record j * capacity + i, so neighbouring
// invocations touch neighbouring records), in two sets of buffers that take
// turns, like ParticleComputeUpdate's. One update:
//   1. prepare (particle_prepare.comp, MOLECULES): sizes the update from the
//      input's live molecule count, which only the GPU knows;
//   2. emit (molecule_emit.comp): invocation g writes newborn molecule g;
//   3. with repulsion, the grid of the input molecules' centres
//      (MoleculeGridGpu);
//   4. update (molecule_update.comp, indirect): each invocation steps one
//      molecule with its members in registers; the survivors are compacted in
//      order after the newborn by the particle update's look-back scan.
// It always runs compute shaders, whichever particle backend the wall has.
// The field is uploaded again for it (its own ParticleEnvironment), only
// while there are molecule emitters. Nothing is read back in the frame loop:
// the draw is instanced and indirect, and the budget reads count(u-2) from a
// persistently mapped ring. A change of molecules.complexity starts afresh.
//
// All calls need this object's GL context current.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/molecules/molecule_grid_gpu.h"
#include "contexts/molecules/molecule_handles.h"
#include "contexts/particles/expression_programs.h"
#include "contexts/particles/particle_environment.h"
#include "contexts/particles/scan_spin.h"
#include "contexts/particles/update_control.h"
#include "core/config/gpu_tuning.h"
#include "core/sim/emission_budget.h"
#include "core/sim/particle.h"
#include "core/sim/particle_state.h"
#include "core/sim/sim_step.h"

namespace sandstorm {

class MoleculeUpdate {
 public:
  // Capacities count molecules; raising molecules.maximum grows the buffers
  // up to `capacityLimit`.
  MoleculeUpdate(std::size_t capacity, std::size_t capacityLimit, const GpuTuning& tuning = {});

  void setField(std::shared_ptr<const VectorField> field, const FieldPlacement& placement,
                std::shared_ptr<const VectorField> next = nullptr) {
    environment_.setField(std::move(field), placement, std::move(next));
  }
  void setEquation(std::shared_ptr<const FieldEquation> equation) {
    environment_.setEquation(std::move(equation));
  }
  void setSparse(std::shared_ptr<const SparseField> sparse) {
    environment_.setSparse(std::move(sparse));
  }
  void setTerrain(std::shared_ptr<const HeightMap> terrain) {
    environment_.setTerrain(std::move(terrain));
  }
  // As ParticleBackend::setFieldBuffer.
  bool setFieldBuffer(std::uint32_t buffer) {
    const bool can = environment_.readsBuffers();
    environment_.setFieldBuffer(can ? buffer : 0);
    return can || buffer == 0;
  }
  // Whether a state emits molecules (a ParticleSystem then makes its MoleculeUpdate).
  static bool wanted(const ParticleState& state);

  void step(const SimStep& step, const ParticleState& state);
  void clear();

  // The current members' records, for drawing without reading anything back
  // (none before the first update).
  MoleculeHandles handles() const;

  std::size_t capacity() const { return capacity_; }
  int complexity() const { return complexity_; }
  std::size_t lateCount() const { return lateCount_; }  // molecules, a frame or two old
  // These wait for the GPU; for tests and dumps, not the frame loop.
  std::size_t liveCount() const;
  std::vector<Particle> readBack() const;  // the members' records, molecule after molecule

 private:
  struct BufferSet {
    gl::Buffer positionLife, velocityKind;
  };

  void allocate(std::size_t capacity, int members, bool keep);
  const gl::Program& updateProgram(const ParticleState& state, FieldRead read, bool obstacles,
                                   bool repulsion);
  const gl::Program& variant(const std::string& file, const std::vector<std::string>& defines);

  std::size_t capacity_ = 0, capacityLimit_;
  int complexity_ = 0;  // the members the buffers hold a molecule (0: none yet)
  std::array<BufferSet, 2> sets_;
  int current_ = 0;
  gl::Buffer control_, tileStatus_, simBlock_, moleculeBlock_;
  UpdateCounts counts_;  // the counts updates left, read late
  std::map<std::string, std::unique_ptr<gl::Program>> variants_;
  ExpressionPrograms expressionPrograms_;
  ScanWait scanWait_;  // how the update's tiles wait for a predecessor
  ParticleEnvironment environment_;
  std::unique_ptr<MoleculeGridGpu> grid_;  // while repulsion is on
  EmissionBudget budget_;
  std::uint64_t updates_ = 0;
  std::size_t lateCount_ = 0;
};

}  // namespace sandstorm
