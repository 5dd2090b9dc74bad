#include "core/util/image_files.h"

#include <algorithm>
#include <exception>
#include <utility>

namespace sandstorm {

ImageFiles::ImageFiles(unsigned threads) : queueLimit_(2 * std::max(1u, threads)) {
  for (unsigned i = 0; i < std::max(1u, threads); ++i)
    threads_.emplace_back([this] { work(); });
}

ImageFiles::~ImageFiles() {
  finish();
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  for (std::thread& t : threads_)
    t.join();
}

void ImageFiles::write(Image image, std::filesystem::path path) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return queue_.size() < queueLimit_; });
  queue_.push_back({std::move(image), std::move(path)});
  changed_.notify_all();
}

std::vector<std::string> ImageFiles::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return queue_.empty() && busy_ == 0; });
  return std::exchange(failures_, {});
}

void ImageFiles::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return closing_ || !queue_.empty(); });
    if (queue_.empty()) return;  // closing, nothing left
    Job job = std::move(queue_.front());
    queue_.pop_front();
    ++busy_;
    changed_.notify_all();  // a writer waiting for room
    lock.unlock();
    std::string failure;
    try {
      writePng(job.image, job.path);
    } catch (const std::exception& e) {
      failure = e.what();
    }
    lock.lock();
    if (!failure.empty()) failures_.push_back(std::move(failure));
    --busy_;
    changed_.notify_all();  // finish() waits for the last
  }
}

}  // namespace sandstorm
