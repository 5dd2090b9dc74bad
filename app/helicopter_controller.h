// HelicopterController: the downdraft demo's interaction model, on the main
// thread. When the helicopter's attributes change (menu, --set, a replayed
// session), it works out their effects (core/sim/helicopter.h) and asks the
// main context for them: the rotor-downwash field re-baked under the rotor
// (plus a little turbulence, so dust billows), and the dust emitter's place,
// size, rate and lifetime and the maximum. These requests are ordinary
// attribute changes and field updates, so every wall gets them at one frame.
#pragma once

#include <memory>
#include <optional>

#include "core/field/height_map.h"
#include "core/sim/helicopter.h"
#include "core/sim/main_context.h"

namespace sandstorm {

class HelicopterController {
 public:
  HelicopterController(std::shared_ptr<const HeightMap> terrain, HelicopterModel model = {});
  // Call once per frame, after MainContext::next().
  void update(MainContext& main);

 private:
  std::shared_ptr<const HeightMap> terrain_;
  HelicopterModel model_;
  std::optional<HelicopterSettings> last_;
  bool lastSolving_ = false;
  bool bakedOnce_ = false;
};

}  // namespace sandstorm
