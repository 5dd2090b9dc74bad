// OpacityShadowMap: volumetric self-shadowing of the dust (issue 13; the Mali
// sample's "volumetric shadows", with more layers and precision). Once a
// frame, after the update, it renders the particles from the light into
// render.shadow_layers opacity layers along the light direction, by compute:
//   bounds      the live particles' extent in the light's frame;
//   frame       the map's place (shadow_frame.comp: square cells no smaller
//               than a particle, layers spanning the cloud) into the block;
//   splat       each particle's optical depth (core/light/light_model.h)
//               into its layer, bilinearly across, as fixed-point sums;
//   accumulate  running sums down the layers into a 3D texture of the
//               optical depth at each layer boundary.
// Receivers (billboards, splats, the ground, the terrain, the helicopter)
// sample it through shaders/shadow_block.glsl: exp(-optical depth) of the
// light reaches them. Every step is exact integer or order-free work on the
// same records, so every wall of every GPU and rank holds the same map.
//
// It does not depend on the view: the owner of a GPU's simulation builds it
// and its walls share it (SimulationShare publishes it with the records).
// Needs its GL context current.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/particles/particle_backend.h"
#include "contexts/shadows/shadow_handles.h"
#include "core/sim/sim_settings.h"

namespace sandstorm {

class OpacityShadowMap {
 public:
  OpacityShadowMap();
  // This frame's map of the live records, or (render.shadows off, no
  // particles) a block that says there is none.
  void build(const ParticleBackend::Records& records, std::size_t capacity,
             const RenderSettings& look);
  ShadowHandles handles() const { return {block_.id(), texture_.id()}; }

  // The light reaching each point, as receivers see it (waits for the GPU: tests).
  std::vector<float> transmittance(const std::vector<glm::vec3>& points) const;

 private:
  // False (said once in the log) when the GPU cannot hold that map; the
  // old one stays.
  bool allocate(int side, int layers);

  gl::Program bounds_, frame_, splat_, accumulate_;
  mutable std::unique_ptr<gl::Program> probe_;
  gl::Buffer extent_, block_;
  gl::Buffer layerSums_;
  gl::Texture texture_;
  int side_ = 0, layers_ = 0;
  int failedSide_ = 0, failedLayers_ = 0;
  bool blockOn_ = false;  // the block's last word: shadows (its storage starts as "none")
};

}  // namespace sandstorm
