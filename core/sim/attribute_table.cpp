#include "core/sim/attribute_table.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "core/expr/field_expression.h"
#include "core/util/error.h"
#include "core/util/nearest_name.h"

namespace sandstorm {
namespace {

// Accessors that reach one member of the state (or of emitter or obstacle i).
template <class T>
using Ref = std::function<T&(ParticleState&, int)>;

// The state defaults are read from: one default emitter and one default obstacle.
const ParticleState& defaults() {
  static const ParticleState state = [] {
    ParticleState s;
    s.obstacles.resize(1);
    return s;
  }();
  return state;
}

template <class T>
AttributeInfo entry(std::string key, AttributeType type, float min, float max, std::string unit,
                    std::string description, Ref<T> ref) {
  AttributeInfo info;
  info.key = std::move(key);
  info.type = type;
  info.min = min;
  info.max = max;
  info.unit = std::move(unit);
  info.description = std::move(description);
  info.get = [ref](const ParticleState& s, int e) {
    return AttributeValue(ref(const_cast<ParticleState&>(s), e));
  };
  info.set = [ref](ParticleState& s, int e, const AttributeValue& v) {
    ref(s, e) = std::get<T>(v);
  };
  info.defaultValue = info.get(defaults(), 0);
  return info;
}

// Enums are stored as C++ enums and exchanged as choice names.
template <class E>
AttributeInfo enumEntry(std::string key, std::vector<std::string> choices, std::string description,
                        Ref<E> ref) {
  AttributeInfo info;
  info.key = std::move(key);
  info.type = AttributeType::Enum;
  info.description = std::move(description);
  info.choices = choices;
  info.get = [ref, choices](const ParticleState& s, int e) {
    return AttributeValue(choices.at(std::size_t(ref(const_cast<ParticleState&>(s), e))));
  };
  info.set = [ref, choices](ParticleState& s, int e, const AttributeValue& v) {
    const auto it = std::find(choices.begin(), choices.end(), std::get<std::string>(v));
    ref(s, e) = E(it - choices.begin());
  };
  info.defaultValue = info.get(defaults(), 0);
  return info;
}

// A name chosen at run time (AttributeType::Name), stored as a std::string.
AttributeInfo nameEntry(std::string key, std::string description, Ref<std::string> ref) {
  AttributeInfo info =
      entry(std::move(key), AttributeType::Name, 0, 0, "", std::move(description), std::move(ref));
  return info;
}

// Why `name` is not a valid Name, or empty.
std::string nameProblem(std::string_view name) {
  if (name.size() > kMaxNameLength)
    return concat("a name of ", name.size(), " characters; at most ", kMaxNameLength);
  for (const char c : name)
    if (c < ' ' || c > '~' || c == '=' || c == '#' || c == '%' || c == '"' || c == '\'')
      return concat("a name with the character '", (c > ' ' && c <= '~') ? std::string(1, c) : "?",
                    "' (code ", int(static_cast<unsigned char>(c)),
                    "); expected printable characters without '=', '#', '%' or quotes");
  if (!name.empty() && (name.front() == ' ' || name.back() == ' '))
    return "a name starting or ending with a space; expected spaces only between words";
  return {};
}

// The name a one-word form (encodeName) stands for; a name as it is otherwise.
std::optional<std::string> decodeName(std::string_view word) {
  if (word == "%") return std::string();
  std::string out;
  for (std::size_t i = 0; i < word.size(); ++i) {
    if (word[i] != '%') {
      out += word[i];
    } else if (word.substr(i, 3) == "%20") {
      out += ' ';
      i += 2;
    } else {
      return std::nullopt;
    }
  }
  return out;
}

#define SIM(member) \
  Ref<decltype(SimSettings::member)>([](ParticleState & s, int) -> auto& { return s.sim.member; })
#define RENDER(member)                   \
  Ref<decltype(RenderSettings::member)>( \
      [](ParticleState & s, int) -> auto& { return s.render.member; })
#define FIELD(member)                   \
  Ref<decltype(FieldPlayback::member)>( \
      [](ParticleState & s, int) -> auto& { return s.field.member; })
#define HELICOPTER(member)                   \
  Ref<decltype(HelicopterSettings::member)>( \
      [](ParticleState & s, int) -> auto& { return s.helicopter.member; })
#define STREAMLINES(member)                  \
  Ref<decltype(StreamlineSettings::member)>( \
      [](ParticleState & s, int) -> auto& { return s.streamlines.member; })
#define SLICE(member)                   \
  Ref<decltype(SliceSettings::member)>( \
      [](ParticleState & s, int) -> auto& { return s.slice.member; })
#define PROBE(member)                   \
  Ref<decltype(ProbeSettings::member)>( \
      [](ParticleState & s, int) -> auto& { return s.probe.member; })
#define MOLECULES(member)                  \
  Ref<decltype(MoleculeSettings::member)>( \
      [](ParticleState & s, int) -> auto& { return s.molecules.member; })
#define SOLVER(member)                  \
  Ref<decltype(FluidSettings::member)>( \
      [](ParticleState & s, int) -> auto& { return s.solver.member; })
#define EMITTER(member)           \
  Ref<decltype(Emitter::member)>( \
      [](ParticleState & s, int e) -> auto& { return s.emitters[std::size_t(e)].member; })
#define PRIMITIVE(member)                \
  Ref<decltype(FieldPrimitive::member)>( \
      [](ParticleState & s, int e) -> auto& { return s.primitives[std::size_t(e)].member; })
#define OBSTACLE(member)           \
  Ref<decltype(Obstacle::member)>( \
      [](ParticleState & s, int e) -> auto& { return s.obstacles[std::size_t(e)].member; })

constexpr float kBig = 1e6f;

std::vector<AttributeInfo> makeEntries() {
  using T = AttributeType;
  std::vector<AttributeInfo> v;
  // The system.
  v.push_back(entry("sim.maximum", T::Int, 0, 1e8f, "particles",
                    "Soft limit on live particles; the buffer capacity is the hard one",
                    SIM(maximum)));
  v.push_back(enumEntry("sim.motion", {"tracer", "force", "drag"},
                        "How the field moves particles: as velocity, acceleration, or drag target",
                        SIM(motion)));
  v.push_back(enumEntry("sim.integrator", {"euler", "rk2", "rk4"}, "Time integration scheme",
                        SIM(integrator)));
  v.push_back(enumEntry("sim.boundary", {"kill", "clamp", "wrap"},
                        "What happens to particles leaving the field's bounds", SIM(boundary)));
  v.push_back(entry("sim.field_strength", T::Float, -100, 100, "x", "Multiplies the field",
                    SIM(fieldStrength)));
  v.push_back(entry("sim.time_scale", T::Float, 0, 10, "x",
                    "Simulated seconds per wall-clock second", SIM(timeScale)));
  v.push_back(entry("sim.drag_time", T::Float, 1e-3f, 100, "s",
                    "Response time tau of the drag model (dust: ~0.05 s)", SIM(dragTime)));
  v.push_back(entry("sim.gravity", T::Vec3, -100, 100, "m/s^2",
                    "Gravity for the force and drag models", SIM(gravity)));
  v.push_back(entry("sim.ground_collision", T::Bool, 0, 1, "",
                    "Particles bounce off the ground or terrain", SIM(groundCollision)));
  v.push_back(entry("sim.restitution", T::Float, 0, 1, "",
                    "Fraction of normal speed kept when bouncing off the ground",
                    SIM(restitution)));
  v.push_back(entry("sim.emitting", T::Bool, 0, 1, "",
                    "Start/stop emission (existing particles live on)", SIM(emitting)));
  v.push_back(entry("sim.paused", T::Bool, 0, 1, "", "Pause: time stands still", SIM(paused)));
  v.push_back(entry(
      "sim.lod", T::Bool, 0, 1, "",
      "Level of detail (Reeves): emit fewer particles when the system covers little of the view "
      "or frames exceed the budget",
      SIM(lod)));
  v.push_back(entry(
      "sim.lod_coverage", T::Float, 0, 1, "",
      "Level of detail: view coverage (fraction of a 90-degree cone) from which emission is full",
      SIM(lodCoverage)));
  v.push_back(entry("sim.lod_budget_ms", T::Float, 0, 1000, "ms",
                    "Level of detail: frame-time budget; longer frames lower emission (0: off)",
                    SIM(lodBudgetMs)));
  v.push_back(entry("sim.lod_min_scale", T::Float, 0, 1, "",
                    "Level of detail: emission never drops below this fraction of the rates",
                    SIM(lodMinScale)));
  // How particles look.
  v.push_back(
      enumEntry("render.mode", {"points", "billboards", "splat", "auto"},
                "Draw particles as points, lit spherical billboards, splats (billboards' look, "
                "by compute: for small particles) or auto (splats where particles are small)",
                RENDER(mode)));
  // From a micro-channel's flow (0.1 um) to an atmospheric field's (the file
  // scene sizes them to the field: 0.4% of its diagonal).
  v.push_back(entry("render.size", T::Float, 1e-7f, 1000, "m", "Particle diameter", RENDER(size)));
  v.push_back(
      entry("render.color_birth", T::Vec3, 0, 1, "rgb", "Colour at birth", RENDER(colorBirth)));
  v.push_back(entry("render.color_death", T::Vec3, 0, 1, "rgb", "Colour at the end of life",
                    RENDER(colorDeath)));
  v.push_back(
      entry("render.opacity_birth", T::Float, 0, 1, "", "Opacity at birth", RENDER(opacityBirth)));
  v.push_back(entry("render.opacity_death", T::Float, 0, 1, "", "Opacity at the end of life",
                    RENDER(opacityDeath)));
  v.push_back(entry("render.light_direction", T::Vec3, -1, 1, "",
                    "Direction towards the light, room space", RENDER(lightDirection)));
  v.push_back(entry("render.ambient", T::Float, 0, 1, "", "Ambient share of particle lighting",
                    RENDER(ambient)));
  v.push_back(
      entry("render.light_color", T::Vec3, 0, 1, "rgb", "The light's colour", RENDER(lightColor)));
  v.push_back(entry("render.light_strength", T::Float, 0, 10, "",
                    "The direct light's strength (the ambient share is not scaled)",
                    RENDER(lightStrength)));
  v.push_back(entry("render.shadows", T::Bool, 0, 1, "",
                    "Volumetric self-shadowing: the dust shades itself, the ground and the "
                    "terrain from the light (opacity shadow maps, built once a frame per GPU)",
                    RENDER(shadows)));
  v.push_back(entry("render.shadow_density", T::Float, 0, 100, "",
                    "Shadows: how much light a particle blocks, times its own opacity's share",
                    RENDER(shadowDensity)));
  v.push_back(entry("render.shadow_layers", T::Int, 8, 64, "",
                    "Shadows: opacity layers along the light (more: finer in depth)",
                    RENDER(shadowLayers)));
  v.push_back(entry("render.shadow_resolution", T::Int, 16, 1024, "texels",
                    "Shadows: the map's side across the light (cells never smaller than a "
                    "particle)",
                    RENDER(shadowResolution)));
  v.push_back(entry("render.scattering", T::Float, 0, 1, "1/m",
                    "Light scattering: a haze of this density lit by the light, darker where "
                    "the dust shadows it (shafts of light with render.shadows); 0: none",
                    RENDER(scattering)));
  v.push_back(entry("render.shutter", T::Float, 0, 1, "s",
                    "Motion blur: each particle is smeared along the path it travelled during "
                    "this shutter time (0: off; splats smear at most 48 pixels)",
                    RENDER(shutter)));
  v.push_back(enumEntry("render.blur", {"filter", "smear"},
                        "Splats' motion blur: the particle images blurred along each pixel's "
                        "motion (fast), or each splat smeared along its own path (exact where "
                        "paths cross, slower by the pixels the smears cover)",
                        RENDER(blur)));
  v.push_back(entry("render.softness", T::Float, 0, 10, "m",
                    "Particles fade out within this distance in front of scene geometry",
                    RENDER(softness)));
  v.push_back(entry("render.splat_pixels", T::Float, 0, 248, "px",
                    "Auto mode: views where particles cover at most this many pixels use splats",
                    RENDER(splatPixels)));
  v.push_back(entry("render.splat_detail", T::Float, 0, 31, "px",
                    "Splats wider than this many pixels are drawn on a grid of half, a quarter or "
                    "an eighth the resolution, so a particle's cost stops growing with its size "
                    "(0: every splat at full resolution, at most 31 pixels wide)",
                    RENDER(splatDetail)));
  v.push_back(entry("render.splat_overlap", T::Float, 0, 100000, "splats",
                    "Where splats cover each pixel of a 32-pixel tile more than this many times "
                    "on average, and around it too, the tile draws them on the next coarser "
                    "grid: a pixel then shows the mean of so many splats that a coarser grid "
                    "samples it nearly as well, at a quarter of the cost (0: never; splats only)",
                    RENDER(splatOverlap)));
  v.push_back(enumEntry("render.order", {"unsorted", "sorted"},
                        "Billboards blend in the particles' order, or sorted back to front in "
                        "each view (a GPU radix sort by depth; splats need no order)",
                        RENDER(order)));
  v.push_back(
      entry("render.field_box", T::Bool, 0, 1, "", "Outline the field's bounds", RENDER(fieldBox)));
  v.push_back(enumEntry(
      "render.color_by",
      {"age", "speed", "velocity_x", "velocity_y", "velocity_z", "vorticity", "array"},
      "What colours a particle: its age (fraction of life), its velocity's length or a component "
      "(m/s), the field's vorticity magnitude |curl| there (1/s), or a scalar array of the "
      "field's file there (render.color_array)",
      RENDER(colorBy)));
  v.push_back(nameEntry("render.color_array",
                        "color_by = array: the field file's scalar array (temperature, pressure); "
                        "empty: its first",
                        RENDER(colorArray)));
  v.push_back(enumEntry(
      "render.color_map",
      {"life", "viridis", "plasma", "inferno", "cividis", "cool_warm", "grey", "fast"},
      "Colour map: life (colour_birth to colour_death), the perceptually uniform viridis, plasma, "
      "inferno and cividis, ParaView's diverging cool_warm, a grey ramp, or fast (ParaView's "
      "default map since 5.13)",
      RENDER(colorMap)));
  v.push_back(enumEntry(
      "render.color_range", {"field", "fixed", "particles"},
      "The colour scale's ends: the field's range of the quantity, render.color_min and "
      "render.color_max, or the live particles' range (measured every render.color_every frames; "
      "the main context writes it into color_min and color_max)",
      RENDER(colorRange)));
  v.push_back(entry("render.color_every", T::Int, 1, 100000, "frames",
                    "color_range = particles: frames between measurements", RENDER(colorEvery)));
  v.push_back(entry("render.color_min", T::Float, -kBig, kBig, "",
                    "Fixed colour range: the value at the map's start (the quantity's unit)",
                    RENDER(colorMin)));
  v.push_back(entry("render.color_max", T::Float, -kBig, kBig, "",
                    "Fixed colour range: the value at the map's end (the quantity's unit)",
                    RENDER(colorMax)));
  v.push_back(entry("render.color_log", T::Bool, 0, 1, "",
                    "Logarithmic colour scale (for positive quantities)", RENDER(colorLog)));
  v.push_back(entry("render.trail_length", T::Int, 0, 64, "frames",
                    "Trails: the last positions each particle keeps, drawn as fading lines behind "
                    "it (0: none; the compute backend)",
                    RENDER(trailLength)));
  v.push_back(entry("render.streaklines", T::Bool, 0, 1, "",
                    "Streaklines: each point emitter's last released points, carried by the flow "
                    "and joined in release order",
                    RENDER(streaklines)));
  v.push_back(entry("render.streak_length", T::Int, 2, 1024, "frames",
                    "Points a streakline keeps (one released a frame)", RENDER(streakLength)));
  v.push_back(entry("render.legend", T::Bool, 0, 1, "",
                    "Show the colour legend on the legend's wall (the menu always shows it)",
                    RENDER(legend)));
  // A time-varying field's playback.
  v.push_back(entry("field.speed", T::Float, 0, 100, "x",
                    "Field seconds per simulated second (time-varying fields)", FIELD(speed)));
  v.push_back(entry("field.loop", T::Bool, 0, 1, "", "Loop a time-varying field", FIELD(loop)));
  v.push_back(enumEntry(
      "field.mode", {"texture", "equation", "expression"},
      "Sample the field's grid (3D texture), evaluate an analytic field's equation in the "
      "shader (analytic fields only; others stay on the texture), or the field written as "
      "field.expression_x/_y/_z (the grid's bounds still bound the particles)",
      FIELD(mode)));
  for (int c = 0; c < 3; ++c) {
    const std::string axis(1, char('x' + c));
    AttributeInfo e =
        entry("field.expression_" + axis, T::Expression, 0, 0, "",
              "The field's " + axis +
                  " component with field.mode = expression: an expression of x, y, z, t, vx, vy, "
                  "vz, age (sin, exp, min, ?:, ...; muParser's language)",
              Ref<std::string>([c](ParticleState& s, int) -> std::string& {
                return s.field.expression[std::size_t(c)];
              }));
    v.push_back(std::move(e));
  }
  v.push_back(entry("field.paused", T::Bool, 0, 1, "",
                    "Hold the time-varying field's current frame", FIELD(paused)));
  v.push_back(entry("field.follow", T::Bool, 0, 1, "",
                    "Show the newest frame of a field that grows while a simulation writes it",
                    FIELD(follow)));
  // Streamlines of the current field from a seed rake (core/flow).
  v.push_back(entry("streamlines.enabled", T::Bool, 0, 1, "",
                    "Draw streamlines of the field from the seed rake", STREAMLINES(enabled)));
  v.push_back(enumEntry("streamlines.shape", {"line", "plane"},
                        "Seeds on the line from..to, or on the plane from..to x from..across",
                        STREAMLINES(shape)));
  v.push_back(entry("streamlines.from", T::Vec3, -kBig, kBig, "m",
                    "The rake's first corner (the particles' coordinates)", STREAMLINES(from)));
  v.push_back(entry("streamlines.to", T::Vec3, -kBig, kBig, "m", "The rake's line ends here",
                    STREAMLINES(to)));
  v.push_back(entry("streamlines.across", T::Vec3, -kBig, kBig, "m",
                    "A plane rake's second edge ends here", STREAMLINES(across)));
  v.push_back(entry("streamlines.seeds", T::Int, 1, 64, "", "Seeds along each edge of the rake",
                    STREAMLINES(seeds)));
  v.push_back(entry("streamlines.step", T::Float, 1e-7f, 10, "m",
                    "Integration step (arc length); rk45's longest", STREAMLINES(step)));
  v.push_back(enumEntry("streamlines.integrator", {"euler", "rk2", "rk4", "rk45"},
                        "Streamline integration: fixed steps, or adaptive Runge-Kutta 4-5 "
                        "within streamlines.tolerance (ParaView's default)",
                        STREAMLINES(integrator)));
  v.push_back(entry("streamlines.tolerance", T::Float, 1e-9f, 1, "m",
                    "rk45: the largest error a step may make (shorter steps where the flow bends)",
                    STREAMLINES(tolerance)));
  v.push_back(entry("streamlines.length", T::Float, 0, 1e5f, "m",
                    "Longest streamline each way from its seed (at most 4096 steps)",
                    STREAMLINES(length)));
  // Up to a kilometre: an atmospheric field's ribbons are tens of metres wide.
  v.push_back(entry("streamlines.width", T::Float, 0, 1000, "m",
                    "Ribbon width (0: one-pixel lines)", STREAMLINES(width)));
  // A slice plane through the field, coloured like the particles.
  v.push_back(entry("slice.enabled", T::Bool, 0, 1, "",
                    "Draw a slice plane through the field, coloured by render.color_by",
                    SLICE(enabled)));
  v.push_back(entry("slice.origin", T::Vec3, -kBig, kBig, "m", "A point of the slice plane",
                    SLICE(origin)));
  v.push_back(entry("slice.normal", T::Vec3, -1, 1, "",
                    "The slice plane's normal: (1 0 0), (0 1 0), (0 0 1) or any direction",
                    SLICE(normal)));
  v.back().direction = true;
  v.push_back(entry("slice.opacity", T::Float, 0, 1, "", "The slice's opacity", SLICE(opacity)));
  v.push_back(entry("slice.arrows", T::Int, 0, 64, "",
                    "Arrow glyphs of the in-plane flow along the slice's longer side (0: none)",
                    SLICE(arrows)));
  // The probe: the field's value and the particles near a point.
  v.push_back(entry("probe.enabled", T::Bool, 0, 1, "",
                    "Read the field and count particles at the probe (menu, legend wall, marker)",
                    PROBE(enabled)));
  v.push_back(entry("probe.position", T::Vec3, -kBig, kBig, "m",
                    "The probe without a tracked wand (the particles' coordinates)",
                    PROBE(position)));
  v.push_back(entry("probe.radius", T::Float, 1e-7f, 100, "m",
                    "Particles within this distance of the probe are counted", PROBE(radius)));
  v.push_back(entry("probe.reach", T::Float, 0, 100, "m",
                    "With a wand and no slice: the probe is this far (room) along its ray",
                    PROBE(reach)));
  // The downdraft demo's helicopter.
  v.push_back(entry("helicopter.enabled", T::Bool, 0, 1, "",
                    "Show the helicopter; its controls drive the dust", HELICOPTER(enabled)));
  v.push_back(entry("helicopter.throttle", T::Float, 0, 1, "",
                    "Throttle: more raises dust rate, lifetime and maximum (about 0.8 hovers)",
                    HELICOPTER(throttle)));
  v.push_back(entry("helicopter.wand_throttle", T::Bool, 0, 1, "",
                    "A tracked wand tilted towards you raises the throttle, away lowers it",
                    HELICOPTER(wandThrottle)));
  v.push_back(entry("helicopter.collide", T::Bool, 0, 1, "",
                    "Dust bounces off the helicopter's body", HELICOPTER(collide)));
  v.push_back(entry("helicopter.collide_rotor", T::Bool, 0, 1, "",
                    "Dust also bounces off the rotor disc (the wash carries air through it)",
                    HELICOPTER(collideRotor)));
  v.push_back(entry("helicopter.altitude", T::Float, 1, 60, "m",
                    "Rotor hub above the ground; high up, less dust", HELICOPTER(altitude)));
  v.push_back(
      entry("helicopter.x", T::Float, -90, 90, "m", "Rotor hub position east", HELICOPTER(x)));
  v.push_back(
      entry("helicopter.y", T::Float, -90, 90, "m", "Rotor hub position north", HELICOPTER(y)));
  // The live flow solver (core/solver/fluid_solver.h, app/fluid_driver.h).
  v.push_back(entry("solver.enabled", T::Bool, 0, 1, "",
                    "The field is a live flow (stable fluids on the field's grid, started from "
                    "it); off: the field as loaded",
                    SOLVER(enabled)));
  v.push_back(enumEntry("solver.device", {"gpu", "cpu", "auto"},
                        "Solve on each GPU beside the particle update (the compute backend), or "
                        "on the main context's CPU (its grids travel to the walls); auto: the GPU "
                        "unless the walls' OpenGL runs in software",
                        SOLVER(device)));
  v.push_back(entry("solver.iterations", T::Int, 1, 500, "",
                    "Pressure iterations a step (more: less divergence left)", SOLVER(iterations)));
  v.push_back(entry("solver.relaxation", T::Float, 1, 1.95f, "",
                    "Over-relaxation of the pressure iterations (1: Gauss-Seidel)",
                    SOLVER(relaxation)));
  v.push_back(entry("solver.every", T::Int, 1, 60, "frames",
                    "Frames between steps (a step covers their simulated time)", SOLVER(every)));
  v.push_back(entry("solver.wind", T::Vec3, -100, 100, "m/s",
                    "Wind blowing in through the domain's upwind sides (the field's frame)",
                    SOLVER(wind)));
  v.push_back(entry("solver.rotor_thrust", T::Float, 0, 4, "x",
                    "The rotor pushes the air down through its disc with this times the "
                    "helicopter's thrust (momentum theory: thrust / disc area is the pressure "
                    "jump across it)",
                    SOLVER(rotorThrust)));
  v.push_back(entry("solver.viscosity", T::Float, 0, 10, "m^2/s", "Kinematic viscosity",
                    SOLVER(viscosity)));
  v.push_back(entry("solver.vorticity", T::Float, 0, 2, "",
                    "Vorticity confinement (epsilon): gives back the swirls the coarse grid's "
                    "advection smears out, such as the ring the rotor's wall jet rolls up",
                    SOLVER(vorticity)));
  v.push_back(entry("solver.turbulence", T::Float, 0, 1, "",
                    "Subgrid eddies the particles feel: the flow's velocity u plus this times "
                    "|u| times a moving curl-noise pattern (the wall jet's turbulence, too fine "
                    "for the grid; it lifts the dust)",
                    SOLVER(turbulence)));
  v.push_back(entry("solver.eddy_size", T::Float, 0.1f, 100, "m", "The subgrid eddies' size",
                    SOLVER(eddySize)));
  v.push_back(entry("solver.closed", T::Bool, 0, 1, "",
                    "Every side of the domain a wall (a room); off: open but for the floor",
                    SOLVER(closed)));
  // Molecules (core/molecules): small mass-spring meshes that turn with the flow.
  v.push_back(entry("molecules.maximum", T::Int, 0, 1e8f, "molecules",
                    "Soft limit on live molecules", MOLECULES(maximum)));
  v.push_back(entry("molecules.complexity", T::Int, MoleculeSettings::kMinComplexity,
                    MoleculeSettings::kMaxComplexity, "particles",
                    "Particles a molecule: 2 a rod, 3 a triangle, 4 a tetrahedron, 5-8 a chain "
                    "(a change starts the molecules afresh)",
                    MOLECULES(complexity)));
  v.push_back(entry("molecules.size", T::Float, 1e-3f, 10, "m", "Rest length of a molecule's edges",
                    MOLECULES(size)));
  v.push_back(entry("molecules.stiffness", T::Float, 0, 1, "",
                    "Share of the springs' stretch removed each step (1: rigid)",
                    MOLECULES(stiffness)));
  v.push_back(entry("molecules.damping", T::Float, 0, 1, "",
                    "Share of the members' motion against their molecule's removed each step "
                    "(stretching and spin)",
                    MOLECULES(damping)));
  v.push_back(entry("molecules.iterations", T::Int, 1, 16, "", "Spring restoration passes a step",
                    MOLECULES(iterations)));
  v.push_back(entry("molecules.head_mass", T::Float, 1, 100, "",
                    "Mass of a molecule's first particle (the others weigh 1)",
                    MOLECULES(headMass)));
  v.push_back(entry("molecules.vane", T::Float, 0, 1, "",
                    "How much more of the flow a molecule's tail feels than its head, so it "
                    "trails downstream like a wind vane (0: it only stretches with the flow)",
                    MOLECULES(vane)));
  v.push_back(entry("molecules.repulsion", T::Bool, 0, 1, "",
                    "Molecules closer than the repulsion radius push apart (a GPU grid)",
                    MOLECULES(repulsion)));
  v.push_back(entry("molecules.repulsion_radius", T::Float, 1e-3f, 10, "m",
                    "Centres closer than this push apart", MOLECULES(repulsionRadius)));
  v.push_back(entry("molecules.repulsion_strength", T::Float, 0, 1, "",
                    "Share of the overlap removed each step", MOLECULES(repulsionStrength)));
  v.push_back(entry("molecules.width", T::Float, 1e-4f, 1, "m", "Drawn width of rods and chains",
                    MOLECULES(width)));
  v.push_back(entry("molecules.push", T::Bool, 0, 1, "",
                    "The push tool blows molecules away from its point (wand button, mouse)",
                    MOLECULES(push)));
  v.push_back(entry("molecules.push_tool", T::Bool, 0, 1, "",
                    "Holding the left mouse button (instead of turning the world) or the wand's "
                    "grab button (off a handle) pushes molecules there",
                    MOLECULES(pushTool)));
  v.push_back(entry("molecules.push_position", T::Vec3, -kBig, kBig, "m",
                    "Where the push tool blows from", MOLECULES(pushPosition)));
  v.push_back(entry("molecules.push_radius", T::Float, 1e-3f, 100, "m", "The push reaches this far",
                    MOLECULES(pushRadius)));
  v.push_back(entry("molecules.push_speed", T::Float, 0, 100, "m/s",
                    "The push's outward wind at its point (none at its reach)",
                    MOLECULES(pushSpeed)));
  // Emitters.
  v.push_back(enumEntry("emitter.*.kind", {"particles", "molecules"},
                        "What it emits: particles, or molecules (the rate then counts molecules)",
                        EMITTER(kind)));
  v.push_back(enumEntry("emitter.*.shape", {"box", "sphere", "disc", "point"},
                        "Emission area shape", EMITTER(shape)));
  v.push_back(entry("emitter.*.position", T::Vec3, -kBig, kBig, "m", "Centre of the emission area",
                    EMITTER(position)));
  v.push_back(entry("emitter.*.width", T::Float, 0, kBig, "m", "Box emission area along x",
                    EMITTER(width)));
  v.push_back(entry("emitter.*.depth", T::Float, 0, kBig, "m", "Box emission area along y",
                    EMITTER(depth)));
  v.push_back(entry("emitter.*.height", T::Float, 0, kBig, "m", "Box emission area along z",
                    EMITTER(height)));
  v.push_back(
      entry("emitter.*.radius", T::Float, 0, kBig, "m", "Sphere or disc radius", EMITTER(radius)));
  v.push_back(entry("emitter.*.rate", T::Float, 0, 1e8f, "particles/s",
                    "Mean emission rate (Reeves)", EMITTER(rate)));
  v.push_back(entry("emitter.*.rate_variance", T::Float, 0, 1e8f, "particles/s",
                    "Emission rate varies uniformly by +- this much (Reeves)",
                    EMITTER(rateVariance)));
  v.push_back(entry("emitter.*.lifetime", T::Float, 1e-3f, 1e4f, "s", "Mean particle lifetime",
                    EMITTER(lifetime)));
  v.push_back(entry("emitter.*.lifetime_variance", T::Float, 0, 1e4f, "s",
                    "Lifetime varies uniformly by +- this much", EMITTER(lifetimeVariance)));
  v.push_back(entry("emitter.*.velocity", T::Vec3, -kBig, kBig, "m/s", "Initial velocity",
                    EMITTER(velocity)));
  v.push_back(entry("emitter.*.spread", T::Float, 0, kBig, "m/s",
                    "Radius of the random ball added to the initial velocity", EMITTER(spread)));
  v.push_back(entry("emitter.*.enabled", T::Bool, 0, 1, "", "Emitter on/off", EMITTER(enabled)));
  // Obstacles (core/obstacles/obstacle.h).
  v.push_back(enumEntry("obstacle.*.shape", {"sphere", "box", "cylinder"}, "Obstacle shape",
                        OBSTACLE(shape)));
  v.push_back(entry("obstacle.*.position", T::Vec3, -kBig, kBig, "m", "Centre of the obstacle",
                    OBSTACLE(position)));
  v.push_back(entry("obstacle.*.radius", T::Float, 0.01f, 1000, "m", "Sphere or cylinder radius",
                    OBSTACLE(radius)));
  v.push_back(entry("obstacle.*.size", T::Vec3, 0.01f, 1000, "m", "Box extent along x, y and z",
                    OBSTACLE(size)));
  v.push_back(entry("obstacle.*.height", T::Float, 0.01f, 1000, "m",
                    "Cylinder height (its axis is vertical)", OBSTACLE(height)));
  v.push_back(entry("obstacle.*.velocity", T::Vec3, -1000, 1000, "m/s",
                    "How fast it moves (its path and a drag set it); flow and bounces feel it",
                    OBSTACLE(velocity)));
  v.push_back(entry("obstacle.*.restitution", T::Float, 0, 1, "",
                    "Fraction of the speed towards its surface a particle keeps on a bounce",
                    OBSTACLE(restitution)));
  v.push_back(entry("obstacle.*.flow", T::Bool, 0, 1, "",
                    "The flow goes around it (off: particles only bounce off it)", OBSTACLE(flow)));
  v.push_back(entry("obstacle.*.path", T::Bool, 0, 1, "",
                    "Follows its scripted path ([[obstacle]] path); off: stays where put",
                    OBSTACLE(path)));
  v.push_back(entry("obstacle.*.enabled", T::Bool, 0, 1, "", "Obstacle on/off", OBSTACLE(enabled)));
  // The field editor's primitives (core/editor/field_primitive.h).
  v.push_back(
      enumEntry("primitive.*.kind",
                {"none", "vortex", "source", "wind", "tornado", "sphere_flow", "curl_noise"},
                "What the primitive adds to the field (none: an empty slot)", PRIMITIVE(kind)));
  v.push_back(entry("primitive.*.strength", T::Float, -1000, 1000, "m/s",
                    "Its speed: a vortex's swirl at its radius, a source's outflow at its radius "
                    "(< 0: a sink), a wind's speed, a tornado's spin",
                    PRIMITIVE(strength)));
  v.push_back(entry("primitive.*.radius", T::Float, 0.01f, 1000, "m",
                    "Its size: a vortex's, source's or tornado's core, the sphere's radius, the "
                    "eddies' size",
                    PRIMITIVE(radius)));
  v.push_back(entry("primitive.*.position", T::Vec3, -kBig, kBig, "m",
                    "Where it is: a vortex's line passes through it, a source's centre, a "
                    "tornado's base, the sphere's centre, the noise's shift",
                    PRIMITIVE(position)));
  v.push_back(entry("primitive.*.axis", T::Vec3, -1000, 1000, "",
                    "Its direction: a vortex's or tornado's axis, the way a wind or stream blows",
                    PRIMITIVE(axis)));
  v.push_back(entry("primitive.*.enabled", T::Bool, 0, 1, "", "Primitive on/off (kept in its slot)",
                    PRIMITIVE(enabled)));
  return v;
}

#undef SIM
#undef RENDER
#undef HELICOPTER
#undef FIELD
#undef EMITTER
#undef MOLECULES
#undef SOLVER
#undef OBSTACLE
#undef PRIMITIVE

struct Alias {
  std::string_view name, target;
};
constexpr Alias kAliases[] = {
    {"Size", "render.size"},          {"Lifetime", "emitter.0.lifetime"},
    {"AreaWidth", "emitter.0.width"}, {"AreaDepth", "emitter.0.depth"},
    {"Maximum", "sim.maximum"},       {"Position", "emitter.0.position"},
};

const char* typeName(AttributeType t) {
  switch (t) {
    case AttributeType::Bool:
      return "a boolean (true/false)";
    case AttributeType::Int:
      return "an integer";
    case AttributeType::Float:
      return "a number";
    case AttributeType::Vec3:
      return "three numbers (x y z)";
    case AttributeType::Enum:
      return "one of the listed choices";
    case AttributeType::Name:
      return "a name";
    case AttributeType::Expression:
      return "an expression";
  }
  return "?";
}

// A number's text without the spaces around it and a leading '+'.
std::string_view numberText(std::string_view s) {
  while (!s.empty() && s.front() == ' ')
    s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ')
    s.remove_suffix(1);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  return s;
}

bool parseFloat(std::string_view s, float& out) {
  s = numberText(s);
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(out);
}

// The whole text as a double: errc() for a finite one (closer to 0 than a
// double holds, 1e-400 or 0.000...1, is 0), result_out_of_range beyond a
// double's range, invalid_argument for anything else.
std::errc parseDouble(std::string_view s, double& out) {
  std::string_view t = numberText(s);
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
  if (t.empty() || end != t.data() + t.size() || (ec == std::errc() && !std::isfinite(out)))
    return std::errc::invalid_argument;
  if (ec == std::errc::result_out_of_range) {
    if (t.front() == '-') t.remove_prefix(1);
    const bool small = t.find("e-") != std::string_view::npos ||
                       t.find("E-") != std::string_view::npos || t.front() == '.' ||
                       (t.size() > 1 && t[0] == '0' && t[1] == '.');
    if (small) {
      out = 0.0;
      return std::errc();
    }
  }
  return ec;
}

// Throws unless a per-item key's item exists in the state.
void checkItem(const AttributeInfo& info, std::string_view key, int index,
               const ParticleState& state) {
  if (info.perEmitter() && index >= int(state.emitters.size()))
    throw Error(concat("attribute '", key, "': there is no emitter ", index, " (there are ",
                       state.emitters.size(), ")"));
  if (info.perPrimitive() && index >= int(state.primitives.size()))
    throw Error(concat("attribute '", key, "': there is no primitive ", index, " (there are ",
                       state.primitives.size(), ")"));
  if (info.perObstacle() && index >= int(state.obstacles.size()))
    throw Error(concat("attribute '", key, "': there is no obstacle ", index, " (there are ",
                       state.obstacles.size(), ": [[obstacle]] in the configuration)"));
}

std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items)
    s += (s.empty() ? "" : ", ") + i;
  return s;
}

}  // namespace

