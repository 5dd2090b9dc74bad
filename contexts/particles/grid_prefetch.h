// GridPrefetch: a time-varying field's coming frame uploaded ahead of need
// (FramePacket::upcomingField), so that the frame a new step comes into use
// pays a swap of grids, not an upload of hundreds of megabytes.
//
// A worker thread writes the frame's texels into a staging buffer that stays
// mapped (no GL call on it); once it is done, the frame is copied into a
// GpuField of this one's own: by an UploadThread where the walls' context
// has one, all at once and beside the walls' work on the GPU; otherwise by
// the walls' thread, at most kCopyBytesPerFrame a frame. ParticleEnvironment
// takes that grid when the frame becomes current or next. There are two
// staging buffers, used in turn: the frame after starts being written the
// moment one is taken, while the GPU still copies out of the other (a
// series' step every other frame leaves the worker two frames, not one).
// Memory beyond the two frames being blended: two frames' texels of host
// staging (one for a frame beyond half of maxStagingBytes) and one grid on
// the GPU.
//
// A hint only: a frame wanted before it is all on the GPU is finished on the
// spot (takeInto()), so what the particles see never depends on the timing.
#pragma once

#include <array>
#include <cstddef>
#include <future>
#include <memory>
#include <string>

#include "contexts/gl/objects.h"
#include "contexts/gl/upload_thread.h"
#include "contexts/particles/gpu_field.h"
#include "core/field/vector_field.h"

namespace sandstorm {

class GridPrefetch {
 public:
  // `uploads`: copies the frames (it must outlive this); null: advance()
  // copies at most `copyBytesPerFrame` (a layer at least) on this thread;
  // `maxStagingBytes`: the largest frame it stages (a larger one ends
  // prefetching, said once: its staging would pin that much host memory on
  // every GPU, beside the steps the series holds; two staging buffers only
  // where both fit within it).
  explicit GridPrefetch(GpuField::Storage preferred, UploadThread* uploads = nullptr,
                        std::size_t copyBytesPerFrame = kCopyBytesPerFrame,
                        std::size_t maxStagingBytes = kMaxStagingBytes)
      : grid_(preferred),
        uploads_(uploads),
        copyBytesPerFrame_(copyBytesPerFrame),
        maxStagingBytes_(maxStagingBytes) {}
  ~GridPrefetch();
  GridPrefetch(const GridPrefetch&) = delete;
  GridPrefetch& operator=(const GridPrefetch&) = delete;

  // Once a frame, with the frame wanted next (null: none): moves the copy on,
  // and starts on `wanted` once the staging buffer is free. Errors (no
  // memory for the staging or the grid) are logged once and end prefetching:
  // frames are then uploaded when they come into use, as without it.
  void advance(std::shared_ptr<const VectorField> wanted);
  // When `field` is the frame this prepares: finishes it now (waits for the
  // worker, copies what is left), swaps its grid with `target` (which then
  // holds `field`; this keeps what it got back, and takes it back if it is
  // wanted again) and returns true. False, changing nothing, otherwise.
  bool takeInto(GpuField& target, const std::shared_ptr<const VectorField>& field);

  // The frame whose every layer is on the GPU, ready to take; null while none is.
  const std::shared_ptr<const VectorField>& ready() const { return grid_.holds(); }

  // Threads the worker writes over: a few, so that the walls' thread and
  // the series' readers keep their cores.
  static constexpr unsigned kWriterThreads = 4;
  // Bytes copied to the GPU in one frame at most, by default (a 256^3 frame
  // of vec4 is 268 MB).
  static constexpr std::size_t kCopyBytesPerFrame = std::size_t{96} << 20;
  // The largest frame staged, by default: a 512^3 frame as a texture (1.6 GB).
  static constexpr std::size_t kMaxStagingBytes = std::size_t{2} << 30;

 private:
  void start(std::shared_ptr<const VectorField> field);
  // Copies up to `bytes` of the written layers (all with SIZE_MAX).
  void copy(std::size_t bytes);
  // Makes the written texels visible to the GPU's copies; with an upload
  // thread, hands it the copy.
  void written();
  // Whether the upload thread's copy of frame_ is under way.
  bool uploading() const {
    return uploads_ && frame_ && !writing_.valid() && copiedLayers_ < layers_;
  }
  // The upload thread's copy: once the GPU has done it, or (`wait`) now,
  // this context's later commands waiting for it on the GPU; grid_ then
  // holds the frame. The staging buffer is busy until the copy's fence.
  void collectUpload(bool wait);
  // Waits for the upload thread's copy, if one is under way, and lets it go.
  void dropUpload();
  // A staging buffer the GPU no longer copies out of (of two, the one not
  // used last first; of one, the first); -1: none.
  int freeStaging(bool two) const;
  void fail(const std::string& what);

  // Host memory the GPU copies from, mapped for good.
  struct Staging {
    gl::Buffer buffer;
    void* mapped = nullptr;
    std::size_t bytes = 0;
    gl::Sync copied;  // the last copy out of it
  };

  GpuField grid_;
  UploadThread* uploads_;
  std::size_t copyBytesPerFrame_, maxStagingBytes_;
  std::array<Staging, 2> staging_;
  int using_ = 0;                             // the staging frame_ is written to and copied from
  std::shared_ptr<const VectorField> frame_;  // being prepared or held by grid_
  std::future<void> writing_;
  std::future<gl::Sync> upload_;  // the upload thread's copy of frame_, until collected
  std::size_t layerBytes_ = 0;
  int layers_ = 0, copiedLayers_ = 0;
  double writeMs_ = 0.0;  // the worker's last writing (read once it is done)
  bool failed_ = false;
};

}  // namespace sandstorm
