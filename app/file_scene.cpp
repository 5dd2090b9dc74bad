#include "app/file_scene.h"

#include <algorithm>
#include <cmath>

#include <set>
#include <utility>
#include <vector>

#include "core/config/config_sets.h"
#include "core/io/field_format.h"
#include "core/io/pvd_file.h"
#include "core/io/vtk_legacy_parser.h"
#include "core/io/vtk_xml_check.h"
#include "core/sim/attribute_table.h"
#include "core/sim/main_context.h"
#include "core/util/error.h"
#include "core/util/log.h"
#include "core/util/parallel_for.h"

namespace sandstorm {
namespace {

// The mean velocity and mean speed over the field's valid points.
struct Flow {
  glm::vec3 mean{0.0f};
  float meanSpeed = 0.0f;
};

// Over the cores in blocks of a fixed size, summed in block order: the same
// sums whatever the machine's cores (one thread took 0.4-0.6 s at 512^3).
Flow meanFlow(const VectorField& field) {
  const auto values = field.values();
  const auto valid = field.validity();
  constexpr std::size_t kBlock = std::size_t{1} << 20;
  struct Sums {
    glm::dvec3 velocity{0.0};
    double speed = 0.0;
    std::size_t points = 0;
  };
  std::vector<Sums> blocks((values.size() + kBlock - 1) / kBlock);
  forChunks(
      blocks.size(),
      [&](std::size_t first, std::size_t last) {
        for (std::size_t b = first; b < last; ++b) {
          Sums& s = blocks[b];
          for (std::size_t i = b * kBlock; i < std::min(values.size(), (b + 1) * kBlock); ++i) {
            if (!valid.empty() && valid[i] == 0) continue;
            s.velocity += glm::dvec3(values[i]);
            s.speed += glm::length(values[i]);
            ++s.points;
          }
        }
      },
      1);
  Sums all;
  for (const Sums& s : blocks) {
    all.velocity += s.velocity;
    all.speed += s.speed;
    all.points += s.points;
  }
  if (all.points == 0) return {};
  return {glm::vec3(all.velocity / double(all.points)), float(all.speed / double(all.points))};
}

// The streamline rake, the slice and the probe where the field is, sized to
// it, as ParaView places its Stream Tracer's line seed (the bounds' diagonal,
// steps a fifth of a cell, lines as long as the diagonal) and its Slice
// (through the centre): the defaults are the tornado scene's, metres from the
// origin, which would miss most files' fields. Off until the user turns them on.
void placeFlowTools(ParticleState& state, const Box& box, glm::ivec3 dims) {
  const glm::vec3 size = box.max - box.min, centre = 0.5f * (box.min + box.max);
  const float diagonal = glm::length(size);
  const glm::vec3 cells = size / glm::max(glm::vec3(dims) - 1.0f, glm::vec3(1.0f));
  float cell = diagonal;
  for (int a = 0; a < 3; ++a)
    if (cells[a] > 0.0f) cell = std::min(cell, cells[a]);

  StreamlineSettings& rake = state.streamlines;
  rake.shape = RakeShape::Line;
  rake.from = box.min;
  rake.to = box.max;
  rake.across = glm::vec3(box.min.x, box.min.y, box.max.z);
  // Within the attributes' ranges (core/sim/attribute_table.cpp).
  rake.step = std::clamp(0.2f * cell, 1e-7f, 10.0f);
  rake.length = std::clamp(diagonal, rake.step, 1e5f);
  // rk45's tolerance in metres: a ten-millionth of the field's size, 1e-6 m
  // for a 10 m field; an absolute 1e-6 m would be below float resolution in a
  // field kilometres wide and force the shortest step everywhere.
  rake.tolerance = std::clamp(1e-7f * diagonal, 1e-9f, 1.0f);
  rake.width = std::clamp(0.003f * diagonal, 0.0f, 1000.0f);

  state.slice.origin = centre;
  state.probe.position = centre;
  state.probe.radius = std::clamp(0.02f * diagonal, 1e-7f, 100.0f);
}

// The seeding plane across `box` for a field whose mean flow is `flow`.
Emitter seedingPlane(const Box& box, const Flow& flow, int maximum) {
  const glm::vec3 size = box.max - box.min, centre = 0.5f * (box.min + box.max);
  Emitter e;
  e.shape = EmitterShape::Box;
  e.position = centre;
  e.width = 0.98f * size.x;
  e.depth = 0.98f * size.y;
  e.height = 0.98f * size.z;
  // The axis the mean flow runs along, if it runs somewhere (a vortex's does not).
  int axis = 2;
  for (int a = 0; a < 3; ++a)
    if (std::abs(flow.mean[a]) > std::abs(flow.mean[axis])) axis = a;
  const bool through = flow.meanSpeed > 0.0f && std::abs(flow.mean[axis]) > 0.1f * flow.meanSpeed;
  float crossing = 0.0f;  // seconds a particle needs to cross the field
  if (through) {
    // A thin slab just inside the upstream face.
    const float upstream = flow.mean[axis] > 0.0f ? box.min[axis] : box.max[axis];
    const float inward = flow.mean[axis] > 0.0f ? 1.0f : -1.0f;
    e.position[axis] = upstream + inward * 0.02f * size[axis];
    crossing = size[axis] / std::abs(flow.mean[axis]);
  } else {
    axis = 2;  // the horizontal middle plane
    crossing = flow.meanSpeed > 0.0f ? glm::length(size) / flow.meanSpeed : 10.0f;
  }
  float* extent[3] = {&e.width, &e.depth, &e.height};
  *extent[axis] = 0.01f * size[axis];
  e.lifetime = std::clamp(crossing, 1.0f, 60.0f);
  e.lifetimeVariance = 0.1f * e.lifetime;
  e.rate = float(maximum) / e.lifetime;  // the field holds `maximum` particles once filled
  return e;
}

void logSeeding(const std::filesystem::path& file, const Emitter& e) {
  log::info("file scene: ", file.string(), ": seeding ", e.rate, " particles/s living ", e.lifetime,
            " s");
}

}  // namespace

Emitter seedingPlane(const VectorField& field, int maximum) {
  return seedingPlane(field.bounds(), meanFlow(field), maximum);
}

FieldSource fileSceneField(AppConfig& config, const std::filesystem::path& file,
                           const std::string& array, const std::vector<std::string>& sets) {
  pointAtFile(config, file, array, sets);
  return makeField(config.field, config.folder);
}

void pointAtFile(AppConfig& config, const std::filesystem::path& file, const std::string& array,
                 const std::vector<std::string>& sets) {
  const AttributeTable& table = AttributeTable::instance();
  for (const std::string& set : sets) {
    const std::string key = table.canonical(set.substr(0, set.find('=')));
    if (key == "field.source")
      throw Error(concat("--set ", set, ": the field file ", file.string(),
                         " is the run's field.source; give one or the other"));
    if (key == "field.name" && !array.empty())
      throw Error(concat("--set ", set, ": --array ", array,
                         " names the file's array already; give one or the other"));
  }
  FieldSpec spec;
  spec.source = std::filesystem::absolute(file).string();
  spec.name = array;
  spec.memoryBudget = config.field.memoryBudget;
  spec.halfPrecision = config.field.halfPrecision;
  spec.autoPrecision = config.field.autoPrecision;
  spec.storage = config.field.storage;
  spec.readAhead = config.field.readAhead;
  spec.uploadAhead = config.field.uploadAhead;
  config.field = spec;
  // The run's settings, read after the configuration's as for any run: its
  // [field] ones shape the file's field (and are checked against it).
  applyConfigSets(config, sets);
}

void frameFileScene(AppConfig& config, const std::filesystem::path& file, const Box& box,
                    glm::ivec3 dims) {
  config.scene = SceneSpec{};
  const glm::vec3 size = box.max - box.min, centre = 0.5f * (box.min + box.max);
  const float radius = 0.5f * glm::length(size);
  config.scene.groundHeight = box.min.z;  // the ground under the field, not through it
  // A flat field (a 2D simulation's plane, one point thick) lies on the
  // ground there: its particles would fade into it (render.softness) and
  // fight it for depth. The ground goes a tenth of the field's width below.
  const float width = std::max(size.x, size.y);
  const bool flat = width > 0.0f && size.z <= 1e-3f * width;
  if (flat) {
    config.scene.groundHeight = box.min.z - 0.1f * width;
    log::info("file scene: ", file.string(), " is flat (", size.z,
              " m thick): the ground is drawn ", 0.1f * width, " m below it");
  }
  // The flat ground reaches well past the field, however large and far it is.
  config.scene.terrainBounds =
      Box{glm::vec3(centre.x - 20.0f * radius, centre.y - 20.0f * radius, 0.0f),
          glm::vec3(centre.x + 20.0f * radius, centre.y + 20.0f * radius, 1.0f)};

  ParticleState& state = config.particles;
  // Until the field's mean flow is known: its horizontal middle plane.
  state.emitters = {seedingPlane(box, Flow{}, state.sim.maximum)};
  state.sim.motion = MotionModel::Tracer;
  state.sim.boundary = BoundaryMode::Kill;
  state.sim.groundCollision = false;
  state.helicopter.enabled = false;
  state.render.colorBy = ColorQuantity::Speed;
  state.render.colorMap = ColorMapName::Viridis;
  state.render.colorRange = ColorRange::Field;
  state.render.legend = true;
  state.render.fieldBox = true;
  state.render.opacityBirth = 0.8f;
  state.render.opacityDeath = 0.3f;

  bool roomWalls = false;
  float cameraNear = 0.0f;  // the camera walls' near plane: 0 without any
  for (WallSpec& wall : config.walls) {
    if (!wall.camera) {
      roomWalls = true;
      continue;
    }
    // ParaView's reset camera: the bounds' sphere fills the view, seen from
    // the front right and a little above.
    const float fov = glm::radians(wall.camera->fovDegrees);
    const float distance = radius / std::sin(0.5f * fov) * 1.05f;
    wall.camera->target = centre;
    wall.camera->position = centre + glm::normalize(glm::vec3(1.0f, -1.0f, 0.45f)) * distance;
    cameraNear = 0.01f * distance;
    config.run.farPlane = std::max(config.run.farPlane, 4.0f * (distance + radius));
  }
  // A hundredth of the camera's distance, so that depth keeps its precision
  // for a field kilometres wide as for one millimetres wide (a CAVE's walls
  // keep theirs: the room is metres whatever the field).
  if (cameraNear > 0.0f)
    config.run.nearPlane = roomWalls ? std::min(config.run.nearPlane, cameraNear) : cameraNear;
  float scale = 1.0f;
  if (roomWalls) {
    // Into the room: the field's largest side 2.4 m, its centre 1.5 m up in
    // the middle; a flat field at a table's height, 1 m up, so that a user
    // standing in the room looks down onto it rather than along it.
    scale = 2.4f / std::max({size.x, size.y, size.z});
    config.navigation.scale = scale;
    config.navigation.yawDegrees = 0.0f;
    config.navigation.offset = glm::vec3(0.0f, 0.0f, flat ? 1.0f : 1.5f) - scale * centre;
  }
  state.render.size = std::clamp(0.004f * 2.0f * radius, 1e-7f, 1000.0f);
  // Particles fade within this of the ground: a hundredth of the field, not
  // the tornado scene's 0.3 m (all of a millimetre-wide field's would fade).
  state.render.softness = std::clamp(0.01f * 2.0f * radius, 0.0f, 10.0f);
  placeFlowTools(state, box, dims);
  log::info("file scene: ", file.string(), " over [", box.min.x, ",", box.min.y, ",", box.min.z,
            "]..[", box.max.x, ",", box.max.y, ",", box.max.z, "] m",
            roomWalls ? concat("; scaled by ", scale, " into the room") : std::string());
}

void openFileScene(AppConfig& config, const std::filesystem::path& file, const VectorField& field) {
  frameFileScene(config, file, field.bounds(), field.dims());
  std::vector<Emitter>& emitters = config.particles.emitters;
  emitters = {seedingPlane(field, config.particles.sim.maximum)};
  logSeeding(file, emitters.front());
}

namespace {

// A file of one grid framed from its header; none for other formats.
std::optional<VtkImageFrame> headerFrame(const std::filesystem::path& file, FieldFormat format) {
  switch (format) {
    case FieldFormat::VtkImageData:
    case FieldFormat::VtkPImageData:
      return readVtkImageFrame(file);
    case FieldFormat::VtkLegacy:
      return readVtkLegacyFrame(file);
    default:
      return std::nullopt;
  }
}

// A .pvd's frame is its first step's (indexSeries: the first step fixes the
// series' grid). None where the collection or that step cannot be read yet:
// the series' read says what is wrong.
std::optional<VtkImageFrame> firstStepFrame(const std::filesystem::path& pvd) {
  try {
    const PvdFrame first = readPvd(pvd).front();
    if (first.parts.size() > 1) return std::nullopt;  // resampled together: not a header's grid
    return headerFrame(first.file(), detectFieldFormat(first.file()));
  } catch (const Error&) {
    return std::nullopt;
  }
}

}  // namespace

std::optional<VtkImageFrame> fileSceneFrame(const FieldSpec& spec) {
  // A resampled grid is not the header's; a watched series starts from the
  // first step found complete, not necessarily the first listed.
  if (spec.resolution != glm::ivec3(0) || spec.watch) return std::nullopt;
  const FieldFormat format = detectFieldFormat(spec.source);
  if (format == FieldFormat::VtkCollection) return firstStepFrame(spec.source);
  return headerFrame(spec.source, format);
}

FieldSeeding seedFileScene(const std::filesystem::path& file, const VtkImageFrame& frame,
                           int maximum, const std::vector<std::string>& sets) {
  // The emitter's settings a --set gave (by key or alias), which stay as given.
  std::set<std::string> given;
  for (const std::string& set : sets)
    given.insert(AttributeTable::instance().canonical(set.substr(0, set.find('='))));
  return [file, frame, maximum, given](MainContext& main, const FieldSource& source) {
    const VectorField* field = source.update.field.get();
    if (!field) return;  // (a file framed from its header is a grid)
    if (field->bounds().min != frame.bounds().min || field->bounds().max != frame.bounds().max ||
        field->dims() != frame.dims())
      log::warn(file.string(), ": the grid read is not the one its header describes; the walls ",
                "were framed by the header");
    const Emitter e = seedingPlane(*field, maximum);
    const std::pair<const char*, AttributeValue> settings[] = {
        {"position", e.position}, {"width", e.width},
        {"depth", e.depth},       {"height", e.height},
        {"lifetime", e.lifetime}, {"lifetime_variance", e.lifetimeVariance},
        {"rate", e.rate}};
    for (const auto& [key, value] : settings) {
      const std::string name = concat("emitter.0.", key);
      if (given.count(name)) continue;
      const AttributeResult r = main.set(name, value);
      if (!r.warning.empty()) log::warn("file scene: ", name, ": ", r.warning);
    }
    logSeeding(file, e);
  };
}

}  // namespace sandstorm
