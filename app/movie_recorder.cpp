#include "app/movie_recorder.h"

#include <algorithm>
#include <filesystem>

#include "core/cave/wall_views.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

constexpr std::size_t kQueuedFrames = 3;  // the walls wait when the encoder is this far behind

// The walls the movie shows, by index: the named one, all, or the first.
std::vector<std::size_t> chosenWalls(const std::vector<WallSpec>& walls, const MovieSpec& spec) {
  if (walls.empty()) throw Error("--movie: this run has no walls to record");
  if (spec.wall.empty()) return {0};
  std::vector<std::size_t> chosen;
  for (std::size_t i = 0; i < walls.size(); ++i)
    if (spec.wall == "all" || walls[i].name == spec.wall) chosen.push_back(i);
  if (chosen.empty()) {
    std::string known;
    for (const WallSpec& w : walls)
      known += (known.empty() ? "" : ", ") + w.name;
    throw Error(
        concat("--movie-wall: no wall named '", spec.wall, "'; expected all or one of ", known));
  }
  return chosen;
}

MovieWallShape shapeOf(const WallSpec& wall) {
  const glm::ivec2 image = wall.window ? wall.window->size : wall.offscreenSize;
  MovieWallShape shape;
  if (!wall.camera) shape.corners = wall.corners;
  shape.eyeImage = glm::ivec2(eyeImageSize(wall.stereo, glm::vec2(image)));
  shape.aspect = float(image.x) / float(std::max(image.y, 1));
  return shape;
}

// The wall the cross unfolds from: the one named "front", else the first.
std::size_t rootOf(const std::vector<WallSpec>& walls, const std::vector<std::size_t>& chosen) {
  for (std::size_t k = 0; k < chosen.size(); ++k)
    if (walls[chosen[k]].name == "front") return k;
  return 0;
}

std::vector<MovieWallShape> shapesOf(const std::vector<WallSpec>& walls,
                                     const std::vector<std::size_t>& chosen) {
  std::vector<MovieWallShape> shapes;
  for (std::size_t i : chosen)
    shapes.push_back(shapeOf(walls[i]));
  return shapes;
}

}  // namespace

void MovieRecorder::prepareWalls(AppConfig& config, const MovieSpec& spec) {
  const std::vector<std::size_t> chosen = chosenWalls(config.walls, spec);
  if (!spec.size) return;
  const MovieLayout layout = layoutMovie(shapesOf(config.walls, chosen), spec.size, spec.stereo,
                                         rootOf(config.walls, chosen));
  std::vector<WallSpec> walls;
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    WallSpec w = config.walls[chosen[k]];
    const glm::ivec2 pixels = layout.walls[k].pixels();
    w.window.reset();
    w.offscreenSize = pixels;
    if (isStereo(w.stereo)) {
      w.stereo = spec.stereo == MovieStereo::Left ? StereoMode::LeftEye : StereoMode::SideBySide;
      if (spec.stereo == MovieStereo::SideBySide) w.offscreenSize.x *= 2;
    }
    walls.push_back(std::move(w));
  }
  config.walls = std::move(walls);
  config.menu.operatorWindow.reset();
}

MovieRecorder::MovieRecorder(const MovieSpec& spec, const std::vector<WallSpec>& walls,
                             const RunSpec& run)
    : spec_(spec) {
  const std::vector<std::size_t> chosen = chosenWalls(walls, spec);
  slots_.assign(walls.size(), -1);
  for (std::size_t k = 0; k < chosen.size(); ++k)
    slots_[chosen[k]] = int(k);
  shown_ = chosen.size();
  compositor_ = std::make_unique<MovieCompositor>(
      layoutMovie(shapesOf(walls, chosen), spec.size, spec.stereo, rootOf(walls, chosen)));
  if (spec.fps) {
    fps_ = *spec.fps;
  } else if (run.fixedDt > 0.0f) {
    fps_ = 1.0 / double(run.fixedDt);
  } else {
    log::info(
        "--movie: run.fixed_dt is 0 (the real clock), so the movie plays at 60 frames/s; "
        "set --movie-fps or run.fixed_dt for another rate");
  }
  const glm::ivec2 size = compositor_->layout().frame;
  const int crf = spec.crf.value_or(defaultCrf(spec.container));
  encoder_ = std::make_unique<MovieEncoder>(MovieEncoder::Options{
      .path = spec.path, .container = spec.container, .size = size, .fps = fps_, .crf = crf});
  std::string names;
  for (std::size_t i : chosen)
    names += (names.empty() ? "" : ", ") + walls[i].name;
  for (std::size_t i : chosen)
    if (spec.stereo == MovieStereo::SideBySide && !isStereo(walls[i].stereo) &&
        walls[i].stereo != StereoMode::LeftEye && walls[i].stereo != StereoMode::RightEye)
      log::info("--movie-stereo side-by-side: wall '", walls[i].name,
                "' draws one picture; both halves show it");
  log::info("movie ", spec.path.string(), ": ", size.x, "x", size.y, " ", encoder_->codec(), " at ",
            fps_, " frames/s (--movie-crf ", crf, "), of ",
            chosen.size() > 1 ? "the walls " : "wall ", names);
  progress_ =
      std::make_unique<ProgressMeter>("writing " + spec.path.filename().string(),
                                      run.frames > 0 ? std::uint64_t(run.frames) : 0, "frames");
  thread_ = std::thread([this] { encodeLoop(); });
}

MovieRecorder::~MovieRecorder() {
  if (thread_.joinable()) finish();
}

bool MovieRecorder::shows(std::size_t index) const {
  return index < slots_.size() && slots_[index] >= 0;
}

void MovieRecorder::add(std::size_t index, std::uint32_t frame, std::vector<Image> eyes) {
  if (!shows(index)) return;
  std::unique_lock lock(mutex_);
  if (failed_ || closing_) return;
  Pending& p = pending_[frame];
  if (p.eyes.empty()) p.eyes.resize(shown_);
  p.eyes[std::size_t(slots_[index])] = std::move(eyes);
  if (++p.in < shown_) return;
  ready_.emplace_back(frame, std::move(p.eyes));
  pending_.erase(frame);
  changed_.notify_all();
  changed_.wait(lock, [&] { return ready_.size() < kQueuedFrames || failed_ || closing_; });
}

void MovieRecorder::encodeLoop() {
  Image frame;
  for (;;) {
    std::vector<std::vector<Image>> eyes;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return !ready_.empty() || closing_; });
      if (ready_.empty()) return;
      eyes = std::move(ready_.front().second);
      ready_.pop_front();
      changed_.notify_all();
    }
    try {
      compositor_->compose(eyes, frame);
      encoder_->add(frame);
      progress_->add(1);
    } catch (const Error& e) {
      log::error(e.what(), "; the movie ends there and plays as written");
      std::lock_guard lock(mutex_);
      failed_ = true;
      ready_.clear();
      changed_.notify_all();
      return;
    }
  }
}

bool MovieRecorder::finish() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
    changed_.notify_all();
  }
  if (thread_.joinable()) thread_.join();
  // Frames no wall finished (a run stopped mid-frame) are left out.
  if (!failed_) {
    try {
      encoder_->close();
    } catch (const Error& e) {
      log::error(e.what());
      failed_ = true;
    }
  }
  if (!failed_) {
    progress_->finish();
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(spec_.path, ec);
    log::info("wrote ", encoder_->frames(), " frames to ", spec_.path.string(), " (",
              ec ? 0.0 : double(bytes) / 1e6, " MB)");
  }
  return !failed_;
}

}  // namespace sandstorm
