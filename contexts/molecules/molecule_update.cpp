#include "contexts/molecules/molecule_update.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <numeric>

#include "contexts/gl/out_of_memory.h"
#include "contexts/molecules/molecule_block.h"
#include "contexts/particles/record_readback.h"
#include "contexts/particles/scan_spin.h"
#include "contexts/particles/sim_block.h"
#include "core/sim/capacity.h"
#include "core/sim/emission.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

using namespace update_control;

enum Binding : GLuint {
  kInPosition = 0,
  kInVelocity,
  kOutPosition,
  kOutVelocity,
  kControl,
  kTileStatus
};

constexpr GLuint kSimBlock = 0, kMoleculeBlock = 5;

// The shape as the update program's constants (shaders/molecule_physics.glsl).
std::vector<std::string> shapeConstants(int complexity) {
  const MoleculeShape& shape = moleculeShape(complexity);
  std::string a, b;
  for (std::size_t k = 0; k < shape.springs.size(); ++k) {
    a += concat(k ? "," : "", shape.springs[k].a);
    b += concat(k ? "," : "", shape.springs[k].b);
  }
  return {concat("MEMBERS ", shape.members), concat("SPRING_COUNT ", shape.springs.size()),
          "SPRINGS_A " + a, "SPRINGS_B " + b, concat("SOLID ", shape.faces.empty() ? 0 : 1)};
}

}  // namespace