const AttributeTable& AttributeTable::instance() {
  static const AttributeTable table;
  return table;
}

AttributeTable::AttributeTable() : entries_(makeEntries()) {}

std::string AttributeTable::canonical(std::string_view key) const {
  for (const Alias& a : kAliases)
    if (a.name == key) return std::string(a.target);
  // A configuration's [field_playback] table holds the field.* playback
  // attributes: its keys spelt as the file spells them name them too.
  constexpr std::string_view kPlayback = "field_playback.";
  if (key.starts_with(kPlayback)) return concat("field.", key.substr(kPlayback.size()));
  return std::string(key);
}

const AttributeInfo& AttributeTable::lookup(std::string_view rawKey, int* emitter) const {
  const std::string key = canonical(rawKey);
  std::string pattern = key;
  int index = 0;
  struct List {
    std::string_view prefix;  // "emitter."
    int count;
  };
  for (const List list : {List{"emitter.", ParticleState::kMaxEmitters},
                          List{"obstacle.", ParticleState::kMaxObstacles},
                          List{"primitive.", ParticleState::kMaxPrimitives}}) {
    if (!key.starts_with(list.prefix)) continue;
    const std::size_t from = list.prefix.size(), dot = key.find('.', from);
    const std::string_view digits = std::string_view(key).substr(from, dot - from);
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
    if (dot == std::string::npos || ec != std::errc() || end != digits.data() + digits.size() ||
        index < 0 || index >= list.count)
      throw Error(concat("attribute '", rawKey, "': expected ", list.prefix, "N.name with N in 0..",
                         list.count - 1));
    pattern = concat(list.prefix, "*.", key.substr(dot + 1));
  }
  for (const AttributeInfo& info : entries_) {
    if (info.key == pattern) {
      if (emitter) *emitter = index;
      return info;
    }
  }
  // The key a typo most likely meant (an emitter's, obstacle's or
  // primitive's with the index typed), then the keys that share the section.
  std::vector<std::string> meant, close;
  const std::string section = pattern.substr(0, pattern.rfind('.') + 1);
  for (const AttributeInfo& info : entries_) {
    meant.push_back(info.itemKey(index));
    if (!section.empty() && info.key.starts_with(section)) close.push_back(info.key);
  }
  throw Error(
      concat("unknown attribute '", rawKey, "'", didYouMean(key, meant),
             close.empty() ? std::string("") : "; known in this section: " + joined(close)));
}

