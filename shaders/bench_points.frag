#version 450 core
in float vShade;
out vec4 fragColor;

void main() { fragColor = vec4(vShade, 0.5, 0.25, 1.0); }
