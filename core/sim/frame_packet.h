// FramePacket: everything a render context needs for one frame, made once by
// the main context and shared read-only by every wall (split first, thesis 5.3).
// A context that applies the same packets in the same order holds the same
// particles as every other: nothing else enters the simulation.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/cave/viewer.h"
#include "core/field/field_equation.h"
#include "core/field/field_placement.h"
#include "core/field/field_range.h"
#include "core/field/field_timeline.h"
#include "core/field/sparse_field.h"
#include "core/field/vector_field.h"
#include "core/sim/counter_rng.h"
#include "core/sim/sim_step.h"
#include "core/sim/state_change.h"
#include "core/tracking/tracking_sample.h"
#include "core/tracking/wand_ray.h"

namespace sandstorm {

struct FieldUpdate {
  std::shared_ptr<const VectorField> field;  // the new grid (shared, never copied per wall)
  FieldPlacement placement;
  std::shared_ptr<const VectorField> next;  // a time-varying field's next frame, or null
  // A streamed series: which steps `field` and `next` are (cluster ranks that
  // read the series themselves take them from their own reader).
  std::optional<FieldSeriesRef> series;
  // An analytic field's equation (field.mode = equation evaluates it in place of
  // `field`, whose bounds still bound the particles), or null.
  std::shared_ptr<const FieldEquation> equation;
  // A sparse grid (field.storage = sparse: core/field/sparse_field.h) read in
  // place of `field`, which is its overview: a dense grid over the same
  // bounds, for what needs one (bounds, colour grids). Null: `field` is the field.
  std::shared_ptr<const SparseField> sparse;
  // `field`'s range of speed, velocity and the colour grid's values (the
  // colour scale's ends by default): computed once by the main context
  // (MainContext::setField and its timeline).
  FieldRange range;
  // While particles are coloured by a grid quantity (usesColorGrid): that
  // quantity on `field`'s and `next`'s points, in x (core/color/color_grid.h):
  // vorticityMagnitude, or the scalar array `colorArray` of the file. Null
  // otherwise, and when the field has no such array.
  std::shared_ptr<const VectorField> colorGrid, nextColorGrid;
  std::string colorArray;  // the array colorGrid holds; empty: vorticity
};

struct FramePacket {
  std::uint32_t frame = 0;
  float dt = 0.0f;       // wall-clock seconds since the previous frame (measured once)
  float simDt = 0.0f;    // simulated seconds: dt * time scale, 0 while paused
  double time = 0.0;     // wall-clock seconds since the first frame
  double simTime = 0.0;  // simulated seconds before this frame (the sum of earlier simDt)
  std::uint64_t seed = 0;
  bool reset = false;                              // drop every particle before this frame
  std::vector<StateChange> changes;                // take effect at this frame, before the update
  std::vector<std::uint32_t> emission;             // Reeves' count per emitter for this frame
  std::shared_ptr<const FieldUpdate> fieldUpdate;  // non-null when the field changed
  Viewer viewer;            // the head and the navigation, sampled once for every wall
  TrackingSample tracking;  // the tracked head and wand (room); inactive without a tracker
  WandRay wand;             // the wand's ray and what it meets, drawn by every wall
  float fieldBlend = 0.0f;  // weight towards fieldUpdate's `next` frame (time-varying fields)
  // A time-varying field's frame after the pair in use, in playback order,
  // when it is in memory already: walls upload it ahead of need. A hint:
  // nothing a wall computes depends on it, and it does not travel to
  // cluster ranks (FramePacketCodec), which upload each frame as it comes.
  std::shared_ptr<const VectorField> upcomingField;
  float lodScale =
      1.0f;  // the level of detail's emission scale, already in `emission` (for display)

  SimStep step() const {
    return SimStep{frame, simDt, Seed::from(seed), emission, fieldBlend, simTime};
  }
};

}  // namespace sandstorm