AttributeValue AttributeTable::parse(std::string_view key, std::string_view text) const {
  const AttributeInfo& info = lookup(key);
  const auto fail = [&]() -> Error {
    const bool choice = info.type == AttributeType::Enum;
    return Error(concat("attribute '", key, "': cannot read '", text, "'",
                        choice ? didYouMean(text, info.choices) : "", " as ", typeName(info.type),
                        choice ? " (" + joined(info.choices) + ")" : ""));
  };
  // A number too large for its type (1e40, or 10^11 for an integer) is
  // outside any attribute's range: say so, with the number as written.
  const auto beyond = [&]() -> Error {
    return Error(concat("attribute '", key, "': ", info.outsideRange(text)));
  };
  switch (info.type) {
    case AttributeType::Bool:
      if (text == "true" || text == "1" || text == "on") return true;
      if (text == "false" || text == "0" || text == "off") return false;
      throw fail();
    case AttributeType::Int: {
      double d = 0.0;
      const std::errc ec = parseDouble(text, d);
      if (ec == std::errc::result_out_of_range) throw beyond();
      if (ec != std::errc() || d != std::floor(d)) throw fail();
      if (std::abs(d) > 2e9) throw beyond();
      return int(d);
    }
    case AttributeType::Float: {
      float f;
      if (parseFloat(text, f)) return f;
      // Not a float: beyond its range, or closer to 0 than its smallest.
      double d = 0.0;
      const std::errc ec = parseDouble(text, d);
      if (ec == std::errc() && std::abs(d) < 1.0) return float(d);
      if (ec == std::errc() || ec == std::errc::result_out_of_range) throw beyond();
      throw fail();
    }
    case AttributeType::Vec3: {
      std::string s(text);
      std::replace(s.begin(), s.end(), ',', ' ');
      std::istringstream in(s);
      std::string part[4];
      glm::vec3 v;
      in >> part[0] >> part[1] >> part[2] >> part[3];
      if (!part[3].empty()) throw fail();
      for (int i = 0; i < 3; ++i)
        if (!parseFloat(part[i], v[i])) throw fail();
      return v;
    }
    case AttributeType::Enum:
      if (std::find(info.choices.begin(), info.choices.end(), text) == info.choices.end())
        throw fail();
      return std::string(text);
    case AttributeType::Expression: {
      const std::optional<std::string> text2 = decodeName(text);
      if (!text2 || text2->empty())
        throw Error(concat("attribute '", key, "': '", text,
                           "': expected an expression (spaces written %20 in one word)"));
      return *text2;
    }
    case AttributeType::Name: {
      const std::optional<std::string> name = decodeName(text);
      if (!name)
        throw Error(concat("attribute '", key, "': '", text,
                           "': a '%' other than %20 (a space) or a lone % (no name)"));
      if (!nameProblem(*name).empty())
        throw Error(concat("attribute '", key, "': ", nameProblem(*name)));
      return *name;
    }
  }
  throw fail();
}

