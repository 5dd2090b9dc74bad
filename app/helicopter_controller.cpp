#include "app/helicopter_controller.h"

#include "core/field/curl_noise_field.h"
#include "core/field/downwash_field.h"
#include "core/field/sum_field.h"
#include "core/field/vortex_ring_field.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

bool same(const HelicopterSettings& a, const HelicopterSettings& b) {
  return a.enabled == b.enabled && a.x == b.x && a.y == b.y && a.altitude == b.altitude &&
         a.throttle == b.throttle;
}

}  // namespace

HelicopterController::HelicopterController(std::shared_ptr<const HeightMap> terrain,
                                           HelicopterModel model)
    : terrain_(std::move(terrain)), model_(model) {}

void HelicopterController::update(MainContext& main) {
  const ParticleState state = main.state();
  const HelicopterSettings s = state.helicopter;
  // The live solver (solver.enabled) makes the wash itself from the rotor's
  // thrust (FluidDriver or each GPU's LiveFlow), starting from still air over
  // the analytic wash's box; the analytic wash is baked when it stops.
  const bool solving = state.solver.enabled;
  if (!s.enabled || (last_ && same(*last_, s) && solving == lastSolving_)) return;
  last_ = s;
  lastSolving_ = solving;
  const HelicopterEffects e = helicopterEffects(s, model_);
  const float ground = terrain_ ? terrain_->heightAt({s.x, s.y}) : 0.0f;

  // The wash in the rotor's own frame (ground at z = 0 under the hub), placed under the hub.
  DownwashParams wash;
  wash.hub = {0.0f, 0.0f, s.altitude};
  wash.radius = model_.rotorRadius;
  wash.thrust = std::max(e.thrust, 1.0f);
  wash.ground = 0.0f;
  wash.groundLayer = 0.35f * model_.rotorRadius;
  const float vh = DownwashField(wash).hoverInducedSpeed();
  // The wall jet rolls up into a ring around the rotor (what lifts the dust),
  // as strong as the wash that still reaches the ground; gusts stir it.
  VortexRingParams ring;
  ring.ringRadius = 1.8f * model_.rotorRadius;
  ring.height = 0.6f * model_.rotorRadius;
  ring.core = 0.7f * model_.rotorRadius;
  ring.strength = 0.6f * vh * e.groundEffect;
  CurlNoiseParams gusts;
  gusts.scale = 5.0f;
  gusts.amplitude = 0.3f * vh;
  std::vector<std::unique_ptr<AnalyticField>> parts;
  parts.push_back(std::make_unique<DownwashField>(wash));
  parts.push_back(std::make_unique<VortexRingField>(ring));
  parts.push_back(std::make_unique<CurlNoiseField>(gusts));
  const SumField air(std::move(parts));
  const float reach = 5.0f * model_.rotorRadius;
  // Room above the rotor for the cloud the recirculation lifts (brownout rises past the disc).
  const Box bounds{{-reach, -reach, 0.0f}, {reach, reach, s.altitude + 2.0f * model_.rotorRadius}};
  // The live flow starts from still air: the wash it shows is all its own.
  const SumField still;
  const AnalyticField& start = solving ? static_cast<const AnalyticField&>(still) : air;
  auto field = std::make_shared<VectorField>(bake(start, bounds, {48, 48, 24}));
  FieldPlacement placement;
  placement.offset = {s.x, s.y, ground};
  // The solver's starting grid once; it makes its own flow from then on.
  if (!solving || !bakedOnce_)
    main.setField(FieldUpdate{.field = std::move(field), .placement = placement});
  bakedOnce_ = true;

  main.set("emitter.0.shape", std::string("disc"));
  main.set("emitter.0.position", glm::vec3(s.x, s.y, ground + 0.15f));
  main.set("emitter.0.radius", e.dustRadius);
  main.set("emitter.0.rate", e.rate);
  main.set("emitter.0.lifetime", e.lifetime);
  main.set("sim.maximum", e.maximum);
  log::info("helicopter: throttle ", s.throttle, ", ", s.altitude, " m up: thrust ", e.thrust,
            " N, v_h ", vh, " m/s, dust ", e.rate, "/s (ground effect ", e.groundEffect, ")");
}

}  // namespace sandstorm
