#include "contexts/particles/particle_system.h"

#include "contexts/particles/particle_compute_update.h"
#include "contexts/particles/particle_geo_update.h"
#include "contexts/particles/particle_trails.h"
#include "contexts/particles/shared_particles.h"
#include "contexts/render/view_targets.h"
#include "core/sim/capacity.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

std::unique_ptr<ParticleBackend> makeParticleBackend(const std::string& name, std::size_t capacity,
                                                     const GpuTuning& tuning,
                                                     UploadThread* uploads) {
  if (name == "tf-gs") return std::make_unique<ParticleGeoUpdate>(capacity, uploads);
  if (name == "compute") return std::make_unique<ParticleComputeUpdate>(capacity, tuning, uploads);
  throw Error(concat("unknown particle backend '", name, "'; expected tf-gs or compute"));
}

namespace {

// A wall's own simulation, the one it runs for its GPU's other walls too, or theirs.
std::unique_ptr<ParticleBackend> backendFor(const ParticleSystem::Options& o) {
  if (o.share && o.shareReader >= 0)
    return std::make_unique<SharedParticles>(o.share, o.shareReader);
  std::unique_ptr<ParticleBackend> own =
      makeParticleBackend(o.backend, o.capacity, o.tuning, o.uploads);
  if (o.share) return std::make_unique<SharingBackend>(std::move(own), o.share);
  return own;
}

}  // namespace

ParticleSystem::ParticleSystem(const ParticleState& initial, const Options& options)
    : state_(initial),
      capacityLimit_(std::max(options.capacity, options.capacityLimit)),
      update_(backendFor(options)),
      splat_(options.tuning),
      tuning_(options.tuning) {
  if (update_->simulates()) shadow_ = std::make_unique<OpacityShadowMap>();
}

void ParticleSystem::endFrame() {
  update_->endFrame();
}

void ParticleSystem::setTerrain(std::shared_ptr<const HeightMap> terrain) {
  terrain_ = terrain;
  update_->setTerrain(terrain);
  if (molecules_) molecules_->setTerrain(std::move(terrain));
}

void ParticleSystem::advance(const FramePacket& packet) {
  splat_.particlesChanged();
  fieldBlend_ = packet.fieldBlend;
  if (packet.reset) {
    update_->clear();
    if (molecules_) molecules_->clear();
  }
  // The main context validated every change; a replica applies them as they come.
  for (const StateChange& change : packet.changes)
    applyChange(state_, change);
  // Raising Maximum above the buffers grows them, at the same frame on every wall.
  const std::size_t capacity =
      grownCapacity(update_->capacity(), state_.sim.maximum, capacityLimit_);
  if (update_->simulates() && capacity > update_->capacity()) {
    log::info("frame ", packet.frame, ": growing the particle buffers from ", update_->capacity(),
              " to ", capacity);
    update_->grow(capacity);
  }
  if (packet.fieldUpdate) {
    field_ = packet.fieldUpdate;
    update_->setField(field_->field, field_->placement, field_->next);
    update_->setEquation(field_->equation);
    update_->setSparse(field_->sparse);
    log::debug("frame ", packet.frame, ": field uploaded in ", update_->lastFieldUploadMs(), " ms");
  }
  update_->prefetchField(packet.upcomingField);
  // The live flow on this GPU, before the particles move through it.
  if (update_->simulates()) {
    const std::uint32_t flow =
        flow_.advance(state_, field_.get(), terrain_.get(), packet.step().dt);
    if (!update_->setFieldBuffer(flow)) {
      flow_.refuse(concat("the '", update_->name(),
                          "' backend keeps the field's grid as a texture; the solver needs "
                          "run.backend = compute and a grid within a storage buffer")
                       .c_str());
      update_->setFieldBuffer(0);
    }
  }
  update_->step(packet.step(), state_);
  // Molecules: the same packets, on every wall (they are not shared between walls).
  if (update_->simulates() && !molecules_ && MoleculeUpdate::wanted(state_)) {
    molecules_ = std::make_unique<MoleculeUpdate>(
        std::size_t(std::max(state_.molecules.maximum, 1)), capacityLimit_ / 8, tuning_);
    if (terrain_) molecules_->setTerrain(terrain_);
    if (field_) setMoleculeField();
  } else if (molecules_ && packet.fieldUpdate) {
    setMoleculeField();
  }
  if (molecules_) {
    molecules_->setFieldBuffer(flow_.solver() ? flow_.solver()->pointBuffer() : 0);
    molecules_->step(packet.step(), state_);
  }
  // The shadow map depends on the particles, not the view: built once here
  // for every wall drawing this simulation, and published with it.
  if (shadow_) {
    shadow_->build(update_->records(), update_->capacity(), state_.render);
    update_->publish(shadow_->handles(), molecules());
  }
  frame_ = packet.frame;
}

