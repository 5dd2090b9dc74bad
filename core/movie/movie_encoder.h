// MovieEncoder: frames (RGBA images) into a movie file through FFmpeg's own
// libraries: H.264 (libx264) in MP4, or VP9 (libvpx) in WebM, 4:2:0 with
// BT.709 colours, a key frame every second. The MP4 is fragmented at each
// key frame, and WebM is written as it goes, so a movie cut short (a full
// disk, a killed run) still plays up to its last whole second.
//
// Not thread-safe: one thread adds frames and closes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>

#include <glm/glm.hpp>

#include "core/movie/movie_spec.h"
#include "core/util/image.h"

namespace sandstorm {

class MovieEncoder {
 public:
  struct Options {
    std::filesystem::path path;
    MovieContainer container = MovieContainer::Mp4;
    glm::ivec2 size{0};  // both even
    double fps = 60.0;
    int crf = 18;
  };
  // Opens the file and the encoder. Throws Error naming --movie and the path.
  explicit MovieEncoder(const Options& options);
  // Closes the movie if close() was not called (errors are logged).
  ~MovieEncoder();
  MovieEncoder(const MovieEncoder&) = delete;
  MovieEncoder& operator=(const MovieEncoder&) = delete;

  // Encodes one frame of exactly the movie's size. Throws Error naming the
  // path and the frame (a full disk shows here); the movie is then closed
  // as far as it can be.
  void add(const Image& frame);
  // Flushes the encoder and ends the file. Throws Error naming the path.
  void close();

  std::int64_t frames() const;
  // The codec's name, e.g. "libx264".
  const char* codec() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace sandstorm
