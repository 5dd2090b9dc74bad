#include "core/movie/movie_encoder.h"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

#include "core/movie/movie_plugin_api.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

constexpr const char* kPluginName = "libsandstorm_ffmpeg.so";

void logFromPlugin(int level, const char* text) {
  if (level <= 1)
    log::warn("FFmpeg: ", text);
  else
    log::debug("FFmpeg: ", text);
}

// Where the plugin is looked for, in turn: beside the running program
// (build/, a packed .bench/), beside the library holding this code (the
// Python module), and where this build wrote it.
std::vector<std::filesystem::path> pluginCandidates() {
  std::vector<std::filesystem::path> out;
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) out.push_back(program.parent_path() / kPluginName);
  Dl_info self{};
  if (dladdr(reinterpret_cast<const void*>(&pluginCandidates), &self) != 0 && self.dli_fname) {
    const std::filesystem::path here =
        std::filesystem::absolute(self.dli_fname, error).parent_path() / kPluginName;
    if (!error && (out.empty() || here != out.front())) out.push_back(here);
  }
#ifdef SANDSTORM_FFMPEG_PLUGIN
  const std::filesystem::path built = SANDSTORM_FFMPEG_PLUGIN;
  if (std::find(out.begin(), out.end(), built) == out.end()) out.push_back(built);
#endif
  return out;
}

// Loads the plugin once per process; throws Error (the movie's --movie
// prefix added by the caller) where it is nowhere or will not load.
const SandstormMovieApi& plugin() {
  static std::mutex mutex;
  static const SandstormMovieApi* api = nullptr;
  const std::lock_guard lock(mutex);
  if (api) return *api;
  std::string tried;
  for (const std::filesystem::path& path : pluginCandidates()) {
    tried += concat(tried.empty() ? "" : ", ", path.string());
    if (::access(path.c_str(), R_OK) != 0) continue;
    // Kept loaded for the process's life: FFmpeg keeps global state.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle)
      throw Error(concat("the movie plugin ", path.string(), " does not load: ", dlerror()));
    using Entry = const SandstormMovieApi* (*)(SandstormMovieLog, int);
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, kSandstormMovieApiSymbol));
    const SandstormMovieApi* found =
        entry ? entry(logFromPlugin, log::level() >= log::Level::Debug ? 1 : 0) : nullptr;
    if (!found || found->version != kSandstormMovieApiVersion)
      throw Error(concat("the movie plugin ", path.string(),
                         " is of another build of Sandstorm; rebuild it with this one"));
    api = found;
    return *api;
  }
  throw Error(concat("movies need the movie plugin ", kPluginName,
                     ", built with Sandstorm; it is in none of: ", tried));
}

}  // namespace

struct MovieEncoder::State {
  const SandstormMovieApi* api = nullptr;
  void* movie = nullptr;
  std::string path;
  MovieContainer container = MovieContainer::Mp4;
  std::array<char, 1024> error{};

  ~State() {
    if (movie) api->destroy(movie);
  }
};

MovieEncoder::MovieEncoder(const Options& options) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.path = options.path.string();
  s.container = options.container;
  try {
    s.api = &plugin();
  } catch (const Error& e) {
    throw Error(concat("--movie ", s.path, ": ", e.what()));
  }
  const SandstormMovieOptions o{s.path.c_str(), options.container == MovieContainer::WebM ? 1 : 0,
                                options.size.x, options.size.y,
                                options.fps,    options.crf};
  s.movie = s.api->open(&o, s.error.data(), s.error.size());
  if (!s.movie) throw Error(s.error.data());
}

MovieEncoder::~MovieEncoder() {
  try {
    close();
  } catch (const Error& e) {
    log::error(e.what());
  }
}

void MovieEncoder::add(const Image& frame) {
  State& s = *state_;
  if (s.api->add(s.movie, frame.rgba.data(), frame.width, frame.height, s.error.data(),
                 s.error.size()) != 0)
    throw Error(s.error.data());
}

void MovieEncoder::close() {
  State& s = *state_;
  if (!s.movie) return;
  if (s.api->close(s.movie, s.error.data(), s.error.size()) != 0) throw Error(s.error.data());
}

std::int64_t MovieEncoder::frames() const {
  return state_->movie ? state_->api->frames(state_->movie) : 0;
}

const char* MovieEncoder::codec() const {
  return state_->container == MovieContainer::Mp4 ? "H.264" : "VP9";
}

}  // namespace sandstorm
