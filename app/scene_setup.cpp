#include "app/scene_setup.h"

#include "core/field/vortex_field.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

double param(const FieldSpec& spec, const std::string& key, double fallback) {
  const auto it = spec.params.find(key);
  return it == spec.params.end() ? fallback : it->second;
}

VortexParams tornadoParams(const FieldSpec& spec) {
  static const char* known[] = {"center_x", "center_y", "center_z", "range", "height", "core", "spin", "pull", "up"};
  for (const auto& [key, value] : spec.params)
    if (std::find(std::begin(known), std::end(known), key) == std::end(known))
      throw Error(concat("field.params.", key, ": not a parameter of the tornado; expected one of center_x, center_y, "
                         "center_z, range, height, core, spin, pull, up"));
  VortexParams p;
  p.center = {param(spec, "center_x", 0), param(spec, "center_y", 0), param(spec, "center_z", 0)};
  p.range = float(param(spec, "range", p.range));
  p.height = float(param(spec, "height", p.height));
  p.core = float(param(spec, "core", p.core));
  p.spin = float(param(spec, "spin", p.spin));
  p.pull = float(param(spec, "pull", p.pull));
  p.up = float(param(spec, "up", p.up));
  return p;
}

}  // namespace

FieldUpdate makeField(const FieldSpec& spec, const std::filesystem::path&) {
  if (spec.source != "analytic")
    throw Error(concat("field.source '", spec.source, "': loading field files needs the field readers (core/io)"));
  if (spec.name != "tornado")
    throw Error(concat("field.name '", spec.name, "': unknown analytic field; expected tornado"));
  auto field = std::make_shared<VectorField>(bake(VortexField(tornadoParams(spec)), spec.bounds, spec.dims));
  log::info("field: analytic '", spec.name, "' baked to ", spec.dims.x, "x", spec.dims.y, "x", spec.dims.z,
            ", max speed ", field->maxMagnitude(), " m/s");
  return FieldUpdate{std::move(field), spec.placement};
}

std::shared_ptr<const HeightMap> makeTerrain(const SceneSpec& spec, const std::filesystem::path&) {
  if (spec.terrain == "flat") return std::make_shared<HeightMap>(HeightMap::flat(spec.groundHeight));
  throw Error(concat("scene.terrain '", spec.terrain, "': expected \"flat\""));
}

}  // namespace sandstorm
