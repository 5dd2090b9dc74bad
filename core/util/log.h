// Levelled logging to stderr. Thread-safe: each line is written whole.
//   log::info("loaded ", n, " points from ", path);
// The level comes from setLevel() (sandstorm --log-level: error, warn, info,
// debug); the default is info.
#pragma once

#include <sstream>
#include <string_view>

namespace sandstorm::log {

enum class Level { Error = 0, Warn = 1, Info = 2, Debug = 3 };

void setLevel(Level level);
// A tag for every line of this process, e.g. "rank 2" (cluster mode): "[sandstorm rank 2 info]
// ...". Set it before other threads log.
void setTag(std::string_view tag);
Level level();
bool parseLevel(std::string_view name, Level& out);
void write(Level level, std::string_view message);

template <class... Args>
void print(Level lvl, const Args&... args) {
  if (static_cast<int>(lvl) > static_cast<int>(level())) return;
  std::ostringstream os;
  (os << ... << args);
  write(lvl, os.str());
}

template <class... Args>
void error(const Args&... args) {
  print(Level::Error, args...);
}
template <class... Args>
void warn(const Args&... args) {
  print(Level::Warn, args...);
}
template <class... Args>
void info(const Args&... args) {
  print(Level::Info, args...);
}
template <class... Args>
void debug(const Args&... args) {
  print(Level::Debug, args...);
}

}  // namespace sandstorm::log
