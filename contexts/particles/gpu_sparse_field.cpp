#include "contexts/particles/gpu_sparse_field.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <span>
#include <vector>

#include "core/util/error.h"

namespace sandstorm {
namespace {

// Where the words divide between the two buffers: kSparseSplitWords of
// shaders/field_sparse.glsl, in bytes (2 GiB less 1 MiB, within NVIDIA's
// storage-buffer limit of 2 GiB less one byte).
constexpr GLint64 kSplitBytes = GLint64(0x1FFC0000) * 4;
// NanoVDB's GLSL addresses bytes with 32 bits.
constexpr GLint64 kMaxBytes = GLint64(1) << 32;
// The region table's entries at most (16 MiB; a 4096^3 box takes 32^3).
constexpr std::size_t kMaxTableEntries = std::size_t{1} << 22;

// The buffer holding words [first, first + count) of the words the GPU gets:
// `prefix` (the region table), then the grid's.
gl::Buffer upload(const std::vector<std::uint32_t>& prefix, std::span<const std::uint32_t> grid,
                  std::size_t first, std::size_t count, GLint64 total) {
  gl::Buffer buffer = gl::createBuffer();
  glGetError();
  glNamedBufferStorage(buffer.id(), GLsizeiptr(count * 4), nullptr, GL_DYNAMIC_STORAGE_BIT);
  if (glGetError() != GL_NO_ERROR)
    throw Error(concat("the sparse field's upload: no GPU memory for its ", total,
                       " bytes; load it densely at a lower resolution (field.storage = "
                       "\"dense\", field.resolution)"));
  const std::size_t end = first + count;
  if (first < prefix.size()) {
    const std::size_t n = std::min(end, prefix.size()) - first;
    glNamedBufferSubData(buffer.id(), 0, GLsizeiptr(n * 4), prefix.data() + first);
  }
  if (end > prefix.size()) {
    const std::size_t from = std::max(first, prefix.size());
    glNamedBufferSubData(buffer.id(), GLintptr((from - first) * 4), GLsizeiptr((end - from) * 4),
                         grid.data() + (from - prefix.size()));
  }
  return buffer;
}

// The words ahead of the grid (shaders/field_sparse.glsl): origin and dims
// of the region table, the grid's byte offset, then the table with every
// address moved by that offset; padded to NanoVDB's 32-byte alignment.
std::vector<std::uint32_t> regionTableWords(const SparseField& field) {
  const SparseField::RegionTable table = field.regionTable(kMaxTableEntries);
  std::vector<std::uint32_t> words(8 + table.entries.size());
  words.resize((words.size() + 7) / 8 * 8, 0u);
  const std::uint32_t gridOffset = std::uint32_t(words.size() * 4);
  for (int a = 0; a < 3; ++a) {
    words[std::size_t(a)] = std::uint32_t(table.origin[a]);
    words[std::size_t(3 + a)] = std::uint32_t(table.dims[a]);
  }
  words[6] = gridOffset;
  for (std::size_t i = 0; i < table.entries.size(); ++i)
    words[8 + i] = table.entries[i] + gridOffset;  // keeps bit 0: the offset is a multiple of 32
  return words;
}

}  // namespace

void GpuSparseField::show(std::shared_ptr<const SparseField> field) {
  if (field == holds_) return;
  low_ = {};
  high_ = {};
  holds_.reset();
  if (!field) return;
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  const std::vector<std::uint32_t> table = regionTableWords(*field);
  const GLint64 bytes = GLint64(table.size() * 4 + field->byteSize());
  // One buffer below the split (the shader never reads the second); two past it.
  const GLint64 fits = maxBlock >= kSplitBytes ? std::min(kSplitBytes + maxBlock, kMaxBytes)
                                               : std::min(maxBlock, kSplitBytes);
  if (bytes > fits)
    throw Error(concat("the sparse field's upload: its ", field->activeVoxelCount(),
                       " active voxels take ", bytes, " bytes, beyond the ", fits,
                       " this GPU's storage buffers hold for a sparse grid; load it densely at a "
                       "lower resolution (field.storage = \"dense\", field.resolution)"));
  low_ = upload(table, field->words(), 0, std::size_t(std::min(bytes, kSplitBytes) / 4), bytes);
  if (bytes > kSplitBytes)
    high_ = upload(table, field->words(), std::size_t(kSplitBytes / 4),
                   std::size_t((bytes - kSplitBytes) / 4), bytes);
  holds_ = std::move(field);
}

void GpuSparseField::bind() const {
  if (!low_) return;
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 14, low_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 15, high_ ? high_.id() : low_.id());
}

}  // namespace sandstorm
