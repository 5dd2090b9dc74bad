// Cash-Karp's embedded Runge-Kutta 4(5) pair (Cash and Karp 1990; VTK's
// vtkRungeKutta45), the coefficients of the streamlines' adaptive integrator.
// One table of floats, which the CPU tracer reads and the GPU's receives as a
// uniform array (streamline_trace.comp), so both compute with the same bits
// rather than with two compilers' foldings of the fractions.
#pragma once

#include <array>

namespace sandstorm {

namespace cash_karp {
// Positions in kCashKarp.
enum : int {
  A21 = 0,
  A31,
  A32,
  A41,
  A42,
  A43,
  A51,
  A52,
  A53,
  A54,
  A61,
  A62,
  A63,
  A64,
  A65,
  B1,
  B3,
  B4,
  B6,  // the fifth-order solution (B2 = B5 = 0)
  E1,
  E3,
  E4,
  E5,
  E6,  // fifth order minus fourth: the error estimate (E2 = 0)
  Count
};
}  // namespace cash_karp

inline constexpr std::array<float, cash_karp::Count> kCashKarp = {
    1.0f / 5.0f,
    3.0f / 40.0f,
    9.0f / 40.0f,
    3.0f / 10.0f,
    -9.0f / 10.0f,
    6.0f / 5.0f,
    -11.0f / 54.0f,
    5.0f / 2.0f,
    -70.0f / 27.0f,
    35.0f / 27.0f,
    1631.0f / 55296.0f,
    175.0f / 512.0f,
    575.0f / 13824.0f,
    44275.0f / 110592.0f,
    253.0f / 4096.0f,
    37.0f / 378.0f,
    250.0f / 621.0f,
    125.0f / 594.0f,
    512.0f / 1771.0f,
    float(37.0 / 378.0 - 2825.0 / 27648.0),
    float(250.0 / 621.0 - 18575.0 / 48384.0),
    float(125.0 / 594.0 - 13525.0 / 55296.0),
    float(-277.0 / 14336.0),
    float(512.0 / 1771.0 - 1.0 / 4.0),
};

}  // namespace sandstorm
