#include "core/field/vector_field.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "core/util/error.h"
#include "core/util/half_arrays.h"
#include "core/util/half_float.h"
#include "core/util/parallel_for.h"

namespace sandstorm {
namespace {

void validate(const Box& bounds, const glm::ivec3& dims) {
  for (int a = 0; a < 3; ++a) {
    if (dims[a] <= 0)
      throw Error(concat("VectorField: dimension ", "xyz"[a], " is ", dims[a],
                         "; expected a positive point count"));
  }
  const double points = double(dims.x) * double(dims.y) * double(dims.z);
  if (points > double(VectorField::kMaxPoints))
    throw Error(concat("VectorField: ", dims.x, "x", dims.y, "x", dims.z, " = ", points,
                       " points exceeds the limit of ", VectorField::kMaxPoints));
  for (int a = 0; a < 3; ++a) {
    const float extent = bounds.max[a] - bounds.min[a];
    if (!std::isfinite(bounds.min[a]) || !std::isfinite(bounds.max[a]))
      throw Error(concat("VectorField: bounds along ", "xyz"[a], " are not finite"));
    if (dims[a] > 1 && !(extent > 0.0f))
      throw Error(concat("VectorField: bounds along ", "xyz"[a], " span ", extent, " m for ",
                         dims[a], " points; expected a positive extent"));
  }
}

}  // namespace

VectorField::VectorField(const Box& bounds, const glm::ivec3& dims)
    : VectorField(bounds, dims, VectorValues()) {}

VectorField::VectorField(const Box& bounds, const glm::ivec3& dims, VectorValues values)
    : bounds_(bounds), dims_(dims), values_(std::move(values)) {
  validate(bounds, dims);
  const std::size_t count = std::size_t(dims.x) * dims.y * dims.z;
  if (values_.empty()) values_ = std::vector<glm::vec3>(count, glm::vec3(0.0f));
  if (values_.size() != count)
    throw Error(concat("VectorField: ", values_.size(), " values for ", count, " grid points"));
  for (int a = 0; a < 3; ++a)
    indexScale_[a] = dims[a] > 1 ? float(dims[a] - 1) / (bounds.max[a] - bounds.min[a]) : 0.0f;
}

void VectorField::roundToHalf() {
  // Checked over the cores before anything changes, then rounded over them:
  // a series rounds a 256^3 step (50 million components) on each reader.
  const std::span<glm::vec3> values = values_.span();
  std::mutex mutex;
  std::size_t firstBad = values.size();  // the message names the first such point
  forChunks(values.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      if (!(std::abs(values[i].x) <= kHalfMax && std::abs(values[i].y) <= kHalfMax &&
            std::abs(values[i].z) <= kHalfMax)) {
        std::lock_guard lock(mutex);
        firstBad = std::min(firstBad, i);
        return;
      }
  });
  if (const std::size_t i = firstBad; i < values.size()) {
    int c = 0;
    while (std::abs(values[i][c]) <= kHalfMax)
      ++c;
    throw beyondHalf(i, values[i][c]);
  }
  // The range of the rounded values is found while the chunk is at hand.
  ValueRange range;
  forChunks(values.size(), [&](std::size_t begin, std::size_t end) {
    roundToHalves(&values[begin].x, 3 * (end - begin));
    ValueRange part;
    for (std::size_t i = begin; i < end; ++i)
      if (valid_.empty() || valid_[i] != 0) part.add(values[i]);
    std::lock_guard lock(mutex);
    range.merge(part);
  });
  half_ = true;
  range_ = range;
}

Error VectorField::beyondHalf(std::size_t point, float value) {
  return Error(concat("field.precision = \"half\": point ", point, " has the component ", value,
                      ", beyond the ", kHalfMax,
                      " that 16-bit floats hold; keep field.precision = \"float\" or scale "
                      "the field's units"));
}

glm::vec3 VectorField::pointPosition(int i, int j, int k) const {
  return bounds_.min + spacing() * glm::vec3(i, j, k);
}

