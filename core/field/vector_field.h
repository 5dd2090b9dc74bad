// VectorField: a dense 3D grid of vectors, the form every field takes before it
// reaches the GPU (where it becomes a 3D texture).
//
// Layout, as in VTK image data and OpenGL 3D textures:
//   - values live at grid points; point (i, j, k) sits at
//       bounds.min + (bounds.max - bounds.min) * (i, j, k) / (dims - 1);
//   - values are stored x-fastest: index = i + dims.x * (j + dims.y * k).
// A dimension of 1 makes the field constant along that axis.
//
// Sampling is trilinear between grid points and clamps to the bounds (a point
// outside takes the value at the nearest boundary point). sample() performs
// exactly the operations of shaders/field_sample.glsl, in the same order, so the
// CPU reference simulator and the GPU agree to the last bit where the hardware
// rounds as IEEE does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/field/box.h"
#include "core/field/value_range.h"
#include "core/field/vector_values.h"
#include "core/util/error.h"

namespace sandstorm {

class VectorField {
 public:
  // A guard against sizes that overflow, not a limit users meet: 2^36 points
  // (768 GiB of vectors) is beyond any GPU's memory and 2048^3 textures. What
  // limits a grid is memory: field.memory_budget, checked by every reader.
  static constexpr std::size_t kMaxPoints = std::size_t{1} << 36;

  VectorField() = default;
  // Throws Error when dims are not positive, the point count exceeds kMaxPoints,
  // the bounds are empty along an axis with more than one point, or the value
  // count differs from the point count. `values` may be a std::vector or a
  // reading library's memory adopted (VectorValues::adopt).
  VectorField(const Box& bounds, const glm::ivec3& dims);
  VectorField(const Box& bounds, const glm::ivec3& dims, VectorValues values);
  VectorField(const Box& bounds, const glm::ivec3& dims, std::vector<glm::vec3> values)
      : VectorField(bounds, dims, VectorValues(std::move(values))) {}

  const Box& bounds() const { return bounds_; }
  const glm::ivec3& dims() const { return dims_; }
  std::size_t pointCount() const { return values_.size(); }
  bool empty() const { return values_.empty(); }

  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(dims_.x) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims_.y) * k);
  }
  const glm::vec3& at(int i, int j, int k) const { return values_[index(i, j, k)]; }
  // Access to change the values forgets their remembered range and that
  // they are halves (roundToHalf again after changing them).
  glm::vec3& at(int i, int j, int k) {
    range_.reset();
    half_ = false;
    return values_[index(i, j, k)];
  }
  std::span<const glm::vec3> values() const { return values_.span(); }
  std::span<glm::vec3> values() {
    range_.reset();
    half_ = false;
    return values_.span();
  }
  // Whether the vectors are the reading library's memory, held rather than copied.
  bool adoptedValues() const { return values_.adopted(); }

  // World position of grid point (i, j, k).
  glm::vec3 pointPosition(int i, int j, int k) const;
  // Grid spacing per axis (0 along an axis of one point).
  glm::vec3 spacing() const;
  // (dims - 1) / extent per axis: multiplies (p - min) into index space. The GPU
  // gets this very value as a uniform, so both sides compute the same indices.
  glm::vec3 indexScale() const { return indexScale_; }

  glm::vec3 sample(const glm::vec3& p) const;
  // A time-varying field's pair blended point by point and then sampled, as
  // the compute update samples the grid FieldPairBlend makes of it: each
  // corner of the cell is at + (next.at - at) * weight, rounded to the
  // nearest half when both grids are halves, then interpolated as sample()
  // does. `next` shares this grid's dims and bounds.
  glm::vec3 sampleBlended(const VectorField& next, float weight, const glm::vec3& p) const;

  // Points the grid has no data for (a curvilinear or unstructured file
  // resampled onto this box leaves points outside the file's cells): one byte
  // per point, 1 valid, 0 not; empty when every point is valid. Particles
  // treat a cell with any invalid corner as outside the field
  // (particle_physics.h), on the GPU too. Throws Error when the size is not
  // the point count; a mask with every point valid is dropped.
  void setValidity(std::vector<std::uint8_t> valid);
  bool hasValidity() const { return !valid_.empty(); }
  std::span<const std::uint8_t> validity() const { return valid_; }
  bool valid(int i, int j, int k) const { return valid_.empty() || valid_[index(i, j, k)] != 0; }
  std::size_t invalidCount() const;
  // Whether every corner of the cell that sample(p) interpolates in is valid
  // (the same cell, found by the same operations, as the shaders').
  bool cellValid(const glm::vec3& p) const;

  // field.precision = "half": every vector component rounded to the nearest
  // 16-bit float (IEEE binary16, ties to even: core/util/half_float.h), so that the GPU keeps the
  // grid as 16-bit floats (half the memory and bandwidth) and reads back exactly these values,
  // which the CPU twin samples too. The error is at most 2^-11 of a component (2^-25 absolute below
  // 2^-14): within 1e-3 of the field's largest speed. Throws Error, changing nothing, when a
  // component is beyond what half holds (65504). Call after the values are final.
  void roundToHalf();
  bool halfPrecision() const { return half_; }
  static constexpr float kHalfMax = 65504.0f;
  // For a reader that rounded every component with roundToHalves as it
  // checked them (one pass over a series' step instead of three): marks the
  // values halves without reading them again.
  void markRoundedToHalf() { half_ = true; }
  // The error roundToHalf throws for component `value` of point `point`.
  static Error beyondHalf(std::size_t point, float value);

  // The speed and velocity range over the valid points, in the grid's own
  // axes (FieldRange::of starts from it), when remembered by whoever last
  // passed over every value anyway: a file's reader checking each vector
  // (after setValidity), roundToHalf. A series' 200 MB step is then not read
  // once more on the main thread. Changing values or validity forgets it;
  // rememberRange must be given the range of the values as they are.
  const std::optional<ValueRange>& rememberedRange() const { return range_; }
  void rememberRange(const ValueRange& range) { range_ = range; }

  // The largest vector length over every point, for colour scales and
  // summaries (the remembered range's when every point is valid).
  float maxMagnitude() const;

  // Scalar arrays the file carried with the vectors (temperature, pressure),
  // one float per grid point in the same layout, for colouring particles by
  // them (render.color_by = array). Non-finite values are stored as given;
  // users of the values skip them. addScalars throws Error when the count is
  // not the point count, the name is empty or already taken.
  struct Scalars {
    std::string name;
    std::vector<float> values;
  };
  void addScalars(std::string name, std::vector<float> values);
  std::span<const Scalars> scalars() const { return scalars_; }
  const Scalars* findScalars(std::string_view name) const;
  // A scalar array sampled at p as sample() samples the vectors.
  float sampleScalars(const Scalars& scalars, const glm::vec3& p) const;
  // "'temperature', 'pressure'", or "none": for messages.
  std::string scalarNames() const;

 private:
  Box bounds_;
  glm::ivec3 dims_{0};
  glm::vec3 indexScale_{0.0f};
  VectorValues values_;
  std::vector<std::uint8_t> valid_;
  std::vector<Scalars> scalars_;
  bool half_ = false;
  std::optional<ValueRange> range_;
};

}  // namespace sandstorm
