#include "contexts/particles/particle_compute_update.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <string>

#include "contexts/gl/out_of_memory.h"
#include "contexts/particles/record_readback.h"
#include "contexts/particles/scan_spin.h"
#include "contexts/particles/sim_block.h"
#include "contexts/particles/update_control.h"
#include "core/sim/emission.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

using namespace update_control;

// Binding points of the shaders' storage blocks.
enum Binding : GLuint {
  kInPosition = 0,
  kInVelocity,
  kOutPosition,
  kOutVelocity,
  kControl,
  kTileStatus,
  kCollideList = 8
};

std::vector<std::string> withScanWait(std::vector<std::string> defines, const ScanWait& wait) {
  if (const char* d = wait.define()) defines.push_back(d);
  return defines;
}

std::string itemsDefine(int items) {
  return concat("ITEMS ", items);
}

// A sparse grid's update advances at most this many records an invocation:
// NanoVDB's walk takes registers, and on an H100 two records ran the update
// 10% faster than four, eight 45% slower (docs/PERFORMANCE.md).
constexpr int kSparseItems = 2;

int checkedItems(int items) {
  if (items != 1 && items != 2 && items != 4 && items != 8)
    throw Error(
        concat("ParticleComputeUpdate: ", items, " records an invocation; expected 1, 2, 4 or 8"));
  return items;
}

}  // namespace

