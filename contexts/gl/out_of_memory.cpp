#include "contexts/gl/out_of_memory.h"

#include <epoxy/gl.h>

#include <atomic>
#include <string>

namespace sandstorm::gl {
namespace {

std::atomic<int> liveChecks{0};

bool mentionsOutOfMemory(std::string_view message) {
  std::string lower(message);
  for (char& c : lower)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return lower.find("out_of_memory") != std::string::npos ||
         lower.find("out of memory") != std::string::npos;
}

}  // namespace

OutOfMemoryCheck::OutOfMemoryCheck() {
  liveChecks.fetch_add(1);
  // A context may hold several error flags; each read clears one.
  for (int i = 0; i < 8 && glGetError() != GL_NO_ERROR; ++i) {
  }
}

OutOfMemoryCheck::~OutOfMemoryCheck() {
  liveChecks.fetch_sub(1);
}

bool OutOfMemoryCheck::failed() const {
  return glGetError() == GL_OUT_OF_MEMORY;
}

bool outOfMemoryIsChecked(std::string_view message) {
  return liveChecks.load() > 0 && mentionsOutOfMemory(message);
}

}  // namespace sandstorm::gl
