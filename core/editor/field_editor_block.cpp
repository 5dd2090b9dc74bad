#include "core/editor/field_editor_block.h"

#include <charconv>
#include <filesystem>
#include <sstream>

#include "core/sim/attribute_table.h"
#include "core/util/toml_text.h"

namespace sandstorm {
namespace {

// The shortest text that reads back to the same float, always a TOML float.
std::string number(double v, bool single = true) {
  char buffer[64];
  const auto result = single ? std::to_chars(buffer, buffer + sizeof buffer, float(v))
                             : std::to_chars(buffer, buffer + sizeof buffer, v);
  std::string s(buffer, result.ptr);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string vec(const glm::vec3& v) {
  return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]";
}

std::string ivec(const glm::ivec3& v) {
  return "[" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + "]";
}

}  // namespace

std::string fieldEditorBlock(const FieldSpec& field, std::span<const FieldPrimitive> primitives) {
  std::ostringstream out;
  out << "# The field editor's composition (Sandstorm): the field below plus each\n"
         "# [[primitive]]. Include it from a configuration with walls\n"
         "# (include = \"this file\") or paste it in.\n\n[field]\n";
  if (field.source == "analytic") {
    out << "source = \"analytic\"\nname = " << tomlString(field.name) << "\n";
    out << "dims = " << ivec(field.dims) << "\n";
    out << "bounds_min = " << vec(field.bounds.min) << "\nbounds_max = " << vec(field.bounds.max)
        << "\n";
    if (!field.params.empty()) {
      out << "params = {";
      bool first = true;
      for (const auto& [key, value] : field.params) {
        out << (first ? " " : ", ") << key << " = " << number(value, false);
        first = false;
      }
      out << " }\n";
    }
  } else {
    out << "source = "
        << tomlString(std::filesystem::absolute(field.source).lexically_normal().string()) << "\n";
    if (!field.name.empty()) out << "name = " << tomlString(field.name) << "\n";
    if (field.resolution != glm::ivec3(0)) out << "resolution = " << ivec(field.resolution) << "\n";
  }
  out << "offset = " << vec(field.placement.offset) << "\nscale = " << number(field.placement.scale)
      << "\nrotation_deg = " << vec(field.rotationDegrees) << "\n";

  // The kinds' names as the attribute table spells them.
  const std::vector<std::string>& kinds =
      AttributeTable::instance().lookup("primitive.0.kind").choices;
  // Slots up to the last filled one, empty ones as kind none: they keep their numbers.
  std::size_t used = primitives.size();
  while (used > 0 && primitives[used - 1].kind == PrimitiveKind::None)
    --used;
  for (std::size_t i = 0; i < used; ++i) {
    const FieldPrimitive& p = primitives[i];
    out << "\n[[primitive]]\nkind = " << tomlString(kinds.at(std::size_t(p.kind)))
        << "\nposition = " << vec(p.position) << "\naxis = " << vec(p.axis)
        << "\nstrength = " << number(p.strength) << "\nradius = " << number(p.radius)
        << "\nenabled = " << (p.enabled ? "true" : "false") << "\n";
  }
  return out.str();
}

}  // namespace sandstorm
