// SolidsKey: what a flow solver's solid cells were last made from (the
// terrain, the solids, the field's placement), so that a step in which
// nothing moved does not make them again. FluidSolver and GpuFluidSolver
// each hold one.
#pragma once

#include <vector>

#include "core/field/field_placement.h"
#include "core/field/height_map.h"
#include "core/obstacles/obstacle.h"

namespace sandstorm {

class SolidsKey {
 public:
  // True, remembering them, when these differ from the last ones (or on the first call).
  bool changed(const HeightMap* terrain, const std::vector<Obstacle>& obstacles,
               const FieldPlacement& placement) {
    if (set_ && terrain == terrain_ && obstacles == obstacles_ &&
        placement.offset == placement_.offset && placement.scale == placement_.scale &&
        placement.rotation == placement_.rotation)
      return false;
    set_ = true;
    terrain_ = terrain;
    obstacles_ = obstacles;
    placement_ = placement;
    return true;
  }

 private:
  bool set_ = false;
  const HeightMap* terrain_ = nullptr;
  std::vector<Obstacle> obstacles_;
  FieldPlacement placement_;
};

}  // namespace sandstorm
