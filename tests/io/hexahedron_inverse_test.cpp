// HexahedronInverse against VTK's own vtkHexahedron::EvaluatePosition: the
// same answer (inside, outside, or no convergence), and where one is found
// the same parametric coordinates and weights, bit for bit, over warped
// hexahedra and points inside, outside and on their faces.
#include <gtest/gtest.h>

#include <random>

#include <vtkHexahedron.h>
#include <vtkNew.h>
#include <vtkPoints.h>

#include "core/io/hexahedron_inverse.h"

namespace sandstorm {
namespace {

// The unit cube's corners in VTK's order.
constexpr int kCube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                             {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

TEST(HexahedronInverse, LocatesPointsAsVtkHexahedronDoes) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25), spread(-0.4, 1.4);
  vtkNew<vtkHexahedron> vtk;
  int counts[3] = {0, 0, 0};  // outside, inside, failed
  for (int cell = 0; cell < 400; ++cell) {
    double corners[24];
    const double scale = cell % 3 == 0 ? 1e-3 : (cell % 3 == 1 ? 1.0 : 250.0);
    for (int c = 0; c < 8; ++c)
      for (int a = 0; a < 3; ++a) {
        // Every tenth cell folded over itself: Newton's method fails there.
        const double warp = cell % 10 == 9 ? 4.0 * jitter(random) : jitter(random);
        corners[3 * c + a] = scale * (kCube[c][a] + warp) + 10.0;
        vtk->GetPoints()->SetPoint(c, &corners[3 * c]);
      }
    const HexahedronInverse ours(corners);
    for (int p = 0; p < 60; ++p) {
      double target[3], weights[8];
      // Two of three points through the cell's own map (some on its faces),
      // the rest anywhere around it.
      double pc[3] = {spread(random), spread(random), spread(random)};
      if (p % 5 == 0) pc[p % 3] = double(p % 2);
      if (p % 3 != 2) {
        HexahedronInverse::weightsAt(pc, weights);
        for (int a = 0; a < 3; ++a) {
          target[a] = 0.0;
          for (int c = 0; c < 8; ++c)
            target[a] += weights[c] * corners[3 * c + a];
        }
      } else {
        for (int a = 0; a < 3; ++a)
          target[a] = scale * spread(random) + 10.0;
      }
      double theirPc[3], theirWeights[8], closest[3], dist2 = 0.0;
      int sub = 0;
      const int theirs = vtk->EvaluatePosition(target, closest, sub, theirPc, dist2, theirWeights);
      double ourPc[3], ourWeights[8];
      const int mine = int(ours.locate(target, ourPc, ourWeights));
      ASSERT_EQ(mine, theirs) << "cell " << cell << " point " << p;
      ++counts[theirs == -1 ? 2 : theirs];
      if (theirs == -1) continue;
      for (int a = 0; a < 3; ++a)
        ASSERT_EQ(ourPc[a], theirPc[a]) << "cell " << cell << " point " << p;
      if (theirs == 1) {
        for (int c = 0; c < 8; ++c)
          ASSERT_EQ(ourWeights[c], theirWeights[c]) << "cell " << cell << " point " << p;
      }
    }
  }
  // The cases all came up.
  EXPECT_GT(counts[0], 1000);
  EXPECT_GT(counts[1], 1000);
  EXPECT_GT(counts[2], 10);
  std::cout << "[ measured ] outside " << counts[0] << ", inside " << counts[1]
            << ", no convergence " << counts[2] << "\n";
}

}  // namespace
}  // namespace sandstorm
