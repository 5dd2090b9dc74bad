#version 450 core
layout(binding = 0) uniform sampler2D uFont;
in vec2 vUv;
in vec4 vColor;
out vec4 fragColor;

void main() { fragColor = vColor * texture(uFont, vUv); }
