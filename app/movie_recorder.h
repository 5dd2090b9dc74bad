// MovieRecorder: the run's movie (--movie). Before the run it settles which
// walls the movie shows and opens the file, so a bad path, extension or
// size stops the start; during the run each chosen wall hands over its
// picture every frame (from its drawing thread, before the menu is drawn
// unless --movie-menu), and once every chosen wall's picture of a frame is in,
// a thread of its own lays them out (MovieLayout) and encodes the frame. The
// walls wait for it only when it falls three frames behind. A failure to
// write (a full disk) is logged with the frame, closes the movie as written
// so far (it plays) and makes the run's exit code 1; the run goes on.
#pragma once

#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "core/config/app_config.h"
#include "core/movie/movie_compositor.h"
#include "core/movie/movie_encoder.h"
#include "core/movie/movie_spec.h"
#include "core/util/progress_meter.h"

namespace sandstorm {

class MovieRecorder {
 public:
  // With --movie-size: keeps only the walls the movie shows, drawn
  // offscreen at their place's size in the movie frame, each stereo wall
  // as the movie's eyes need it (its left eye alone, or side by side).
  // Throws Error naming an unknown --movie-wall.
  static void prepareWalls(AppConfig& config, const MovieSpec& spec);

  // `walls`: this run's walls. Opens the file. Throws Error.
  MovieRecorder(const MovieSpec& spec, const std::vector<WallSpec>& walls, const RunSpec& run);
  ~MovieRecorder();
  MovieRecorder(const MovieRecorder&) = delete;
  MovieRecorder& operator=(const MovieRecorder&) = delete;

  // Whether wall `index` (of the walls given) is in the movie.
  bool shows(std::size_t index) const;
  // A wall's eye images of a frame (WallRenderer::captureEyes); any thread.
  void add(std::size_t index, std::uint32_t frame, std::vector<Image> eyes);
  // Encodes what is queued and closes the file. Returns false when the movie
  // failed (said in the log).
  bool finish();

 private:
  void encodeLoop();

  MovieSpec spec_;
  std::vector<int> slots_;  // per wall of the run: its place in the layout, or -1
  std::size_t shown_ = 0;
  std::unique_ptr<MovieCompositor> compositor_;
  std::unique_ptr<MovieEncoder> encoder_;
  std::unique_ptr<ProgressMeter> progress_;
  double fps_ = 60.0;

  std::mutex mutex_;
  std::condition_variable changed_;
  struct Pending {
    std::vector<std::vector<Image>> eyes;
    std::size_t in = 0;
  };
  std::map<std::uint32_t, Pending> pending_;  // frames still missing a wall
  std::deque<std::pair<std::uint32_t, std::vector<std::vector<Image>>>> ready_;
  bool closing_ = false;
  bool failed_ = false;
  std::thread thread_;
};

}  // namespace sandstorm
