#include "core/sim/helicopter.h"

#include <algorithm>

namespace sandstorm {

HelicopterEffects helicopterEffects(const HelicopterSettings& s, const HelicopterModel& m) {
  HelicopterEffects e;
  const float throttle = std::clamp(s.throttle, 0.0f, 1.0f);
  e.thrust = throttle * m.maxThrustRatio * m.mass * 9.81f;
  const float lo = m.fullEffectHeight * m.rotorRadius, hi = m.noEffectHeight * m.rotorRadius;
  e.groundEffect = std::clamp((hi - s.altitude) / (hi - lo), 0.0f, 1.0f);
  const float drive = throttle * e.groundEffect;
  e.rate = m.maxRate * drive;
  e.lifetime = std::max(0.5f, m.maxLifetime * (0.4f + 0.6f * drive));
  e.maximum = std::max(1000, int(float(m.maxParticles) * drive));
  e.dustRadius = m.rotorRadius * (1.5f + 1.5f * drive);
  return e;
}

}  // namespace sandstorm
