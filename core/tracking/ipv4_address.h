// Ipv4Address: an IPv4 address as a user writes it in a configuration
// ("192.168.0.20"): four decimal numbers 0..255 joined by dots, nothing else
// (no signs, spaces, leading zeros beyond one digit's worth, or host names:
// a tracker's controller has a fixed address, and a name would need a lookup
// the main context must not wait for).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace sandstorm {

// The address in host byte order, or nothing if `text` is not one.
std::optional<std::uint32_t> parseIpv4(std::string_view text);

// The address as dotted quads, as parseIpv4 reads it.
std::string formatIpv4(std::uint32_t address);

inline bool isMulticast(std::uint32_t address) {
  return (address >> 28) == 0xEu;
}

}  // namespace sandstorm
