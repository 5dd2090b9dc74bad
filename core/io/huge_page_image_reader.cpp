#include "core/io/huge_page_image_reader.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <thread>

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>
#include <vtkAbstractArray.h>
#include <vtkObjectFactory.h>
#include <vtkXMLDataElement.h>

#include "core/util/parallel_for.h"

namespace sandstorm {

vtkStandardNewMacro(HugePageImageReader);

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
// Only arrays the C library maps on their own: from 32 MiB up glibc's malloc
// always does (its mmap threshold rises with freed blocks up to 32 MiB), so
// the advice ends with the array. Advice on a smaller one could fall on
// the heap, which outlives it, and leave memory the array no longer uses in
// huge pages. The same size is where copying over the cores starts to pay.
constexpr std::uintptr_t kSmallestAdvised = std::uintptr_t{32} << 20;
// A thread's read at a time: large enough that a read costs little beside
// its copy, small enough that the cores share a 200 MB step evenly.
constexpr std::uint64_t kBlock = std::uint64_t{8} << 20;

std::uint64_t arrayBytes(vtkAbstractArray* array) {
  return std::uint64_t(array->GetDataSize()) * std::uint64_t(array->GetDataTypeSize());
}

}  // namespace

void adviseHugePages(vtkAbstractArray* array) {
  if (!array || !array->HasStandardMemoryLayout()) return;
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(array->GetVoidPointer(0));
  const std::uintptr_t bytes = std::uintptr_t(arrayBytes(array));
  if (bytes < kSmallestAdvised) return;
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHugePage - 1);
  if (begin == 0 || last <= first) return;
  // Advice only: a kernel without huge pages refuses it, and the array reads as before.
  madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

int HugePageImageReader::ReadArrayForPoints(vtkXMLDataElement* da, vtkAbstractArray* outArray) {
  adviseHugePages(outArray);
  const int copied = copyRaw(da, outArray);
  if (copied != 0) return copied > 0 ? 1 : 0;
  return vtkXMLImageDataReader::ReadArrayForPoints(da, outArray);
}

int HugePageImageReader::copyRaw(vtkXMLDataElement* da, vtkAbstractArray* outArray) {
  if (raw_.empty() && rawOf_ && FileName) raw_ = rawOf_(FileName);
  if (raw_.empty() || !FileName || ReadFromInputString || !da || !outArray ||
      !outArray->HasStandardMemoryLayout())
    return 0;
  const char* format = da->GetAttribute("format");
  const char* offsetText = da->GetAttribute("offset");
  if (!format || std::strcmp(format, "appended") != 0 || !offsetText) return 0;
  std::uint64_t offset = 0;
  const char* end = offsetText + std::strlen(offsetText);
  if (std::from_chars(offsetText, end, offset).ec != std::errc()) return 0;
  const auto raw = std::find_if(raw_.begin(), raw_.end(),
                                [&](const VtkXmlRawArray& r) { return r.offset == offset; });
  const std::uint64_t bytes = arrayBytes(outArray);
  if (raw == raw_.end() || raw->bytes != bytes || bytes < kSmallestAdvised) return 0;
  // VTK reads a piece that is only part of what it reads line by line into
  // place; only a piece read whole lands in the array as it lies in the file.
  const int* piece = PieceExtents + 6 * Piece;
  if (!std::equal(piece, piece + 6, UpdateExtent)) return 0;

  const int fd = ::open(FileName, O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    vtkErrorMacro(<< FileName << ": cannot open it to read " << bytes
                  << " bytes of point data: " << std::strerror(errno));
    return -1;
  }
  auto* out = static_cast<std::uint8_t*>(outArray->GetVoidPointer(0));
  const std::uint64_t at = raw->dataAt;
  std::atomic<bool> failed{false};
  std::atomic<int> error{0};
  const std::thread::id caller = std::this_thread::get_id();
  const float from = ProgressRange[0], width = ProgressRange[1] - ProgressRange[0];
  const std::size_t blocks = std::size_t((bytes + kBlock - 1) / kBlock);
  forChunks(
      blocks,
      [&](std::size_t first, std::size_t last) {
        // Progress from the reader's own thread only (VTK's observers run there);
        // its chunk is as large as any other's.
        const bool reports = std::this_thread::get_id() == caller;
        for (std::size_t b = first; b < last && !failed.load(std::memory_order_relaxed); ++b) {
          std::uint64_t done = std::uint64_t(b) * kBlock;
          const std::uint64_t stop = std::min(bytes, done + kBlock);
          while (done < stop) {
            const ssize_t n = ::pread(fd, out + done, std::size_t(stop - done), off_t(at + done));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
              error = n < 0 ? errno : 0;
              failed = true;
              return;
            }
            done += std::uint64_t(n);
          }
          if (reports)
            UpdateProgressDiscrete(from + width * float(b + 1 - first) / float(last - first));
        }
      },
      1);
  ::close(fd);
  if (failed) {
    vtkErrorMacro(<< FileName << ": reading " << bytes << " bytes of point data at byte " << at
                  << " failed: "
                  << (error != 0 ? std::strerror(error) : "the file ends before them"));
    return -1;
  }
  ++copied_;
  return 1;
}

}  // namespace sandstorm