glm::vec3 VectorField::spacing() const {
  glm::vec3 s(0.0f);
  for (int a = 0; a < 3; ++a)
    if (dims_[a] > 1) s[a] = (bounds_.max[a] - bounds_.min[a]) / float(dims_[a] - 1);
  return s;
}

namespace {

// Trilinear interpolation of the cell around p of a grid with `dims`, its
// corners given by corner(i, j, k): fieldSample() in
// shaders/particle_physics.glsl, operation by operation.
template <class Corner>
glm::vec3 interpolate(const glm::vec3& p, const glm::vec3& boundsMin, const glm::vec3& indexScale,
                      const glm::ivec3& dims, const Corner& corner) {
  const glm::vec3 last = glm::vec3(dims - 1);
  const glm::vec3 u = glm::clamp((p - boundsMin) * indexScale, glm::vec3(0.0f), last);
  const glm::ivec3 i0 = glm::min(glm::ivec3(glm::floor(u)), glm::max(dims - 2, glm::ivec3(0)));
  const glm::ivec3 i1 = glm::min(i0 + 1, dims - 1);
  const glm::vec3 f = u - glm::vec3(i0);

  const glm::vec3 c000 = corner(i0.x, i0.y, i0.z), c100 = corner(i1.x, i0.y, i0.z);
  const glm::vec3 c010 = corner(i0.x, i1.y, i0.z), c110 = corner(i1.x, i1.y, i0.z);
  const glm::vec3 c001 = corner(i0.x, i0.y, i1.z), c101 = corner(i1.x, i0.y, i1.z);
  const glm::vec3 c011 = corner(i0.x, i1.y, i1.z), c111 = corner(i1.x, i1.y, i1.z);

  const glm::vec3 c00 = c000 + (c100 - c000) * f.x;
  const glm::vec3 c10 = c010 + (c110 - c010) * f.x;
  const glm::vec3 c01 = c001 + (c101 - c001) * f.x;
  const glm::vec3 c11 = c011 + (c111 - c011) * f.x;
  const glm::vec3 c0 = c00 + (c10 - c00) * f.y;
  const glm::vec3 c1 = c01 + (c11 - c01) * f.y;
  return c0 + (c1 - c0) * f.z;
}

}  // namespace

glm::vec3 VectorField::sample(const glm::vec3& p) const {
  return interpolate(p, bounds_.min, indexScale_, dims_,
                     [this](int i, int j, int k) { return at(i, j, k); });
}

glm::vec3 VectorField::sampleBlended(const VectorField& next, float weight,
                                     const glm::vec3& p) const {
  // Each corner as shaders/field_blend.comp writes it.
  const bool halves = half_ && next.half_;
  return interpolate(p, bounds_.min, indexScale_, dims_, [&](int i, int j, int k) {
    const glm::vec3 a = at(i, j, k);
    glm::vec3 c = a + (next.at(i, j, k) - a) * weight;
    if (halves)
      for (int n = 0; n < 3; ++n)
        c[n] = nearestHalf(c[n]);
    return c;
  });
}

float VectorField::sampleScalars(const Scalars& scalars, const glm::vec3& p) const {
  const glm::vec3 last = glm::vec3(dims_ - 1);
  const glm::vec3 u = glm::clamp((p - bounds_.min) * indexScale_, glm::vec3(0.0f), last);
  const glm::ivec3 i0 = glm::min(glm::ivec3(glm::floor(u)), glm::max(dims_ - 2, glm::ivec3(0)));
  const glm::ivec3 i1 = glm::min(i0 + 1, dims_ - 1);
  const glm::vec3 f = u - glm::vec3(i0);
  const auto v = [&](int i, int j, int k) { return scalars.values[index(i, j, k)]; };
  const float c00 = v(i0.x, i0.y, i0.z) + (v(i1.x, i0.y, i0.z) - v(i0.x, i0.y, i0.z)) * f.x;
  const float c10 = v(i0.x, i1.y, i0.z) + (v(i1.x, i1.y, i0.z) - v(i0.x, i1.y, i0.z)) * f.x;
  const float c01 = v(i0.x, i0.y, i1.z) + (v(i1.x, i0.y, i1.z) - v(i0.x, i0.y, i1.z)) * f.x;
  const float c11 = v(i0.x, i1.y, i1.z) + (v(i1.x, i1.y, i1.z) - v(i0.x, i1.y, i1.z)) * f.x;
  const float c0 = c00 + (c10 - c00) * f.y;
  const float c1 = c01 + (c11 - c01) * f.y;
  return c0 + (c1 - c0) * f.z;
}

