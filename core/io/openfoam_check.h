// checkOpenFoamFile(): an OpenFOAM file (a dictionary, a polyMesh list, a
// field), checked before VTK's vtkOpenFOAMReader reads it, because the
// reader allocates every list at the size its header claims ("1000000000\n(")
// before it reads an element.
//
// The file is read once as OpenFOAM's own parser would read it (plain or
// gzip-compressed, ascii or binary as its FoamFile header says), and every
// list in it is held to its count:
// - ascii: the elements between the parentheses are counted (a face "4(...)"
//   is one element, its own four checked in turn), and must be the count;
// - binary: the count times the element's size (from the list's type,
//   List<vector>, or the file's class: vectorField, labelList,
//   faceCompactList ...; labels of the width the header's arch gives) must lie
//   within the file, and the list must close after it;
// - uniform lists ("3{0}") and every list: the count times 24 bytes within
//   the memory budget, and below 2^31;
// - braces, parentheses and comments close, strings end.
// Throws Error naming the file, the line and what was wrong.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace sandstorm {

// What a file's lists and dictionaries say, for the checks across a mesh's files.
struct OpenFoamFacts {
  struct List {
    std::uint64_t count = 0;     // its elements
    std::uint64_t maxLabel = 0;  // the largest whole number in it
    // A binary list of labels: its first and last, and the smallest step
    // from one to the next (negative: it runs backwards somewhere).
    std::int64_t first = 0, last = 0, minStep = std::numeric_limits<std::int64_t>::max();
    // An ascii list of lists (faces): the smallest of the inner lists' counts.
    std::uint64_t minInner = std::numeric_limits<std::uint64_t>::max();
  };
  std::vector<List> lists;                                       // the top-level lists, in order
  std::vector<std::pair<std::uint64_t, std::uint64_t>> patches;  // (startFace, nFaces)
  std::optional<std::uint64_t> internalField;                    // a nonuniform field's count
};

OpenFoamFacts checkOpenFoamFile(const std::filesystem::path& file, std::size_t memoryBudget);

// A mesh's files checked together (vtkOpenFOAMReader counts the cells as the
// largest owner plus one, and indexes the points by the faces' labels
// unchecked): every face's points among the points, an owner for each face
// and no more cells than faces, neighbours among the cells, every patch
// within the faces. Returns the cell count.
std::uint64_t checkOpenFoamMesh(const std::filesystem::path& root, std::size_t memoryBudget);

// The meshes of a case (the case folder, or each processor* folder of a
// decomposed one) and the files of the time folder for `timeStep` (an index
// into the numeric time folders, in time order) in each.
struct OpenFoamRoot {
  std::filesystem::path root;
  std::vector<std::filesystem::path> fields;
};
std::vector<OpenFoamRoot> openFoamFilesToRead(const std::filesystem::path& caseDir, bool decomposed,
                                              std::size_t timeStep);

}  // namespace sandstorm
