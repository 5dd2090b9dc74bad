// derivedScalars(): quantities a scientist computes from a velocity field
// (ParaView's Gradient and Calculator filters), as scalar arrays on the
// field's points, to colour particles by or to store with the field
// (sandstorm-field derive):
//   speed         |v|
//   vorticity     |curl v|
//   divergence    div v (0 for an incompressible flow)
//   q_criterion   Q = (|W|^2 - |S|^2) / 2 of the velocity gradient's
//                 antisymmetric (W) and symmetric (S) parts (Frobenius
//                 norms): positive where rotation beats strain, the usual
//                 way to find vortex cores (Hunt, Wray and Moin, 1988)
//   helicity      v . curl v
// Derivatives by velocityGradient; points without data get 0.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "core/field/vector_field.h"

namespace sandstorm {

std::span<const std::string_view> derivedScalarNames();
// Throws Error for a name not in derivedScalarNames, listing them.
VectorField::Scalars derivedScalars(const VectorField& field, std::string_view name);

}  // namespace sandstorm
