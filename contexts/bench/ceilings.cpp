#include "contexts/bench/ceilings.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <vector>

#include "contexts/bench/gpu_stopwatch.h"
#include "contexts/gl/out_of_memory.h"
#include "contexts/particles/particle_compute_update.h"
#include "core/util/error.h"

namespace sandstorm::bench {
namespace {

constexpr GLsizeiptr kRecord = 16;

gl::Buffer recordBuffer(std::size_t records, float fill) {
  gl::Buffer b = gl::createBuffer();
  const gl::OutOfMemoryCheck memory;
  glNamedBufferStorage(b.id(), GLsizeiptr(records) * kRecord, nullptr, 0);
  if (memory.failed()) throw Error(concat("ceilings: no GPU memory for ", records, " records"));
  const float value[4] = {fill, fill, fill, 1.0f};
  glClearNamedBufferData(b.id(), GL_RGBA32F, GL_RGBA, GL_FLOAT, value);
  return b;
}

gl::VertexArray twoStreams(GLuint a, GLuint b) {
  gl::VertexArray vao = gl::createVertexArray();
  for (GLuint i = 0; i < 2; ++i) {
    glEnableVertexArrayAttrib(vao.id(), i);
    glVertexArrayAttribFormat(vao.id(), i, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao.id(), i, i);
  }
  glVertexArrayVertexBuffer(vao.id(), 0, a, 0, kRecord);
  glVertexArrayVertexBuffer(vao.id(), 1, b, 0, kRecord);
  return vao;
}

}  // namespace

double copyBandwidth(std::size_t bytes, int repeats) {
  gl::Buffer from = gl::createBuffer(), to = gl::createBuffer();
  glNamedBufferStorage(from.id(), GLsizeiptr(bytes), nullptr, 0);
  glNamedBufferStorage(to.id(), GLsizeiptr(bytes), nullptr, 0);
  const float one = 1.0f;
  glClearNamedBufferData(from.id(), GL_R32F, GL_RED, GL_FLOAT, &one);
  glCopyNamedBufferSubData(from.id(), to.id(), 0, 0, GLsizeiptr(bytes));  // warm up
  GpuStopwatch watch;
  for (int r = 0; r < repeats; ++r) {
    watch.begin();
    glCopyNamedBufferSubData(from.id(), to.id(), 0, 0, GLsizeiptr(bytes));
    watch.end();
  }
  const double ms = median(watch.intervalsMs());
  return ms > 0.0 ? 2.0 * double(bytes) / (ms * 1e-3) : 0.0;
}

double shaderCopyBandwidth(std::size_t bytes, int repeats) {
  const std::size_t records = bytes / 16;
  gl::Buffer from = recordBuffer(records, 1.0f), to = recordBuffer(records, 0.0f);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, from.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, to.id());
  double best = 0.0;
  for (int items : {1, 2, 4, 8, 16}) {
    gl::Program copy(gl::ProgramDesc{{"bench_copy.comp"}, {concat("ITEMS ", items)}, {}});
    copy.use();
    glProgramUniform1ui(copy.id(), 0, GLuint(records));
    const std::size_t groups = (records + 256 * items - 1) / (256 * items);
    const GLuint x = GLuint(std::min<std::size_t>(groups, 32768)),
                 y = GLuint((groups + 32767) / 32768);
    GpuStopwatch watch;
    for (int r = -1; r < repeats; ++r) {
      if (r >= 0) watch.begin();
      glDispatchCompute(x, y, 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      if (r >= 0) watch.end();
    }
    const double ms = median(watch.intervalsMs());
    if (ms > 0.0) best = std::max(best, 2.0 * double(records * 16) / (ms * 1e-3));
  }
  return best;
}

BareComputeUpdate::BareComputeUpdate(std::size_t records, int items)
    : records_(records),
      items_(items),
      in_{recordBuffer(records, 0.5f), recordBuffer(records, 0.25f)},
      out_{recordBuffer(records, 0.0f), recordBuffer(records, 0.0f)},
      control_(gl::createBuffer()),
      tiles_(gl::createBuffer()),
      simBlock_(gl::createBuffer()),
      program_(
          gl::ProgramDesc{{"particle_update.comp"}, {"BARE_UPDATE", concat("ITEMS ", items)}, {}}) {
  glNamedBufferStorage(control_.id(), 64, nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(tiles_.id(), GLsizeiptr((records / 256 + 2) * 4), nullptr, 0);
  glNamedBufferStorage(simBlock_.id(), 4096, nullptr, 0);
}

double BareComputeUpdate::passMs(int repeats) {
  const std::uint32_t tile = 256u * std::uint32_t(items_);
  const std::uint32_t tiles = std::uint32_t((records_ + tile - 1) / tile);
  const std::uint32_t control[16] = {std::uint32_t(records_), 0, 0,
                                     tiles};  // count[0], count[1], ticket, tiles
  program_.use();
  glProgramUniform1i(program_.id(), 0, 0);
  glProgramUniform1ui(program_.id(), 1, 0);
  glProgramUniform1ui(program_.id(), 2, GLuint(records_));
  glProgramUniform1ui(program_.id(), 3, 1u << 20);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, simBlock_.id());
  for (GLuint b = 0; b < 2; ++b) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, in_[b].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2 + b, out_[b].id());
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, control_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, tiles_.id());
  const GLuint zero = 0;
  GpuStopwatch watch;
  for (int r = -1; r < repeats; ++r) {
    glNamedBufferSubData(control_.id(), 0, sizeof(control), control);
    glClearNamedBufferData(tiles_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    if (r >= 0) watch.begin();
    glDispatchCompute(std::min(tiles, 32768u), (tiles + 32767) / 32768, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    if (r >= 0) watch.end();
  }
  return median(watch.intervalsMs());
}

BareTransformFeedback::BareTransformFeedback(std::size_t records)
    : records_(records),
      in_{recordBuffer(records, 0.5f), recordBuffer(records, 0.25f)},
      out_{recordBuffer(records, 0.0f), recordBuffer(records, 0.0f)},
      feedback_(gl::createTransformFeedback()),
      target_(gl::createFramebuffer()),
      color_(gl::createRenderbuffer()),
      program_(
          gl::ProgramDesc{{"bench_passthrough.vert"}, {}, {"outPositionLife", "outVelocityKind"}}) {
  vao_ = twoStreams(in_[0].id(), in_[1].id());
  glTransformFeedbackBufferBase(feedback_.id(), 0, out_[0].id());
  glTransformFeedbackBufferBase(feedback_.id(), 1, out_[1].id());
  glNamedRenderbufferStorage(color_.id(), GL_R8, 1, 1);
  glNamedFramebufferRenderbuffer(target_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.id());
}

double BareTransformFeedback::passMs(int repeats) {
  glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
  glEnable(GL_RASTERIZER_DISCARD);
  program_.use();
  glBindVertexArray(vao_.id());
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, feedback_.id());
  GpuStopwatch watch;
  for (int r = -1; r < repeats; ++r) {  // one untimed warm-up pass
    if (r >= 0) watch.begin();
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, GLsizei(records_));
    glEndTransformFeedback();
    if (r >= 0) watch.end();
  }
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
  glBindVertexArray(0);
  glDisable(GL_RASTERIZER_DISCARD);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return median(watch.intervalsMs());
}

