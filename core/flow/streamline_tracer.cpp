#include "core/flow/streamline_tracer.h"

#include <algorithm>
#include <cmath>

namespace sandstorm {
namespace {

constexpr float kStill = 1e-6f;  // m/s: slower flow ends a streamline

bool inside(const glm::vec3& x, const PhysicsInputs& in) {
  const glm::vec3 local = in.placement.toLocal(x);
  return particleDomain(*in.field).contains(local) && in.field->cellValid(local) &&
         (!in.nextField || in.nextField->cellValid(local));
}

// The unit direction of the flow at x, times `sign`; false where it stands still.
bool direction(const glm::vec3& x, float sign, const PhysicsInputs& in, glm::vec3& d) {
  const glm::vec3 f = fieldAt(x, in);
  const float speed = glm::length(f);
  if (!(speed >= kStill)) return false;
  d = f * (sign / speed);
  return true;
}

// One step of `h` metres from x; false where a stage meets still air.
bool step(glm::vec3& x, float h, float sign, const PhysicsInputs& in) {
  glm::vec3 k1, k2, k3, k4;
  if (!direction(x, sign, in, k1)) return false;
  if (in.settings.integrator == Integrator::Euler) {
    x = x + h * k1;
    return true;
  }
  const float h2 = 0.5f * h;
  if (!direction(x + h2 * k1, sign, in, k2)) return false;
  if (in.settings.integrator == Integrator::RK2) {
    x = x + h * k2;
    return true;
  }
  if (!direction(x + h2 * k2, sign, in, k3)) return false;
  if (!direction(x + h * k3, sign, in, k4)) return false;
  x = x + h * ((k1 + 2.0f * k2 + 2.0f * k3 + k4) * (1.0f / 6.0f));
  return true;
}

std::vector<StreamlinePoint> oneWay(glm::vec3 x, float sign, int steps, float h,
                                    const PhysicsInputs& in) {
  std::vector<StreamlinePoint> out;
  for (int s = 0; s < steps; ++s) {
    if (!step(x, h, sign, in) || !inside(x, in)) break;
    out.push_back({x, fieldAt(x, in)});
  }
  return out;
}

}  // namespace

std::vector<glm::vec3> rakeSeeds(const StreamlineSettings& rake) {
  const int n = std::clamp(rake.seeds, 1, kMaxStreamlineSeeds);
  auto at = [n](int i) { return n == 1 ? 0.5f : float(i) / float(n - 1); };
  std::vector<glm::vec3> seeds;
  const glm::vec3 along = rake.to - rake.from, up = rake.across - rake.from;
  for (int j = 0; j < (rake.shape == RakeShape::Plane ? n : 1); ++j)
    for (int i = 0; i < n; ++i)
      seeds.push_back(rake.from + at(i) * along +
                      (rake.shape == RakeShape::Plane ? at(j) * up : glm::vec3(0.0f)));
  return seeds;
}

int streamlineSteps(const StreamlineSettings& rake) {
  if (!(rake.step > 0.0f) || !(rake.length > 0.0f)) return 0;
  const int lines = 2 * int(rakeSeeds(rake).size());
  // Rounded: 12 m in steps of 0.05f (a little over 0.05) is 240 steps, not 239.
  const double wanted = std::round(double(rake.length) / double(rake.step));
  return int(
      std::min({wanted, double(kMaxStreamlineSteps), double(kMaxStreamlinePoints / lines - 1)}));
}

std::vector<Streamline> traceStreamlines(const StreamlineSettings& rake, const PhysicsInputs& in) {
  std::vector<Streamline> lines;
  if (!in.field) return lines;
  const int steps = streamlineSteps(rake);
  for (const glm::vec3& seed : rakeSeeds(rake)) {
    if (!inside(seed, in)) continue;
    std::vector<StreamlinePoint> back = oneWay(seed, -1.0f, steps, rake.step, in);
    Streamline line;
    line.points.assign(back.rbegin(), back.rend());
    line.seedIndex = int(line.points.size());
    line.points.push_back({seed, fieldAt(seed, in)});
    const std::vector<StreamlinePoint> ahead = oneWay(seed, 1.0f, steps, rake.step, in);
    line.points.insert(line.points.end(), ahead.begin(), ahead.end());
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace sandstorm
