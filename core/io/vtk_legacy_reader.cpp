#include "core/io/vtk_legacy_reader.h"

#include <algorithm>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkStructuredGrid.h>
#include <vtkStructuredPoints.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "core/io/vtk_cell_check.h"
#include "core/io/vtk_legacy_parser.h"

namespace sandstorm {
namespace {

// The array as VTK's: the floats handed over (VTK deletes them with
// delete[]), the doubles copied and given back, so a file's arrays are held
// once, or twice one at a time.
vtkSmartPointer<vtkDataArray> toVtk(LegacyArray& a) {
  vtkSmartPointer<vtkDataArray> out;
  if (a.singlePrecision) {
    auto f = vtkSmartPointer<vtkFloatArray>::New();
    f->SetNumberOfComponents(a.components);
    if (a.floatCount > 0)
      f->SetArray(a.floats.release(), vtkIdType(a.floatCount), 0,
                  vtkAbstractArray::VTK_DATA_ARRAY_DELETE);
    a.floatCount = 0;
    out = f;
  } else {
    auto d = vtkSmartPointer<vtkDoubleArray>::New();
    d->SetNumberOfComponents(a.components);
    d->SetNumberOfTuples(vtkIdType(a.values.size() / std::size_t(a.components)));
    std::copy(a.values.begin(), a.values.end(), d->GetPointer(0));
    std::vector<double>().swap(a.values);
    out = d;
  }
  out->SetName(a.name.c_str());
  return out;
}

// A file's one VECTORS section is its active vectors, as VTK's reader makes
// it. Several are not: the format has no way to mark one, and VTK's reader
// would take the first silently, so the loader asks which (--array).
void attach(vtkDataSetAttributes* to, std::vector<LegacyArray>& arrays) {
  const auto vectors = std::count_if(arrays.begin(), arrays.end(),
                                     [](const LegacyArray& a) { return a.kind == "vectors"; });
  for (LegacyArray& a : arrays) {
    vtkSmartPointer<vtkDataArray> array = toVtk(a);
    if (a.kind == "vectors" && vectors == 1)
      to->SetVectors(array);
    else
      to->AddArray(array);
  }
}

vtkSmartPointer<vtkDoubleArray> coordinates(const std::vector<double>& values) {
  auto c = vtkSmartPointer<vtkDoubleArray>::New();
  c->SetNumberOfTuples(vtkIdType(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    c->SetValue(vtkIdType(i), values[i]);
  return c;
}

vtkSmartPointer<vtkPoints> pointsOf(const std::vector<double>& xyz) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(vtkIdType(xyz.size() / 3));
  for (vtkIdType i = 0; i < vtkIdType(xyz.size() / 3); ++i)
    points->SetPoint(i, &xyz[std::size_t(3 * i)]);
  return points;
}

vtkSmartPointer<vtkCellArray> cellArray(const LegacyCells& cells) {
  vtkNew<vtkTypeInt64Array> offsets, connectivity;
  offsets->SetNumberOfTuples(vtkIdType(cells.offsets.size()));
  for (std::size_t i = 0; i < cells.offsets.size(); ++i)
    offsets->SetValue(vtkIdType(i), cells.offsets[i]);
  connectivity->SetNumberOfTuples(vtkIdType(cells.connectivity.size()));
  for (std::size_t i = 0; i < cells.connectivity.size(); ++i)
    connectivity->SetValue(vtkIdType(i), cells.connectivity[i]);
  auto array = vtkSmartPointer<vtkCellArray>::New();
  array->SetData(offsets, connectivity);
  return array;
}

}  // namespace

vtkSmartPointer<vtkDataSet> readVtkLegacy(const std::filesystem::path& path,
                                          const LoadOptions& options) {
  LegacyVtkData d = parseVtkLegacy(path, options.memoryBudget);
  const int dims[3] = {int(d.dims[0]), int(d.dims[1]), int(d.dims[2])};
  vtkSmartPointer<vtkDataSet> out;
  switch (d.type) {
    case LegacyVtkData::Type::StructuredPoints: {
      auto image = vtkSmartPointer<vtkStructuredPoints>::New();
      image->SetDimensions(dims);
      image->SetOrigin(d.origin.data());
      image->SetSpacing(d.spacing.data());
      out = image;
      break;
    }
    case LegacyVtkData::Type::RectilinearGrid: {
      auto grid = vtkSmartPointer<vtkRectilinearGrid>::New();
      grid->SetDimensions(dims);
      grid->SetXCoordinates(coordinates(d.coordinates[0]));
      grid->SetYCoordinates(coordinates(d.coordinates[1]));
      grid->SetZCoordinates(coordinates(d.coordinates[2]));
      out = grid;
      break;
    }
    case LegacyVtkData::Type::StructuredGrid: {
      auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
      grid->SetDimensions(dims);
      vtkNew<vtkPoints> points;
      points->SetDataTypeToDouble();
      points->SetNumberOfPoints(vtkIdType(d.pointCount()));
      for (vtkIdType i = 0; i < vtkIdType(d.pointCount()); ++i)
        points->SetPoint(i, &d.points[std::size_t(3 * i)]);
      grid->SetPoints(points);
      out = grid;
      break;
    }
    case LegacyVtkData::Type::UnstructuredGrid: {
      auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
      grid->SetPoints(pointsOf(d.points));
      vtkNew<vtkUnsignedCharArray> types;
      types->SetNumberOfTuples(vtkIdType(d.cellTypes.size()));
      for (std::size_t i = 0; i < d.cellTypes.size(); ++i)
        types->SetValue(vtkIdType(i), static_cast<unsigned char>(d.cellTypes[i]));
      grid->SetCells(types, cellArray(d.cells));
      out = grid;
      break;
    }
    case LegacyVtkData::Type::PolyData: {
      auto poly = vtkSmartPointer<vtkPolyData>::New();
      poly->SetPoints(pointsOf(d.points));
      poly->SetVerts(cellArray(d.polyCells[0]));
      poly->SetLines(cellArray(d.polyCells[1]));
      poly->SetPolys(cellArray(d.polyCells[2]));
      poly->SetStrips(cellArray(d.polyCells[3]));
      out = poly;
      break;
    }
  }
  checkVtkCells(out, path.string());
  attach(out->GetPointData(), d.pointData);
  attach(out->GetCellData(), d.cellData);
  return out;
}

}  // namespace sandstorm
