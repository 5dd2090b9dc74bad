#include "contexts/gl/upload_thread.h"

#include <epoxy/gl.h>

#include <exception>

namespace sandstorm {

UploadThread::UploadThread(std::unique_ptr<GlContext> context) : context_(std::move(context)) {
  thread_ = std::thread([this] { run(); });
}

UploadThread::~UploadThread() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

std::future<gl::Sync> UploadThread::submit(gl::Sync after, std::function<void()> job) {
  Job j{std::move(after), std::move(job), {}};
  std::future<gl::Sync> done = j.done.get_future();
  {
    std::lock_guard lock(mutex_);
    jobs_.push_back(std::move(j));
  }
  wake_.notify_one();
  return done;
}

void UploadThread::run() {
  std::exception_ptr broken;  // why no job can run here
  try {
    context_->makeCurrent();
  } catch (...) {
    broken = std::current_exception();
  }
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stop_ || !jobs_.empty(); });
      if (jobs_.empty()) break;  // stopping, every job done
      job = std::move(jobs_.front());
      jobs_.pop_front();
    }
    if (broken) {
      job.done.set_exception(broken);
      // A sync object is deleted on a context of its share group: without one
      // here, the drawing context's fence is left to its context's end.
      job.after.release();
      continue;
    }
    try {
      if (job.after) {
        glWaitSync(reinterpret_cast<GLsync>(job.after.handle()), 0, GL_TIMEOUT_IGNORED);
        job.after.reset();
      }
      job.work();
      gl::Sync fence = gl::createFence();
      glFlush();  // so that the fence, and the job, reach the GPU now
      job.done.set_value(std::move(fence));
    } catch (...) {
      job.done.set_exception(std::current_exception());
    }
  }
  if (!broken) context_->releaseCurrent();
}

}  // namespace sandstorm
