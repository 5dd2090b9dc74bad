#include "core/flow/streamline_tracer.h"

#include <algorithm>
#include <cmath>

#include "core/flow/cash_karp.h"

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

// One fixed step of `h` metres from x; false where a stage meets still air.
bool fixedStep(glm::vec3& x, float h, float sign, StreamIntegrator method,
               const PhysicsInputs& in) {
  glm::vec3 k1, k2, k3, k4;
  if (!direction(x, sign, in, k1)) return false;
  if (method == StreamIntegrator::Euler) {
    x = x + h * k1;
    return true;
  }
  const float h2 = 0.5f * h;
  if (!direction(x + h2 * k1, sign, in, k2)) return false;
  if (method == StreamIntegrator::RK2) {
    x = x + h * k2;
    return true;
  }
  if (!direction(x + h2 * k2, sign, in, k3)) return false;
  if (!direction(x + h * k3, sign, in, k4)) return false;
  x = x + h * ((k1 + 2.0f * k2 + 2.0f * k3 + k4) * (1.0f / 6.0f));
  return true;
}

enum class Trial { Accepted, Rejected, Still };

constexpr float kMaxTurnCosine = 0.875f;

// One try of an RK45 step of `h` from x: accepted (x moved by the fifth-order
// solution) when the two orders are at most `tolerance` apart, or h can
// shrink no further; `small`: the error was under tolerance / 32, so twice the
// step would still pass (a fifth-order error grows 32-fold).
Trial rk45Step(glm::vec3& x, float h, float sign, float tolerance, bool shortest, bool& small,
               const PhysicsInputs& in) {
  using namespace cash_karp;
  const auto& c = kCashKarp;
  glm::vec3 k1, k2, k3, k4, k5, k6;
  if (!direction(x, sign, in, k1)) return Trial::Still;
  if (!direction(x + h * (c[A21] * k1), sign, in, k2)) return Trial::Still;
  if (!direction(x + h * (c[A31] * k1 + c[A32] * k2), sign, in, k3)) return Trial::Still;
  if (!direction(x + h * (c[A41] * k1 + c[A42] * k2 + c[A43] * k3), sign, in, k4))
    return Trial::Still;
  if (!direction(x + h * (c[A51] * k1 + c[A52] * k2 + c[A53] * k3 + c[A54] * k4), sign, in, k5))
    return Trial::Still;
  if (!direction(x + h * (c[A61] * k1 + c[A62] * k2 + c[A63] * k3 + c[A64] * k4 + c[A65] * k5),
                 sign, in, k6))
    return Trial::Still;
  const glm::vec3 error = h * (c[E1] * k1 + c[E3] * k3 + c[E4] * k4 + c[E5] * k5 + c[E6] * k6);
  // Squared lengths against the squared tolerance: no square root, so the
  // GPU decides exactly as the CPU where its arithmetic is IEEE's.
  const float error2 = glm::dot(error, error), tolerance2 = tolerance * tolerance;
  // A step that turns the line by more than about 29 degrees (cos = 0.875)
  // is too long whatever its error estimate says: round a circle much smaller
  // than the step, or across a cell face's kink in the interpolated field, the
  // two orders can agree by chance.
  const bool turns = glm::dot(k1, k6) < kMaxTurnCosine;
  if ((error2 > tolerance2 || turns) && !shortest) return Trial::Rejected;
  small = error2 * 1024.0f < tolerance2;  // |error| < tolerance / 32
  x = x + h * (c[B1] * k1 + c[B3] * k3 + c[B4] * k4 + c[B6] * k6);
  return Trial::Accepted;
}

std::vector<StreamlinePoint> oneWay(glm::vec3 x, float sign, int steps,
                                    const StreamlineSettings& rake, const PhysicsInputs& in) {
  std::vector<StreamlinePoint> out;
  if (rake.integrator != StreamIntegrator::RK45) {
    for (int s = 0; s < steps; ++s) {
      if (!fixedStep(x, rake.step, sign, rake.integrator, in) || !inside(x, in)) break;
      out.push_back({x, fieldAt(x, in)});
    }
    return out;
  }
  // Steps between step / 64 and step, halved and doubled (exact in floats).
  // A rejected step is retried; the loop ends since rejections stop at the shortest.
  const float longest = rake.step, shortest = rake.step * (1.0f / 64.0f);
  float h = longest, travelled = 0.0f;
  while (int(out.size()) < steps && travelled < rake.length) {
    const float tried = std::min(h, rake.length - travelled);
    bool small = false;
    glm::vec3 next = x;
    const Trial t = rk45Step(next, tried, sign, rake.tolerance, tried <= shortest, small, in);
    // Too inexact, or out of the field or into still air (a stage or the end):
    // shorter, down to the shortest step, so a line ends close to the edge.
    const bool outside = t == Trial::Accepted && !inside(next, in);
    if (t == Trial::Rejected || ((t == Trial::Still || outside) && tried > shortest)) {
      h = std::max(0.5f * tried, shortest);
      continue;
    }
    if (t == Trial::Still || outside) break;
    x = next;
    travelled += tried;
    out.push_back({x, fieldAt(x, in)});
    if (small) h = std::min(2.0f * h, longest);
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
  // RK45's steps may be shorter where the flow bends: room for 16 times as many.
  const double wanted = std::round(double(rake.length) / double(rake.step)) *
                        (rake.integrator == StreamIntegrator::RK45 ? 16.0 : 1.0);
  return int(
      std::min({wanted, double(kMaxStreamlineSteps), double(kMaxStreamlinePoints / lines - 1)}));
}

std::vector<Streamline> traceStreamlines(const StreamlineSettings& rake, const PhysicsInputs& in) {
  std::vector<Streamline> lines;
  if (!in.field) return lines;
  const int steps = streamlineSteps(rake);
  for (const glm::vec3& seed : rakeSeeds(rake)) {
    if (!inside(seed, in)) continue;
    std::vector<StreamlinePoint> back = oneWay(seed, -1.0f, steps, rake, in);
    Streamline line;
    line.points.assign(back.rbegin(), back.rend());
    line.seedIndex = int(line.points.size());
    line.points.push_back({seed, fieldAt(seed, in)});
    const std::vector<StreamlinePoint> ahead = oneWay(seed, 1.0f, steps, rake, in);
    line.points.insert(line.points.end(), ahead.begin(), ahead.end());
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace sandstorm
