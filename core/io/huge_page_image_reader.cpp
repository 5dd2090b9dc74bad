#include "core/io/huge_page_image_reader.h"

#include <cstdint>

#include <sys/mman.h>
#include <vtkAbstractArray.h>
#include <vtkObjectFactory.h>

namespace sandstorm {

vtkStandardNewMacro(HugePageImageReader);

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
// Only arrays the C library maps on their own: from 32 MiB up glibc's malloc
// always does (its mmap threshold rises with freed blocks up to 32 MiB), so
// the advice ends with the array. Advice on a smaller one could fall on
// the heap, which outlives it, and leave memory the array no longer uses in
// huge pages.
constexpr std::uintptr_t kSmallestAdvised = std::uintptr_t{32} << 20;

// The whole 2 MiB pages inside the array's memory, advised; smaller arrays
// (and memory that is not the array's own) are left as they are.
void adviseHugePages(vtkAbstractArray* array) {
  if (!array || !array->HasStandardMemoryLayout()) return;
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(array->GetVoidPointer(0));
  const std::uintptr_t bytes =
      std::uintptr_t(array->GetDataSize()) * std::uintptr_t(array->GetDataTypeSize());
  if (bytes < kSmallestAdvised) return;
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHugePage - 1);
  if (begin == 0 || last <= first) return;
  // Advice only: a kernel without huge pages refuses it, and the array reads as before.
  madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

}  // namespace

int HugePageImageReader::ReadArrayForPoints(vtkXMLDataElement* da, vtkAbstractArray* outArray) {
  adviseHugePages(outArray);
  return vtkXMLImageDataReader::ReadArrayForPoints(da, outArray);
}

}  // namespace sandstorm
