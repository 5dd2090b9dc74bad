#include "core/sim/state_change.h"

#include "core/util/error.h"

namespace sandstorm {

StateChange StateChange::set(std::string key, AttributeValue value) {
  StateChange c;
  c.kind = Kind::Set;
  c.key = std::move(key);
  c.value = std::move(value);
  return c;
}

StateChange StateChange::addEmitter(const Emitter& emitter) {
  StateChange c;
  c.kind = Kind::AddEmitter;
  c.emitter = emitter;
  return c;
}

StateChange StateChange::removeEmitter(int index) {
  StateChange c;
  c.kind = Kind::RemoveEmitter;
  c.index = index;
  return c;
}

StateChange StateChange::reset() {
  StateChange c;
  c.kind = Kind::Reset;
  return c;
}

void applyChange(ParticleState& state, const StateChange& change) {
  switch (change.kind) {
    case StateChange::Kind::Set:
      AttributeTable::instance().set(state, change.key, change.value);
      break;
    case StateChange::Kind::AddEmitter:
      if (int(state.emitters.size()) >= ParticleState::kMaxEmitters)
        throw Error(concat("cannot add an emitter: the limit is ", ParticleState::kMaxEmitters));
      state.emitters.push_back(change.emitter);
      break;
    case StateChange::Kind::RemoveEmitter:
      if (change.index < 0 || change.index >= int(state.emitters.size()))
        throw Error(
            concat("cannot remove emitter ", change.index, ": there are ", state.emitters.size()));
      state.emitters.erase(state.emitters.begin() + change.index);
      break;
    case StateChange::Kind::Reset:
      break;  // the particles go; the state stays
  }
}

std::string describe(const StateChange& change) {
  switch (change.kind) {
    case StateChange::Kind::Set:
      return change.key + " = " + toString(change.value);
    case StateChange::Kind::AddEmitter:
      return "add emitter";
    case StateChange::Kind::RemoveEmitter:
      return concat("remove emitter ", change.index);
    case StateChange::Kind::Reset:
      return "reset";
  }
  return "?";
}

}  // namespace sandstorm
