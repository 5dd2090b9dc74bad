#include "contexts/particles/particle_geo_update.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <numeric>

#include "contexts/gl/out_of_memory.h"
#include "contexts/particles/record_readback.h"
#include "contexts/particles/sim_block.h"
#include "core/sim/emission.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr GLsizeiptr kRecord = sizeof(glm::vec4);

gl::Program makeProgram(const char* vert, const char* geom, std::vector<std::string> defines = {}) {
  std::vector<std::string> varyings{"outPositionLife", "outVelocityKind"};
  if (std::find(defines.begin(), defines.end(), "TRAILS") != defines.end())
    varyings.push_back("outSource");  // ParticleTrails' source, a third buffer
  return gl::Program(gl::ProgramDesc{{vert, geom}, std::move(defines), std::move(varyings)});
}

void attach(GLuint vao, GLuint positionLife, GLuint velocityKind, GLintptr firstRecord) {
  glVertexArrayVertexBuffer(vao, 0, positionLife, firstRecord * kRecord, kRecord);
  glVertexArrayVertexBuffer(vao, 1, velocityKind, firstRecord * kRecord, kRecord);
}

}  // namespace

ParticleGeoUpdate::ParticleGeoUpdate(std::size_t capacity, UploadThread* uploads)
    : capacity_(capacity),
      emptyVao_(gl::createVertexArray()),
      simBlock_(gl::createBuffer()),
      survivorCounts_(gl::createBuffer()),
      dummyTarget_(gl::createFramebuffer()),
      dummyColor_(gl::createRenderbuffer()),
      emitProgram_(makeProgram("particle_emit.vert", "particle_emit.geom")),
      environment_(GpuField::Storage::Texture, uploads) {
  if (capacity == 0 || capacity > (std::size_t{1} << 31) / kRecord)
    throw Error(
        concat("ParticleGeoUpdate: capacity ", capacity, " is outside 1..", (1u << 31) / kRecord));
  for (BufferSet& set : sets_)
    allocate(set, capacity);
  glNamedBufferStorage(simBlock_.id(), sizeof(SimBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  const std::uint32_t zeros[2] = {0, 0};
  glNamedBufferStorage(survivorCounts_.id(), sizeof(zeros), zeros, GL_DYNAMIC_STORAGE_BIT);
  glNamedRenderbufferStorage(dummyColor_.id(), GL_R8, 1, 1);
  glNamedFramebufferRenderbuffer(dummyTarget_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                 dummyColor_.id());
  for (gl::Query& q : survivorQueries_)
    q = gl::createQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
}

void ParticleGeoUpdate::allocate(BufferSet& set, std::size_t capacity) {
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
  for (gl::VertexArray* vao : {&set.all, &set.survivors}) {
    *vao = gl::createVertexArray();
    for (GLuint a = 0; a < 2; ++a) {
      glEnableVertexArrayAttrib(vao->id(), a);
      glVertexArrayAttribFormat(vao->id(), a, 4, GL_FLOAT, GL_FALSE, 0);
      glVertexArrayAttribBinding(vao->id(), a, a);
    }
    attach(vao->id(), set.positionLife.id(), set.velocityKind.id(), 0);
  }
  set.emit = gl::createTransformFeedback();
  set.update = gl::createTransformFeedback();
  glTransformFeedbackBufferBase(set.emit.id(), 0, set.positionLife.id());
  glTransformFeedbackBufferBase(set.emit.id(), 1, set.velocityKind.id());
  set.born = 0;
  set.hasSurvivors = false;
}

void ParticleGeoUpdate::grow(std::size_t capacity) {
  if (capacity <= capacity_) return;
  const std::size_t count = liveCount();
  std::array<BufferSet, 2> grown;
  for (BufferSet& set : grown)
    allocate(set, capacity);
  // The live particles keep their order: all of them become the new set's "newborn" range.
  const BufferSet& from = sets_[std::size_t(current_)];
  BufferSet& to = grown[std::size_t(current_)];
  if (count > 0) {
    glCopyNamedBufferSubData(from.positionLife.id(), to.positionLife.id(), 0, 0,
                             GLsizeiptr(count) * kRecord);
    glCopyNamedBufferSubData(from.velocityKind.id(), to.velocityKind.id(), 0, 0,
                             GLsizeiptr(count) * kRecord);
  }
  to.born = std::uint32_t(count);
  sets_ = std::move(grown);
  const std::uint32_t zeros[2] = {0, 0};
  glNamedBufferSubData(survivorCounts_.id(), 0, sizeof(zeros), zeros);
  capacity_ = capacity;
  // The last update's count now lives entirely in `born`; its survivor query no longer applies.
  const std::size_t last = std::size_t((updates_ + kHistory - 1) % kHistory);
  if (updates_ > 0) {
    bornHistory_[last] = std::uint32_t(count);
    queried_[last] = false;
  }
}

void ParticleGeoUpdate::setField(std::shared_ptr<const VectorField> field,
                                 const FieldPlacement& placement,
                                 std::shared_ptr<const VectorField> next) {
  environment_.setField(std::move(field), placement, std::move(next));
}

void ParticleGeoUpdate::setTerrain(std::shared_ptr<const HeightMap> terrain) {
  environment_.setTerrain(std::move(terrain));
}

void ParticleGeoUpdate::clear() {
  for (BufferSet& set : sets_) {
    set.born = 0;
    set.hasSurvivors = false;
  }
  budget_.reset();
  updates_ = 0;
  const std::uint32_t zeros[2] = {0, 0};
  glNamedBufferSubData(survivorCounts_.id(), 0, sizeof(zeros), zeros);
  queried_.fill(false);
  bornHistory_.fill(0);
}

std::size_t ParticleGeoUpdate::countAfter(std::uint64_t update) const {
  const int slot = int(update % kHistory);
  std::size_t count = bornHistory_[std::size_t(slot)];
  if (queried_[std::size_t(slot)]) {
    GLuint survivors = 0;
    glGetQueryObjectuiv(survivorQueries_[std::size_t(slot)].id(), GL_QUERY_RESULT, &survivors);
    count += survivors;
  }
  return count;
}

void ParticleGeoUpdate::step(const SimStep& step, const ParticleState& state) {
  if (step.dt <= 0.0f) return;  // paused: nothing moves, dies or is born

  // Count(u - 2) was produced a whole update ago, so this rarely waits.
  const std::size_t count2 = updates_ >= 2 ? countAfter(updates_ - 2) : 0;
  lateCount_ = count2;
  const std::size_t limit = std::min(std::size_t(std::max(state.sim.maximum, 0)), capacity_);
  SimBlockInputs inputs;
  environment_.describe(inputs);
  inputs.state = &state;
  inputs.step = step;
  inputs.granted =
      budget_.allocate(emissionOfKind(step.emission, state, EmitterKind::Particles), limit, count2);
  inputs.granted.resize(state.emitters.size(), 0);
  const std::uint32_t born = std::accumulate(inputs.granted.begin(), inputs.granted.end(), 0u);
  SimBlock block;
  const int slots = fillSimBlock(inputs, block);
  glNamedBufferSubData(simBlock_.id(), 0, sizeof(block), &block);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, simBlock_.id());
  const FieldRead read = environment_.bind(state);
  if (state.render.trailLength > 0) {
    if (!trails_) trails_ = std::make_unique<ParticleTrails>();
    trails_->prepare(capacity_, state.render.trailLength);
  } else {
    trails_.reset();
  }
  // The update program: reading the field's texture, equation or sparse
  // grid, capturing each
  // survivor's source record for the trails or not, with the obstacles' code
  // only where there are obstacles (it costs registers even unused); made on
  // first use.
  const bool obstacles = block.obstacleCount.x > 0;
  std::unique_ptr<gl::Program>& variant =
      updatePrograms_[std::size_t(read) + (trails_ ? 3 : 0) + (obstacles ? 6 : 0)];
  std::vector<std::string> defines;
  if (trails_) defines.push_back("TRAILS");
  if (obstacles) defines.push_back("OBSTACLES");
  if (!variant) {
    std::vector<std::string> all = defines;
    if (const char* d = fieldReadDefine(read, GpuField::Storage::Texture)) all.push_back(d);
    variant = std::make_unique<gl::Program>(
        makeProgram("particle_update.vert", "particle_update.geom", all));
  }
  const gl::Program* expression = nullptr;
  if (state.field.mode == FieldMode::Expression)
    expression = expressionPrograms_.get(state, defines, [](const std::vector<std::string>& d) {
      return makeProgram("particle_update.vert", "particle_update.geom", d);
    });
  const gl::Program& updateProgram = expression ? *expression : *variant;
  if (obstacles && !emitObstacleProgram_)
    emitObstacleProgram_ = std::make_unique<gl::Program>(
        makeProgram("particle_emit.vert", "particle_emit.geom", {"OBSTACLES"}));
  const gl::Program& emitProgram = obstacles ? *emitObstacleProgram_ : emitProgram_;

  const BufferSet& in = sets_[std::size_t(current_)];
  BufferSet& out = sets_[std::size_t(1 - current_)];
  glBindFramebuffer(GL_FRAMEBUFFER, dummyTarget_.id());
  glEnable(GL_RASTERIZER_DISCARD);

  if (born > 0) {
    emitProgram.use();
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, out.emit.id());
    glBeginTransformFeedback(GL_POINTS);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_POINTS, 0, slots);
    glEndTransformFeedback();
  }
  out.born = born;
  out.hasSurvivors = false;
  const int slot = int(updates_ % kHistory);
  queried_[std::size_t(slot)] = false;
  if ((in.born > 0 || in.hasSurvivors) && born < capacity_) {
    const GLintptr offset = GLintptr(born) * kRecord, size = GLsizeiptr(capacity_ - born) * kRecord;
    glTransformFeedbackBufferRange(out.update.id(), 0, out.positionLife.id(), offset, size);
    glTransformFeedbackBufferRange(out.update.id(), 1, out.velocityKind.id(), offset, size);
    if (trails_)
      glTransformFeedbackBufferRange(out.update.id(), 2, trails_->source(), GLintptr(born) * 4,
                                     GLsizeiptr(capacity_ - born) * 4);
    updateProgram.use();
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, out.update.id());
    glBeginQueryIndexed(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, 0,
                        survivorQueries_[std::size_t(slot)].id());
    glBeginTransformFeedback(GL_POINTS);
    drawSet(in, trails_ ? variant.get() : nullptr);
    glEndTransformFeedback();
    glEndQueryIndexed(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, 0);
    attach(out.survivors.id(), out.positionLife.id(), out.velocityKind.id(), GLintptr(born));
    out.hasSurvivors = true;
    queried_[std::size_t(slot)] = true;
    // The GPU copies the count into survivorCounts_ when the query ends: no wait here.
    glGetQueryBufferObjectuiv(survivorQueries_[std::size_t(slot)].id(), survivorCounts_.id(),
                              GL_QUERY_RESULT, GLintptr(1 - current_) * 4);
  } else {
    const std::uint32_t zero = 0;
    glNamedBufferSubData(survivorCounts_.id(), GLintptr(1 - current_) * 4, 4, &zero);
  }
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
  glDisable(GL_RASTERIZER_DISCARD);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  if (trails_) {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_QUERY_BUFFER_BARRIER_BIT);
    trails_->advance(out.positionLife.id(), born, survivorCounts_.id(), 1 - current_, born);
  }
  bornHistory_[std::size_t(slot)] = born;
  budget_.recordEmitted(born);
  current_ = 1 - current_;
  ++updates_;
}

