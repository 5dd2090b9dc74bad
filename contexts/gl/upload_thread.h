// UploadThread: a second GL context of a drawing context's share group,
// current on a thread of its own, that issues uploads (copies out of host
// memory into buffers and textures the drawing context reads), so that the
// GPU can run them beside the drawing context's work. A copy the drawing
// context issues itself sits in its command stream and holds back the
// compute and draws after it; one from another context is free to run on a
// copy engine meanwhile (NVIDIA's driver does; docs/PERFORMANCE.md measures
// a series' steps copied so).
//
// submit() queues a job: GL calls run on the thread once the GPU has passed
// `after`, a fence of the submitting context (so that what that context
// wrote or allocated before it is there), then fenced and flushed. The
// future gives that fence. The submitting context makes its later commands
// wait for it (glWaitSync) before reading what the job wrote, and binds those
// objects again, as GL's rules for objects shared between contexts require.
// Jobs run in order; the destructor runs those still queued, then ends the
// thread. A job's exception reaches its future; one the thread cannot
// start (no current context) reaches every job's.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>

#include "contexts/gl/objects.h"
#include "contexts/platform/gl_context.h"

namespace sandstorm {

class UploadThread {
 public:
  // `context`: shares objects with the drawing context, current on no thread.
  explicit UploadThread(std::unique_ptr<GlContext> context);
  ~UploadThread();
  UploadThread(const UploadThread&) = delete;
  UploadThread& operator=(const UploadThread&) = delete;

  // Any thread: runs `job` on the upload thread after `after` (may be empty).
  std::future<gl::Sync> submit(gl::Sync after, std::function<void()> job);

 private:
  struct Job {
    gl::Sync after;
    std::function<void()> work;
    std::promise<gl::Sync> done;
  };
  void run();

  std::unique_ptr<GlContext> context_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Job> jobs_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace sandstorm
