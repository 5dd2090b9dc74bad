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
#include <filesystem>
#include <vector>

namespace sandstorm {

void checkOpenFoamFile(const std::filesystem::path& file, std::size_t memoryBudget);

// The files of a case the reader opens for the time step `timeStep` (an
// index into the case's numeric time folders, in time order): each mesh's
// constant/polyMesh files and every file of that time folder (and a mesh in
// it), for the case itself or, decomposed, each processor* folder.
std::vector<std::filesystem::path> openFoamFilesToRead(const std::filesystem::path& caseDir,
                                                       bool decomposed, std::size_t timeStep);

}  // namespace sandstorm
