// Telling a GPU allocation's failure apart, and saying it once.
//
// Allocations whose size the user chooses (sim.maximum, a wall's size, the
// trails' length) are checked: on GL_OUT_OF_MEMORY they throw a message that
// names the setting to lower. The driver reports the same failure through
// the debug output too, as a GL error the user cannot act on, printed before
// the message that helps. While any OutOfMemoryCheck lives, debug messages
// about memory running out are logged at debug level only (a global count,
// not a thread's: a driver may call the debug callback from its own thread).
//
//   gl::OutOfMemoryCheck check;
//   glNamedBufferStorage(buffer.id(), bytes, nullptr, 0);
//   if (check.failed()) throw Error("... lower sim.maximum");
#pragma once

#include <string_view>

namespace sandstorm::gl {

class OutOfMemoryCheck {
 public:
  OutOfMemoryCheck();  // clears the context's error flag
  ~OutOfMemoryCheck();
  OutOfMemoryCheck(const OutOfMemoryCheck&) = delete;
  OutOfMemoryCheck& operator=(const OutOfMemoryCheck&) = delete;

  // Whether a call since construction (or since the last failed()) ran out of memory.
  bool failed() const;
};

// Whether the debug output's `message` is an out-of-memory report that a
// live OutOfMemoryCheck will turn into a message of its own.
bool outOfMemoryIsChecked(std::string_view message);

}  // namespace sandstorm::gl