void VectorField::setValidity(std::vector<std::uint8_t> valid) {
  if (!valid.empty() && valid.size() != values_.size())
    throw Error(concat("VectorField: a validity mask of ", valid.size(), " points for ",
                       values_.size(), " grid points"));
  range_.reset();
  for (std::uint8_t& v : valid)
    v = v != 0;
  const bool all = std::all_of(valid.begin(), valid.end(), [](std::uint8_t v) { return v != 0; });
  valid_ = all ? std::vector<std::uint8_t>() : std::move(valid);
}

void VectorField::addScalars(std::string name, std::vector<float> values) {
  if (name.empty()) throw Error("VectorField: a scalar array needs a name");
  if (values.size() != values_.size())
    throw Error(concat("VectorField: scalar array '", name, "' has ", values.size(), " values for ",
                       values_.size(), " grid points"));
  if (findScalars(name)) throw Error(concat("VectorField: two scalar arrays named '", name, "'"));
  scalars_.push_back({std::move(name), std::move(values)});
}

const VectorField::Scalars* VectorField::findScalars(std::string_view name) const {
  for (const Scalars& s : scalars_)
    if (s.name == name) return &s;
  return nullptr;
}

std::string VectorField::scalarNames() const {
  std::string out;
  for (const Scalars& s : scalars_)
    out += (out.empty() ? "'" : ", '") + s.name + "'";
  return out.empty() ? "none" : out;
}

std::size_t VectorField::invalidCount() const {
  return std::size_t(std::count(valid_.begin(), valid_.end(), std::uint8_t{0}));
}

bool VectorField::cellValid(const glm::vec3& p) const {
  if (valid_.empty()) return true;
  // The cell as sample() finds it.
  const glm::vec3 last = glm::vec3(dims_ - 1);
  const glm::vec3 u = glm::clamp((p - bounds_.min) * indexScale_, glm::vec3(0.0f), last);
  const glm::ivec3 i0 = glm::min(glm::ivec3(glm::floor(u)), glm::max(dims_ - 2, glm::ivec3(0)));
  const glm::ivec3 i1 = glm::min(i0 + 1, dims_ - 1);
  for (int k : {i0.z, i1.z})
    for (int j : {i0.y, i1.y})
      for (int i : {i0.x, i1.x})
        if (!valid_[index(i, j, k)]) return false;
  return true;
}

float VectorField::maxMagnitude() const {
  // Every point counts here, so a range over the valid ones answers only
  // when all are valid. Otherwise over the cores: said once a field opens,
  // and a 1024^3 grid is 10^9 vectors.
  if (range_ && valid_.empty()) return range_->any ? range_->maxSpeed() : 0.0f;
  const std::span<const glm::vec3> values = values_.span();
  std::mutex mutex;
  float fastest2 = 0.0f;  // squared: the square root commutes with max
  forChunks(values.size(), [&](std::size_t begin, std::size_t end) {
    float m2 = 0.0f;
    for (std::size_t i = begin; i < end; ++i)
      m2 = std::max(m2, glm::dot(values[i], values[i]));
    std::lock_guard lock(mutex);
    fastest2 = std::max(fastest2, m2);
  });
  return std::sqrt(fastest2);
}

}  // namespace sandstorm
