#include "core/util/log.h"

#include <atomic>
#include <cstdio>
#include <mutex>
#include <string>

namespace sandstorm::log {
namespace {

std::atomic<Level>& currentLevel() {
  static std::atomic<Level> level{Level::Info};
  return level;
}

const char* tag(Level level) {
  switch (level) {
    case Level::Error:
      return "error";
    case Level::Warn:
      return "warn";
    case Level::Info:
      return "info";
    case Level::Debug:
      return "debug";
  }
  return "?";
}

std::string& processTag() {
  static std::string tag;
  return tag;
}

}  // namespace

void setTag(std::string_view tag) {
  processTag() = std::string(tag) + (tag.empty() ? "" : " ");
}

void setLevel(Level level) {
  currentLevel() = level;
}
Level level() {
  return currentLevel();
}

bool parseLevel(std::string_view name, Level& out) {
  if (name == "error")
    out = Level::Error;
  else if (name == "warn")
    out = Level::Warn;
  else if (name == "info")
    out = Level::Info;
  else if (name == "debug")
    out = Level::Debug;
  else
    return false;
  return true;
}

void write(Level level, std::string_view message) {
  static std::mutex mutex;
  std::string line = "[sandstorm ";
  line += processTag();
  line += tag(level);
  line += "] ";
  line += message;
  line += '\n';
  std::lock_guard lock(mutex);
  std::fputs(line.c_str(), stderr);
}

}  // namespace sandstorm::log
