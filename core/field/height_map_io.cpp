#include "core/field/height_map_io.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/field/gradient_noise.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// The next header token of a PGM, skipping whitespace and # comments.
std::string token(std::istream& in, const std::string& file) {
  std::string t;
  char c;
  while (in.get(c)) {
    if (c == '#') {
      std::string comment;
      std::getline(in, comment);
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      if (!t.empty()) return t;
    } else {
      t += c;
    }
  }
  if (t.empty()) throw Error(concat(file, ": truncated PGM header"));
  return t;
}

int number(std::istream& in, const std::string& file, const char* what, int lo, int hi) {
  const std::string t = token(in, file);
  int v = 0;
  try {
    std::size_t used = 0;
    v = std::stoi(t, &used);
    if (used != t.size()) throw std::invalid_argument(t);
  } catch (...) {
    throw Error(concat(file, ": PGM ", what, " '", t, "' is not a number"));
  }
  if (v < lo || v > hi)
    throw Error(concat(file, ": PGM ", what, " ", v, " is outside ", lo, "..", hi));
  return v;
}

}  // namespace

HeightMap readHeightMapPgm(const std::filesystem::path& path, const Box& extent) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(concat(file, ": cannot open the height map"));
  if (token(in, file) != "P5")
    throw Error(concat(file, ": not a binary PGM (expected the magic 'P5')"));
  const int w = number(in, file, "width", 2, 16384), h = number(in, file, "height", 2, 16384);
  const int maxval = number(in, file, "maxval", 1, 65535);
  const int bytes = maxval > 255 ? 2 : 1;
  std::vector<unsigned char> raw(std::size_t(w) * std::size_t(h) * std::size_t(bytes));
  in.read(reinterpret_cast<char*>(raw.data()), std::streamsize(raw.size()));
  if (in.gcount() != std::streamsize(raw.size()))
    throw Error(
        concat(file, ": truncated: ", in.gcount(), " of ", raw.size(), " bytes of samples"));
  std::vector<float> heights(std::size_t(w) * std::size_t(h));
  const float lo = extent.min.z, span = extent.max.z - extent.min.z;
  for (int row = 0; row < h; ++row)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(row) * std::size_t(w) + std::size_t(x);
      const int v = bytes == 2 ? (raw[2 * i] << 8) | raw[2 * i + 1] : raw[i];  // PGM is big-endian
      const int y = h - 1 - row;  // the first row is the northern edge
      heights[std::size_t(y) * std::size_t(w) + std::size_t(x)] =
          lo + span * float(v) / float(maxval);
    }
  return HeightMap(glm::vec2(extent.min), glm::vec2(extent.max), {w, h}, std::move(heights));
}

void writeHeightMapPgm(const HeightMap& map, const std::filesystem::path& path, float minHeight,
                       float maxHeight) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error(concat(path.string(), ": cannot write the height map"));
  const glm::ivec2 d = map.dims();
  out << "P5\n# Sandstorm height map: 0 = " << minHeight << " m, 65535 = " << maxHeight << " m\n"
      << d.x << " " << d.y << "\n65535\n";
  for (int y = d.y - 1; y >= 0; --y)
    for (int x = 0; x < d.x; ++x) {
      const float t = std::clamp((map.at(x, y) - minHeight) / (maxHeight - minHeight), 0.0f, 1.0f);
      const int v = int(std::lround(t * 65535.0f));
      out.put(char(v >> 8)).put(char(v & 0xff));
    }
  if (!out) throw Error(concat(path.string(), ": writing failed"));
}

HeightMap duneTerrain(glm::ivec2 dims, glm::vec2 size, std::uint32_t seed) {
  const GradientNoise noise(seed);
  std::vector<float> h(std::size_t(dims.x) * std::size_t(dims.y));
  float lo = 1e9f, hi = -1e9f;
  for (int j = 0; j < dims.y; ++j)
    for (int i = 0; i < dims.x; ++i) {
      const glm::vec2 p = (glm::vec2(i, j) / glm::vec2(dims - 1) - 0.5f) * size;
      // Transverse dunes: ridges across the wind (+x), bent and varied by noise,
      // with a steep lee face; a gentle swell underneath.
      const float bend = 6.0f * noise.value(glm::vec3(p * 0.015f, 0.5f));
      const float phase = (p.x + bend) / 23.0f;
      const float ridge = std::pow(
          0.5f + 0.5f * std::sin(6.2831853f * (phase - 0.15f * std::sin(6.2831853f * phase))),
          1.6f);
      const float amp = 0.6f + 0.4f * noise.value(glm::vec3(p * 0.02f, 3.1f));
      const float swell = 0.5f + 0.5f * noise.value(glm::vec3(p * 0.006f, 7.7f));
      const float v =
          0.6f * amp * ridge + 0.4f * swell + 0.05f * noise.value(glm::vec3(p * 0.2f, 1.3f));
      h[std::size_t(j) * std::size_t(dims.x) + std::size_t(i)] = v;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  for (float& v : h)
    v = (v - lo) / (hi - lo);
  return HeightMap(-0.5f * size, 0.5f * size, dims, std::move(h));
}

}  // namespace sandstorm
