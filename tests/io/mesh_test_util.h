// Meshes for the io tests: an L-shaped region of jittered tetrahedra carrying
// a point or cell array of an analytic field, so that what lies in the notch
// is outside the mesh and every value has an answer to compare with.
#pragma once

#include <functional>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <glm/glm.hpp>

#include "core/field/vector_field.h"

namespace sandstorm::test {

using Flow = std::function<glm::dvec3(const glm::dvec3&)>;

// The region: [0, 2] x [0, 2] x [0, 1] less the notch x > 1 and y > 1.
inline bool inL(const glm::dvec3& p, double eps = 1e-9) {
  const bool box = p.x >= -eps && p.x <= 2.0 + eps && p.y >= -eps && p.y <= 2.0 + eps &&
                   p.z >= -eps && p.z <= 1.0 + eps;
  return box && (p.x <= 1.0 + eps || p.y <= 1.0 + eps);
}

// n cells per unit length; each hexahedron split in six tetrahedra about its
// diagonal (Kuhn), points off the region's boundary moved by up to 5% of a
// cell, deterministically. The flow is written at the points ("velocity",
// float) or, with `cells`, at each cell's centroid as cell data.
inline vtkSmartPointer<vtkUnstructuredGrid> lMesh(int n, const Flow& flow, bool cells = false) {
  const int nx = 2 * n, ny = 2 * n, nz = n;
  const double h = 1.0 / n;
  auto id = [&](int i, int j, int k) { return vtkIdType(i + (nx + 1) * (j + (ny + 1) * k)); };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        glm::dvec3 p(i * h, j * h, k * h);
        const bool boundary = i == 0 || i == nx || j == 0 || j == ny || k == 0 || k == nz ||
                              (i == n && j >= n) || (j == n && i >= n);
        if (!boundary) {
          const unsigned hash =
              unsigned(i * 73856093) ^ unsigned(j * 19349663) ^ unsigned(k * 83492791);
          p +=
              0.05 * h *
              glm::dvec3(double(hash % 201) / 100.0 - 1.0, double((hash / 201) % 201) / 100.0 - 1.0,
                         double((hash / 40401) % 201) / 100.0 - 1.0);
        }
        points->InsertNextPoint(p.x, p.y, p.z);
      }
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  mesh->SetPoints(points);
  mesh->Allocate();
  const int order[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        if (i >= n && j >= n) continue;  // the notch
        for (const auto& o : order) {
          glm::ivec3 c(i, j, k);
          vtkIdType tet[4];
          tet[0] = id(c.x, c.y, c.z);
          for (int s = 0; s < 2; ++s) {
            c[o[s]] += 1;
            tet[s + 1] = id(c.x, c.y, c.z);
          }
          tet[3] = id(i + 1, j + 1, k + 1);
          mesh->InsertNextCell(VTK_TETRA, 4, tet);
        }
      }
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  if (cells) {
    v->SetNumberOfTuples(mesh->GetNumberOfCells());
    for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c) {
      vtkIdType npts = 0;
      const vtkIdType* ids = nullptr;
      mesh->GetCellPoints(c, npts, ids);
      glm::dvec3 centroid(0.0);
      for (vtkIdType i = 0; i < npts; ++i) {
        double x[3];
        points->GetPoint(ids[i], x);
        centroid += glm::dvec3(x[0], x[1], x[2]) / double(npts);
      }
      const glm::dvec3 f = flow(centroid);
      v->SetTuple3(c, f.x, f.y, f.z);
    }
    mesh->GetCellData()->SetVectors(v);
  } else {
    v->SetNumberOfTuples(points->GetNumberOfPoints());
    for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p) {
      double x[3];
      points->GetPoint(p, x);
      const glm::dvec3 f = flow({x[0], x[1], x[2]});
      v->SetTuple3(p, f.x, f.y, f.z);
    }
    mesh->GetPointData()->SetVectors(v);
  }
  return mesh;
}

// Every grid point of `f` valid exactly where it lies in the L, and there
// within `tolerance` of the flow.
inline void expectL(const VectorField& f, const Flow& flow, double tolerance) {
  std::size_t checked = 0;
  for (int k = 0; k < f.dims().z; ++k)
    for (int j = 0; j < f.dims().y; ++j)
      for (int i = 0; i < f.dims().x; ++i) {
        const glm::dvec3 p(f.pointPosition(i, j, k));
        ASSERT_EQ(f.valid(i, j, k), inL(p, 1e-6)) << "at " << p.x << " " << p.y << " " << p.z;
        if (!f.valid(i, j, k)) {
          ASSERT_EQ(f.at(i, j, k), glm::vec3(0.0f));
          continue;
        }
        const glm::dvec3 expected = flow(p);
        ASSERT_LE(glm::length(glm::dvec3(f.at(i, j, k)) - expected), tolerance)
            << "at " << p.x << " " << p.y << " " << p.z;
        ++checked;
      }
  EXPECT_GT(checked, std::size_t(0));
}

}  // namespace sandstorm::test
