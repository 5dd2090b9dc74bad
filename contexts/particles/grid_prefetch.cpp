#include "contexts/particles/grid_prefetch.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <limits>

#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

GridPrefetch::~GridPrefetch() {
  if (writing_.valid()) writing_.wait();  // the worker writes into staging_'s mapping
  dropUpload();
}

void GridPrefetch::advance(std::shared_ptr<const VectorField> wanted) {
  if (failed_) return;
  try {
    if (writing_.valid() && writing_.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
      written();
    if (uploading()) collectUpload(false);
    if (frame_ && !writing_.valid() && !uploads_ && copiedLayers_ < layers_)
      copy(copyBytesPerFrame_);
    // Another frame wanted: the worker and the upload are not stopped midway,
    // and the staging buffer is rewritten only once the GPU has copied out of it.
    if (wanted && wanted != frame_ && !writing_.valid() && !uploading()) start(std::move(wanted));
  } catch (const std::exception& e) {
    fail(e.what());
  }
}

bool GridPrefetch::takeInto(GpuField& target, const std::shared_ptr<const VectorField>& field) {
  if (failed_ || !field || field != frame_) return false;
  const auto start = std::chrono::steady_clock::now();
  const bool wasWriting = writing_.valid();
  const int left = layers_ - copiedLayers_;
  const bool byThread = uploads_ && left > 0;
  try {
    if (writing_.valid()) written();
    if (uploading())
      collectUpload(true);
    else
      copy(std::numeric_limits<std::size_t>::max());
  } catch (const std::exception& e) {
    fail(e.what());
    return false;
  }
  if (layers_ > 0)
    log::debug(
        "field: a step uploaded ahead of need taken; its texels written in ", writeMs_, " ms",
        wasWriting ? " (still being written: waited for)" : "", ", ", left, " of ", layers_,
        byThread ? " layers being copied by the upload thread (waited for on the GPU)"
                 : " layers left to copy",
        "; took ",
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(),
        " ms");
  std::swap(target, grid_);
  // What target held is whole on the GPU: given back if it is wanted again
  // (playback turned round).
  frame_ = grid_.holds();
  layers_ = copiedLayers_ = 0;
  return true;
}

void GridPrefetch::start(std::shared_ptr<const VectorField> field) {
  // Checked before anything is allocated: a vec4 a point at most (8 bytes in half).
  const double most = double(field->pointCount()) * (field->halfPrecision() ? 8.0 : 16.0);
  if (most > double(maxStagingBytes_))
    throw Error(concat("a step of ", field->pointCount(), " points would stage up to ", most,
                       " bytes of host memory on each GPU, beyond the ", maxStagingBytes_,
                       " it may"));
  // Two staging buffers where both fit within the limit, else one.
  const bool two = 2.0 * most <= double(maxStagingBytes_);
  if (!two) staging_[1] = Staging{};
  // Rewritten only once the GPU has copied out of it: until then, wait.
  const int slot = freeStaging(two);
  if (slot < 0) return;
  frame_ = nullptr;
  layers_ = copiedLayers_ = 0;
  layerBytes_ = grid_.prepare(*field);  // GL: on this thread, before the worker starts
  const std::size_t bytes = layerBytes_ * std::size_t(field->dims().z);
  Staging& staging = staging_[std::size_t(slot)];
  if (bytes != staging.bytes) {
    staging = Staging{};  // deleting a buffer unmaps it
    staging.buffer = gl::createBuffer();
    glGetError();
    // In host memory (CLIENT_STORAGE), mapped for good: the worker writes
    // there, and the GPU copies from it (FLUSH_EXPLICIT: written() says when).
    glNamedBufferStorage(staging.buffer.id(), GLsizeiptr(bytes), nullptr,
                         GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_CLIENT_STORAGE_BIT);
    if (glGetError() == GL_NO_ERROR)
      staging.mapped = glMapNamedBufferRange(
          staging.buffer.id(), 0, GLsizeiptr(bytes),
          GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_FLUSH_EXPLICIT_BIT);
    if (!staging.mapped) {
      staging = Staging{};
      throw Error(concat("no memory to stage a frame of ", bytes, " bytes"));
    }
    staging.bytes = bytes;
  }
  using_ = slot;
  frame_ = field;
  layers_ = field->dims().z;
  // The worker only reads the frame and grid_'s layout, and writes the
  // mapping; takeInto() and the destructor wait for it before either changes.
  writing_ = std::async(std::launch::async, [this, out = staging.mapped, field = std::move(field)] {
    const auto begin = std::chrono::steady_clock::now();
    grid_.writeLayers(*field, 0, layers_, out, kWriterThreads);
    writeMs_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
  });
}

void GridPrefetch::written() {
  writing_.get();  // rethrows what the worker threw
  const Staging& staging = staging_[std::size_t(using_)];
  glFlushMappedNamedBufferRange(staging.buffer.id(), 0, GLsizeiptr(staging.bytes));
  if (!uploads_) return;
  // The whole frame at once, after what this context did before (the
  // grid's allocation, the flush). The thread reads only grid_'s layout and
  // the staging buffer's name, which stay until the upload is collected.
  gl::Sync after = gl::createFence();
  glFlush();
  upload_ = uploads_->submit(std::move(after), [this, buffer = &staging.buffer] {
    grid_.copyLayers(*buffer, 0, 0, layers_);
  });
}

void GridPrefetch::collectUpload(bool wait) {
  Staging& staging = staging_[std::size_t(using_)];
  if (upload_.valid()) {
    if (!wait && upload_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    staging.copied = upload_.get();  // the copy's fence; rethrows what the copy threw
  }
  const GLsync copied = reinterpret_cast<GLsync>(staging.copied.handle());
  if (wait) {
    // This context's commands from now on wait for the copy on the GPU.
    glWaitSync(copied, 0, GL_TIMEOUT_IGNORED);
  } else {
    const GLenum state = glClientWaitSync(copied, 0, 0);
    if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) return;
  }
  // Done (or waited for): the grid's readers bind it again each frame, which
  // makes what another context wrote visible in this one.
  copiedLayers_ = layers_;
  grid_.hold(frame_);
}

void GridPrefetch::dropUpload() {
  if (!upload_.valid()) return;
  try {
    upload_.get();  // its fence is deleted here, on this context
  } catch (const std::exception&) {
  }
}

void GridPrefetch::copy(std::size_t bytes) {
  if (copiedLayers_ >= layers_) return;
  const int layers =
      int(std::clamp<std::size_t>(bytes / layerBytes_, 1, std::size_t(layers_ - copiedLayers_)));
  Staging& staging = staging_[std::size_t(using_)];
  grid_.copyLayers(staging.buffer, std::size_t(copiedLayers_) * layerBytes_, copiedLayers_, layers);
  copiedLayers_ += layers;
  staging.copied = gl::createFence();
  glFlush();  // so that the fence signals without waiting for the frame's end
  if (copiedLayers_ == layers_) grid_.hold(frame_);
}

int GridPrefetch::freeStaging(bool two) const {
  const auto free = [this](int slot) {
    const Staging& s = staging_[std::size_t(slot)];
    if (!s.copied) return true;
    const GLenum state = glClientWaitSync(reinterpret_cast<GLsync>(s.copied.handle()), 0, 0);
    return state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED;
  };
  if (!two) return free(0) ? 0 : -1;
  // The other one first: the last one may still be being copied out of.
  const int other = 1 - using_;
  if (free(other)) return other;
  return free(using_) ? using_ : -1;
}

void GridPrefetch::fail(const std::string& what) {
  log::warn("field: uploading the next step ahead of need stopped (", what,
            "); each step is uploaded when it comes into use, as with field.upload_ahead = false");
  if (writing_.valid()) writing_.wait();
  dropUpload();
  failed_ = true;
  frame_ = nullptr;
  grid_.hold(nullptr);
  layers_ = copiedLayers_ = 0;
  staging_ = {};
}

}  // namespace sandstorm
