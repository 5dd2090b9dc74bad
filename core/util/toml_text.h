// checkTomlText: the checks every TOML text passes before toml11 parses it.
// - The text is UTF-8 (checkUtf8): toml11 3.7 reads outside its buffer when it
//   reports invalid UTF-8 inside a literal string.
// - Every integer literal in a value (decimal, 0x, 0o, 0b) fits in 64 bits:
//   toml11 overflows a signed integer on a long 0b literal and silently clamps
//   long decimal, hex and octal ones to the largest integer.
// - Arrays and inline tables nest at most 32 deep: toml11 parses them by
//   recursion, and a few thousand levels overflow the stack.
// Throws Error "name:line: ..." naming the literal and what was expected.
// Strings and comments are skipped; keys are not values and are not checked.
// tomlString: text as a TOML basic string ("..." with " and \ escaped).
#pragma once

#include <string>
#include <string_view>

namespace sandstorm {

void checkTomlText(std::string_view text, const std::string& name);

std::string tomlString(std::string_view text);

}  // namespace sandstorm
