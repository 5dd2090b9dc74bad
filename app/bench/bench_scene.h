// sandstorm-bench's fixed scene: a tornado (texture or equation), one disc
// emitter at its foot, tracer particles that live longer than the run and are
// clamped to the field's box, so a run holds exactly N particles from its
// first frame (all born then) to its last. Views circle the tornado at 14 m.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "core/cave/view.h"
#include "core/sim/frame_packet.h"
#include "core/sim/particle_state.h"

namespace sandstorm::bench {

struct SceneChoice {
  std::size_t particles = 0;
  std::string field = "texture";        // texture | equation
  std::string renderer = "billboards";  // billboards | points | splat (tiled) | splat-atomic
  float particleSize = 0.045f;
  std::string integrator = "rk2";
  int trailLength = 0;   // render.trail_length
  bool shadows = false;  // render.shadows
  int obstacles = 0;     // in the cloud: 1 a sphere the flow goes around, 2 and a box
  int molecules = 0;     // > 0: the particles are molecules of this many members
  bool turnover =
      false;  // short lives, deaths at the box: every frame births, deaths and compaction
};

ParticleState benchState(const SceneChoice& choice);
std::shared_ptr<const FieldUpdate> benchField(const std::string& mode);
// Packet `frame` of the run: frame 0 carries the field and all the particles.
FramePacket benchPacket(std::uint32_t frame, const SceneChoice& choice,
                        const std::shared_ptr<const FieldUpdate>& field);
// `count` cameras evenly around the tornado; view `index` of them.
View benchView(int index, int count, glm::ivec2 size);

}  // namespace sandstorm::bench
