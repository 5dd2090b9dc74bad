#include "core/util/utf8.h"

#include <cstdint>

#include "core/util/error.h"

namespace sandstorm {

void checkUtf8(std::string_view text, const std::string& name) {
  std::size_t line = 1, lineStart = 0;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') ++line, lineStart = i + 1;
    int length = 0;
    std::uint32_t code = 0, least = 0;
    if (c < 0x80)
      length = 1, code = c;
    else if ((c & 0xE0) == 0xC0)
      length = 2, code = c & 0x1F, least = 0x80;
    else if ((c & 0xF0) == 0xE0)
      length = 3, code = c & 0x0F, least = 0x800;
    else if ((c & 0xF8) == 0xF0)
      length = 4, code = c & 0x07, least = 0x10000;
    bool ok = length > 0 && i + std::size_t(length) <= text.size();
    for (int k = 1; ok && k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + std::size_t(k)]);
      ok = (next & 0xC0) == 0x80;
      code = (code << 6) | (next & 0x3F);
    }
    ok = ok && code >= least && code <= 0x10FFFF && !(code >= 0xD800 && code <= 0xDFFF);
    if (!ok)
      throw Error(concat(name, ":", line, ": byte 0x", std::hex, int(c), std::dec, " at column ",
                         i - lineStart + 1, " is not valid UTF-8; expected a UTF-8 text file"));
    i += std::size_t(length);
  }
}

}  // namespace sandstorm
