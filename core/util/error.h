// The one exception type Sandstorm throws for bad input and failed set-up.
// Messages say where (file, line, key) and what was expected, so callers can
// print them as they are.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace sandstorm {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Builds a message from parts: throw Error(concat("key '", key, "' must be > 0"));
template <class... Args>
std::string concat(const Args&... args) {
  std::ostringstream os;
  (os << ... << args);
  return os.str();
}

}  // namespace sandstorm
