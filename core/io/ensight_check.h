// EnSight Gold cases checked before VTK's vtkGenericEnSightReader reads them:
// the reader allocates the node and element counts a geometry file states
// before it reads them, and opens whatever files the case names.
//
// parseEnSightCase() reads the .case file (FORMAT, GEOMETRY, VARIABLE, TIME
// sections) and checkEnSightStep() one time step's files:
// - every file the case names for that step (wildcards "***" filled from the
//   time set's numbers) lies inside the case's folder tree and exists;
// - the geometry file (C binary, either byte order, or ascii), part by part:
//   every count within the file's remaining bytes (ascii: its lines) and the
//   memory budget, every element type one EnSight Gold has;
// - each per-node or per-element variable file holds the values its parts'
//   nodes or elements need.
// Fortran binary and EnSight 6 cases are refused with a message. Throws
// Error naming the file, the part and what was wrong.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace sandstorm {

struct EnSightCase {
  std::filesystem::path folder;
  std::string geometry;  // the model's file name, perhaps with wildcards
  struct Variable {
    std::string kind;  // "vector per node", "scalar per element", ...
    std::string file;
  };
  std::vector<Variable> variables;
  std::vector<double> times;           // of the first time set; empty: one step
  std::vector<long long> fileNumbers;  // what fills the wildcards, step by step
};

EnSightCase parseEnSightCase(const std::filesystem::path& caseFile);

void checkEnSightStep(const EnSightCase& c, std::size_t step, std::size_t memoryBudget);

}  // namespace sandstorm
