// StateChange: one edit of the ParticleState, as the main context validated it.
// Render contexts apply changes blindly with applyChange(); validation, clamping
// and messages happen once, on the main context, before a change is shipped.
#pragma once

#include <string>

#include "core/sim/attribute_table.h"
#include "core/sim/emitter.h"
#include "core/sim/particle_state.h"

namespace sandstorm {

struct StateChange {
  enum class Kind { Set, AddEmitter, RemoveEmitter, Reset };
  Kind kind = Kind::Set;
  std::string key;       // Set: canonical attribute key
  AttributeValue value;  // Set: the validated value
  int index = 0;         // RemoveEmitter: which one
  Emitter emitter;       // AddEmitter: the new emitter, appended at the end

  static StateChange set(std::string key, AttributeValue value);
  static StateChange addEmitter(const Emitter& emitter);
  static StateChange removeEmitter(int index);
  static StateChange reset();  // drop every particle (the thesis's F10 reset)
};

// Applies a validated change. Throws Error for a change that does not fit the
// state (an emitter index out of range, too many emitters).
void applyChange(ParticleState& state, const StateChange& change);

std::string describe(const StateChange& change);

}  // namespace sandstorm
