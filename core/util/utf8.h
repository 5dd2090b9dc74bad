// checkUtf8: throws Error "name:line: byte 0x.. at column c is not valid
// UTF-8" for text that is not well-formed UTF-8 (overlong forms, surrogates
// and code points past U+10FFFF included). TOML text must be UTF-8, and
// toml11 3.7 reads outside its buffer when it reports invalid UTF-8 inside a
// literal string, so every TOML text is checked here first.
#pragma once

#include <string>
#include <string_view>

namespace sandstorm {

void checkUtf8(std::string_view text, const std::string& name);

}  // namespace sandstorm
