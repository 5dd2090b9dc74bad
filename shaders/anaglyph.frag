#version 450 core
// Red-cyan anaglyph: the left eye's luminance in red, the right eye's green
// and blue (a "half-colour" anaglyph, which keeps retinal rivalry low).
layout(binding = 0) uniform sampler2D uLeft;
layout(binding = 1) uniform sampler2D uRight;
layout(location = 0) uniform ivec2 uOrigin;
out vec4 fragColor;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy) - uOrigin;
  vec3 left = texelFetch(uLeft, p, 0).rgb;
  vec3 right = texelFetch(uRight, p, 0).rgb;
  fragColor = vec4(dot(left, vec3(0.299, 0.587, 0.114)), right.g, right.b, 1.0);
}
