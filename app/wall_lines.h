// The polylines a wall shows at a frame, for export (--dump-streamlines,
// --dump-trails, the Python module): its streamlines traced on the CPU (the
// GPU's twin) from the wall's replica of the state and field, and its
// particles' trails as lines ending at their particle.
#pragma once

#include <memory>
#include <vector>

#include "core/field/height_map.h"
#include "core/flow/streamline_tracer.h"
#include "core/sim/frame_packet.h"
#include "core/sim/particle.h"

namespace sandstorm {

std::vector<Streamline> wallStreamlines(const ParticleState& state,
                                        const std::shared_ptr<const FieldUpdate>& field,
                                        float fieldBlend, const HeightMap* terrain);

// Lines of two points or more, oldest first; owners[i]: the particle of line i.
std::vector<Streamline> trailLines(const std::vector<Particle>& particles,
                                   const std::vector<std::vector<glm::vec3>>& trails,
                                   std::vector<std::size_t>& owners);

}  // namespace sandstorm
