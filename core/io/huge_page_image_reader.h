// HugePageImageReader: VTK's .vti reader, with each large point array it is
// about to fill (32 MiB or more: memory of its own) marked for transparent
// huge pages (madvise MADV_HUGEPAGE) before its first byte is written.
//
// A series' 256^3 step is a 200 MB array that VTK allocates and fills anew
// for every step. In 4 KiB pages the kernel takes 49 000 page faults to map
// it, each zeroing and charging its page: half the time of reading a step
// from the page cache, and worse with several readers faulting at once. In
// 2 MiB pages it takes about a hundred. Where the kernel gives no huge pages
// (transparent_hugepage = never) the advice changes nothing. What is read is
// VTK's own reader's result, unchanged.
#pragma once

#include <vtkXMLImageDataReader.h>

namespace sandstorm {

class HugePageImageReader : public vtkXMLImageDataReader {
 public:
  static HugePageImageReader* New();
  vtkTypeMacro(HugePageImageReader, vtkXMLImageDataReader)

 protected:
  HugePageImageReader() = default;
  ~HugePageImageReader() override = default;
  int ReadArrayForPoints(vtkXMLDataElement* da, vtkAbstractArray* outArray) override;

 public:
  HugePageImageReader(const HugePageImageReader&) = delete;
  void operator=(const HugePageImageReader&) = delete;
};

}  // namespace sandstorm
