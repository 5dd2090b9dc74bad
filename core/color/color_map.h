// ColorMap: a colour for every t in [0, 1], as ParaView's and matplotlib's
// colour maps give it. The perceptually uniform maps (viridis, plasma,
// inferno, cividis) are their published colours at evenly spaced stops,
// interpolated linearly in sRGB between stops; cool-warm is Moreland's
// diverging map ("Diverging Color Maps for Scientific Visualization", 2009;
// ParaView's "Cool to Warm"), computed in his Msh space; fast is ParaView's
// default map since 5.13 ("Fast", Samsel and Scott), its published control
// points interpolated in CIELAB as ParaView does; grey is a ramp; life is the
// particles' birth-to-death colours (the look before colour maps).
//
// The GPU gets kGpuSamples samples (gpuTable) and interpolates them linearly,
// as lookupTable does on the CPU: tests compare a render with lookupTable.
#pragma once

#include <array>
#include <string_view>

#include <glm/glm.hpp>

namespace sandstorm {

enum class ColorMapName : int {
  Life = 0,
  Viridis = 1,
  Plasma = 2,
  Inferno = 3,
  Cividis = 4,
  CoolWarm = 5,
  Grey = 6,
  Fast = 7,
};

class ColorMap {
 public:
  // 90 intervals: every stop of the 10- and 11-stop maps (and the middle) is a sample.
  static constexpr int kGpuSamples = 91;
  using Table = std::array<glm::vec3, kGpuSamples>;

  // `birth` and `death`: the Life map's ends (unused by the others).
  ColorMap(ColorMapName name, glm::vec3 birth = glm::vec3(0.0f), glm::vec3 death = glm::vec3(1.0f));

  ColorMapName name() const { return name_; }
  // The map's colour at t (clamped to [0, 1]), sRGB components in [0, 1].
  glm::vec3 at(float t) const;
  // kGpuSamples colours at t = i / (kGpuSamples - 1): what the shaders interpolate.
  Table gpuTable() const;
  // What the GPU shows for t: gpuTable interpolated linearly (shaders/render_block.glsl).
  static glm::vec3 lookupTable(const Table& table, float t);

 private:
  ColorMapName name_;
  glm::vec3 birth_, death_;
};

// The last map's GPU table, made again only when the map or its life colours
// change (a table is 91 evaluations; cool-warm's take ~25 us, every view of
// every frame otherwise).
class ColorTableCache {
 public:
  const ColorMap::Table& get(ColorMapName name, glm::vec3 birth, glm::vec3 death);

 private:
  bool valid_ = false;
  ColorMapName name_ = ColorMapName::Life;
  glm::vec3 birth_{0.0f}, death_{0.0f};
  ColorMap::Table table_{};
};

// Moreland's diverging interpolation between two sRGB colours in Msh space
// (a white-ish middle when both ends are saturated and far apart in hue).
glm::vec3 divergingColor(glm::vec3 low, glm::vec3 high, float t);

}  // namespace sandstorm
