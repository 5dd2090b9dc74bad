#include "core/field/field_range.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include "core/util/parallel_for.h"

namespace sandstorm {

FieldRange FieldRange::of(const VectorField& field, const glm::mat3& rotation,
                          const VectorField* colorGrid) {
  const auto values = field.values();
  const auto valid = field.validity();
  // Over the grid's cores in chunks, merged after: min and max do not depend
  // on the order (a 256^3 step took the main thread 0.1 s alone).
  struct Part {
    FieldRange r;
    bool any = false;
  };
  const auto empty = [] {
    Part p;
    p.r.minSpeed = std::numeric_limits<float>::max();
    p.r.maxSpeed = 0.0f;
    p.r.minVelocity = glm::vec3(std::numeric_limits<float>::max());
    p.r.maxVelocity = glm::vec3(std::numeric_limits<float>::lowest());
    return p;
  };
  std::mutex mutex;
  Part all = empty();
  forChunks(values.size(), [&](std::size_t begin, std::size_t end) {
    Part p = empty();
    for (std::size_t i = begin; i < end; ++i) {
      if (!valid.empty() && valid[i] == 0) continue;
      const glm::vec3 v = rotation * values[i];
      const float speed = glm::length(v);
      p.r.minSpeed = std::min(p.r.minSpeed, speed);
      p.r.maxSpeed = std::max(p.r.maxSpeed, speed);
      p.r.minVelocity = glm::min(p.r.minVelocity, v);
      p.r.maxVelocity = glm::max(p.r.maxVelocity, v);
      p.any = true;
    }
    std::lock_guard lock(mutex);
    all.r.minSpeed = std::min(all.r.minSpeed, p.r.minSpeed);
    all.r.maxSpeed = std::max(all.r.maxSpeed, p.r.maxSpeed);
    all.r.minVelocity = glm::min(all.r.minVelocity, p.r.minVelocity);
    all.r.maxVelocity = glm::max(all.r.maxVelocity, p.r.maxVelocity);
    all.any = all.any || p.any;
  });
  FieldRange r = all.r;
  const bool any = all.any;
  if (!any) return FieldRange{};
  if (colorGrid && colorGrid->pointCount() == values.size()) {
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    const auto w = colorGrid->values();
    for (std::size_t i = 0; i < w.size(); ++i) {
      if ((!valid.empty() && valid[i] == 0) || !std::isfinite(w[i].x)) continue;
      lo = std::min(lo, w[i].x);
      hi = std::max(hi, w[i].x);
    }
    if (lo <= hi) {
      r.minScalar = lo;
      r.maxScalar = hi;
    }
  }
  return r;
}

FieldRange FieldRange::of(const SparseField& field, const glm::mat3& rotation) {
  FieldRange r;
  r.minSpeed = std::numeric_limits<float>::max();
  r.maxSpeed = 0.0f;
  r.minVelocity = glm::vec3(std::numeric_limits<float>::max());
  r.maxVelocity = glm::vec3(std::numeric_limits<float>::lowest());
  bool any = false;
  field.forEachActive([&](const glm::vec3& value, std::uint64_t) {
    const glm::vec3 v = rotation * value;
    if (!std::isfinite(v.x + v.y + v.z)) return;
    const float speed = glm::length(v);
    r.minSpeed = std::min(r.minSpeed, speed);
    r.maxSpeed = std::max(r.maxSpeed, speed);
    r.minVelocity = glm::min(r.minVelocity, v);
    r.maxVelocity = glm::max(r.maxVelocity, v);
    any = true;
  });
  return any ? r : FieldRange{};
}

}  // namespace sandstorm
