// ColorScale: which quantity colours a particle and how its value becomes the
// colour map's coordinate t in [0, 1]. The shaders compute the same t
// (colorCoordinate in shaders/render_block.glsl) from the same four numbers
// (RenderBlock::colorScale), so a test can predict a rendered colour.
#pragma once

#include <string>
#include <string_view>

#include "core/field/field_range.h"
#include "core/sim/particle.h"

namespace sandstorm {

// What colours a particle. Age is the fraction of its life gone (0 at birth,
// 1 at death); the others are its velocity's length or a component, in m/s.
// Vorticity is |curl| of the field the particles feel, at the particle (1/s).
// Array is a scalar array of the field's file (render.color_array), sampled at
// the particle like the field, in the file's own unit.
enum class ColorQuantity : int {
  Age = 0,
  Speed = 1,
  VelocityX = 2,
  VelocityY = 3,
  VelocityZ = 4,
  Vorticity = 5,
  Array = 6
};

// Whether the quantity is sampled from a scalar grid sent with the field
// (FieldUpdate::colorGrid): vorticity and file arrays.
inline bool usesColorGrid(ColorQuantity q) {
  return q == ColorQuantity::Vorticity || q == ColorQuantity::Array;
}

// Where the scale's ends come from: the current field's range of the quantity
// (as ParaView's "data range"; age: 0..1), render.color_min/max, or the live
// particles' range, which the main context measures and writes into
// render.color_min/max (so it reaches every wall at one frame, and replays).
enum class ColorRange : int { Field = 0, Fixed = 1, Particles = 2 };

struct ColorScale {
  ColorQuantity quantity = ColorQuantity::Age;
  float low = 0.0f;       // the value at t = 0
  float high = 1.0f;      // the value at t = 1
  bool log = false;       // t from log(value); needs 0 < low < high
  std::string note;       // why the scale differs from what was asked, or empty
  std::string arrayName;  // Array: the file's array, the legend's title

  // t for a value: clamped to [0, 1]; 0.5 for every value when low == high.
  float coordinate(float value) const;
  // The value at t (the legend's ticks sit at coordinate(value)).
  float valueAt(float t) const;
};

// The quantity's value for a particle; `gridValue`: the colour grid's value
// there (only Vorticity and Array read it).
float colorValue(const Particle& particle, ColorQuantity quantity, float gridValue = 0.0f);
std::string_view quantityName(ColorQuantity quantity);  // "speed"
std::string_view quantityUnit(ColorQuantity quantity);  // "m/s"; "" for age and arrays

// How the particles feel the field: velocity = velocityFactor * (rotated)
// field value (sim.field_strength * the placement's scale), vorticity =
// |strength| * the field's; a file's scalar array is felt as it is.
struct FieldFeel {
  float velocityFactor = 1.0f;
  float strength = 1.0f;
};

// The scale the walls use: ends from the field's range (as the particles feel
// it) or the fixed ones; a log scale with an end at or below 0 keeps three
// decades below the upper end (or falls back to linear when the upper end is
// not above 0), saying so in `note`.
ColorScale resolveColorScale(ColorQuantity quantity, ColorRange range, float fixedLow,
                             float fixedHigh, bool log, const FieldRange& field,
                             FieldFeel feel = {});

}  // namespace sandstorm
