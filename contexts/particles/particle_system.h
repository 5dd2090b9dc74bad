// ParticleSystem: one render context's complete copy of the particle system
// (split first, thesis 5.3). It changes only by applying the main context's
// frame packets, in order, so every copy holds the same particles. It owns the
// thesis's three stages: ParticleGeoUpdate, ParticleRender and ParticlePost.
//
// Needs its GL context current for every call.
#pragma once

#include <memory>
#include <string>

#include "contexts/gl/upload_thread.h"
#include "contexts/molecules/molecule_renderer.h"
#include "contexts/molecules/molecule_update.h"
#include "contexts/particles/particle_backend.h"
#include "contexts/particles/particle_post.h"
#include "contexts/particles/particle_render.h"
#include "contexts/particles/particle_splat.h"
#include "contexts/shadows/opacity_shadow_map.h"
#include "contexts/solver/live_flow.h"
#include "core/cave/view.h"
#include "core/config/gpu_tuning.h"
#include "core/sim/frame_packet.h"
#include "core/sim/particle_state.h"

namespace sandstorm {

class SimulationShare;
class ViewTargets;

// The backend of that name ("tf-gs" or "compute"); throws Error for others.
// `uploads`: copies a series' steps ahead of need (GridPrefetch); null: the backend's thread.
std::unique_ptr<ParticleBackend> makeParticleBackend(const std::string& name, std::size_t capacity,
                                                     const GpuTuning& tuning = {},
                                                     UploadThread* uploads = nullptr);

class ParticleSystem {
 public:
  struct Options {
    std::size_t capacity = 1u << 20;
    std::size_t capacityLimit = 1u << 26;  // how far raising sim.maximum may grow the buffers
    std::string backend =
        "compute";  // "compute" (default: the faster, docs/PERFORMANCE.md) or "tf-gs"
    // One simulation for the walls of one GPU (contexts sharing objects):
    // with a share, shareReader < 0 runs the simulation and publishes it,
    // shareReader = k >= 0 draws the owner's particles as reader k.
    std::shared_ptr<SimulationShare> share;
    int shareReader = -1;
    GpuTuning tuning;                 // how the backend and the splats work ([gpu])
    UploadThread* uploads = nullptr;  // copies steps ahead of need; null: this thread does
  };

  ParticleSystem(const ParticleState& initial, const Options& options);

  void setTerrain(std::shared_ptr<const HeightMap> terrain);
  // After every view of a frame is drawn (a shared simulation's readers release it).
  void endFrame();
  // Applies the packet (reset, changes, field) and runs this frame's update.
  void advance(const FramePacket& packet);
  // Before packet 0: uploads the field it is to carry (FrameChannel::offerField)
  // as advance() would, so that the packet finds it held.
  void uploadFieldAhead(const FieldUpdate& field);
  // Draws the particles of the view whose scene is in `targets` and composites
  // the result into `destination` at `origin`. The view and render blocks
  // must be bound.
  // `view` (the one the bound view block describes) lets render.mode = auto
  // choose splats or billboards; without it auto draws billboards.
  void render(const ViewTargets& targets, std::uint32_t destination, glm::ivec2 origin,
              const View* view = nullptr) const;
  // render()'s two halves, for callers that time them apart (sandstorm-bench):
  // the particles into the view's particle buffers, then the lit composite.
  // `next`: the view drawn next from these particles, or null (SplatViews).
  void renderParticles(const ViewTargets& targets, const View* view = nullptr,
                       const View* next = nullptr) const;
  // Whether this view draws splats (render.mode splat, or auto and particles
  // at the field's centre cover at most render.splat_pixels pixels).
  bool splats(const View* view, glm::ivec2 size) const;
  void composite(const ViewTargets& targets, std::uint32_t destination, glm::ivec2 origin) const;
  // The particles' trails (render.trail_length) over the view's scene
  // colour, with the view and render blocks bound; views drawing splats
  // (splats(view, size)) add them to the splats instead (ParticleSplat).
  void drawTrails(const View* view, const ViewTargets& targets) const;
  // This frame's shadow map (render.shadows; says "none" when off), this
  // system's own or, for a shared simulation's reader, the owner's.
  ShadowHandles shadow() const { return shadow_ ? shadow_->handles() : update_->sharedShadow(); }
  // The owner's map itself (tests); null for a shared simulation's reader.
  const OpacityShadowMap* shadowMap() const { return shadow_.get(); }
  // The live particles' trails, newest point first (waits for the GPU: dumps, tests).
  std::vector<std::vector<glm::vec3>> readBackTrails() const;

  const ParticleState& state() const { return state_; }
  const ParticleBackend& update() const { return *update_; }
  // The live flow this system solves on its GPU (null while none).
  const GpuFluidSolver* flow() const { return flow_.solver(); }
  // This frame's molecules: this system's own (a MoleculeUpdate, made when
  // the state first has a molecule emitter) or, for a shared simulation's
  // reader, the owner's; none without molecules.
  MoleculeHandles molecules() const {
    return molecules_ ? molecules_->handles() : update_->sharedMolecules();
  }
  // Their members' records (waits for the GPU: dumps, tests).
  std::vector<Particle> readBackMolecules() const { return readMolecules(molecules()); }
  std::shared_ptr<const FieldUpdate> field() const { return field_; }
  // The last packet's weight towards a time-varying field's next frame.
  float fieldBlend() const { return fieldBlend_; }
  std::uint32_t frame() const { return frame_; }

 private:
  void setMoleculeField();

  ParticleState state_;
  std::size_t capacityLimit_;
  std::unique_ptr<ParticleBackend> update_;
  ParticleRender render_;
  ParticleSplat splat_;
  ParticlePost post_;
  std::unique_ptr<MoleculeUpdate> molecules_;  // the simulation's owner's (once per GPU)
  LiveFlow flow_;                              // solver.device = gpu: the owner's
  mutable std::unique_ptr<MoleculeRenderer> moleculeRenderer_;
  std::shared_ptr<const HeightMap> terrain_;
  GpuTuning tuning_;
  std::unique_ptr<OpacityShadowMap> shadow_;  // the simulation's owner's (once per GPU)
  std::shared_ptr<const FieldUpdate> field_;
  std::uint32_t frame_ = 0;
  float fieldBlend_ = 0.0f;
};

}  // namespace sandstorm
