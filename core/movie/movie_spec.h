// MovieSpec: what `--movie` and its options ask for, checked before a run
// starts. A movie is one picture a frame: one wall, or every wall unfolded
// as a CAVE's cross (movie_layout.h); of a stereo wall its left eye, or both
// eyes side by side.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace sandstorm {

enum class MovieStereo { Left, SideBySide };
enum class MovieContainer { Mp4, WebM };  // H.264 in MP4, VP9 in WebM

struct MovieSpec {
  std::filesystem::path path;
  MovieContainer container = MovieContainer::Mp4;
  std::string wall;  // a wall's name, "all" (the unfolded cross), or empty: the first wall
  MovieStereo stereo = MovieStereo::Left;
  std::optional<glm::ivec2> size;  // render the walls offscreen for a frame of this size
  std::optional<double> fps;       // unset: 1 / run.fixed_dt
  std::optional<int> crf;          // unset: the codec's default (defaultCrf)
  bool menu = false;               // draw the menu panel into the movie
};

// The container a file name asks for: .mp4 or .webm (any case). Throws Error
// naming --movie and the extensions known.
MovieContainer movieContainerFor(const std::filesystem::path& path);
// "1920x1080": both even (the codecs' 4:2:0 colour halves each side), 16 to
// 16384. Throws Error naming --movie-size.
glm::ivec2 parseMovieSize(const std::string& text);
MovieStereo parseMovieStereo(const std::string& text);
// Constant rate factor: lower is better and larger. H.264 0-51 (default 13,
// visually lossless for most pictures), VP9 0-63 (default 20).
int defaultCrf(MovieContainer container);
int maxCrf(MovieContainer container);
// Checks the values that do not need the configuration; throws Error naming the option.
void validateMovieSpec(const MovieSpec& spec);

// --movie and its options as the command line (or the Python module) gives
// them: parsed, checked, and the file tried for writing. Throws Error naming
// the option.
struct MovieRequest {
  std::filesystem::path path;
  std::string wall;
  std::string stereo = "left";
  std::optional<std::string> size;
  std::optional<double> fps;
  std::optional<int> crf;
  bool menu = false;
};
MovieSpec movieSpecFrom(const MovieRequest& request);

}  // namespace sandstorm
