// chooseVectorArray(): which vectors of a file's blocks become the field, and
// pointVectors(): a block with them as point data.
//
// The choice, over every block (a file of one dataset is one block):
// - options.arrayName names it: a 3-component array in point or cell data, or
//   three one-component arrays joined into one vector ("u,v,w", "U_X,U_Y,U_Z";
//   a configuration's field.name = ["u", "v", "w"]);
// - else the point data's active vectors;
// - else the only 3-component array (point data first, then cell data);
// - else the only set of components named alike: u/v/w, or a common stem
//   ending in x/y/z (vel_x, vel_y, vel_z; U_X, U_Y, U_Z; vx, vy, vz), joined;
// - else the only 2-component array (a 2D simulation's velocity), read as
//   (x, y, 0) with a note; a named array may have 2 components too.
// Anything else throws Error naming the file and listing the arrays present
// (each with its components, cell data marked) and how to choose
// (--array NAME, or the configuration's field.name). Blocks without the chosen
// array are left out and named in report.notes.
//
// Cell data (what finite-volume codes write) becomes point data as ParaView's
// Cell Data to Point Data makes it (vtkCellDataToPointData: each point takes
// the mean of the cells around it), so the field is continuous, as particles
// and streamlines need; one-component cell arrays move with it, to colour by.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "core/io/load_options.h"
#include "core/io/vtk_blocks.h"

namespace sandstorm {

struct VectorChoice {
  std::string name;                     // the field's array name
  std::vector<std::string> components;  // three one-component arrays joined, or empty
  // A two-component array (a 2D simulation's velocity), read as (x, y, 0).
  bool planar = false;
};

VectorChoice chooseVectorArray(const std::vector<VtkBlock>& blocks,
                               const std::filesystem::path& path, const LoadOptions& options,
                               LoadReport& report);

// The block's dataset with the chosen vectors as a point array named
// choice.name (joined, and moved from the cells, as needed) and its other
// arrays as point data; null when the block lacks them. What was moved is
// noted in report.notes.
vtkSmartPointer<vtkDataSet> pointVectors(const VtkBlock& block, const VectorChoice& choice,
                                         const std::filesystem::path& path, LoadReport& report);

// "'velocity' (3 components), 'p' (1 component, cell data)": every block's
// arrays, each name once.
std::string arrayInventory(const std::vector<VtkBlock>& blocks);

}  // namespace sandstorm
