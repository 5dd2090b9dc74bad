#include "core/io/vtk_blocks.h"

#include <cctype>

#include <vtkCompositeDataSet.h>
#include <vtkDataObjectTree.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDataSet.h>
#include <vtkInformation.h>
#include <vtkNew.h>

#include "core/util/error.h"

namespace sandstorm {
namespace {

// The leaf's name as its file gives it, or its place among the blocks.
std::string leafName(vtkDataObjectTreeIterator* it) {
  vtkInformation* info = it->HasCurrentMetaData() ? it->GetCurrentMetaData() : nullptr;
  const char* name = info && info->Has(vtkCompositeDataSet::NAME())
                         ? info->Get(vtkCompositeDataSet::NAME())
                         : nullptr;
  if (name && *name) return name;
  return concat("block ", it->GetCurrentFlatIndex());
}

}  // namespace

std::vector<VtkBlock> vtkBlocks(vtkDataObject* object) {
  std::vector<VtkBlock> blocks;
  if (auto* data = vtkDataSet::SafeDownCast(object)) {
    blocks.push_back({"", data});
    return blocks;
  }
  auto* tree = vtkDataObjectTree::SafeDownCast(object);
  if (!tree) return blocks;
  vtkSmartPointer<vtkDataObjectTreeIterator> it;
  it.TakeReference(tree->NewTreeIterator());
  it->VisitOnlyLeavesOn();
  it->SkipEmptyNodesOn();
  it->TraverseSubTreeOn();
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) {
    auto* data = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
    if (!data || data->GetNumberOfPoints() == 0) continue;
    blocks.push_back({leafName(it), data});
  }
  return blocks;
}

std::string describeBlock(vtkDataSet* data) {
  std::string kind = data->GetClassName();
  if (kind.rfind("vtk", 0) == 0) kind = kind.substr(3);
  std::string words;
  for (char c : kind) {
    if (std::isupper(static_cast<unsigned char>(c)) && !words.empty()) words += ' ';
    words += char(std::tolower(static_cast<unsigned char>(c)));
  }
  return concat(words, ", ", data->GetNumberOfCells(), " cells, ", data->GetNumberOfPoints(),
                " points");
}

}  // namespace sandstorm
