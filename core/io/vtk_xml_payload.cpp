#include "core/io/vtk_xml_payload.h"

#include <lz4.h>
#include <lzma.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>

#include "core/io/budget_advice.h"
#include "core/util/error.h"
#include "core/util/parallel_for.h"

namespace sandstorm {
namespace {

constexpr std::size_t kScratch = 64 * 1024;       // decompressed bytes looked at per step
constexpr std::size_t kBatchBytes = 16 << 20;     // compressed bytes gathered, then decompressed
constexpr std::uint64_t kLzmaMemory = 256 << 20;  // the decoder's dictionary, at most
// The most output one input byte can give: zlib's deflate 1032:1, LZ4 255:1.
constexpr std::uint64_t kZlibRatio = 1032, kLz4Ratio = 255;

}  // namespace

VtkCompressor vtkCompressorNamed(const std::string& name, const std::string& where) {
  if (name.empty()) return VtkCompressor::None;
  if (name == "vtkZLibDataCompressor") return VtkCompressor::ZLib;
  if (name == "vtkLZ4DataCompressor") return VtkCompressor::LZ4;
  if (name == "vtkLZMADataCompressor") return VtkCompressor::LZMA;
  throw Error(concat(where, ": compressor '", name.substr(0, 80),
                     "': expected vtkZLibDataCompressor, vtkLZ4DataCompressor or ",
                     "vtkLZMADataCompressor"));
}

VtkXmlPayload::VtkXmlPayload(const VtkPayloadFormat& format, std::string where,
                             std::optional<std::uint64_t> needed, std::string needText)
    : format_(format), where_(std::move(where)), needed_(needed), needText_(std::move(needText)) {
  if (needText_.empty() && needed_) needText_ = concat("the array needs ", *needed_);
  const int words = format_.compressor == VtkCompressor::None ? 1 : 3;
  remaining_ = std::uint64_t(words * format_.headerSize);
}

VtkXmlPayload::~VtkXmlPayload() = default;

void VtkXmlPayload::fail(const std::string& message) const {
  throw Error(concat(where_, ": ", message));
}

std::uint64_t VtkXmlPayload::word(std::size_t index) const {
  const int hs = format_.headerSize;
  std::uint64_t v = 0;
  for (int i = 0; i < hs; ++i) {
    const std::uint8_t b = bytes_[index * std::size_t(hs) + std::size_t(i)];
    v |= std::uint64_t(b) << (8 * (format_.bigEndian ? hs - 1 - i : i));
  }
  return v;
}

std::size_t VtkXmlPayload::push(const std::uint8_t* data, std::size_t n) {
  std::size_t taken = 0;
  while (taken < n && state_ != State::Done) {
    const std::uint8_t* at = data + taken;
    const std::size_t left = n - taken;
    switch (state_) {
      case State::Header:
        bytes_.push_back(*at);
        ++taken;
        if (--remaining_ == 0) headerComplete();
        break;
      case State::Sizes:
        bytes_.push_back(*at);
        ++taken;
        if (bytes_.size() == std::size_t(format_.headerSize)) {
          sizes_.push_back(word(0));
          bytes_.clear();
          if (sizes_.size() == blocks_) startBlock();
        }
        break;
      case State::Data: {
        const std::size_t k = std::size_t(std::min<std::uint64_t>(left, remaining_));
        if (sink_) sink_->insert(sink_->end(), at, at + k);
        taken += k;
        remaining_ -= k;
        if (remaining_ == 0) state_ = State::Done;
        break;
      }
      case State::Block: {
        const std::size_t k = std::size_t(std::min<std::uint64_t>(left, remaining_));
        batch_.insert(batch_.end(), at, at + k);
        taken += k;
        remaining_ -= k;
        if (remaining_ == 0) endBlock();
        break;
      }
      case State::Done:
        break;
    }
  }
  return taken;
}

std::uint64_t VtkXmlPayload::wanted() const {
  switch (state_) {
    case State::Sizes:
      return std::uint64_t(format_.headerSize) - bytes_.size();
    case State::Done:
      return 0;
    default:
      return remaining_;
  }
}

std::uint64_t VtkXmlPayload::skippable() const {
  return state_ == State::Data && !sink_ ? remaining_ : 0;
}

std::uint64_t VtkXmlPayload::declaredBytes() const {
  return declared_;
}

void VtkXmlPayload::skipped(std::uint64_t bytes) {
  remaining_ -= std::min(bytes, skippable());
  if (state_ == State::Data && remaining_ == 0) state_ = State::Done;
}

void VtkXmlPayload::finish() const {
  switch (state_) {
    case State::Done:
      return;
    case State::Header:
      fail(
          concat("truncated: the data ends inside its ", format_.headerSize, "-byte header words"));
    case State::Sizes:
      fail(concat("truncated: the compression header lists ", blocks_, " blocks; the sizes of ",
                  sizes_.size(), " are there"));
    case State::Data:
      fail(concat("truncated: the header declares ", declared_, " bytes, ", declared_ - remaining_,
                  " follow it"));
    case State::Block:
      fail(concat("truncated: compressed block ", block_ + 1, " of ", blocks_, " holds ",
                  sizes_[block_] - remaining_, " of its ", sizes_[block_], " bytes"));
  }
}

void VtkXmlPayload::headerComplete() {
  const auto expect = [&](std::uint64_t declared, const char* what) {
    if (needed_ && declared != *needed_)
      fail(concat("its ", what, " declares ", declared, " bytes; ", needText_));
    if (!needed_ && declared > format_.memoryBudget)
      fail(concat("its ", what, " declares ", declared,
                  " bytes, beyond the memory budget (field.memory_budget) of ",
                  format_.memoryBudget, " bytes", raiseBudget(double(declared))));
  };
  if (format_.compressor == VtkCompressor::None) {
    declared_ = word(0);
    expect(declared_, "header");
    bytes_.clear();
    remaining_ = declared_;
    state_ = remaining_ == 0 ? State::Done : State::Data;
    return;
  }
  blocks_ = word(0), blockSize_ = word(1), lastSize_ = word(2);
  bytes_.clear();
  if (blocks_ > 0 && blockSize_ == 0) fail(concat(blocks_, " compressed blocks of 0 bytes"));
  if (blockSize_ > format_.memoryBudget)
    fail(concat("compression blocks of ", blockSize_,
                " bytes, beyond the memory budget (field.memory_budget) of ", format_.memoryBudget,
                " bytes", raiseBudget(double(blockSize_))));
  if (lastSize_ > blockSize_)
    fail(concat("the last compressed block (", lastSize_, " bytes) is larger than a block (",
                blockSize_, ")"));
  // blocks_ - 1 whole blocks must fit in the budget before they are multiplied.
  if (blocks_ > 1 && blocks_ - 1 > format_.memoryBudget / blockSize_)
    fail(concat(blocks_, " compressed blocks of ", blockSize_,
                " bytes, beyond the memory budget (field.memory_budget) of ", format_.memoryBudget,
                " bytes", raiseBudget(double(blocks_ - 1) * double(blockSize_))));
  declared_ = blocks_ == 0 ? 0 : (blocks_ - 1) * blockSize_ + (lastSize_ ? lastSize_ : blockSize_);
  expect(declared_, "compression header (uncompressed size)");
  state_ = blocks_ == 0 ? State::Done : State::Sizes;
}

std::uint64_t VtkXmlPayload::blockOutput(std::uint64_t b) const {
  return b + 1 == blocks_ && lastSize_ ? lastSize_ : blockSize_;
}

void VtkXmlPayload::startBlock() {
  state_ = State::Block;
  remaining_ = sizes_[block_];
  if (remaining_ == 0)
    fail(concat("compressed block ", block_ + 1, " of ", blocks_, " is empty; it should give ",
                blockOutput(block_), " bytes"));
}

void VtkXmlPayload::endBlock() {
  const std::uint64_t size = sizes_[block_];
  pending_.push_back({block_, batch_.size() - size, size});
  const bool last = ++block_ == blocks_;
  // A captured array is decompressed block by block, in order, into its sink.
  if (last || sink_ || batch_.size() >= kBatchBytes) inflatePending();
  if (last)
    state_ = State::Done;
  else
    startBlock();
}

void VtkXmlPayload::inflatePending() {
  std::vector<std::string> errors(pending_.size());
  const auto body = [&](std::size_t begin, std::size_t end) {
    std::vector<std::uint8_t> scratch;
    for (std::size_t i = begin; i < end; ++i) {
      const Pending& p = pending_[i];
      try {
        errors[i] = inflateBlock(p.block, batch_.data() + p.offset, p.size, scratch, sink_);
      } catch (const std::exception& e) {  // out of memory on a worker thread
        errors[i] = concat("compressed block ", p.block + 1, ": ", e.what());
      }
    }
  };
  if (sink_ || pending_.size() == 1)
    body(0, pending_.size());
  else
    forChunks(pending_.size(), body, 1);
  for (const std::string& e : errors)
    if (!e.empty()) fail(e);
  pending_.clear();
  batch_.clear();
}

std::string VtkXmlPayload::inflateBlock(std::uint64_t b, const std::uint8_t* bytes,
                                        std::uint64_t in, std::vector<std::uint8_t>& scratch,
                                        std::vector<std::uint8_t>* sink) const {
  const std::uint64_t expected = blockOutput(b);
  const std::string which = concat("compressed block ", b + 1, " of ", blocks_);
  std::uint64_t out = 0;
  switch (format_.compressor) {
    case VtkCompressor::ZLib: {
      if (expected > in * kZlibRatio)
        return concat(which, ": ", in, " zlib bytes cannot give ", expected);
      z_stream z{};
      if (inflateInit(&z) != Z_OK) return "zlib cannot start";
      scratch.resize(kScratch);
      z.next_in = const_cast<std::uint8_t*>(bytes);
      z.avail_in = uInt(in);
      int status = Z_OK;
      while (status == Z_OK && out <= expected) {
        z.next_out = scratch.data();
        z.avail_out = uInt(scratch.size());
        status = inflate(&z, Z_NO_FLUSH);
        if (sink) sink->insert(sink->end(), scratch.data(), z.next_out);
        out += scratch.size() - z.avail_out;
        if (status == Z_BUF_ERROR && z.avail_in == 0) break;  // the stream stops short
      }
      const std::string message = z.msg ? z.msg : "";
      inflateEnd(&z);
      if (status != Z_STREAM_END && out <= expected)
        return concat(which, " is not a whole zlib stream",
                      message.empty() ? std::string() : " (" + message + ")");
      break;
    }
    case VtkCompressor::LZ4: {
      if (expected > in * kLz4Ratio + 64)
        return concat(which, ": ", in, " LZ4 bytes cannot give ", expected);
      if (in > 0x7fffffff || expected > 0x7fffffff)
        return concat(which, ": an LZ4 block holds at most 2 GiB");
      scratch.resize(std::size_t(expected));
      const int n =
          LZ4_decompress_safe(reinterpret_cast<const char*>(bytes),
                              reinterpret_cast<char*>(scratch.data()), int(in), int(expected));
      if (n < 0) return concat(which, " is not a valid LZ4 block");
      if (sink) sink->insert(sink->end(), scratch.data(), scratch.data() + n);
      out = std::uint64_t(n);
      break;
    }
    case VtkCompressor::LZMA: {
      lzma_stream z = LZMA_STREAM_INIT;
      if (lzma_auto_decoder(&z, kLzmaMemory, 0) != LZMA_OK) return "LZMA cannot start";
      scratch.resize(kScratch);
      z.next_in = bytes;
      z.avail_in = std::size_t(in);
      lzma_ret status = LZMA_OK;
      while (status == LZMA_OK && out <= expected) {
        z.next_out = scratch.data();
        z.avail_out = scratch.size();
        status = lzma_code(&z, z.avail_in == 0 ? LZMA_FINISH : LZMA_RUN);
        if (sink) sink->insert(sink->end(), scratch.data(), z.next_out);
        out += scratch.size() - z.avail_out;
      }
      lzma_end(&z);
      if (status == LZMA_MEMLIMIT_ERROR)
        return concat(which, " needs an LZMA dictionary above ", kLzmaMemory, " bytes");
      if (status != LZMA_STREAM_END && out <= expected)
        return concat(which, " is not a whole LZMA stream (liblzma error ", int(status), ")");
      break;
    }
    case VtkCompressor::None:
      break;
  }
  if (out != expected)
    return concat(which, " decompresses to ", out > expected ? "more than " : "", out,
                  " bytes; the header says ", expected);
  return {};
}

}  // namespace sandstorm
