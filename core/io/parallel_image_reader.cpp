#include "core/io/parallel_image_reader.h"

#include <algorithm>
#include <cstring>
#include <string>

#include <sys/stat.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkExtentSplitter.h>
#include <vtkObjectFactory.h>

#include "core/io/huge_page_image_reader.h"
#include "core/util/parallel_for.h"

namespace sandstorm {

vtkStandardNewMacro(ParallelImageReader);

namespace {

std::pair<unsigned long, unsigned long> fileId(const char* file) {
  struct stat st {};
  if (!file || ::stat(file, &st) != 0) return {0, 0};
  return {static_cast<unsigned long>(st.st_dev), static_cast<unsigned long>(st.st_ino)};
}

// Tuple (i, j, k)'s index in an array over `extent` with `increments` (VTK's
// GetStartTuple).
vtkIdType tupleAt(const int* extent, const vtkIdType* increments, int i, int j, int k) {
  return vtkIdType(i - extent[0]) * increments[0] + vtkIdType(j - extent[2]) * increments[1] +
         vtkIdType(k - extent[4]) * increments[2];
}

bool within(const int* inner, const int* outer) {
  for (int a = 0; a < 3; ++a)
    if (inner[2 * a] < outer[2 * a] || inner[2 * a + 1] > outer[2 * a + 1]) return false;
  return true;
}

}  // namespace

void ParallelImageReader::addPieceRawArrays(const std::filesystem::path& file,
                                            std::vector<VtkXmlRawArray> raw) {
  const auto id = fileId(file.c_str());
  if (id != std::pair<unsigned long, unsigned long>{0, 0}) raw_[id] = std::move(raw);
}

std::size_t ParallelImageReader::arraysReadOverTheCores() const {
  std::size_t n = 0;
  for (int i = 0; PieceReaders && i < NumberOfPieces; ++i)
    if (auto* piece = HugePageImageReader::SafeDownCast(PieceReaders[i]))
      n += piece->arraysCopied();
  return n;
}

vtkXMLDataReader* ParallelImageReader::CreatePieceReader() {
  HugePageImageReader* reader = HugePageImageReader::New();
  // The piece readers live as long as this reader does.
  reader->setRawArraysOf([this](const char* file) {
    const auto it = raw_.find(fileId(file));
    return it == raw_.end() ? std::vector<VtkXmlRawArray>{} : it->second;
  });
  return reader;
}

void ParallelImageReader::ReadXMLData() {
  subExtent_ = 0;
  vtkXMLPImageDataReader::ReadXMLData();
}

int ParallelImageReader::ReadPieceData() {
  // VTK's ReadXMLData reads the image's parts in ExtentSplitter's order, one
  // call each; a piece may give several.
  const int part = subExtent_++;
  const int read = vtkXMLPImageDataReader::ReadPieceData();
  bool later = false;
  for (int i = part + 1; i < ExtentSplitter->GetNumberOfSubExtents(); ++i)
    later = later || ExtentSplitter->GetSubExtentSource(i) == Piece;
  // Its last part copied: the piece's arrays go (those the image was lent live on in it).
  if (!later && PieceReaders && PieceReaders[Piece])
    if (vtkDataObject* piece = PieceReaders[Piece]->GetOutputDataObject(0)) piece->ReleaseData();
  return read;
}

void ParallelImageReader::CopyArrayForPoints(vtkAbstractArray* in, vtkAbstractArray* out) {
  if (!in || !out) return;
  if (!copy(SubPieceExtent, SubPiecePointIncrements, SubPiecePointDimensions, PointIncrements,
            PointDimensions, SubPointDimensions, in, out))
    vtkXMLPImageDataReader::CopyArrayForPoints(in, out);
}

void ParallelImageReader::CopyArrayForCells(vtkAbstractArray* in, vtkAbstractArray* out) {
  if (!in || !out) return;
  if (!copy(SubPieceExtent, SubPieceCellIncrements, SubPieceCellDimensions, CellIncrements,
            CellDimensions, SubCellDimensions, in, out))
    vtkXMLPImageDataReader::CopyArrayForCells(in, out);
}

bool ParallelImageReader::copy(const int* inExtent, const vtkIdType* inIncrements,
                               const int* inDims, const vtkIdType* outIncrements,
                               const int* outDims, const int* subDims, vtkAbstractArray* in,
                               vtkAbstractArray* out) {
  auto* from = vtkDataArray::SafeDownCast(in);
  auto* to = vtkDataArray::SafeDownCast(out);
  if (!from || !to || from->GetDataType() != to->GetDataType() ||
      from->GetNumberOfComponents() != to->GetNumberOfComponents() ||
      !from->HasStandardMemoryLayout() || !to->HasStandardMemoryLayout())
    return false;
  const int* outExtent = UpdateExtent;
  const int* subExtent = SubExtent;
  // The tuples the copy reads and writes lie in the arrays (VTK trusts that they do).
  vtkIdType inTuples = 1, outTuples = 1, subTuples = 1;
  for (int a = 0; a < 3; ++a) {
    if (inDims[a] < 1 || outDims[a] < 1 || subDims[a] < 1) return false;
    inTuples *= inDims[a];
    outTuples *= outDims[a];
    subTuples *= subDims[a];
  }
  if (!within(subExtent, inExtent) || !within(subExtent, outExtent) ||
      from->GetNumberOfTuples() < inTuples || to->GetNumberOfTuples() < outTuples)
    return false;

  // The piece is the whole image: the image takes the piece's array.
  if (std::equal(inExtent, inExtent + 6, outExtent) && subTuples == outTuples &&
      inTuples == outTuples && from->GetNumberOfTuples() == to->GetNumberOfTuples()) {
    const std::string name = to->GetName() ? to->GetName() : "";
    to->ShallowCopy(from);
    to->SetName(name.empty() ? nullptr : name.c_str());
    ++lent_;
    return true;
  }

  adviseHugePages(to);
  const std::size_t tupleBytes =
      std::size_t(from->GetDataTypeSize()) * std::size_t(from->GetNumberOfComponents());
  const std::size_t rowBytes = std::size_t(subDims[0]) * tupleBytes;
  const auto* source = static_cast<const unsigned char*>(from->GetVoidPointer(0));
  auto* target = static_cast<unsigned char*>(to->GetVoidPointer(0));
  const std::size_t rows = std::size_t(subDims[1]) * std::size_t(subDims[2]);
  forChunks(
      rows,
      [&](std::size_t first, std::size_t last) {
        for (std::size_t r = first; r < last; ++r) {
          const int j = subExtent[2] + int(r % std::size_t(subDims[1]));
          const int k = subExtent[4] + int(r / std::size_t(subDims[1]));
          const vtkIdType src = tupleAt(inExtent, inIncrements, subExtent[0], j, k);
          const vtkIdType dst = tupleAt(outExtent, outIncrements, subExtent[0], j, k);
          std::memcpy(target + std::size_t(dst) * tupleBytes,
                      source + std::size_t(src) * tupleBytes, rowBytes);
        }
      },
      std::max<std::size_t>(1, (std::size_t{1} << 20) / std::max<std::size_t>(rowBytes, 1)));
  ++copied_;
  return true;
}

}  // namespace sandstorm