AttributeResult AttributeTable::validate(std::string_view key, const AttributeValue& value) const {
  const AttributeInfo& info = lookup(key);
  AttributeValue v = value;
  // Accept numbers across int/float, as configs and menus mix them.
  if (info.type == AttributeType::Float && std::holds_alternative<int>(v))
    v = float(std::get<int>(v));
  if (info.type == AttributeType::Int && std::holds_alternative<float>(v)) {
    const float f = std::get<float>(v);
    if (f != std::floor(f))
      throw Error(concat("attribute '", key, "': expected an integer, got ", f));
    v = int(std::clamp(f, -2e9f, 2e9f));
  }
  const std::size_t expected = [&] {
    switch (info.type) {
      case AttributeType::Bool:
        return std::size_t{0};
      case AttributeType::Int:
        return std::size_t{1};
      case AttributeType::Float:
        return std::size_t{2};
      case AttributeType::Vec3:
        return std::size_t{3};
      case AttributeType::Enum:
      case AttributeType::Name:
      case AttributeType::Expression:
        return std::size_t{4};
    }
    return std::size_t{0};
  }();
  if (v.index() != expected)
    throw Error(
        concat("attribute '", key, "': expected ", typeName(info.type), ", got ", toString(value)));

  AttributeResult result{v, {}};
  const auto clampReport = [&](float x) {
    if (!std::isfinite(x)) throw Error(concat("attribute '", key, "': value is not finite"));
    return std::clamp(x, info.min, info.max);
  };
  switch (info.type) {
    case AttributeType::Int: {
      const int x = std::get<int>(v);
      result.applied = int(clampReport(float(x)));
      break;
    }
    case AttributeType::Float:
      result.applied = clampReport(std::get<float>(v));
      break;
    case AttributeType::Vec3: {
      glm::vec3 x = std::get<glm::vec3>(v);
      for (int i = 0; i < 3; ++i)
        x[i] = clampReport(x[i]);
      if (info.direction && x == glm::vec3(0.0f))
        throw Error(concat("attribute '", key, "': expected a direction, not (0, 0, 0)"));
      result.applied = x;
      break;
    }
    case AttributeType::Enum:
      if (std::find(info.choices.begin(), info.choices.end(), std::get<std::string>(v)) ==
          info.choices.end())
        throw Error(concat("attribute '", key, "': '", std::get<std::string>(v),
                           "' is not one of: ", joined(info.choices)));
      break;
    case AttributeType::Name:
      if (const std::string problem = nameProblem(std::get<std::string>(v)); !problem.empty())
        throw Error(concat("attribute '", key, "': ", problem));
      break;
    case AttributeType::Expression: {
      const std::string& text = std::get<std::string>(v);
      for (const char ch : text)
        if (ch < ' ' || ch > '~' || ch == '#' || ch == '%' || ch == '"' || ch == '\'')
          throw Error(concat("attribute '", key, "': the character '", std::string(1, ch), "' in '",
                             text, "'; expected an expression of printable characters"));
      try {
        const std::string component(1, key.empty() ? '?' : key.back());
        FieldExpression::check(text, component.c_str());
      } catch (const Error& e) {
        throw Error(concat("attribute '", key, "': ", e.what()));
      }
      break;
    }
    case AttributeType::Bool:
      break;
  }
  if (toString(result.applied) != toString(v))
    result.warning = concat("attribute '", key, "': ", info.outsideRange(toString(v)),
                            "; clamped to ", toString(result.applied));
  return result;
}

