#include "core/io/point_cloud_interpolator.h"

#include <vtkCellType.h>
#include <vtkCharArray.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointInterpolator.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkShepardKernel.h>
#include <vtkStaticPointLocator.h>

#include "core/util/error.h"

namespace sandstorm {

bool isPointCloud(vtkDataSet* data) {
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
    const int type = data->GetCellType(c);
    if (type != VTK_VERTEX && type != VTK_POLY_VERTEX && type != VTK_EMPTY_CELL) return false;
  }
  return true;
}

ResampledArrays interpolatePointCloud(std::span<const MeshSource> sources, const UniformGrid& grid,
                                      double radius, const std::string& what) {
  // Every source's points and arrays as one cloud.
  vtkNew<vtkPolyData> cloud;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  for (vtkDataArray* a : sources.front().arrays) {
    vtkSmartPointer<vtkDataArray> copy;
    copy.TakeReference(vtkDataArray::CreateDataArray(VTK_DOUBLE));
    copy->SetNumberOfComponents(a->GetNumberOfComponents());
    copy->SetName(concat("array", arrays.size()).c_str());
    arrays.push_back(copy);
  }
  for (const MeshSource& s : sources) {
    if (s.arrays.size() != arrays.size())
      throw Error(concat(what, ": the blocks carry different arrays"));
    for (vtkIdType p = 0; p < s.data->GetNumberOfPoints(); ++p) {
      double x[3];
      s.data->GetPoint(p, x);
      points->InsertNextPoint(x);
      for (std::size_t a = 0; a < arrays.size(); ++a)
        arrays[a]->InsertNextTuple(s.arrays[a]->GetTuple(p));
    }
  }
  cloud->SetPoints(points);
  for (const auto& a : arrays)
    cloud->GetPointData()->AddArray(a);

  vtkNew<vtkImageData> image;
  image->SetDimensions(grid.dims.x, grid.dims.y, grid.dims.z);
  image->SetOrigin(grid.origin.x, grid.origin.y, grid.origin.z);
  image->SetSpacing(grid.spacing.x, grid.spacing.y, grid.spacing.z);
  vtkNew<vtkShepardKernel> kernel;
  kernel->SetPowerParameter(2.0);
  kernel->SetKernelFootprintToRadius();
  kernel->SetRadius(radius);
  vtkNew<vtkStaticPointLocator> locator;
  vtkNew<vtkPointInterpolator> interpolator;
  interpolator->SetInputData(image);
  interpolator->SetSourceData(cloud);
  interpolator->SetKernel(kernel);
  interpolator->SetLocator(locator);
  interpolator->SetNullPointsStrategyToMaskPoints();
  interpolator->SetValidPointsMaskArrayName("valid");
  interpolator->Update();
  vtkDataSet* out = interpolator->GetOutput();
  vtkDataArray* mask = out->GetPointData()->GetArray("valid");
  if (!mask) throw Error(concat(what, ": VTK's point interpolator gave no mask"));

  ResampledArrays result;
  const std::size_t n = grid.points();
  result.valid.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    result.valid[p] = mask->GetComponent(vtkIdType(p), 0) != 0.0 ? 1 : 0;
    result.validCount += result.valid[p];
  }
  for (std::size_t a = 0; a < arrays.size(); ++a) {
    vtkDataArray* values = out->GetPointData()->GetArray(arrays[a]->GetName());
    if (!values) throw Error(concat(what, ": VTK's point interpolator lost an array"));
    const int c = values->GetNumberOfComponents();
    std::vector<float> v(n * std::size_t(c), 0.0f);
    for (std::size_t p = 0; p < n; ++p)
      if (result.valid[p])
        for (int k = 0; k < c; ++k)
          v[p * std::size_t(c) + std::size_t(k)] = float(values->GetComponent(vtkIdType(p), k));
    result.values.push_back(std::move(v));
  }
  return result;
}

}  // namespace sandstorm
