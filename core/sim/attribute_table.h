// AttributeTable: the table of dynamic attributes (thesis section 5.4, Table 5.1).
//
// Every value of ParticleState that may change at run time has one entry here,
// with a type, a range, a unit, a default and a one-line description. The menu,
// the config file, the command line (--set key=value), recorded sessions and
// C++ callers all change the state through this table, so they share one set of
// names, one validation and one set of messages.
//
// Keys are dotted: "sim.maximum", "render.size", "emitter.0.rate". The thesis's
// names are accepted as aliases of the first emitter and the system:
// Size, Lifetime, AreaWidth, AreaDepth, Maximum, Position.
//
// Out-of-range numbers are clamped, and the clamp is reported in the result's
// message; wrong types, unknown keys and unknown enum choices are refused with
// an Error that names the key and what was expected. The table is immutable and
// safe to share between threads.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "core/sim/particle_state.h"

namespace sandstorm {

// Name: a name chosen at run time (a field array's, "Temperature (K)"), 0 to
// kMaxNameLength printable ASCII characters without '=', '#', '%' or quotes,
// spaces only between words; empty means "the default". Where a name must be
// one word (session logs, --set) a space is written %20 and the empty name a
// lone %: encodeName and AttributeTable::parse.
// Expression: one component of a field written at run time (muParser's
// language, core/expr/field_expression.h), at most kMaxExpressionLength
// characters; checked by both muParser and the GLSL translation. It travels
// like a Name (spaces as %20 where one word is needed).
enum class AttributeType { Bool, Int, Float, Vec3, Enum, Name, Expression };
inline constexpr std::size_t kMaxNameLength = 64;
inline constexpr std::size_t kMaxExpressionLength = 256;

// Enum and Name values travel as strings ("rk4"), so they print and parse as written.
using AttributeValue = std::variant<bool, int, float, glm::vec3, std::string>;

struct AttributeInfo {
  std::string key;  // "render.size"; emitter entries use "emitter.*.rate"
  AttributeType type;
  float min = 0.0f;  // Int, Float and each Vec3 component
  float max = 0.0f;
  std::string unit;
  AttributeValue defaultValue;
  std::string description;
  std::vector<std::string> choices;  // Enum only
  bool direction = false;            // Vec3 only: a direction, so (0, 0, 0) is refused
  std::function<AttributeValue(const ParticleState&, int emitter)> get;
  std::function<void(ParticleState&, int emitter, const AttributeValue&)> set;

  bool perEmitter() const { return key.starts_with("emitter.*."); }
  bool perObstacle() const { return key.starts_with("obstacle.*."); }
  // Whether the key is one of a list's (emitter.N.x, obstacle.N.x).
  bool perPrimitive() const { return key.starts_with("primitive.*."); }
  bool perItem() const { return perEmitter() || perObstacle() || perPrimitive(); }
  // The key of item `index`: "emitter.*.rate" -> "emitter.2.rate".
  std::string itemKey(int index) const;
  // "5000 is outside [1e-07, 1000] m": `value` as written, against the range.
  std::string outsideRange(std::string_view value) const;
};

// What set() did: the value it stored and, if it had to clamp, a message saying so.
struct AttributeResult {
  AttributeValue applied;
  std::string warning;  // empty unless the value was clamped
};

class AttributeTable {
 public:
  static const AttributeTable& instance();

  std::span<const AttributeInfo> entries() const { return entries_; }

  // The entry for a key ("emitter.2.rate" finds "emitter.*.rate" and sets
  // *emitter to 2; obstacle.N.x alike); aliases resolve too. Throws Error for unknown keys, listing
  // close matches.
  const AttributeInfo& lookup(std::string_view key, int* emitter = nullptr) const;

  // Converts text ("0.5", "true", "1 2 3", "rk4") to the entry's type. Throws
  // Error naming the key and the expected form.
  AttributeValue parse(std::string_view key, std::string_view text) const;

  // Checks and clamps a value against the entry; does not touch any state.
  AttributeResult validate(std::string_view key, const AttributeValue& value) const;

  // validate(), then store. Throws for an emitter index that does not exist.
  AttributeResult set(ParticleState& state, std::string_view key,
                      const AttributeValue& value) const;
  AttributeValue get(const ParticleState& state, std::string_view key) const;

  // Every attribute as "key=value" lines, emitters included: a fingerprint of a
  // replica's state.
  std::string describe(const ParticleState& state) const;

  // Canonical key: aliases map to their target ("Size" -> "render.size").
  std::string canonical(std::string_view key) const;

 private:
  AttributeTable();
  std::vector<AttributeInfo> entries_;
};

std::string toString(const AttributeValue& value);
// A Name (or any string value) as one word: spaces as %20, empty as %.
std::string encodeName(std::string_view name);

}  // namespace sandstorm
