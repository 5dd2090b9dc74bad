// How closely a GPU can follow its CPU twin, for the tests that compare them.
//
// Where the GPU rounds every operation as IEEE 754 does (llvmpipe), an update
// on the GPU equals the CPU's bit for bit, and the tests say so. NVIDIA's
// GLSL does not: GLSL 4.50 section 4.7.1 allows a division 2.5 ulp, an
// inversesqrt 2 ulp, sqrt as 1/inversesqrt (about 3), and the compiler may
// fuse a multiply and an add wherever `precise` does not forbid it. Those
// differences are a few ulps in one update; carried through many updates they
// grow without bound wherever the motion is sensitive (a particle at a
// sphere's stagnation point goes either way round; a molecule's springs
// amplify a difference every frame). So on such a GPU the tests run in
// lockstep: after each frame the CPU twin adopts the GPU's records, and every
// update is held to the bound one update's inexact operations allow.
#pragma once

#include <epoxy/gl.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace sandstorm::test {

// Whether the current context's GPU rounds sqrt and division as IEEE does.
inline bool exactArithmetic() {
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer && std::strstr(renderer, "llvmpipe");
}

// The spacing of floats at `scale`: one ulp there.
inline float ulpAt(float scale) {
  const float s = std::abs(scale);
  return std::nextafter(s, std::numeric_limits<float>::infinity()) - s;
}

// The most one update may differ, for values no larger than `scale`. One
// update of a particle or a molecule member is a chain of at most about 16
// operations the rules above leave inexact (a trilinear sample's cell
// division per integrator stage, an obstacle's or spring's length and
// normalisation, the fused products of the step), each within 3 ulp of a
// value no larger than the largest position or velocity in the frame, and the
// chain's sum adds as much again: 16 * 3 * 2 = 96 ulp.
inline constexpr float kOneUpdateUlps = 96.0f;
inline float oneUpdateBound(float scale) {
  return kOneUpdateUlps * ulpAt(scale);
}

}  // namespace sandstorm::test