ParticleComputeUpdate::ParticleComputeUpdate(std::size_t capacity, const GpuTuning& tuning,
                                             UploadThread* uploads)
    : capacity_(capacity),
      control_(gl::createBuffer()),
      simBlock_(gl::createBuffer()),
      counts_("ParticleComputeUpdate"),
      scanWait_(scanWait(tuning)),
      prepareProgram_(std::vector<std::string>{"particle_prepare.comp"},
                      {itemsDefine(checkedItems(tuning.updateItems))}),
      emitProgram_(std::vector<std::string>{"particle_emit.comp"}),
      // The field's grid is a storage buffer (environment_).
      updateProgram_(std::vector<std::string>{"particle_update.comp"},
                     withScanWait({itemsDefine(tuning.updateItems), "FIELD_BUFFER"}, scanWait_)),
      items_(tuning.updateItems),
      environment_(tuning.fieldStorage == GpuTuning::FieldStorage::Texture
                       ? GpuField::Storage::Texture
                       : GpuField::Storage::Buffer,
                   uploads) {
  if (capacity == 0 || capacity > (std::size_t{1} << 31) / kRecord)
    throw Error(concat("a particle capacity of ", capacity, " is outside 1..", (1u << 31) / kRecord,
                       " (a buffer's 2 GiB); lower sim.maximum"));
  for (BufferSet& set : sets_)
    allocate(set, capacity);
  allocateTiles(capacity);
  const std::uint32_t zeros[kControlSize / 4] = {};
  glNamedBufferStorage(control_.id(), kControlSize, zeros, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(simBlock_.id(), sizeof(SimBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void ParticleComputeUpdate::allocate(BufferSet& set, std::size_t capacity) {
  set.positionLife = gl::createBuffer();
  set.velocityKind = gl::createBuffer();
  const gl::OutOfMemoryCheck memory;
  glNamedBufferStorage(set.positionLife.id(), GLsizeiptr(capacity) * kRecord, nullptr, 0);
  glNamedBufferStorage(set.velocityKind.id(), GLsizeiptr(capacity) * kRecord, nullptr, 0);
  if (memory.failed())
    throw Error(concat("the GPU has no memory for ", capacity, " particles (",
                       2 * capacity * kRecord >> 20,
                       " MiB for each of the update's two copies); lower sim.maximum or "
                       "run.capacity_limit"));
  set.vao = gl::createVertexArray();
  for (GLuint a = 0; a < 2; ++a) {
    glEnableVertexArrayAttrib(set.vao.id(), a);
    glVertexArrayAttribFormat(set.vao.id(), a, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(set.vao.id(), a, a);
  }
  glVertexArrayVertexBuffer(set.vao.id(), 0, set.positionLife.id(), 0, kRecord);
  glVertexArrayVertexBuffer(set.vao.id(), 1, set.velocityKind.id(), 0, kRecord);
}

void ParticleComputeUpdate::allocateTiles(std::size_t capacity) {
  tileStatus_ = gl::createBuffer();
  // Enough for the smallest tile any variant takes (a sparse grid's).
  const std::size_t tile = 256u * std::size_t(std::min(items_, kSparseItems));
  const std::size_t tiles = (capacity + tile - 1) / tile + 1;
  glNamedBufferStorage(tileStatus_.id(), GLsizeiptr(tiles * sizeof(std::uint32_t)), nullptr, 0);
}

void ParticleComputeUpdate::setCount(int set, std::uint32_t count) {
  const std::uint32_t draw[4] = {count, 1, 0, 0};
  glNamedBufferSubData(control_.id(), kCountOffset + set * 4, 4, &count);
  glNamedBufferSubData(control_.id(), kDrawOffset + set * 16, 16, draw);
}

void ParticleComputeUpdate::grow(std::size_t capacity) {
  if (capacity <= capacity_) return;
  const std::size_t count = liveCount();
  std::array<BufferSet, 2> grown;
  for (BufferSet& set : grown)
    allocate(set, capacity);
  // The live particles keep their place and order; the counts stay as they are.
  const BufferSet& from = sets_[std::size_t(current_)];
  BufferSet& to = grown[std::size_t(current_)];
  if (count > 0) {
    glCopyNamedBufferSubData(from.positionLife.id(), to.positionLife.id(), 0, 0,
                             GLsizeiptr(count) * kRecord);
    glCopyNamedBufferSubData(from.velocityKind.id(), to.velocityKind.id(), 0, 0,
                             GLsizeiptr(count) * kRecord);
  }
  sets_ = std::move(grown);
  allocateTiles(capacity);
  capacity_ = capacity;
}

void ParticleComputeUpdate::setField(std::shared_ptr<const VectorField> field,
                                     const FieldPlacement& placement,
                                     std::shared_ptr<const VectorField> next) {
  environment_.setField(std::move(field), placement, std::move(next));
}

void ParticleComputeUpdate::setTerrain(std::shared_ptr<const HeightMap> terrain) {
  environment_.setTerrain(std::move(terrain));
}

void ParticleComputeUpdate::clear() {
  setCount(0, 0);
  setCount(1, 0);
  budget_.reset();
  updates_ = 0;
}

void ParticleComputeUpdate::step(const SimStep& step, const ParticleState& state) {
  if (step.dt <= 0.0f) return;  // paused: nothing moves, dies or is born

  // Count(u - 2) was produced a whole update ago, so this rarely waits.
  const std::size_t count2 = updates_ >= 2 ? counts_.after(updates_ - 2) : 0;
  lateCount_ = count2;
  const std::size_t limit = std::min(std::size_t(std::max(state.sim.maximum, 0)), capacity_);
  // A time-varying field's pair blended into one grid first (FieldPairBlend).
  environment_.blendPair(state, step.fieldBlend);
  SimBlockInputs inputs;
  environment_.describe(inputs);
  inputs.state = &state;
  inputs.step = step;
  inputs.granted =
      budget_.allocate(emissionOfKind(step.emission, state, EmitterKind::Particles), limit, count2);
  inputs.granted.resize(state.emitters.size(), 0);
  const std::uint32_t born = std::accumulate(inputs.granted.begin(), inputs.granted.end(), 0u);
  SimBlock block;
  fillSimBlock(inputs, block);
  glNamedBufferSubData(simBlock_.id(), 0, sizeof(block), &block);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, simBlock_.id());
  const FieldRead read = environment_.bind(state);
  const char* readDefine = fieldReadDefine(read, environment_.gridStorage());
  // The plain program reads the grid's buffer of vec4.
  const bool plain =
      read == FieldRead::Grid && environment_.gridStorage() == GpuField::Storage::Buffer;
  const bool obstacles = block.obstacleCount.x > 0;
  bool flow = false;  // some obstacle turns the flow
  for (int i = 0; i < block.obstacleCount.x; ++i)
    flow = flow || block.obstacles[i].shapeFlow.y != 0;
  // The update's variant: how it reads the field, and the obstacles' code
  // only where there are obstacles (it costs registers even unused).
  const int items = read == FieldRead::Sparse ? std::min(items_, kSparseItems) : items_;
  std::vector<std::string> defines{itemsDefine(items)};
  if (readDefine) defines.push_back(readDefine);
  // Every word of a sparse grid below 2 GiB is in the first buffer: its
  // reads, two dozen a sample, skip the choice of buffer.
  if (read == FieldRead::Sparse && environment_.sparseInOneBuffer())
    defines.push_back("FIELD_SPARSE_ONE_BUFFER");
  // The flow around the obstacles is the update's; putting particles out of
  // them is a pass of its own (obstacle_collide.comp), below, over the
  // records the update lists as not clear of an obstacle.
  if (flow) defines.push_back("OBSTACLE_FLOW");
  if (obstacles) defines.push_back("OBSTACLE_LIST");
  defines = withScanWait(std::move(defines), scanWait_);
  const auto make = [](const std::vector<std::string>& d) {
    return gl::Program(gl::ProgramDesc{{"particle_update.comp"}, d, {}});
  };
  const gl::Program* expression = nullptr;
  if (state.field.mode == FieldMode::Expression)
    expression = expressionPrograms_.get(state, defines, make);
  const gl::Program& update = expression            ? *expression
                              : plain && !obstacles ? updateProgram_
                                                    : variant(defines, make);

  if (state.render.trailLength > 0) {
    if (!trails_) trails_ = std::make_unique<ParticleTrails>();
    trails_->prepare(capacity_, state.render.trailLength);
  } else {
    trails_.reset();
  }
  const BufferSet& in = sets_[std::size_t(current_)];
  const BufferSet& out = sets_[std::size_t(1 - current_)];
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInPosition, in.positionLife.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInVelocity, in.velocityKind.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kOutPosition, out.positionLife.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kOutVelocity, out.velocityKind.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kControl, control_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileStatus, tileStatus_.id());
  const GLuint zero = 0;
  glClearNamedBufferData(tileStatus_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  if (obstacles) {
    const GLsizeiptr listBytes = GLsizeiptr((capacity_ + 1) * sizeof(std::uint32_t));
    if (collideListBytes_ < listBytes) {
      collideList_ = gl::createBuffer();
      glNamedBufferStorage(collideList_.id(), listBytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
      collideListBytes_ = listBytes;
    }
    glClearNamedBufferSubData(collideList_.id(), GL_R32UI, 0, sizeof(std::uint32_t), GL_RED_INTEGER,
                              GL_UNSIGNED_INT, &zero);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCollideList, collideList_.id());
  }

  // The update's dispatch is sized for its records an invocation.
  if (items != items_ && !narrowPrepare_)
    narrowPrepare_ =
        std::make_unique<gl::Program>(std::vector<std::string>{"particle_prepare.comp"},
                                      std::vector<std::string>{itemsDefine(items)});
  const gl::Program& prepare = items != items_ ? *narrowPrepare_ : prepareProgram_;
  prepare.use();
  glProgramUniform1i(prepare.id(), 0, current_);
  glProgramUniform1ui(prepare.id(), 1, born);
  glDispatchCompute(1, 1, 1);

  if (born > 0) {
    const gl::Program& emit =
        obstacles ? variant({"OBSTACLES"},
                            [](const std::vector<std::string>& d) {
                              return gl::Program(gl::ProgramDesc{{"particle_emit.comp"}, d, {}});
                            })
                  : emitProgram_;
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
  glProgramUniform1i(update.id(), 4, trails_ ? 1 : 0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, control_.id());
  glDispatchComputeIndirect(kDispatchOffset);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);

  if (obstacles) {
    // The last step of advance(): out of the obstacles, over the output set.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    const gl::Program& collide = variant({"COLLIDE"}, [](const std::vector<std::string>&) {
      return gl::Program(std::vector<std::string>{"obstacle_collide.comp"});
    });
    collide.use();
    // A few records at a time are inside an obstacle: a small grid strides the list.
    const std::size_t groups = std::min<std::size_t>((capacity_ + 255) / 256, 256);
    glDispatchCompute(GLuint(std::max<std::size_t>(groups, 1)), 1, 1);
  }

  // Drawing, the next update and the count's copy all read what this wrote.
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT |
                  GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  if (trails_)
    trails_->advance(out.positionLife.id(), born, control_.id(),
                     int(kCountOffset / 4) + 1 - current_);
  counts_.record(updates_, control_.id(), kCountOffset + (1 - current_) * 4);

  budget_.recordEmitted(born);
  current_ = 1 - current_;
  ++updates_;
}

void ParticleComputeUpdate::draw() const {
  glBindVertexArray(sets_[std::size_t(current_)].vao.id());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, control_.id());
  glDrawArraysIndirect(GL_POINTS, reinterpret_cast<const void*>(kDrawOffset + current_ * 16));
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
}

ParticleBackend::Records ParticleComputeUpdate::records() const {
  const BufferSet& set = sets_[std::size_t(current_)];
  return {set.positionLife.id(),
          set.velocityKind.id(),
          control_.id(),
          std::uint32_t(kCountOffset + current_ * 4),
          0,
          std::int64_t(kDrawOffset + current_ * 16),
          trails_ ? trails_->ring() : 0u,
          trails_ ? trails_->length() : 0,
          trails_ ? trails_->head() : 0};
}

std::vector<std::vector<glm::vec3>> ParticleComputeUpdate::readBackTrails() const {
  return trails_ ? trails_->readBack(liveCount()) : std::vector<std::vector<glm::vec3>>{};
}

std::size_t ParticleComputeUpdate::liveCount() const {
  // From the mapped history, never from the control block (record_readback.h says why).
  return updates_ == 0 ? 0 : counts_.after(updates_ - 1);
}

std::vector<Particle> ParticleComputeUpdate::readBack() const {
  const std::size_t count = liveCount();
  const BufferSet& set = sets_[std::size_t(current_)];
  const std::vector<glm::vec4> pos = readRecords(set.positionLife.id(), count);
  const std::vector<glm::vec4> vel = readRecords(set.velocityKind.id(), count);
  std::vector<Particle> particles(count);
  for (std::size_t i = 0; i < count; ++i)
    particles[i] = Particle{pos[i], vel[i]};
  return particles;
}

const gl::Program& ParticleComputeUpdate::variant(
    const std::vector<std::string>& defines,
    const std::function<gl::Program(const std::vector<std::string>&)>& make) {
  std::string key;
  for (const std::string& d : defines)
    key += d + ";";
  std::unique_ptr<gl::Program>& p = variants_[key];
  if (!p) p = std::make_unique<gl::Program>(make(defines));
  return *p;
}

}  // namespace sandstorm
