// checkVtkCells(): the cells of an unstructured grid or polydata that a reader
// built from a file, checked before anything walks them: VTK's readers copy
// connectivity as the file gives it, and a point id past the points, offsets
// that run backwards or past the connectivity, or a cell type with the wrong
// number of points would make the resampler (and any VTK filter) read outside
// the arrays.
//
// Checked: the offsets start at 0, never decrease and end at the
// connectivity's length (vtkCellArray::IsValid); every point id is a point of
// the dataset; every cell type is one Sandstorm samples in (VTK's linear and
// quadratic cells, polygons, polylines, strips, polyhedra; not the arbitrary
// order Lagrange or Bezier cells) with the points its type needs; a
// polyhedron's face stream lies within the faces array and names points of
// the dataset. Other datasets (image data, rectilinear and structured grids)
// have no connectivity and pass. Throws Error starting with `where`.
#pragma once

#include <string>

class vtkDataSet;

namespace sandstorm {

void checkVtkCells(vtkDataSet* data, const std::string& where);

}  // namespace sandstorm