void ParticleGeoUpdate::drawSet(const BufferSet& set, const gl::Program* sourceProgram) const {
  // With trails, the update program numbers its survivors' sources by draw.
  const int base = sourceProgram ? sourceProgram->uniform("uSourceBase") : -1;
  if (set.born > 0) {
    if (base >= 0) glProgramUniform1ui(sourceProgram->id(), base, 0u);
    glBindVertexArray(set.all.id());
    glDrawArrays(GL_POINTS, 0, GLsizei(set.born));
  }
  if (set.hasSurvivors) {
    if (base >= 0) glProgramUniform1ui(sourceProgram->id(), base, set.born);
    glBindVertexArray(set.survivors.id());
    glDrawTransformFeedback(GL_POINTS, set.update.id());
  }
  glBindVertexArray(0);
}

void ParticleGeoUpdate::draw() const {
  drawSet(sets_[std::size_t(current_)]);
}

ParticleBackend::Records ParticleGeoUpdate::records() const {
  const BufferSet& set = sets_[std::size_t(current_)];
  return {set.positionLife.id(),
          set.velocityKind.id(),
          survivorCounts_.id(),
          std::uint32_t(current_ * 4),
          set.born,
          -1,
          trails_ ? trails_->ring() : 0u,
          trails_ ? trails_->length() : 0,
          trails_ ? trails_->head() : 0};
}

std::size_t ParticleGeoUpdate::liveCount() const {
  if (updates_ == 0) return 0;
  return countAfter(updates_ - 1);
}

std::vector<Particle> ParticleGeoUpdate::readBack() const {
  const std::size_t count = liveCount();
  const BufferSet& set = sets_[std::size_t(current_)];
  const std::vector<glm::vec4> pos = readRecords(set.positionLife.id(), count);
  const std::vector<glm::vec4> vel = readRecords(set.velocityKind.id(), count);
  std::vector<Particle> particles(count);
  for (std::size_t i = 0; i < count; ++i)
    particles[i] = Particle{pos[i], vel[i]};
  return particles;
}

}  // namespace sandstorm
