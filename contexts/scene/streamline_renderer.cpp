#include "contexts/scene/streamline_renderer.h"

#include <epoxy/gl.h>

#include "core/flow/cash_karp.h"

namespace sandstorm {
namespace {

// Grows `buffer` to hold at least `bytes` (contents are not kept).
void reserve(gl::Buffer& buffer, std::size_t& capacity, std::size_t bytes) {
  if (bytes <= capacity && buffer.id() != 0) return;
  buffer = gl::createBuffer();
  capacity = std::max<std::size_t>(bytes, 16);
  glNamedBufferStorage(buffer.id(), GLsizeiptr(capacity), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

}  // namespace

bool StreamlineRenderer::Key::operator==(const Key& o) const {
  const StreamlineSettings &a = rake, &b = o.rake;
  return field == o.field && next == o.next && blend == o.blend &&
         placement.offset == o.placement.offset && placement.scale == o.placement.scale &&
         placement.rotation == o.placement.rotation && a.shape == b.shape && a.from == b.from &&
         a.to == b.to && a.across == b.across && a.seeds == b.seeds && a.step == b.step &&
         a.length == b.length && a.integrator == b.integrator && a.tolerance == b.tolerance &&
         strength == o.strength && obstacles == o.obstacles;
}

StreamlineRenderer::StreamlineRenderer(SceneField& field)
    : trace_({"streamline_trace.comp"}, {"OBSTACLES"}),
      ribbons_(std::vector<std::string>{"streamline.vert", "streamline.geom", "streamline.frag"}),
      lines_(std::vector<std::string>{"streamline.vert", "streamline.frag"}, {"LINES"}),
      emptyVao_(gl::createVertexArray()),
      field_(field) {}

void StreamlineRenderer::update(const ParticleState& state,
                                std::shared_ptr<const FieldUpdate> field, float blend) {
  enabled_ = state.streamlines.enabled && field && field->field;
  width_ = state.streamlines.width;
  if (!enabled_) return;
  const Key key{field->field.get(), field->next.get(), field->next ? blend : 0.0f,
                field->placement,   state.streamlines, state.sim.fieldStrength,
                field_.obstacles()};
  if (traced_ && *traced_ == key) return;
  trace(state);
  traced_ = key;
}

void StreamlineRenderer::trace(const ParticleState& state) {
  const std::vector<glm::vec3> seeds = rakeSeeds(state.streamlines);
  steps_ = streamlineSteps(state.streamlines);
  lineCount_ = steps_ > 0 ? 2 * int(seeds.size()) : 0;
  if (lineCount_ == 0) return;
  std::vector<glm::vec4> seedData;
  for (const glm::vec3& s : seeds)
    seedData.emplace_back(s, 1.0f);
  reserve(seeds_, seedCapacity_, seedData.size() * sizeof(glm::vec4));
  glNamedBufferSubData(seeds_.id(), 0, GLsizeiptr(seedData.size() * sizeof(glm::vec4)),
                       seedData.data());
  reserve(points_, pointCapacity_,
          std::size_t(lineCount_) * std::size_t(steps_ + 1) * 2 * sizeof(glm::vec4));
  reserve(counts_, countCapacity_, std::size_t(lineCount_) * sizeof(std::uint32_t));

  const SceneField::Binding binding(field_, state);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, seeds_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, points_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, counts_.id());
  const gl::Program& trace = trace_.get(field_);
  trace.use();
  glProgramUniform1ui(trace.id(), 0, GLuint(lineCount_));
  glProgramUniform1i(trace.id(), 1, steps_);
  glProgramUniform1f(trace.id(), 2, state.streamlines.step);
  glProgramUniform1i(trace.id(), 3, int(state.streamlines.integrator));
  glProgramUniform1f(trace.id(), 4, state.streamlines.tolerance);
  glProgramUniform1f(trace.id(), 5, state.streamlines.length);
  glProgramUniform1fv(trace.id(), 6, GLsizei(kCashKarp.size()), kCashKarp.data());
  glDispatchCompute(GLuint((lineCount_ + 63) / 64), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void StreamlineRenderer::draw() const {
  if (!visible()) return;
  const gl::Program& program = width_ > 0.0f ? ribbons_ : lines_;
  program.use();
  glProgramUniform1i(program.id(), 0, steps_);
  if (width_ > 0.0f) glProgramUniform1f(program.id(), 1, width_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, points_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, counts_.id());
  glBindVertexArray(emptyVao_.id());
  glDisable(GL_CULL_FACE);
  glDrawArrays(GL_LINES, 0, GLsizei(lineCount_) * GLsizei(steps_) * 2);
  glBindVertexArray(0);
}

std::vector<Streamline> StreamlineRenderer::readBack() const {
  std::vector<Streamline> out;
  if (!enabled_ || lineCount_ == 0) return out;
  std::vector<std::uint32_t> counts(static_cast<std::size_t>(lineCount_));
  glGetNamedBufferSubData(counts_.id(), 0, GLsizeiptr(counts.size() * sizeof(std::uint32_t)),
                          counts.data());
  const std::size_t perLine = std::size_t(steps_ + 1) * 2;
  std::vector<glm::vec4> points(std::size_t(lineCount_) * perLine);
  glGetNamedBufferSubData(points_.id(), 0, GLsizeiptr(points.size() * sizeof(glm::vec4)),
                          points.data());
  auto point = [&](int line, std::uint32_t k) {
    const std::size_t at = std::size_t(line) * perLine + 2 * std::size_t(k);
    return StreamlinePoint{glm::vec3(points[at]), glm::vec3(points[at + 1])};
  };
  for (int seed = 0; 2 * seed < lineCount_; ++seed) {
    const std::uint32_t back = counts[std::size_t(2 * seed)],
                        ahead = counts[std::size_t(2 * seed + 1)];
    if (back == 0) continue;  // the seed lies outside the field
    Streamline line;
    for (std::uint32_t k = back; k-- > 1;)
      line.points.push_back(point(2 * seed, k));
    line.seedIndex = int(line.points.size());
    for (std::uint32_t k = 0; k < ahead; ++k)
      line.points.push_back(point(2 * seed + 1, k));
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace sandstorm
