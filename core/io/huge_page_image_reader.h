// HugePageImageReader: VTK's .vti reader, with each large point array (32 MiB
// or more: memory of its own) marked for transparent huge pages before its
// first byte is written, and, where the file stores it as it lies in memory,
// copied from the file over the cores.
//
// Huge pages: a series' 256^3 step is a 200 MB array that VTK allocates and
// fills anew for every step. In 4 KiB pages the kernel takes 49 000 page
// faults to map it, each zeroing and charging its page: half the time of
// reading a step from the page cache, and worse with several readers
// faulting at once. In 2 MiB pages it takes about a hundred. Where the
// kernel gives no huge pages (transparent_hugepage = never) the advice
// changes nothing (madvise MADV_HUGEPAGE).
//
// Copies over the cores: VTK reads an array on one thread, at about 2.4 GB/s
// from the page cache on an H200's host where `cat` reads the same file at
// 8 GB/s. Given the file's raw arrays (setRawArrays, from checkVtkXml: raw
// appended data, uncompressed, this machine's byte order, every byte held
// by the file), a large one that VTK reads whole into its array (the piece
// is what is read, the sizes agree) is read with pread() in 8 MiB blocks on
// forChunks' threads (ChunkThreadLimit holds) instead; anything else is
// VTK's own read. Either way the array holds the file's bytes unchanged.
// A failed read is VTK's error, naming the file and the bytes.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include <vtkXMLImageDataReader.h>

#include "core/io/vtk_xml_check.h"

namespace sandstorm {

class HugePageImageReader : public vtkXMLImageDataReader {
 public:
  static HugePageImageReader* New();
  vtkTypeMacro(HugePageImageReader, vtkXMLImageDataReader)

  // The file's raw appended arrays (VtkXmlSummary::raw of the file it reads).
  void setRawArrays(std::vector<VtkXmlRawArray> raw) { raw_ = std::move(raw); }
  // Or, for a reader whose file is named later (a .pvti's piece reader,
  // ParallelImageReader), the raw arrays of the file it is given.
  void setRawArraysOf(std::function<std::vector<VtkXmlRawArray>(const char* file)> rawOf) {
    rawOf_ = std::move(rawOf);
  }
  // Arrays copied over the cores so far (the rest VTK read).
  std::size_t arraysCopied() const { return copied_; }

 protected:
  HugePageImageReader() = default;
  ~HugePageImageReader() override = default;
  int ReadArrayForPoints(vtkXMLDataElement* da, vtkAbstractArray* outArray) override;

 public:
  HugePageImageReader(const HugePageImageReader&) = delete;
  void operator=(const HugePageImageReader&) = delete;

 private:
  // 1: read; 0: not one to copy (VTK reads it); -1: the read failed (reported).
  int copyRaw(vtkXMLDataElement* da, vtkAbstractArray* outArray);

  std::vector<VtkXmlRawArray> raw_;
  std::function<std::vector<VtkXmlRawArray>(const char*)> rawOf_;
  std::size_t copied_ = 0;
};

// Advises the whole 2 MiB pages inside an array's memory of 32 MiB or more
// for transparent huge pages, before its first byte is written; smaller
// arrays (and memory that is not the array's own) are left as they are.
void adviseHugePages(vtkAbstractArray* array);

}  // namespace sandstorm
