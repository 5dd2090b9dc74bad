#include "core/io/hexahedron_inverse.h"

#include <algorithm>
#include <cmath>

namespace sandstorm {
namespace {

constexpr int kMaxIterations = 10;
constexpr double kConverged = 1e-5;
constexpr double kDiverged = 1e6;
constexpr double kInsideTolerance = 1e-6;

// In VTK's order of terms (vtkMath::Determinant3x3 of three columns), so
// that the rounding is the same.
double determinant(const double a[3], const double b[3], const double c[3]) {
  return a[0] * b[1] * c[2] + b[0] * c[1] * a[2] + c[0] * a[1] * b[2] - a[0] * c[1] * b[2] -
         b[0] * a[1] * c[2] - c[0] * b[1] * a[2];
}

// d(weights)/d(r, s, t): 8 each.
void derivativesAt(const double p[3], double d[24]) {
  const double rm = 1.0 - p[0], sm = 1.0 - p[1], tm = 1.0 - p[2];
  d[0] = -sm * tm, d[1] = sm * tm, d[2] = p[1] * tm, d[3] = -p[1] * tm;
  d[4] = -sm * p[2], d[5] = sm * p[2], d[6] = p[1] * p[2], d[7] = -p[1] * p[2];
  d[8] = -rm * tm, d[9] = -p[0] * tm, d[10] = p[0] * tm, d[11] = rm * tm;
  d[12] = -rm * p[2], d[13] = -p[0] * p[2], d[14] = p[0] * p[2], d[15] = rm * p[2];
  d[16] = -rm * sm, d[17] = -p[0] * sm, d[18] = -p[0] * p[1], d[19] = -rm * p[1];
  d[20] = rm * sm, d[21] = p[0] * sm, d[22] = p[0] * p[1], d[23] = rm * p[1];
}

}  // namespace

HexahedronInverse::HexahedronInverse(const double corners[24]) {
  std::copy(corners, corners + 24, corners_);
  // A bound on the volume gives the scale of a determinant too small to step by.
  constexpr int kDiagonals[4][2] = {{0, 6}, {1, 7}, {2, 4}, {3, 5}};
  double longest2 = 0.0;
  for (const auto& d : kDiagonals) {
    const double* a = corners_ + 3 * d[0];
    const double* b = corners_ + 3 * d[1];
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    longest2 = std::max(longest2, dx * dx + dy * dy + dz * dz);
  }
  determinantTolerance_ = std::min(1e-20, 1e-5 * std::pow(longest2, 1.5));
}

void HexahedronInverse::weightsAt(const double p[3], double w[8]) {
  const double rm = 1.0 - p[0], sm = 1.0 - p[1], tm = 1.0 - p[2];
  w[0] = rm * sm * tm;
  w[1] = p[0] * sm * tm;
  w[2] = p[0] * p[1] * tm;
  w[3] = rm * p[1] * tm;
  w[4] = rm * sm * p[2];
  w[5] = p[0] * sm * p[2];
  w[6] = p[0] * p[1] * p[2];
  w[7] = rm * p[1] * p[2];
}

HexahedronInverse::Result HexahedronInverse::locate(const double x[3], double pcoords[3],
                                                    double weights[8]) const {
  double params[3] = {0.5, 0.5, 0.5};
  pcoords[0] = pcoords[1] = pcoords[2] = 0.5;
  bool converged = false;
  for (int iteration = 0; !converged && iteration < kMaxIterations; ++iteration) {
    double derivs[24];
    weightsAt(pcoords, weights);
    derivativesAt(pcoords, derivs);
    double f[3] = {0, 0, 0}, r[3] = {0, 0, 0}, s[3] = {0, 0, 0}, t[3] = {0, 0, 0};
    for (int i = 0; i < 8; ++i) {
      const double* pt = corners_ + 3 * i;
      for (int j = 0; j < 3; ++j) {
        f[j] += pt[j] * weights[i];
        r[j] += pt[j] * derivs[i];
        s[j] += pt[j] * derivs[i + 8];
        t[j] += pt[j] * derivs[i + 16];
      }
    }
    for (int i = 0; i < 3; ++i)
      f[i] -= x[i];
    const double d = determinant(r, s, t);
    if (std::fabs(d) < determinantTolerance_) return Result::Failed;
    pcoords[0] = params[0] - determinant(f, s, t) / d;
    pcoords[1] = params[1] - determinant(r, f, t) / d;
    pcoords[2] = params[2] - determinant(r, s, f) / d;
    if (std::fabs(pcoords[0] - params[0]) < kConverged &&
        std::fabs(pcoords[1] - params[1]) < kConverged &&
        std::fabs(pcoords[2] - params[2]) < kConverged) {
      converged = true;
    } else if (std::fabs(pcoords[0]) > kDiverged || std::fabs(pcoords[1]) > kDiverged ||
               std::fabs(pcoords[2]) > kDiverged) {
      return Result::Failed;
    } else {
      std::copy(pcoords, pcoords + 3, params);
    }
  }
  if (!converged) return Result::Failed;
  weightsAt(pcoords, weights);
  constexpr double lo = -kInsideTolerance, hi = 1.0 + kInsideTolerance;
  const bool inside = pcoords[0] >= lo && pcoords[0] <= hi && pcoords[1] >= lo &&
                      pcoords[1] <= hi && pcoords[2] >= lo && pcoords[2] <= hi;
  return inside ? Result::Inside : Result::Outside;
}

}  // namespace sandstorm
