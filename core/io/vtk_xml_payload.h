// VtkXmlPayload: one binary DataArray payload of a VTK XML file, checked byte
// by byte as its decoded bytes arrive (from inline base64, appended base64 or
// appended raw data), so that VTK's reader never meets a payload it fails on
// halfway: vtkXMLStructuredDataReader leaks the arrays it was filling when a
// read fails, and it allocates what a header claims before reading.
//
// Layout (VTK's, header words UInt32 or UInt64 in the file's byte order):
//   uncompressed: [bytes] data
//   compressed:   [blocks][block size][last block size][size of each block] blocks
// Checked: the declared size equals `needed` (the array's tuples x components x
// type size) when that is known, or is within the memory budget; the data is
// all there; every compressed block decompresses (zlib, LZ4 or LZMA, as the
// file's compressor says) to exactly its size. Memory grows only with bytes
// that are actually there: a block's compressed bytes are kept, the size table
// as it arrives, and an LZ4 block's output only when its size is one its input
// can produce. Compressed blocks are gathered (up to kBatchBytes) and
// decompressed over the cores; an error names the first bad block in order.
// Errors throw Error starting with `where` (the file, the piece, the array).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sandstorm {

enum class VtkCompressor { None, ZLib, LZ4, LZMA };

// The compressor a VTKFile's `compressor` attribute names; throws for others.
VtkCompressor vtkCompressorNamed(const std::string& name, const std::string& where);

struct VtkPayloadFormat {
  int headerSize = 4;  // bytes in a header word
  bool bigEndian = false;
  VtkCompressor compressor = VtkCompressor::None;
  std::uint64_t memoryBudget = 0;
};

class VtkXmlPayload {
 public:
  // `needText` says how `needed` comes about, for the error message.
  VtkXmlPayload(const VtkPayloadFormat& format, std::string where,
                std::optional<std::uint64_t> needed, std::string needText = {});
  ~VtkXmlPayload();
  VtkXmlPayload(const VtkXmlPayload&) = delete;
  VtkXmlPayload& operator=(const VtkXmlPayload&) = delete;

  // Takes up to `n` decoded bytes and returns how many it took: all of them
  // unless the payload completes first (bytes after that are not part of it).
  std::size_t push(const std::uint8_t* data, std::size_t n);
  bool complete() const { return state_ == State::Done; }
  // Bytes the payload takes before it next decides anything (the rest of a
  // header word, of a block, of the data): a decoder that produces no more
  // than this before pushing reads no further into the file than needed.
  std::uint64_t wanted() const;
  // Uncompressed data bytes still to come that need no check: a reader of raw
  // bytes may skip them (then calls skipped()) instead of pushing each one.
  std::uint64_t skippable() const;
  void skipped(std::uint64_t bytes);
  // Throws "truncated" unless the payload is complete.
  void finish() const;
  // Keeps the decoded (decompressed) data in `sink` as it arrives; nothing is
  // skippable then. For the few arrays whose values must be looked at.
  void capture(std::vector<std::uint8_t>* sink) { sink_ = sink; }
  // The data bytes the header declares (after decompression).
  std::uint64_t declaredBytes() const;

 private:
  enum class State { Header, Sizes, Data, Block, Done };
  [[noreturn]] void fail(const std::string& message) const;
  std::uint64_t word(std::size_t index) const;
  void headerComplete();
  void startBlock();
  void endBlock();
  void inflatePending();
  std::uint64_t blockOutput(std::uint64_t b) const;
  // Decompresses one block, checking its size; returns an error, or nothing.
  std::string inflateBlock(std::uint64_t b, const std::uint8_t* in, std::uint64_t size,
                           std::vector<std::uint8_t>& scratch,
                           std::vector<std::uint8_t>* sink) const;

  VtkPayloadFormat format_;
  std::string where_;
  std::optional<std::uint64_t> needed_;
  std::string needText_;
  State state_ = State::Header;
  std::vector<std::uint8_t> bytes_;  // the header words being read
  struct Pending {
    std::uint64_t block, offset, size;  // in batch_
  };
  std::vector<std::uint8_t> batch_;  // compressed blocks not decompressed yet
  std::vector<Pending> pending_;
  std::uint64_t remaining_ = 0;  // bytes left in the current state
  std::uint64_t declared_ = 0;   // uncompressed bytes the header declares
  std::uint64_t blocks_ = 0, blockSize_ = 0, lastSize_ = 0;
  std::vector<std::uint64_t> sizes_;
  std::uint64_t block_ = 0;
  std::vector<std::uint8_t>* sink_ = nullptr;
};

}  // namespace sandstorm
