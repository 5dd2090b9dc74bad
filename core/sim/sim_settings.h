// SimSettings: how particles move. RenderSettings: how they look.
// Both are plain values; the attribute table (attribute_table.h) names, ranges
// and documents every field, and is the only way they change at run time.
#pragma once

#include <array>
#include <string>

#include <glm/glm.hpp>

#include "core/color/color_map.h"
#include "core/color/color_scale.h"

namespace sandstorm {

// How the field drives a particle (position x, velocity v, field f at x):
enum class MotionModel : int {
  Tracer = 0,  // dx/dt = s f(x): f is a velocity (measured wind; VTK's tracers)
  Force = 1,   // dv/dt = s f(x) + g, dx/dt = v: f is an acceleration (the thesis)
  Drag = 2,    // dv/dt = (s f(x) - v) / tau + g, dx/dt = v: dust with response time tau
};

enum class Integrator : int { Euler = 0, RK2 = 1, RK4 = 2 };

// What happens to a particle that leaves the field's bounds.
enum class BoundaryMode : int { Kill = 0, Clamp = 1, Wrap = 2 };

struct SimSettings {
  int maximum = 100000;  // soft limit on live particles (the buffer capacity is the hard one)
  MotionModel motion = MotionModel::Tracer;
  Integrator integrator = Integrator::RK2;
  BoundaryMode boundary = BoundaryMode::Kill;
  float fieldStrength = 1.0f;             // s: multiplies the field
  float timeScale = 1.0f;                 // simulated seconds per wall-clock second
  float dragTime = 0.05f;                 // s: tau of the drag model
  glm::vec3 gravity{0.0f, 0.0f, -9.81f};  // m/s^2, force and drag models
  bool groundCollision = true;  // particles stop at the ground (z = ground height, or terrain)
  float restitution = 0.2f;     // fraction of normal speed kept on a bounce
  bool emitting = true;         // start/stop: emitters emit only while true
  bool paused = false;          // pause: time stands still, nothing moves or dies
  // Level of detail (Reeves; core/sim/level_of_detail.h): the main context scales emission down
  bool lod = false;
  float lodCoverage =
      0.2f;  // view coverage (fraction of a 90-degree cone) at and above which emission is full
  float lodBudgetMs = 0.0f;  // frame-time budget; over it emission drops (0: coverage only)
  float lodMinScale = 0.1f;  // emission never drops below this fraction of the rates
};

// How the particle update reads the field: the baked grid (a 3D texture) or,
// for analytic fields, their equations evaluated in the shader.
// Expression: the field written at run time (FieldPlayback::expression, core/expr).
enum class FieldMode : int { Texture = 0, Equation = 1, Expression = 2 };

// How a time-varying field plays (the main context's field clock).
struct FieldPlayback {
  float speed = 1.0f;  // field seconds per simulated second
  bool loop = true;
  bool paused = false;  // hold the current frame while particles move on
  bool follow = false;  // show the newest frame (a field that grows as a simulation runs)
  FieldMode mode =
      FieldMode::Texture;  // Equation: only where the field has one (FieldUpdate::equation)
  // Mode Expression: each component as an expression of x, y, z, t, vx, vy,
  // vz, age (core/expr/field_expression.h), in the field's own coordinates.
  std::array<std::string, 3> expression{"0", "0", "0"};
};

// Splat: billboards' look, drawn by a compute pass (ParticleSplat); each
// particle wider than RenderSettings::splatDetail pixels on a coarser grid.
// Auto: per view, splats when a particle at the field's centre covers at most
// RenderSettings::splatPixels pixels, billboards otherwise.
enum class RenderMode : int { Points = 0, Billboards = 1, Splat = 2, Auto = 3 };

// How billboards blend: in the particle buffer's order (fast, and exact for
// particles of one colour and opacity), or sorted back to front per view on
// the GPU (GpuRadixSort), so nearer dust covers farther dust as it should.
// Splats average the particles in a pixel and need no order.
enum class RenderOrder : int { Unsorted = 0, Sorted = 1 };
// How splats show motion blur (render.blur): the particle buffers blurred
// along each pixel's motion (ParticleMotionFilter), or each splat smeared
// along its own path (exact, and slower by the pixels its smear covers).
enum class BlurMethod : int { Filter = 0, Smear = 1 };

struct RenderSettings {
  RenderMode mode = RenderMode::Billboards;
  RenderOrder order = RenderOrder::Unsorted;
  float size = 0.08f;  // m: billboard diameter; points use it as a projected size
  glm::vec3 colorBirth{0.85f, 0.72f, 0.52f};
  glm::vec3 colorDeath{0.55f, 0.45f, 0.35f};
  float opacityBirth = 0.6f;
  float opacityDeath = 0.0f;
  glm::vec3 lightDirection{0.4f, -0.3f, 0.85f};  // towards the light, room space
  float ambient = 0.35f;
  glm::vec3 lightColor{1.0f, 1.0f, 1.0f};
  float lightStrength = 1.0f;  // scales the direct (not the ambient) light
  // Volumetric self-shadowing (opacity shadow maps, core/light/light_model.h).
  bool shadows = false;
  float shadowDensity = 1.0f;  // scales how much light each particle blocks
  int shadowLayers = 16;       // opacity layers along the light
  int shadowResolution = 256;  // the map's largest side, texels
  float scattering = 0.0f;     // 1/m: the air's haze, lit through the dust's shadow (0: none)
  float shutter = 0.0f;        // s: motion blur over this much of the particles' path (0: off)
  BlurMethod blur = BlurMethod::Filter;  // splats' motion blur
  float softness = 0.3f;                 // m: particles fade out this close to scene geometry
  float splatPixels = 64.0f;             // Auto mode: splat particles up to this projected diameter
  float splatDetail = 4.0f;  // px: splats twice this wide go to coarser grids (0: never)
  // Where splats cover a pixel more than this many times on average over its
  // 32-pixel tile and the eight around it, the tile draws them one grid
  // coarser (0: never).
  float splatOverlap = 64.0f;
  bool fieldBox = true;  // outline the field's bounds
  // Colour by a quantity (core/color): which, through which map, over which range.
  ColorQuantity colorBy = ColorQuantity::Age;
  std::string colorArray;  // ColorQuantity::Array: the field's scalar array ("": its first)
  ColorMapName colorMap = ColorMapName::Life;  // Life: colorBirth to colorDeath
  ColorRange colorRange = ColorRange::Field;
  int colorEvery = 30;    // ColorRange::Particles: frames between measurements
  float colorMin = 0.0f;  // the fixed range's ends (ColorRange::Fixed; Particles writes them)
  float colorMax = 1.0f;
  bool colorLog = false;
  bool legend = false;  // show the colour bar (the menu always has one)
  int trailLength = 0;  // positions each particle's trail keeps (0: no trails; compute backend)
  bool streaklines = false;  // point emitters' streaklines (core/flow/streaklines.h)
  int streakLength = 120;    // points a streakline keeps (one released a frame)
};

}  // namespace sandstorm
