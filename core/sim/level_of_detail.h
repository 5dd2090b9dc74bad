// LevelOfDetail: Reeves' level of detail for emission (1983): fewer particles
// when the system covers little of the view, or when frames take longer than a
// budget (the thesis: the system scales itself back "as less and less
// resources become available").
//
// The main context alone decides (split first): it scales every emitter's
// rate by scale() before drawing the Reeves counts, and the counts travel in
// the frame packet, so every wall emits the same particles. Nothing is
// measured per wall. Settings: SimSettings::lod* (attributes sim.lod,
// sim.lod_coverage, sim.lod_budget_ms, sim.lod_min_scale).
#pragma once

#include <optional>

#include "core/cave/viewer.h"
#include "core/field/box.h"
#include "core/field/field_placement.h"
#include "core/sim/sim_settings.h"

namespace sandstorm {

// The solid angle a box (its bounding sphere) subtends at the viewer's head,
// as a fraction of a 90-degree viewing cone (1.84 sr), at most 1. The box is in
// field coordinates, placed in the world by `placement`; the head is in the
// room, which the viewer's navigation relates to the world.
float viewCoverage(const Box& box, const FieldPlacement& placement, const Viewer& viewer);

class LevelOfDetail {
 public:
  // The emission scale for the next frame, in [lodMinScale, 1] (1 when lod is
  // off). `coverage`: viewCoverage() of the system; `frameMs`: how long the
  // last frame took, if known. Over budget, the scale drops in proportion
  // (budget / frame time); under 90% of it, it recovers by 5% a frame.
  float update(const SimSettings& settings, float coverage, std::optional<double> frameMs);
  float scale() const { return scale_; }

 private:
  float budgetScale_ = 1.0f;
  float scale_ = 1.0f;
};

}  // namespace sandstorm
