// SceneField: the field as the scene's own passes read it (streamlines, the
// slice): a copy of the grid on the GPU (a 3D texture, or a sparse grid's
// words: ParticleEnvironment)
// and a SimBlock describing it (placement, strength, blend, integrator), so
// their shaders sample it with particle_physics.glsl's fieldAt(), the
// particles' very function. Independent of the particle backend and of a
// shared simulation. Needs its GL context current for every call.
#pragma once

#include <memory>
#include <vector>

#include "contexts/gl/objects.h"
#include "contexts/particles/particle_environment.h"
#include "core/obstacles/obstacle.h"
#include "core/sim/frame_packet.h"

namespace sandstorm {

class SceneField {
 public:
  SceneField();

  // Uploads a field it does not hold yet and refills the block (`dt`: the
  // frame's simulated seconds, for passes that move points as particles).
  // `ground`: the scene's terrain, which the helicopter's solid parts stand over.
  void set(const ParticleState& state, const FieldUpdate& field, float blend, float dt = 0.0f,
           const HeightMap* ground = nullptr);
  // The solids the last set() placed in the flow (collisionShapes).
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }
  bool has() const { return has_; }
  // Whether the field is a sparse grid its passes sample (SceneFieldProgram).
  bool sparse() const { return sparse_; }
  // The field's colour grids (FieldUpdate::colorGrid), when it has them, on
  // texture units 5 (current) and 6 (next): shaders/render_block.glsl's colorGridAt().
  void bindColorGrid() const;

  // Binds the block (binding 0) and the grids for a pass; the destructor of
  // the returned guard puts back the uniform buffer that was at binding 0
  // (the particle update's).
  class Binding {
   public:
    explicit Binding(const SceneField& field, const ParticleState& state);
    ~Binding();
    Binding(const Binding&) = delete;
    Binding& operator=(const Binding&) = delete;

   private:
    int previous_ = 0;
  };

 private:
  std::vector<Obstacle> obstacles_;
  ParticleEnvironment environment_{GpuField::Storage::Texture};
  gl::Buffer block_;
  GpuField colorGrid_{GpuField::Storage::Texture}, nextColorGrid_{GpuField::Storage::Texture};
  bool has_ = false;
  bool sparse_ = false;
};

}  // namespace sandstorm
