// ImageFiles: PNGs written on threads of their own, so that the thread that
// read an image back (a wall's) does not wait for the encoder: a 3840x1080
// image takes stb's PNG encoder 1.3-2 s, which held each wall of a CAVE run
// that long at its closing images (and at every --screenshot-every image).
//
// write() queues an image; it waits only while more images than the threads
// can take are queued (so a fast producer holds a bounded number in memory).
// finish() waits for every queued image and returns what failed, one line
// each naming the file; the destructor finishes too.
#pragma once

#include <condition_variable>
#include <deque>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/util/image.h"

namespace sandstorm {

class ImageFiles {
 public:
  explicit ImageFiles(unsigned threads);
  ~ImageFiles();
  ImageFiles(const ImageFiles&) = delete;
  ImageFiles& operator=(const ImageFiles&) = delete;

  void write(Image image, std::filesystem::path path);
  std::vector<std::string> finish();

 private:
  struct Job {
    Image image;
    std::filesystem::path path;
  };
  void work();

  std::size_t queueLimit_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> queue_;
  std::size_t busy_ = 0;
  bool closing_ = false;
  std::vector<std::string> failures_;
  std::vector<std::thread> threads_;
};

}  // namespace sandstorm