void ParticleSystem::uploadFieldAhead(const FieldUpdate& field) {
  update_->setField(field.field, field.placement, field.next);
  update_->setEquation(field.equation);
  update_->setSparse(field.sparse);
}

void ParticleSystem::setMoleculeField() {
  molecules_->setField(field_->field, field_->placement, field_->next);
  molecules_->setEquation(field_->equation);
  molecules_->setSparse(field_->sparse);
}

void ParticleSystem::render(const ViewTargets& targets, std::uint32_t destination,
                            glm::ivec2 origin, const View* view) const {
  renderParticles(targets, view);
  composite(targets, destination, origin);
}

bool ParticleSystem::splats(const View* view, glm::ivec2 size) const {
  const RenderSettings& r = state_.render;
  if (r.mode == RenderMode::Splat) return true;
  if (r.mode != RenderMode::Auto || !view) return false;
  // A particle where the field is (or the first emitter, without a field).
  glm::vec3 where = state_.emitters.empty() ? glm::vec3(0.0f) : state_.emitters[0].position;
  if (field_ && field_->field) where = field_->placement.toRoom(field_->field->bounds().center());
  const glm::vec4 eye = view->view * glm::vec4(where, 1.0f);
  const float distance = std::max(-eye.z, 1e-3f);
  const float pixels = r.size * view->projection[1][1] * 0.5f * float(size.y) / distance;
  return pixels <= r.splatPixels;
}

void ParticleSystem::renderParticles(const ViewTargets& targets, const View* view,
                                     const View* next) const {
  if (splats(view, targets.size())) {
    const RenderSettings& r = state_.render;
    using Blur = SplatLook::Blur;
    splat_.draw(*update_, targets, render_.sprite(),
                {.shadows = r.shadows,
                 .blur = r.shutter <= 0.0f             ? Blur::None
                         : r.blur == BlurMethod::Smear ? Blur::Smear
                                                       : Blur::Filter,
                 .levels = r.splatDetail > 0.0f},
                {.view = view, .next = next});
  } else
    render_.draw(*update_, targets, state_.render.mode, state_.render.order);
  if (const MoleculeHandles m = molecules()) {
    if (!moleculeRenderer_) moleculeRenderer_ = std::make_unique<MoleculeRenderer>();
    moleculeRenderer_->draw(m, targets);
  }
}

void ParticleSystem::composite(const ViewTargets& targets, std::uint32_t destination,
                               glm::ivec2 origin) const {
  post_.draw(targets, destination, origin);
}

}  // namespace sandstorm

namespace sandstorm {

void ParticleSystem::drawTrails(const View* view, const ViewTargets& targets) const {
  if (state_.render.trailLength < 2) return;
  if (!splats(view, targets.size())) splat_.drawTrailsOverScene(*update_, targets);
}

std::vector<std::vector<glm::vec3>> ParticleSystem::readBackTrails() const {
  const ParticleBackend::Records r = update_->records();
  return ParticleTrails::read(r.trails, r.trailLength, r.trailHead, update_->liveCount());
}

}  // namespace sandstorm
