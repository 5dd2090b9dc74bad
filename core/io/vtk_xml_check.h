// checkVtkXml: a VTK XML file (.vti .vtr .vts .vtu .vtp, or any VTKFile) checked before
// VTK reads it, because vtkXML*Reader allocates what a DataArray's attributes
// claim before it notices that the payload is short.
//
// One streaming pass: the XML is read tag by tag, inline data is decoded
// without being kept, appended data is visited at each array's offset and
// decoded. Every DataArray of every Piece is checked:
// - `type` is a numeric VTK type; NumberOfComponents a whole number >= 1;
// - NumberOfTuples, when given, is what the piece's Extent gives the array
//   (its points, its cells, or one axis of its coordinates), or its counts
//   (NumberOfPoints, NumberOfCells, NumberOfVerts/Lines/Strips/Polys: the
//   points, the cell data, the offsets and types); each count is within the
//   memory budget, and a piece that claims points has a Points array;
//   connectivity has no count to check here (checkVtkCells, after reading,
//   holds it against the offsets and the points);
// - tuples x components x type size is within the memory budget, and all
//   arrays together within twice it;
// - a Piece's Extent lies inside the WholeExtent; the compressor is one VTK has;
// - the payload holds exactly it (VtkXmlPayload): a binary header's byte count,
//   or a compressed header's uncompressed size, must equal it; every byte is
//   there (inline base64, appended raw or base64, UInt32 or UInt64 headers,
//   either byte order); every compressed block (zlib, LZ4, LZMA) decompresses
//   to its size; every ascii value is a finite number of the array's type.
// VTK's structured readers leak the arrays they were filling when a payload
// fails halfway, so a payload VTK would fail on must not reach it.
// Throws Error naming the file, the piece and array, and the numbers; returns
// the bytes the arrays take (for a budget over several files), the arrays
// declared (to hold a parallel file's pieces to its declarations) and where
// the raw appended ones lie.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/io/vtk_image_frame.h"

namespace sandstorm {

// One DataArray as a file declares it.
struct VtkXmlArray {
  std::string section;  // "Points", "PointData", "CellData", "Coordinates", ...
  std::string name;
  std::string type;  // "Float32", ...
  std::uint64_t components = 1;
};

// An appended array whose bytes lie in the file as they lie in memory here
// (raw, uncompressed, this machine's byte order): a reader may copy them
// straight from the file (HugePageImageReader).
struct VtkXmlRawArray {
  std::uint64_t offset = 0;  // its DataArray's `offset` attribute
  std::uint64_t dataAt = 0;  // where its first byte lies in the file (after the header)
  std::uint64_t bytes = 0;   // its header's byte count, checked: the file holds them all
};

struct VtkXmlSummary {
  double bytes = 0.0;                             // all arrays together
  std::vector<VtkXmlArray> arrays;                // every piece's, in file order
  std::vector<std::array<long long, 6>> extents;  // every piece's Extent, where given
  std::vector<VtkXmlRawArray> raw;                // the appended arrays stored as in memory
};

VtkXmlSummary checkVtkXml(const std::filesystem::path& path, std::size_t memoryBudget);

// The image's frame from the tags before its first Piece, read by the same
// tokenizer, none of the arrays (nor, for a .pvti, any of its pieces): none
// where the file is not VTK ImageData or parallel image data (PImageData), or
// its header gives no usable frame (no WholeExtent, an empty or huge extent,
// a spacing that is not positive and finite, a Direction that is not the
// identity: only axis-aligned images are read). Never throws: the read that
// follows says what is wrong with such a file.
std::optional<VtkImageFrame> readVtkImageFrame(const std::filesystem::path& path);

}  // namespace sandstorm
