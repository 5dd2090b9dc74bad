// HexahedronInverse: where a point lies in a trilinear hexahedron, in the
// cell's parametric coordinates, by the Newton iteration VTK's
// vtkHexahedron::EvaluatePosition runs (start at the centre, at most 10
// steps, converged when each coordinate moves by less than 1e-5, inside within
// 1e-6 of the unit cube), so that the mesh resampler's hexahedra come out as
// VTK's do without building a vtkHexahedron per cell. Corners in VTK's order:
// the bottom face (0 1 2 3) counter-clockwise, the top face (4 5 6 7) above it.
#pragma once

namespace sandstorm {

class HexahedronInverse {
 public:
  // `corners`: 8 points, x y z each.
  explicit HexahedronInverse(const double corners[24]);

  enum class Result { Outside = 0, Inside = 1, Failed = -1 };  // Failed: no convergence
  // The parametric coordinates of `x` and the corners' trilinear weights there.
  Result locate(const double x[3], double pcoords[3], double weights[8]) const;

  static void weightsAt(const double pcoords[3], double weights[8]);

 private:
  double corners_[24];
  double determinantTolerance_ = 0.0;
};

}  // namespace sandstorm
