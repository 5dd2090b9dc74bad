#include "core/io/vtk_cell_check.h"

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkCellTypes.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "core/util/error.h"

namespace sandstorm {
namespace {

// Points a cell of `type` must have (`exact`), or at least (`!exact`); -1 for
// types not accepted.
int pointsFor(int type, bool& exact) {
  exact = true;
  switch (type) {
    case VTK_EMPTY_CELL:
      return 0;
    case VTK_VERTEX:
      return 1;
    case VTK_LINE:
      return 2;
    case VTK_TRIANGLE:
      return 3;
    case VTK_PIXEL:
    case VTK_QUAD:
    case VTK_TETRA:
      return 4;
    case VTK_VOXEL:
    case VTK_HEXAHEDRON:
      return 8;
    case VTK_WEDGE:
      return 6;
    case VTK_PYRAMID:
      return 5;
    case VTK_PENTAGONAL_PRISM:
      return 10;
    case VTK_HEXAGONAL_PRISM:
      return 12;
    case VTK_QUADRATIC_EDGE:
      return 3;
    case VTK_QUADRATIC_TRIANGLE:
      return 6;
    case VTK_QUADRATIC_QUAD:
      return 8;
    case VTK_QUADRATIC_TETRA:
      return 10;
    case VTK_QUADRATIC_HEXAHEDRON:
      return 20;
    case VTK_QUADRATIC_WEDGE:
      return 15;
    case VTK_QUADRATIC_PYRAMID:
      return 13;
    case VTK_BIQUADRATIC_QUAD:
      return 9;
    case VTK_TRIQUADRATIC_HEXAHEDRON:
      return 27;
    case VTK_QUADRATIC_LINEAR_QUAD:
      return 6;
    case VTK_QUADRATIC_LINEAR_WEDGE:
      return 12;
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE:
      return 18;
    case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON:
      return 24;
    case VTK_BIQUADRATIC_TRIANGLE:
      return 7;
    case VTK_CUBIC_LINE:
      return 4;
    default:
      break;
  }
  exact = false;
  switch (type) {
    case VTK_POLY_VERTEX:
      return 1;
    case VTK_POLY_LINE:
      return 2;
    case VTK_TRIANGLE_STRIP:
    case VTK_POLYGON:
      return 3;
    case VTK_POLYHEDRON:
      return 4;
    default:
      break;
  }
  return -1;
}

// f(offsets, connectivity): the cell array's own storage, 32 or 64 bits, read
// in place (an iterator or GetCellAtId copies each cell's ids).
template <class F>
void withStorage(vtkCellArray* cells, F&& f) {
  if (cells->IsStorage64Bit())
    f(cells->GetOffsetsArray64()->GetPointer(0), cells->GetConnectivityArray64()->GetPointer(0));
  else
    f(cells->GetOffsetsArray32()->GetPointer(0), cells->GetConnectivityArray32()->GetPointer(0));
}

// Offsets and point ids of one cell array. `minimum` points a cell needs.
void checkCellArray(vtkCellArray* cells, vtkIdType points, const std::string& where,
                    const char* what, int minimum) {
  if (!cells) return;
  const std::string kind = *what ? concat(what, " ") : std::string();
  if (!cells->IsValid())
    throw Error(concat(where, ": the offsets of the ", kind,
                       "cells do not run from 0 upwards to the connectivity's length"));
  const vtkIdType count = cells->GetNumberOfCells();
  withStorage(cells, [&](const auto* offsets, const auto* ids) {
    for (vtkIdType c = 0; c < count; ++c) {
      const vtkIdType begin = vtkIdType(offsets[c]), n = vtkIdType(offsets[c + 1]) - begin;
      if (n < minimum)
        throw Error(concat(where, ": ", kind, "cell ", c, " has ", n, " points; expected at least ",
                           minimum));
      for (vtkIdType i = begin; i < begin + n; ++i)
        if (ids[i] < 0 || vtkIdType(ids[i]) >= points)
          throw Error(concat(where, ": ", kind, "cell ", c, " names point ", vtkIdType(ids[i]),
                             "; the points are 0..", points - 1));
    }
  });
}

void checkPolyhedron(vtkUnstructuredGrid* grid, vtkIdType cell, const std::string& where) {
  vtkIdTypeArray* faces = grid->GetFaces();
  vtkIdTypeArray* locations = grid->GetFaceLocations();
  const vtkIdType points = grid->GetNumberOfPoints();
  if (!faces || !locations || locations->GetNumberOfTuples() <= cell)
    throw Error(concat(where, ": polyhedron cell ", cell, " has no faces"));
  const vtkIdType size = faces->GetNumberOfTuples();
  vtkIdType at = locations->GetValue(cell);
  auto next = [&]() {
    if (at < 0 || at >= size)
      throw Error(concat(where, ": polyhedron cell ", cell, "'s faces run past the faces array (",
                         size, " values)"));
    return faces->GetValue(at++);
  };
  const vtkIdType count = next();
  if (count < 4 || count > size)
    throw Error(
        concat(where, ": polyhedron cell ", cell, " has ", count, " faces; expected at least 4"));
  for (vtkIdType f = 0; f < count; ++f) {
    const vtkIdType n = next();
    if (n < 3 || n > size)
      throw Error(concat(where, ": polyhedron cell ", cell, " face ", f, " has ", n,
                         " points; expected at least 3"));
    for (vtkIdType i = 0; i < n; ++i)
      if (const vtkIdType id = next(); id < 0 || id >= points)
        throw Error(concat(where, ": polyhedron cell ", cell, " face ", f, " names point ", id,
                           "; the points are 0..", points - 1));
  }
}

void checkUnstructured(vtkUnstructuredGrid* grid, const std::string& where) {
  vtkCellArray* cells = grid->GetCells();
  const vtkIdType count = cells ? cells->GetNumberOfCells() : 0;
  if (count == 0) return;
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  if (!types || types->GetNumberOfTuples() != count)
    throw Error(concat(where, ": ", count, " cells but ", types ? types->GetNumberOfTuples() : 0,
                       " cell types"));
  checkCellArray(cells, grid->GetNumberOfPoints(), where, "", 0);
  const unsigned char* type = types->GetPointer(0);
  withStorage(cells, [&](const auto* offsets, const auto*) {
    for (vtkIdType c = 0; c < count; ++c) {
      bool exact = true;
      const int need = pointsFor(type[c], exact);
      if (need < 0)
        throw Error(concat(where, ": cell ", c, " is of VTK type ", int(type[c]), " (",
                           vtkCellTypes::GetClassNameFromTypeId(type[c]),
                           "), which Sandstorm does not sample in; expected linear or quadratic "
                           "cells, polygons or polyhedra"));
      const vtkIdType n = vtkIdType(offsets[c + 1]) - vtkIdType(offsets[c]);
      if (exact ? n != need : n < need)
        throw Error(concat(where, ": cell ", c, " (", vtkCellTypes::GetClassNameFromTypeId(type[c]),
                           ") has ", n, " points; expected ", exact ? "" : "at least ", need));
      if (type[c] == VTK_POLYHEDRON) checkPolyhedron(grid, c, where);
    }
  });
}

}  // namespace

void checkVtkCells(vtkDataSet* data, const std::string& where) {
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data)) {
    checkUnstructured(grid, where);
  } else if (auto* poly = vtkPolyData::SafeDownCast(data)) {
    const vtkIdType points = poly->GetNumberOfPoints();
    checkCellArray(poly->GetVerts(), points, where, "vertex", 1);
    checkCellArray(poly->GetLines(), points, where, "line", 2);
    checkCellArray(poly->GetPolys(), points, where, "polygon", 3);
    checkCellArray(poly->GetStrips(), points, where, "triangle strip", 3);
  }
}

}  // namespace sandstorm
