// parseByteSize(): a size as people write it in a configuration: "12 GiB",
// "800 MiB", "2.5 GB", "65536" (bytes). Binary units (KiB, MiB, GiB, TiB)
// count in 1024s, decimal ones (kB, MB, GB, TB) in 1000s; "B" or no unit is
// bytes. Returns nullopt for anything else (the caller names the key).
// formatByteSize(): the other way, for messages ("1.5 GiB").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace sandstorm {

std::optional<std::uint64_t> parseByteSize(std::string_view text);
std::string formatByteSize(double bytes);

// Physical memory of this machine in bytes (0 when the system does not say).
std::uint64_t hostMemoryBytes();

}  // namespace sandstorm
