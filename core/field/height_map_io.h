// Height maps as 16-bit binary PGM (P5, maxval 65535): the one image format
// every tool reads. The file holds only the samples; where they sit in the
// room comes from the configuration: `min` and `max` give the xy extent, and
// the height range, with sample 0 at min.z and 65535 at max.z. Row 0 of the
// image is the map's southern edge (smallest y), so images read as maps do
// not turn upside down: the file's first row is written last.
#pragma once

#include <filesystem>

#include "core/field/box.h"
#include "core/field/height_map.h"

namespace sandstorm {

// Throws Error naming the file and what was expected (magic, size, maxval, truncation).
HeightMap readHeightMapPgm(const std::filesystem::path& path, const Box& extent);
void writeHeightMapPgm(const HeightMap& map, const std::filesystem::path& path, float minHeight,
                       float maxHeight);

// Dunes: long wind-made ridges with noise, heights in [0, 1]. Deterministic.
HeightMap duneTerrain(glm::ivec2 dims, glm::vec2 size, std::uint32_t seed);

}  // namespace sandstorm
