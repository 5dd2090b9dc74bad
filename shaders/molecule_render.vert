#version 450 core
// MoleculeRenderer: molecule gl_VertexID / n's vertex gl_VertexID % n (n its
// vertices: molecule.drawing.z), pulled from the members' records
// (MoleculeUpdate's buffers); one draw for every molecule (as instances, one
// a molecule, an H100 drew them far slower). Solid shapes draw their faces
// (flat normals); rods and chains draw each line as a ribbon
// molecules.width wide, turned to face the eye and shaded as a tube (the
// same on every wall, like the billboards).
#include "view_block.glsl"
#include "render_block.glsl"
#include "shadow_block.glsl"
#include "molecule_block.glsl"

layout(std430, binding = 0) readonly restrict buffer PositionLife { vec4 positionLife[]; };
layout(std430, binding = 1) readonly restrict buffer VelocityKind { vec4 velocityKind[]; };

out vec3 vPosition;
out vec3 vNormal;  // a face's (either side); a ribbon's across-axis
flat out int vRibbon;
out float vAcross;  // ribbons: -1 .. 1 across
out float vAge;
out float vColor;
out float vLight;

vec3 memberPosition(uint first, int j) {
  return positionLife[moleculeRecord(first, j)].xyz;
}

void main() {
  int perMolecule = molecule.drawing.z;
  uint first = uint(gl_VertexID / perMolecule);  // the molecule
  int v = gl_VertexID % perMolecule;
  int member;
  vec3 position;
  if (molecule.drawing.x > 0) {
    ivec4 f = molecule.faces[v / 3];
    vec3 a = memberPosition(first, f.x), b = memberPosition(first, f.y), c = memberPosition(first, f.z);
    vec3 n = cross(b - a, c - a);
    float len = length(n);
    vNormal = len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
    member = f[v % 3];
    position = memberPosition(first, member);
    vRibbon = 0;
    vAcross = 0.0;
  } else {
    // Two triangles a line: (a, -), (b, -), (b, +), (a, -), (b, +), (a, +).
    ivec4 l = molecule.lines[v / 6];
    int k = v % 6;
    bool atB = k == 1 || k == 2 || k == 4;
    float side = (k == 2 || k == 4 || k == 5) ? 1.0 : -1.0;
    vec3 a = memberPosition(first, l.x), b = memberPosition(first, l.y);
    member = atB ? l.y : l.x;
    vec3 at = atB ? b : a;
    vec3 toEye = view.eye.xyz - at;
    vec3 across = cross(b - a, toEye);
    float len = length(across);
    across = len > 0.0 ? across / len : vec3(0.0, 0.0, 1.0);
    position = at + across * (side * 0.5 * molecule.look.x);
    vNormal = across;
    vRibbon = 1;
    vAcross = side;
  }
  vec4 pl = positionLife[moleculeRecord(first, member)];
  vec4 vk = velocityKind[moleculeRecord(first, member)];
  vAge = clamp(1.0 - pl.w / max(vk.w, 1e-6), 0.0, 1.0);
  vColor = colorCoordinate(vAge, vk.xyz, pl.xyz);
  vLight = lightTransmittance(pl.xyz);
  vPosition = position;
  gl_Position = view.viewProjection * vec4(position, 1.0);
}