MoleculeUpdate::MoleculeUpdate(std::size_t capacity, std::size_t capacityLimit,
                               const GpuTuning& tuning)
    : capacityLimit_(std::max(capacity, capacityLimit)),
      control_(gl::createBuffer()),
      simBlock_(gl::createBuffer()),
      moleculeBlock_(gl::createBuffer()),
      counts_("MoleculeUpdate"),
      scanWait_(scanWait(tuning)),
      environment_(tuning.fieldStorage == GpuTuning::FieldStorage::Texture
                       ? GpuField::Storage::Texture
                       : GpuField::Storage::Buffer) {
  capacity_ = std::max<std::size_t>(capacity, 1);
  const std::uint32_t zeros[kControlSize / 4] = {};
  glNamedBufferStorage(control_.id(), kControlSize, zeros, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(simBlock_.id(), sizeof(SimBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(moleculeBlock_.id(), sizeof(MoleculeBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void MoleculeUpdate::allocate(std::size_t capacity, int members, bool keep) {
  const std::size_t records = capacity * std::size_t(members);
  if (records > (std::size_t{1} << 31) / kRecord)
    throw Error(concat(capacity, " molecules of ", members,
                       " particles exceed a buffer's 2 GiB; lower molecules.maximum"));
  const std::size_t count = keep ? liveCount() : 0;
  std::array<BufferSet, 2> grown;
  const gl::OutOfMemoryCheck memory;
  for (BufferSet& set : grown) {
    set.positionLife = gl::createBuffer();
    set.velocityKind = gl::createBuffer();
    glNamedBufferStorage(set.positionLife.id(), GLsizeiptr(records) * kRecord, nullptr, 0);
    glNamedBufferStorage(set.velocityKind.id(), GLsizeiptr(records) * kRecord, nullptr, 0);
  }
  if (memory.failed())
    throw Error(concat("the GPU has no memory for ", capacity, " molecules of ", members,
                       " particles; lower molecules.maximum"));
  if (count > 0) {
    // Member by member: member j's slice starts at j * capacity.
    const BufferSet& from = sets_[std::size_t(current_)];
    BufferSet& to = grown[std::size_t(current_)];
    const GLsizeiptr bytes = GLsizeiptr(count) * kRecord;
    for (int j = 0; j < complexity_; ++j) {
      const GLintptr src = GLintptr(std::size_t(j) * capacity_) * kRecord;
      const GLintptr dst = GLintptr(std::size_t(j) * capacity) * kRecord;
      glCopyNamedBufferSubData(from.positionLife.id(), to.positionLife.id(), src, dst, bytes);
      glCopyNamedBufferSubData(from.velocityKind.id(), to.velocityKind.id(), src, dst, bytes);
    }
  }
  sets_ = std::move(grown);
  tileStatus_ = gl::createBuffer();
  glNamedBufferStorage(tileStatus_.id(), GLsizeiptr(((capacity + 255) / 256 + 1) * 4), nullptr, 0);
  capacity_ = capacity;
}

bool MoleculeUpdate::wanted(const ParticleState& state) {
  for (const Emitter& e : state.emitters)
    if (e.kind == EmitterKind::Molecules) return true;
  return false;
}

void MoleculeUpdate::clear() {
  const std::uint32_t zeros[kControlSize / 4] = {};
  glNamedBufferSubData(control_.id(), 0, kControlSize, zeros);
  budget_.reset();
  updates_ = 0;
  lateCount_ = 0;
}

std::size_t MoleculeUpdate::liveCount() const {
  return updates_ == 0 ? 0 : counts_.after(updates_ - 1);
}

const gl::Program& MoleculeUpdate::variant(const std::string& file,
                                           const std::vector<std::string>& defines) {
  std::string key = file;
  for (const std::string& d : defines)
    key += ";" + d;
  std::unique_ptr<gl::Program>& p = variants_[key];
  if (!p) p = std::make_unique<gl::Program>(std::vector<std::string>{file}, defines);
  return *p;
}

const gl::Program& MoleculeUpdate::updateProgram(const ParticleState& state, FieldRead read,
                                                 bool obstacles, bool repulsion) {
  std::vector<std::string> defines = shapeConstants(state.molecules.complexity);
  if (const char* d = fieldReadDefine(read, environment_.gridStorage())) defines.push_back(d);
  if (obstacles) defines.push_back("OBSTACLES");
  if (repulsion) defines.push_back("REPULSION");
  if (const char* d = scanWait_.define()) defines.push_back(d);
  if (state.field.mode == FieldMode::Expression) {
    const auto make = [](const std::vector<std::string>& d) {
      return gl::Program(gl::ProgramDesc{{"molecule_update.comp"}, d, {}});
    };
    if (const gl::Program* p = expressionPrograms_.get(state, defines, make)) return *p;
  }
  return variant("molecule_update.comp", defines);
}

void MoleculeUpdate::step(const SimStep& step, const ParticleState& state) {
  const MoleculeSettings& ms = state.molecules;
  // A new shape starts afresh; more molecules grow the buffers, keeping them.
  if (complexity_ != ms.complexity) {
    const std::size_t capacity = grownCapacity(capacity_, ms.maximum, capacityLimit_);
    allocate(capacity, ms.complexity, false);
    complexity_ = ms.complexity;
    clear();
  } else if (const std::size_t grown = grownCapacity(capacity_, ms.maximum, capacityLimit_);
             grown > capacity_) {
    allocate(grown, complexity_, true);
  }
  if (step.dt <= 0.0f) return;

  const std::size_t count2 = updates_ >= 2 ? counts_.after(updates_ - 2) : 0;
  lateCount_ = count2;
  const std::size_t limit = std::min(std::size_t(std::max(ms.maximum, 0)), capacity_);
  SimBlockInputs inputs;
  environment_.describe(inputs);
  inputs.state = &state;
  inputs.step = step;
  inputs.granted =
      budget_.allocate(emissionOfKind(step.emission, state, EmitterKind::Molecules), limit, count2);
  inputs.granted.resize(state.emitters.size(), 0);
  const std::uint32_t born = std::accumulate(inputs.granted.begin(), inputs.granted.end(), 0u);
  SimBlock block;
  fillSimBlock(inputs, block);
  glNamedBufferSubData(simBlock_.id(), 0, sizeof(block), &block);
  const bool repulsion = ms.repulsion && ms.repulsionStrength > 0.0f;
  const MoleculeBlock mb = makeMoleculeBlock(
      ms, step.dt, capacity_, repulsion ? MoleculeGridGpu::tableMask(capacity_) : 0u);
  glNamedBufferSubData(moleculeBlock_.id(), 0, sizeof(mb), &mb);
  glBindBufferBase(GL_UNIFORM_BUFFER, kSimBlock, simBlock_.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, kMoleculeBlock, moleculeBlock_.id());
  const FieldRead read = environment_.bind(state);
  const bool obstacles = block.obstacleCount.x > 0;
  const gl::Program& update = updateProgram(state, read, obstacles, repulsion);
  const GLuint vertices = GLuint(mb.drawing.z);

  const BufferSet& in = sets_[std::size_t(current_)];
  const BufferSet& out = sets_[std::size_t(1 - current_)];
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kControl, control_.id());
  if (repulsion) {
    if (!grid_) grid_ = std::make_unique<MoleculeGridGpu>();
    grid_->build(capacity_, in.positionLife.id(), current_, control_.id(),
                 std::uint32_t(kCountOffset + current_ * 4));
  } else {
    grid_.reset();
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInPosition, in.positionLife.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInVelocity, in.velocityKind.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kOutPosition, out.positionLife.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kOutVelocity, out.velocityKind.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kControl, control_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileStatus, tileStatus_.id());
  const GLuint zero = 0;
  glClearNamedBufferData(tileStatus_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);

  const gl::Program& prepare = variant("particle_prepare.comp", {"ITEMS 1", "MOLECULES"});
  prepare.use();
  glProgramUniform1i(prepare.id(), 0, current_);
  glProgramUniform1ui(prepare.id(), 1, born);
  glProgramUniform1ui(prepare.id(), 2, vertices);
  glDispatchCompute(1, 1, 1);

  if (born > 0) {
    const gl::Program& emit = obstacles ? variant("molecule_emit.comp", {"OBSTACLES"})
                                        : variant("molecule_emit.comp", {});
    emit.use();
    glProgramUniform1ui(emit.id(), 1, born);
    glDispatchCompute((born + 255) / 256, 1, 1);
  }

  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  update.use();
  glProgramUniform1i(update.id(), 0, current_);
  glProgramUniform1ui(update.id(), 1, born);
  glProgramUniform1ui(update.id(), 2, std::uint32_t(capacity_));
  if (!scanWait_.waits) glProgramUniform1ui(update.id(), 3, scanWait_.spins);
  glProgramUniform1ui(update.id(), 5, vertices);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, control_.id());
  glDispatchComputeIndirect(kDispatchOffset);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);

  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT |
                  GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  counts_.record(updates_, control_.id(), kCountOffset + (1 - current_) * 4);

  budget_.recordEmitted(born);
  current_ = 1 - current_;
  ++updates_;
}

MoleculeHandles MoleculeUpdate::handles() const {
  if (updates_ == 0) return {};
  const BufferSet& set = sets_[std::size_t(current_)];
  return {set.positionLife.id(),
          set.velocityKind.id(),
          control_.id(),
          moleculeBlock_.id(),
          std::uint32_t(kCountOffset + current_ * 4),
          std::uint32_t(kDrawOffset + current_ * 16),
          complexity_,
          std::uint32_t(capacity_),
          lateCount_};
}

std::vector<Particle> MoleculeUpdate::readBack() const {
  const std::size_t count = liveCount(), n = std::size_t(std::max(complexity_, 0));
  if (count == 0 || n == 0) return {};
  const BufferSet& set = sets_[std::size_t(current_)];
  // The buffers member by member (the last member's slice only up to the count).
  const std::size_t span = (n - 1) * capacity_ + count;
  const std::vector<glm::vec4> pos = readRecords(set.positionLife.id(), span);
  const std::vector<glm::vec4> vel = readRecords(set.velocityKind.id(), span);
  std::vector<Particle> out(count * n);
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = 0; j < n; ++j)
      out[i * n + j] = Particle{pos[j * capacity_ + i], vel[j * capacity_ + i]};
  return out;
}

}  // namespace sandstorm
