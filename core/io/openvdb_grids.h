// OpenVDB's grids of the four value types Sandstorm reads and writes,
// compiled once (openvdb_grids.cpp) instead of in every file that uses them.
// Include this in place of <openvdb/openvdb.h>.
//
// Why: OpenVDB 10 instantiates its tools in its library, but not its Grid
// and Tree class templates, so every file that made or read a grid compiled
// all of Grid's and Tree's virtual members for each type once more
// (vdb_writer.cpp: 33 s, 12 s with these declarations). Compiled one after
// another here, the seven files that use OpenVDB took 177 s, and take 158 s
// with openvdb_grids.cpp's 67 s; the sanitizer build compiles them too.
#pragma once

#include <openvdb/openvdb.h>

extern template class openvdb::Grid<openvdb::Vec3STree>;
extern template class openvdb::tree::Tree<openvdb::Vec3STree::RootNodeType>;
extern template class openvdb::Grid<openvdb::FloatTree>;
extern template class openvdb::tree::Tree<openvdb::FloatTree::RootNodeType>;
extern template class openvdb::Grid<openvdb::Vec3DTree>;
extern template class openvdb::tree::Tree<openvdb::Vec3DTree::RootNodeType>;
extern template class openvdb::Grid<openvdb::DoubleTree>;
extern template class openvdb::tree::Tree<openvdb::DoubleTree::RootNodeType>;
