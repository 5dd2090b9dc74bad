// The one place OpenVDB's Grid and Tree templates of Sandstorm's four value
// types are compiled (openvdb_grids.h says why).
#include "core/io/openvdb_grids.h"

template class openvdb::Grid<openvdb::Vec3STree>;
template class openvdb::tree::Tree<openvdb::Vec3STree::RootNodeType>;
template class openvdb::Grid<openvdb::FloatTree>;
template class openvdb::tree::Tree<openvdb::FloatTree::RootNodeType>;
template class openvdb::Grid<openvdb::Vec3DTree>;
template class openvdb::tree::Tree<openvdb::Vec3DTree::RootNodeType>;
template class openvdb::Grid<openvdb::DoubleTree>;
template class openvdb::tree::Tree<openvdb::DoubleTree::RootNodeType>;
