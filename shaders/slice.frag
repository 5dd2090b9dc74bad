#version 450 core
// SliceRenderer: the field where the slice is, coloured like the particles
// (the render block's colour quantity and map); cells the field has no data
// for are left out.
#include "sim_block.glsl"
#include "particle_physics.glsl"
#include "render_block.glsl"
#include "scene_occlusion.glsl"

layout(location = 6) uniform float uOpacity;
in vec3 vPosition;
out vec4 fragColor;

void main() {
  if (behindScene()) discard;
  vec3 local = toLocal(vPosition);
  if (sim.fieldBlend.z != 0.0 &&
      (!cellValid(false, local) || (sim.fieldBlend.y != 0.0 && !cellValid(true, local))))
    discard;
  vec3 f = fieldAt(vPosition);
  fragColor = vec4(colorAt(colorCoordinate(0.0, f, vPosition)), uOpacity);
}
