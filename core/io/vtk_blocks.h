// vtkBlocks(): the datasets a VTK data object holds, as a list: a dataset is
// one block; a multiblock or other composite (a .vtm, an Exodus file's
// element blocks, an EnSight case's parts, an OpenFOAM case's mesh) gives
// each leaf with points, named as the file names it ("internalMesh",
// "block_1"), or by its place ("block 3") where the file names none.
#pragma once

#include <string>
#include <vector>

#include <vtkSmartPointer.h>

class vtkDataObject;
class vtkDataSet;

namespace sandstorm {

struct VtkBlock {
  std::string name;
  vtkSmartPointer<vtkDataSet> data;
};

std::vector<VtkBlock> vtkBlocks(vtkDataObject* object);

// "unstructured grid, 1400000 cells, 250000 points" for logs and `info`.
std::string describeBlock(vtkDataSet* data);

}  // namespace sandstorm
