// The downdraft demo's helicopter (thesis chapter 6): its controls are
// attributes (helicopter.throttle, .altitude, .x, .y), and, as in the thesis's
// interaction model, they drive the dust: more throttle raises the emission
// rate, the particles' lifetime and the maximum; climbing past a height where
// the rotor wash stops reaching the ground lowers them again. The thrust and
// rotor size also set the rotor-downwash field (core/field/downwash_field.h).
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

struct HelicopterSettings {
  bool enabled = false;
  float x = 0.0f, y = 0.0f;   // m: rotor hub over the ground
  float altitude = 8.0f;      // m: hub above the ground below it
  float throttle = 0.8f;      // 0..1; about 0.8 hovers
  bool wandThrottle = true;   // a tracked wand tilted up/down raises/lowers the throttle
  bool collide = true;        // dust bounces off its body (core/obstacles/helicopter_shape.h)
  bool collideRotor = false;  // ... and off the rotor disc
};

// The aircraft and how strongly its wash raises dust.
struct HelicopterModel {
  float mass = 4000.0f;           // kg
  float rotorRadius = 7.0f;       // m
  float maxThrustRatio = 1.25f;   // thrust / weight at full throttle
  float maxRate = 40000.0f;       // dust particles/s at full throttle near the ground
  int maxParticles = 200000;      // maximum at full throttle near the ground
  float maxLifetime = 6.0f;       // s
  float fullEffectHeight = 1.0f;  // x rotor radius: below this the wash raises all it can
  float noEffectHeight = 4.0f;    // x rotor radius: above this it raises none
};

struct HelicopterEffects {
  float thrust = 0.0f;        // N
  float groundEffect = 0.0f;  // 0..1: how much of the wash reaches the ground
  float rate = 0.0f;          // dust particles/s
  float lifetime = 0.0f;      // s
  int maximum = 0;
  float dustRadius = 0.0f;  // m: the disc on the ground that dust rises from
};

HelicopterEffects helicopterEffects(const HelicopterSettings& s, const HelicopterModel& m);

}  // namespace sandstorm
