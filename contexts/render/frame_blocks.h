// The std140 uniform blocks every render pass shares: the twins of
// shaders/view_block.glsl (binding 1) and shaders/render_block.glsl (binding 2).
#pragma once

#include <glm/glm.hpp>

#include "core/cave/view.h"
#include "core/color/color_map.h"
#include "core/field/field_range.h"
#include "core/sim/frame_packet.h"
#include "core/sim/sim_settings.h"

namespace sandstorm {

struct alignas(16) ViewBlock {
  glm::mat4 view;
  glm::mat4 projection;
  glm::mat4 viewProjection;
  glm::mat4 inverseViewProjection;
  glm::vec4 eye;
  glm::vec4 viewport;
};
static_assert(sizeof(ViewBlock) == 4 * 64 + 2 * 16);

struct alignas(16) RenderBlock {
  glm::vec4 colorBirth;
  glm::vec4 colorDeath;
  glm::vec4 lightDirection;
  glm::vec4 params;
  glm::vec4 colorScale;  // x: ColorQuantity, y: value at t = 0, z: at t = 1, w: 1 for a log scale
  glm::vec4 colorTable[ColorMap::kGpuSamples];  // rgb at t = i / (kGpuSamples - 1)
  // Where the colour grids (texture units 5 and 6) sit, for colouring by them.
  glm::vec4 fieldMin;
  glm::vec4 fieldIndexScale;
  glm::ivec4 fieldDims;
  glm::vec4 placementOffset;  // xyz, w: scale
  glm::vec4 placementRotation[3];
  glm::vec4 colorGrid;  // x: blend towards the next frame, y: 1 with a next frame, z: |strength|,
                        // w: 1 with a grid
  glm::vec4 light;      // rgb: the direct light's colour times its strength, w: 1 with shadows
  glm::vec4 haze;       // x: render.scattering (1/m)
  glm::vec4 splat;      // x: render.splat_detail (px), y: render.splat_overlap
};
static_assert(sizeof(RenderBlock) == (5 + ColorMap::kGpuSamples + 11) * 16);

ViewBlock makeViewBlock(const View& view, glm::ivec2 size);
// `field`: the field the particles move in (the colour scale's default ends,
// the colour grid's place), or null. `blend`: towards its next frame.
// `table`: render.color_map's GPU table (a ColorTableCache keeps it).
RenderBlock makeRenderBlock(const ParticleState& state, const FieldUpdate* field, float blend,
                            const ColorMap::Table& table);

}  // namespace sandstorm
