#include "core/movie/movie_spec.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "core/util/error.h"
#include "core/util/output_file.h"

namespace sandstorm {
namespace {

std::string lower(std::string s) {
  std::ranges::transform(s, s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

bool parseInt(std::string_view text, int& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && !text.empty();
}

}  // namespace

MovieContainer movieContainerFor(const std::filesystem::path& path) {
  const std::string ext = lower(path.extension().string());
  if (ext == ".mp4") return MovieContainer::Mp4;
  if (ext == ".webm") return MovieContainer::WebM;
  throw Error(concat("--movie ", path.string(), ": unknown extension '", ext,
                     "'; expected .mp4 (H.264) or .webm (VP9)"));
}

glm::ivec2 parseMovieSize(const std::string& text) {
  const std::size_t x = lower(text).find('x');
  glm::ivec2 size{0};
  if (x == std::string::npos || !parseInt(std::string_view(text).substr(0, x), size.x) ||
      !parseInt(std::string_view(text).substr(x + 1), size.y))
    throw Error(concat("--movie-size '", text, "': expected WIDTHxHEIGHT, e.g. 3840x2160"));
  if (size.x < 16 || size.y < 16 || size.x > 16384 || size.y > 16384)
    throw Error(concat("--movie-size ", text, ": expected 16 to 16384 pixels a side"));
  if (size.x % 2 || size.y % 2)
    throw Error(concat("--movie-size ", text,
                       ": expected even numbers (the codecs store colour at half resolution)"));
  return size;
}

MovieStereo parseMovieStereo(const std::string& text) {
  if (text == "left") return MovieStereo::Left;
  if (text == "side-by-side") return MovieStereo::SideBySide;
  throw Error(concat("--movie-stereo '", text, "': expected left or side-by-side"));
}

int defaultCrf(MovieContainer container) {
  return container == MovieContainer::Mp4 ? 13 : 20;
}

int maxCrf(MovieContainer container) {
  return container == MovieContainer::Mp4 ? 51 : 63;
}

void validateMovieSpec(const MovieSpec& spec) {
  if (spec.fps && !(*spec.fps >= 1.0 && *spec.fps <= 240.0))
    throw Error(concat("--movie-fps ", *spec.fps, ": expected 1 to 240 frames per second"));
  if (spec.crf && (*spec.crf < 0 || *spec.crf > maxCrf(spec.container)))
    throw Error(concat("--movie-crf ", *spec.crf, ": expected 0 (lossless) to ",
                       maxCrf(spec.container), " for a .",
                       spec.container == MovieContainer::Mp4 ? "mp4" : "webm", " movie"));
}

MovieSpec movieSpecFrom(const MovieRequest& request) {
  MovieSpec spec;
  spec.path = request.path;
  spec.container = movieContainerFor(spec.path);
  spec.wall = request.wall;
  spec.stereo = parseMovieStereo(request.stereo);
  if (request.size) spec.size = parseMovieSize(*request.size);
  spec.fps = request.fps;
  spec.crf = request.crf;
  spec.menu = request.menu;
  validateMovieSpec(spec);
  checkOutputFile(spec.path, "--movie");
  return spec;
}

}  // namespace sandstorm