BarePointDraw::BarePointDraw(std::size_t points, glm::ivec2 size)
    : points_(points),
      size_(size),
      records_{recordBuffer(points, 0.0f), recordBuffer(points, 0.5f)},
      color_(gl::createTexture(GL_TEXTURE_2D)),
      target_(gl::createFramebuffer()),
      fill_(std::vector<std::string>{"bench_scatter.comp"}),
      draw_(std::vector<std::string>{"bench_points.vert", "bench_points.frag"}) {
  vao_ = twoStreams(records_[0].id(), records_[1].id());
  glTextureStorage2D(color_.id(), 1, GL_RGBA16F, size.x, size.y);
  glNamedFramebufferTexture(target_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
  // Points spread over the whole image (clip space), so no pixel is a hot spot.
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, records_[0].id());
  fill_.use();
  glProgramUniform1ui(fill_.id(), 0, std::uint32_t(points));
  const std::size_t groups = (points + 255) / 256;
  glDispatchCompute(GLuint(std::min<std::size_t>(groups, 65535)), GLuint((groups + 65534) / 65535),
                    1);
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
}

double BarePointDraw::drawMs(int repeats) {
  glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
  glViewport(0, 0, size_.x, size_.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  draw_.use();
  glBindVertexArray(vao_.id());
  GpuStopwatch watch;
  for (int r = -1; r < repeats; ++r) {
    if (r >= 0) watch.begin();
    glDrawArrays(GL_POINTS, 0, GLsizei(points_));
    if (r >= 0) watch.end();
  }
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return median(watch.intervalsMs());
}

}  // namespace sandstorm::bench
