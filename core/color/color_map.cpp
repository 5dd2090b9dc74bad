#include "core/color/color_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

namespace sandstorm {
namespace {

constexpr glm::vec3 hex(unsigned rgb) {
  return glm::vec3(float((rgb >> 16) & 255u), float((rgb >> 8) & 255u), float(rgb & 255u)) / 255.0f;
}

// The published maps at evenly spaced stops (matplotlib's colours, which
// ParaView ships under the same names).
constexpr std::array kViridis{hex(0x440154), hex(0x482475), hex(0x414487), hex(0x355f8d),
                              hex(0x2a788e), hex(0x21918c), hex(0x22a884), hex(0x44bf70),
                              hex(0x7ad151), hex(0xbddf26), hex(0xfde725)};
constexpr std::array kPlasma{hex(0x0d0887), hex(0x41049d), hex(0x6a00a8), hex(0x8f0da4),
                             hex(0xb12a90), hex(0xcc4778), hex(0xe16462), hex(0xf2844b),
                             hex(0xfca636), hex(0xfcce25), hex(0xf0f921)};
constexpr std::array kInferno{hex(0x000004), hex(0x160b39), hex(0x420a68), hex(0x6a176e),
                              hex(0x932667), hex(0xbc3754), hex(0xdd513a), hex(0xf37819),
                              hex(0xfca50a), hex(0xf6d746), hex(0xfcffa4)};
constexpr std::array kCividis{hex(0x00224e), hex(0x123570), hex(0x3b496c), hex(0x575d6d),
                              hex(0x707173), hex(0x8a8779), hex(0xa59c74), hex(0xc3b369),
                              hex(0xe1cc55), hex(0xfee838)};
// ParaView's "Fast" (Remoting/Views/ColorMaps.json): sRGB control points at
// uneven positions, interpolated in CIELAB.
struct LabStop {
  float t;
  glm::vec3 rgb;
};
constexpr std::array kFast{
    LabStop{0.0f, {0.0564f, 0.0564f, 0.47f}},
    LabStop{0.17159224f, {0.243f, 0.46035f, 0.81f}},
    LabStop{0.29849148f, {0.35681438f, 0.74502465f, 0.9543677f}},
    LabStop{0.43212874f, {0.6882f, 0.93f, 0.91791f}},
    LabStop{0.5f, {0.89949596f, 0.94464640f, 0.76865671f}},
    LabStop{0.58822604f, {0.95710798f, 0.83381851f, 0.50891563f}},
    LabStop{0.70614126f, {0.92752076f, 0.62143891f, 0.31535706f}},
    LabStop{0.84763953f, {0.8f, 0.352f, 0.16f}},
    LabStop{1.0f, {0.59f, 0.0767f, 0.119475f}},
};
// Moreland's ends of ParaView's "Cool to Warm".
constexpr glm::vec3 kCool = hex(0x3b4cc0);  // (59, 76, 192)
constexpr glm::vec3 kWarm = hex(0xb40426);  // (180, 4, 38)

glm::vec3 stops(std::span<const glm::vec3> colors, float t) {
  const float x = t * float(colors.size() - 1);
  const std::size_t i = std::min(std::size_t(x), colors.size() - 2);
  return glm::mix(colors[i], colors[i + 1], x - float(i));
}

// sRGB <-> CIELAB (D65).
constexpr glm::vec3 kWhite{0.95047f, 1.0f, 1.08883f};

double toLinear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
double fromLinear(double c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}
double labF(double t) {
  return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
}
double labFInverse(double f) {
  const double t = f * f * f;
  return t > 216.0 / 24389.0 ? t : (116.0 * f - 16.0) * 27.0 / 24389.0;
}

struct Lab {
  double l, a, b;
};

Lab toLab(glm::vec3 srgb) {
  const double r = toLinear(srgb.x), g = toLinear(srgb.y), b = toLinear(srgb.z);
  const double x = 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
  const double y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
  const double z = 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
  const double fx = labF(x / kWhite.x), fy = labF(y / kWhite.y), fz = labF(z / kWhite.z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

glm::vec3 fromLab(Lab c) {
  const double fy = (c.l + 16.0) / 116.0, fx = fy + c.a / 500.0, fz = fy - c.b / 200.0;
  const double x = kWhite.x * labFInverse(fx), y = kWhite.y * labFInverse(fy),
               z = kWhite.z * labFInverse(fz);
  const double r = 3.2404542 * x - 1.5371385 * y - 0.4985314 * z;
  const double g = -0.9692660 * x + 1.8760108 * y + 0.0415560 * z;
  const double b = 0.0556434 * x - 0.2040259 * y + 1.0572252 * z;
  auto channel = [](double v) { return float(std::clamp(fromLinear(std::max(v, 0.0)), 0.0, 1.0)); };
  return {channel(r), channel(g), channel(b)};
}

// Control points at uneven positions, each interval interpolated in Lab.
glm::vec3 labStops(std::span<const LabStop> points, float t) {
  std::size_t i = 0;
  while (i + 2 < points.size() && t > points[i + 1].t)
    ++i;
  const LabStop &lo = points[i], &hi = points[i + 1];
  const double x = std::clamp(double(t - lo.t) / double(hi.t - lo.t), 0.0, 1.0);
  const Lab a = toLab(lo.rgb), b = toLab(hi.rgb);
  return fromLab({a.l + x * (b.l - a.l), a.a + x * (b.a - a.a), a.b + x * (b.b - a.b)});
}

// Moreland's Msh: the polar form of Lab.
struct Msh {
  double m, s, h;
};

Msh toMsh(glm::vec3 srgb) {
  const Lab c = toLab(srgb);
  const double m = std::sqrt(c.l * c.l + c.a * c.a + c.b * c.b);
  return {m, m > 0.0 ? std::acos(std::clamp(c.l / m, -1.0, 1.0)) : 0.0, std::atan2(c.b, c.a)};
}

glm::vec3 fromMsh(Msh c) {
  return fromLab({c.m * std::cos(c.s), c.m * std::sin(c.s) * std::cos(c.h),
                  c.m * std::sin(c.s) * std::sin(c.h)});
}

// The hue to give an unsaturated end so the path to a saturated one turns
// its hue gradually (Moreland's AdjustHue).
double adjustHue(Msh saturated, double unsaturatedM) {
  if (saturated.m >= unsaturatedM) return saturated.h;
  const double spin = saturated.s *
                      std::sqrt(unsaturatedM * unsaturatedM - saturated.m * saturated.m) /
                      (saturated.m * std::sin(saturated.s));
  return saturated.h > -std::numbers::pi / 3.0 ? saturated.h + spin : saturated.h - spin;
}

}  // namespace

glm::vec3 divergingColor(glm::vec3 low, glm::vec3 high, float t) {
  Msh a = toMsh(low), b = toMsh(high);
  double x = std::clamp(double(t), 0.0, 1.0);
  double hueGap = std::abs(a.h - b.h);
  if (hueGap > std::numbers::pi) hueGap = 2.0 * std::numbers::pi - hueGap;
  if (a.s > 0.05 && b.s > 0.05 && hueGap > std::numbers::pi / 3.0) {
    const double middle = std::max({a.m, b.m, 88.0});
    if (x < 0.5) {
      b = {middle, 0.0, 0.0};
      x *= 2.0;
    } else {
      a = {middle, 0.0, 0.0};
      x = 2.0 * x - 1.0;
    }
  }
  if (a.s < 0.05 && b.s > 0.05)
    a.h = adjustHue(b, a.m);
  else if (b.s < 0.05 && a.s > 0.05)
    b.h = adjustHue(a, b.m);
  return fromMsh({(1.0 - x) * a.m + x * b.m, (1.0 - x) * a.s + x * b.s, (1.0 - x) * a.h + x * b.h});
}

ColorMap::ColorMap(ColorMapName name, glm::vec3 birth, glm::vec3 death)
    : name_(name), birth_(birth), death_(death) {}

glm::vec3 ColorMap::at(float t) const {
  t = std::isfinite(t) ? std::clamp(t, 0.0f, 1.0f) : 0.0f;
  switch (name_) {
    case ColorMapName::Life:
      return glm::mix(birth_, death_, t);
    case ColorMapName::Viridis:
      return stops(kViridis, t);
    case ColorMapName::Plasma:
      return stops(kPlasma, t);
    case ColorMapName::Inferno:
      return stops(kInferno, t);
    case ColorMapName::Cividis:
      return stops(kCividis, t);
    case ColorMapName::CoolWarm:
      return divergingColor(kCool, kWarm, t);
    case ColorMapName::Grey:
      return glm::vec3(t);
    case ColorMapName::Fast:
      return labStops(kFast, t);
  }
  return glm::vec3(t);
}

ColorMap::Table ColorMap::gpuTable() const {
  Table table;
  for (int i = 0; i < kGpuSamples; ++i)
    table[std::size_t(i)] = at(float(i) / float(kGpuSamples - 1));
  return table;
}

const ColorMap::Table& ColorTableCache::get(ColorMapName name, glm::vec3 birth, glm::vec3 death) {
  // Only the life map depends on the birth and death colours.
  const bool life = name == ColorMapName::Life;
  if (!valid_ || name != name_ || (life && (birth != birth_ || death != death_))) {
    table_ = ColorMap(name, birth, death).gpuTable();
    valid_ = true;
    name_ = name;
    birth_ = birth;
    death_ = death;
  }
  return table_;
}

glm::vec3 ColorMap::lookupTable(const Table& table, float t) {
  const float x = (std::isfinite(t) ? std::clamp(t, 0.0f, 1.0f) : 0.0f) * float(kGpuSamples - 1);
  const int i = std::min(int(x), kGpuSamples - 2);
  return glm::mix(table[std::size_t(i)], table[std::size_t(i + 1)], x - float(i));
}

}  // namespace sandstorm
