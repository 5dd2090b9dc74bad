// readVtkXmlPieces(): the pieces of a parallel VTK XML file (.pvtr .pvts .pvtu
// .pvtp) read each by VTK's reader for one file, several at once (a piece a
// thread, up to the cores or the ChunkThreadLimit of the calling thread), and
// kept apart as the partitions of one vtkPartitionedDataSet rather than
// merged: the resampler takes them as separate sources (ghost cells skipped,
// ties between pieces to the earlier one), so no merged copy is made, and
// neither is VTK's serial piece-by-piece merge run.
//
// The pieces must have been checked first (readVtkXmlIndex: names, kinds,
// arrays against the index and the memory budget). Each partition carries
// its file's name (vtkCompositeDataSet::NAME: "Piece 2 (run_2.vtu)"), and
// its cells are checked (checkVtkCells) on the thread that read it. A piece
// VTK fails on, or whose cells fail the check, stops the read with an error naming it; the first
// such piece in the index's order is the one named. Progress: the pieces' bytes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "core/io/field_format.h"

class vtkPartitionedDataSet;

namespace sandstorm {

struct VtkXmlPiece {
  std::filesystem::path file;
  std::string where;  // "run.pvtu: Piece 2 (run_2.vtu)", for errors
  std::string name;   // "Piece 2 (run_2.vtu)", the partition's name
};

// `format`: the pieces' own (.vtr, .vts, .vtu or .vtp); `what`: "reading run.pvtu".
vtkSmartPointer<vtkPartitionedDataSet> readVtkXmlPieces(const std::vector<VtkXmlPiece>& pieces,
                                                        FieldFormat format, const std::string& what,
                                                        bool showProgress);

}  // namespace sandstorm
