#include "core/tracking/wand_handles.h"

#include "core/util/error.h"

namespace sandstorm {

std::vector<WandHandle> wandHandles(const ParticleState& state) {
  std::vector<WandHandle> handles;
  for (std::size_t i = 0; i < state.emitters.size(); ++i)
    handles.push_back({concat("emitter.", i, ".position"), state.emitters[i].position});
  for (std::size_t i = 0; i < state.obstacles.size(); ++i)
    if (state.obstacles[i].enabled)
      handles.push_back({concat("obstacle.", i, ".position"), state.obstacles[i].position});
  for (std::size_t i = 0; i < state.primitives.size(); ++i)
    if (state.primitives[i].active())
      handles.push_back({concat("primitive.", i, ".position"), state.primitives[i].position});
  if (state.streamlines.enabled) {
    handles.push_back({"streamlines.from", state.streamlines.from});
    handles.push_back({"streamlines.to", state.streamlines.to});
  }
  if (state.slice.enabled) handles.push_back({"slice.origin", state.slice.origin});
  if (state.probe.enabled) handles.push_back({"probe.position", state.probe.position});
  return handles;
}

}  // namespace sandstorm
