// ParallelImageReader: VTK's .pvti reader, with each piece read as a .vti is
// (HugePageImageReader: a large raw array in huge pages, copied from the file
// over the cores) and each piece's arrays put into the image over the cores.
//
// VTK reads a .pvti's pieces on one thread into arrays in 4 KiB pages, then
// copies each into the whole image on one thread, into more 4 KiB pages: a
// 512^3 grid in one piece took 2.0-2.4 s from the page cache on an H200's
// host and twice its size in memory, where the same grid as a .vti took 0.2
// s and its size once. Here:
// - a piece that is the whole image (its points are all the image's, as
//   written by a one-rank run or a tool that names one .vti) lends the image
//   its arrays: no copy and no second allocation;
// - any other piece's arrays are copied row by row over the cores, into
//   arrays advised for huge pages before their first byte is written, and
//   the piece's own arrays are released once the last part of the image it
//   gives is copied (VTK keeps every piece's until the read ends: twice the
//   grid at the peak).
// The image holds the same values either way: the rows VTK would copy, from
// the same pieces (ParallelImageReader.* compares them with VTK's reader).
// Arrays of another layout or type than the image's keep VTK's own copy.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <utility>
#include <vector>

#include <vtkXMLPImageDataReader.h>

#include "core/io/vtk_xml_check.h"

namespace sandstorm {

class ParallelImageReader : public vtkXMLPImageDataReader {
 public:
  static ParallelImageReader* New();
  vtkTypeMacro(ParallelImageReader, vtkXMLPImageDataReader)

  // A piece file's raw appended arrays (VtkXmlSummary::raw of that file).
  void addPieceRawArrays(const std::filesystem::path& file, std::vector<VtkXmlRawArray> raw);
  // Arrays the image took from a piece whole, and arrays copied over the cores.
  std::size_t arraysLent() const { return lent_; }
  std::size_t arraysCopied() const { return copied_; }
  // Piece arrays read from their files over the cores (the rest VTK read).
  std::size_t arraysReadOverTheCores() const;

 protected:
  ParallelImageReader() = default;
  ~ParallelImageReader() override = default;
  vtkXMLDataReader* CreatePieceReader() override;
  void ReadXMLData() override;
  int ReadPieceData() override;
  void CopyArrayForPoints(vtkAbstractArray* in, vtkAbstractArray* out) override;
  void CopyArrayForCells(vtkAbstractArray* in, vtkAbstractArray* out) override;

 public:
  ParallelImageReader(const ParallelImageReader&) = delete;
  void operator=(const ParallelImageReader&) = delete;

 private:
  // Copies the sub-extent being read (SubExtent) from the piece's part read
  // (`inExtent`, its increments and dimensions: points' or cells') into the
  // image's update extent (its increments and dimensions), or lends the
  // piece's array where the part is the whole image. False: not one this
  // reader copies (VTK copies it).
  bool copy(const int* inExtent, const vtkIdType* inIncrements, const int* inDims,
            const vtkIdType* outIncrements, const int* outDims, const int* subDims,
            vtkAbstractArray* in, vtkAbstractArray* out);

  // By the file's device and inode: VTK names a piece by its own path.
  std::map<std::pair<unsigned long, unsigned long>, std::vector<VtkXmlRawArray>> raw_;
  std::size_t lent_ = 0;
  std::size_t copied_ = 0;
  int subExtent_ = 0;  // the image's part being read: its index in ExtentSplitter's list
};

}  // namespace sandstorm
