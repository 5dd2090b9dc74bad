#include "core/color/color_scale.h"

#include <algorithm>
#include <cmath>

#include "core/util/error.h"

namespace sandstorm {

float ColorScale::coordinate(float value) const {
  float v = value, lo = low, hi = high;
  if (log) {
    v = std::log(std::max(v, lo));
    lo = std::log(lo);
    hi = std::log(hi);
  }
  if (!(hi > lo)) return 0.5f;
  return std::isfinite(v) ? std::clamp((v - lo) / (hi - lo), 0.0f, 1.0f) : 0.0f;
}

float ColorScale::valueAt(float t) const {
  if (log) return std::exp(std::log(low) + t * (std::log(high) - std::log(low)));
  return low + t * (high - low);
}

float colorValue(const Particle& p, ColorQuantity q, float gridValue) {
  switch (q) {
    case ColorQuantity::Age:
      return std::clamp(1.0f - p.life() / std::max(p.lifetime(), 1e-6f), 0.0f, 1.0f);
    case ColorQuantity::Speed:
      return glm::length(p.velocity());
    case ColorQuantity::VelocityX:
      return p.velocity().x;
    case ColorQuantity::VelocityY:
      return p.velocity().y;
    case ColorQuantity::VelocityZ:
      return p.velocity().z;
    case ColorQuantity::Vorticity:
    case ColorQuantity::Array:
      return gridValue;
  }
  return 0.0f;
}

std::string_view quantityName(ColorQuantity q) {
  switch (q) {
    case ColorQuantity::Age:
      return "age (fraction of life)";
    case ColorQuantity::Speed:
      return "speed";
    case ColorQuantity::VelocityX:
      return "velocity x";
    case ColorQuantity::VelocityY:
      return "velocity y";
    case ColorQuantity::VelocityZ:
      return "velocity z";
    case ColorQuantity::Vorticity:
      return "vorticity";
    case ColorQuantity::Array:
      return "array";
  }
  return "";
}

std::string_view quantityUnit(ColorQuantity q) {
  switch (q) {
    case ColorQuantity::Age:
    case ColorQuantity::Array:
      return "";
    case ColorQuantity::Vorticity:
      return "1/s";
    default:
      return "m/s";
  }
}

ColorScale resolveColorScale(ColorQuantity quantity, ColorRange range, float fixedLow,
                             float fixedHigh, bool log, const FieldRange& field, FieldFeel feel) {
  ColorScale s;
  s.quantity = quantity;
  auto scaled = [&](float lo, float hi, float factor) {
    s.low = std::min(lo * factor, hi * factor);
    s.high = std::max(lo * factor, hi * factor);
  };
  if (range == ColorRange::Fixed || range == ColorRange::Particles) {
    s.low = fixedLow;
    s.high = fixedHigh;
  } else if (quantity == ColorQuantity::Age) {
    s.low = 0.0f;
    s.high = 1.0f;
  } else if (quantity == ColorQuantity::Speed) {
    scaled(field.minSpeed, field.maxSpeed, std::abs(feel.velocityFactor));
  } else if (quantity == ColorQuantity::Vorticity) {
    scaled(field.minScalar, field.maxScalar, std::abs(feel.strength));
  } else if (quantity == ColorQuantity::Array) {
    scaled(field.minScalar, field.maxScalar, 1.0f);
  } else {
    const int axis = int(quantity) - int(ColorQuantity::VelocityX);
    scaled(field.minVelocity[axis], field.maxVelocity[axis], feel.velocityFactor);
  }
  if (log) {
    if (!(s.high > 0.0f)) {
      s.note = concat("log scale needs values above 0 (range ", s.low, " to ", s.high, "): linear");
    } else {
      if (!(s.low > 0.0f)) {
        s.note = concat("log scale: lower end ", s.low, " is not above 0; using ", s.high / 1000.0f,
                        " (three decades)");
        s.low = s.high / 1000.0f;
      }
      s.log = true;
    }
  }
  return s;
}

}  // namespace sandstorm