AttributeResult AttributeTable::set(ParticleState& state, std::string_view key,
                                    const AttributeValue& value) const {
  int emitter = 0;
  const AttributeInfo& info = lookup(key, &emitter);
  checkItem(info, key, emitter, state);
  AttributeResult result = validate(key, value);
  info.set(state, emitter, result.applied);
  return result;
}

AttributeValue AttributeTable::get(const ParticleState& state, std::string_view key) const {
  int emitter = 0;
  const AttributeInfo& info = lookup(key, &emitter);
  checkItem(info, key, emitter, state);
  return info.get(state, emitter);
}

std::string AttributeTable::describe(const ParticleState& state) const {
  std::string out;
  for (const AttributeInfo& info : entries_) {
    if (!info.perItem()) {
      out += info.key + "=" + toString(info.get(state, 0)) + "\n";
      continue;
    }
    const std::size_t count = info.perEmitter()    ? state.emitters.size()
                              : info.perObstacle() ? state.obstacles.size()
                                                   : state.primitives.size();
    for (std::size_t e = 0; e < count; ++e)
      out += info.itemKey(int(e)) + "=" + toString(info.get(state, int(e))) + "\n";
  }
  return out;
}

std::string AttributeInfo::outsideRange(std::string_view value) const {
  return concat(value, " is outside [", min, ", ", max, "] ", unit);
}

std::string AttributeInfo::itemKey(int index) const {
  const std::size_t star = key.find('*');
  if (star == std::string::npos) return key;
  return key.substr(0, star) + std::to_string(index) + key.substr(star + 1);
}

std::string encodeName(std::string_view name) {
  if (name.empty()) return "%";
  std::string out;
  for (const char c : name)
    if (c == ' ')
      out += "%20";
    else
      out += c;
  return out;
}

std::string toString(const AttributeValue& value) {
  std::ostringstream os;
  std::visit(
      [&](const auto& x) {
        using X = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<X, bool>)
          os << (x ? "true" : "false");
        else if constexpr (std::is_same_v<X, glm::vec3>)
          os << x.x << ' ' << x.y << ' ' << x.z;
        else
          os << x;
      },
      value);
  return os.str();
}

}  // namespace sandstorm
