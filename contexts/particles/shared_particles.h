// Sharing one simulation between the walls of one GPU (SimulationShare):
//   SharingBackend wraps the owner wall's real backend and publishes what each
//     update wrote;
//   SharedParticles is a reader wall's backend: it simulates nothing and draws
//     the owner's buffers, through a vertex array of its own (vertex arrays,
//     unlike buffers, are not shared between contexts).
// Only backends whose records carry a draw command (compute) can be shared.
#pragma once

#include <memory>

#include "contexts/gl/objects.h"
#include "contexts/particles/particle_backend.h"
#include "contexts/particles/simulation_share.h"

namespace sandstorm {

class SharingBackend final : public ParticleBackend {
 public:
  SharingBackend(std::unique_ptr<ParticleBackend> inner, std::shared_ptr<SimulationShare> share);

  void setField(std::shared_ptr<const VectorField> field, const FieldPlacement& placement,
                std::shared_ptr<const VectorField> next) override {
    inner_->setField(std::move(field), placement, std::move(next));
  }
  void prefetchField(std::shared_ptr<const VectorField> upcoming) override {
    inner_->prefetchField(std::move(upcoming));
  }
  void setEquation(std::shared_ptr<const FieldEquation> equation) override {
    inner_->setEquation(std::move(equation));
  }
  void setSparse(std::shared_ptr<const SparseField> sparse) override {
    inner_->setSparse(std::move(sparse));
  }
  void setTerrain(std::shared_ptr<const HeightMap> terrain) override {
    inner_->setTerrain(std::move(terrain));
  }
  bool setFieldBuffer(std::uint32_t buffer) override { return inner_->setFieldBuffer(buffer); }
  void step(const SimStep& step, const ParticleState& state) override;
  void publish(const ShadowHandles& shadow, const MoleculeHandles& molecules) override;
  void clear() override { inner_->clear(); }
  void grow(std::size_t capacity) override { inner_->grow(capacity); }
  void draw() const override { inner_->draw(); }
  Records records() const override { return inner_->records(); }
  std::size_t capacity() const override { return inner_->capacity(); }
  std::size_t liveCount() const override { return inner_->liveCount(); }
  std::size_t lateCount() const override { return inner_->lateCount(); }
  std::vector<Particle> readBack() const override { return inner_->readBack(); }
  double lastFieldUploadMs() const override { return inner_->lastFieldUploadMs(); }
  const char* name() const override { return inner_->name(); }
  bool blendsPairPointwise(const ParticleState& state) const override {
    return inner_->blendsPairPointwise(state);
  }

 private:
  std::unique_ptr<ParticleBackend> inner_;
  std::shared_ptr<SimulationShare> share_;
  std::uint32_t frame_ = 0;  // the frame step() updated and publish() publishes
};

class SharedParticles final : public ParticleBackend {
 public:
  SharedParticles(std::shared_ptr<SimulationShare> share, int reader);

  void setField(std::shared_ptr<const VectorField>, const FieldPlacement&,
                std::shared_ptr<const VectorField>) override {}
  void setEquation(std::shared_ptr<const FieldEquation>) override {}
  void setSparse(std::shared_ptr<const SparseField>) override {}
  void setTerrain(std::shared_ptr<const HeightMap>) override {}
  void step(const SimStep& step,
            const ParticleState& state) override;  // acquires the owner's frame
  void clear() override {}
  void grow(std::size_t) override {}
  void draw() const override;
  Records records() const override { return current_.records; }
  bool simulates() const override { return false; }
  ShadowHandles sharedShadow() const override { return current_.shadow; }
  MoleculeHandles sharedMolecules() const override { return current_.molecules; }
  void endFrame() override;

  std::size_t capacity() const override { return current_.capacity; }
  std::size_t liveCount() const override;
  std::size_t lateCount() const override { return current_.lateCount; }
  std::vector<Particle> readBack() const override;
  double lastFieldUploadMs() const override { return 0.0; }
  const char* name() const override { return "shared"; }

 private:
  std::shared_ptr<SimulationShare> share_;
  int reader_;
  std::uint32_t frame_ = 0;
  bool holding_ = false;
  SimulationShare::Publication current_;
  gl::VertexArray vao_;
  gl::Buffer staging_;
};

}  // namespace sandstorm
