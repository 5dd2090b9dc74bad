#include "core/tracking/dtrack_writer.h"

#include <charconv>

namespace sandstorm {
namespace {

// The shortest text that reads back as the same float.
void number(std::string& out, double v) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, float(v));
  out.append(buffer, ec == std::errc() ? end : buffer);
}

void numbers(std::string& out, const glm::vec3& v) {
  for (int i = 0; i < 3; ++i) {
    if (i) out += ' ';
    number(out, v[i]);
  }
}

void matrix(std::string& out, const glm::mat3& m, bool zero) {
  out += '[';
  for (int i = 0; i < 9; ++i) {
    if (i) out += ' ';
    number(out, zero ? 0.0 : m[i / 3][i % 3]);
  }
  out += ']';
}

}  // namespace

std::string writeDTrack(const TrackerFrame& f, FlystickFormat format) {
  std::string out;
  if (f.frame) out += "fr " + std::to_string(*f.frame) + "\r\n";
  if (f.timestamp) {
    char buffer[32];
    const auto [end, ec] =
        std::to_chars(buffer, buffer + sizeof buffer, *f.timestamp, std::chars_format::fixed, 6);
    out += "ts " + std::string(buffer, ec == std::errc() ? end : buffer) + "\r\n";
  }
  out += "6dcal " + std::to_string(f.bodies.size()) + "\r\n";
  out += "6d " + std::to_string(f.bodies.size()) + " ";
  for (const TrackedBody& b : f.bodies) {
    out += "[" + std::to_string(b.id) + " ";
    number(out, b.quality);
    out += "][";
    numbers(out, b.position);
    out += "]";
    matrix(out, b.rotation, false);
  }
  out += "\r\n";
  if (format == FlystickFormat::V2) {
    out += "6df2 " + std::to_string(f.flysticks.size()) + " " + std::to_string(f.flysticks.size()) +
           " ";
    for (const TrackedFlystick& s : f.flysticks) {
      out += "[" + std::to_string(s.id) + " ";
      number(out, s.quality);
      out += " " + std::to_string(s.buttonCount) + " " + std::to_string(s.controllerCount) + "][";
      numbers(out, s.tracked() ? s.position : glm::vec3(0.0f));
      out += "]";
      matrix(out, s.rotation, !s.tracked());
      out += "[";
      bool first = true;
      for (int w = 0; w < (s.buttonCount + 31) / 32; ++w, first = false)
        out += (first ? "" : " ") + std::to_string(w == 0 ? s.buttons : 0u);
      for (int c = 0; c < s.controllerCount; ++c, first = false) {
        if (!first) out += ' ';
        number(out, s.controllers[std::size_t(c)]);
      }
      out += "]";
    }
  } else {
    out += "6df " + std::to_string(f.flysticks.size()) + " ";
    for (const TrackedFlystick& s : f.flysticks) {
      out += "[" + std::to_string(s.id) + " ";
      number(out, s.quality);
      out += " " + std::to_string(s.buttons & 0xffu) + "][";
      numbers(out, s.tracked() ? s.position : glm::vec3(0.0f));
      out += " 0 0 0]";
      matrix(out, s.rotation, !s.tracked());
    }
  }
  out += "\r\n";
  if (!f.markers.empty()) {
    out += "3d " + std::to_string(f.markers.size()) + " ";
    for (const TrackedMarker& m : f.markers) {
      out += "[" + std::to_string(m.id) + " ";
      number(out, m.quality);
      out += "][";
      numbers(out, m.position);
      out += "]";
    }
    out += "\r\n";
  }
  return out;
}

}  // namespace sandstorm
