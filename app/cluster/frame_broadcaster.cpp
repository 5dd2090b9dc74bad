#include "app/cluster/frame_broadcaster.h"

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstring>
#include <thread>
#include <tuple>

#include "core/color/color_grid.h"
#include "core/sim/frame_packet_codec.h"
#include "core/util/byte_reader.h"
#include "core/util/byte_writer.h"
#include "core/util/error.h"
#include "core/util/hash.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

constexpr std::uint32_t kSlotMagic = 0x4d535353;  // "SSSM"
// magic, kind + 3 spare, sequence, length (u64), checksum (FNV-1a 64 of the payload)
constexpr std::size_t kHeaderBytes = 28;
constexpr std::size_t kInline = FrameBroadcaster::kSlotBytes - kHeaderBytes;

// A series step's key in the FieldStores: its index and file, as every rank
// names it, so that no rank hashes the step's bytes. Never 0 (no grid).
std::uint64_t stepKey(std::uint32_t step, const FileIdentity& file) {
  ByteWriter w;
  w.u32(0x53544550);  // "STEP": apart from content hashes
  w.u32(step);
  w.boolean(file.present);
  w.u64(file.size);
  w.u64(std::uint64_t(file.modified));
  return fnv1a64(w.bytes()) | 1u;
}

std::string stepName(std::uint32_t step, const FieldSteps& steps) {
  return concat("step ", step, " (", steps.name(step), ")");
}

}  // namespace

FrameBroadcaster::FrameBroadcaster(MpiSession& mpi, std::size_t chunkBytes, std::size_t fieldCache)
    : mpi_(mpi),
      chunkBytes_(std::clamp<std::size_t>(chunkBytes, 1024, INT_MAX)),
      store_(fieldCache) {}

void FrameBroadcaster::readSeries(std::shared_ptr<FieldSteps> steps, MPI_Comm blind,
                                  bool uploadAhead) {
  series_ = true;
  steps_ = std::move(steps);
  blind_ = blind;
  uploadAhead_ = uploadAhead;
}

void FrameBroadcaster::announceSteps(std::shared_ptr<FieldSteps> steps, std::size_t known) {
  announcing_ = std::move(steps);
  announced_ = known;
}

void FrameBroadcaster::post(Kind kind, std::span<const std::byte> payload, bool perFrame,
                            MPI_Comm comm) {
  std::uint32_t& sequence = comm == MPI_COMM_WORLD ? sequence_ : blindSequence_;
  ByteWriter slot;
  slot.u32(kSlotMagic);
  slot.u8(std::uint8_t(kind));
  slot.u8(0);
  slot.u16(0);
  slot.u32(sequence++);
  slot.u64(payload.size());
  slot.u64(fnv1a64(payload));
  const std::size_t inlined = std::min(payload.size(), kInline);
  slot.raw(payload.first(inlined));
  std::vector<std::byte> bytes = slot.take();
  bytes.resize(kSlotBytes);
  if (kind == Kind::Packet && int(nextFrame_) == corruptFrame_ && !payload.empty())
    bytes[kHeaderBytes] ^= std::byte{0x5a};  // --debug-corrupt-at-frame
  const std::string what = kind == Kind::Packet
                               ? concat("every rank to take the packet of frame ", nextFrame_)
                               : concat("every rank to take a message before frame ", nextFrame_);
  double seconds = 0.0;
  std::uint64_t moved = kSlotBytes;
  MPI_Request request;
  MPI_Ibcast(bytes.data(), int(kSlotBytes), MPI_BYTE, 0, comm, &request);
  seconds += mpi_.wait(request, what);
  for (std::size_t at = inlined; at < payload.size(); at += chunkBytes_) {
    const std::size_t n = std::min(chunkBytes_, payload.size() - at);
    // MPI reads the root's buffer only; the cast is MPI's C signature.
    MPI_Ibcast(const_cast<std::byte*>(payload.data() + at), int(n), MPI_BYTE, 0, comm, &request);
    seconds += mpi_.wait(request, what);
    moved += n;
  }
  if (perFrame) {
    stats_.broadcastBytes += moved;
    stats_.broadcastSeconds += seconds;
    stats_.maxBroadcastSeconds = std::max(stats_.maxBroadcastSeconds, seconds);
  } else if (kind == Kind::Grid) {
    ++stats_.grids;
    stats_.gridBytes += moved;
    stats_.gridSeconds += seconds;
  }
}

FrameBroadcaster::Message FrameBroadcaster::take(const std::string& what, bool perFrame,
                                                 MPI_Comm comm) {
  std::uint32_t& expected = comm == MPI_COMM_WORLD ? sequence_ : blindSequence_;
  std::vector<std::byte> slot(kSlotBytes);
  MPI_Request request;
  MPI_Ibcast(slot.data(), int(kSlotBytes), MPI_BYTE, 0, comm, &request);
  double seconds = mpi_.wait(request, what);
  ByteReader header(slot, concat("rank ", mpi_.rank(), ": message from rank 0"));
  if (header.u32("magic") != kSlotMagic) header.fail("magic", "not a Sandstorm cluster message");
  const std::uint8_t kind = header.u8("kind");
  if (kind < 1 || kind > 6) header.fail("kind", concat("unknown message kind ", int(kind)));
  header.raw(3, "spare");
  const std::uint32_t sequence = header.u32("sequence");
  if (sequence != expected)
    header.fail("sequence",
                concat("message ", sequence, " arrived where ", expected, " was expected"));
  ++expected;
  const std::uint64_t length = header.u64("length");
  if (length > (std::uint64_t{1} << 36))
    header.fail("length", concat(length, " bytes is beyond any packet or grid"));
  const std::uint64_t checksum = header.u64("checksum");
  Message m{Kind(kind), std::vector<std::byte>(std::size_t(length))};
  const std::size_t inlined = std::min<std::size_t>(m.payload.size(), kInline);
  std::copy_n(slot.begin() + kHeaderBytes, inlined, m.payload.begin());
  std::uint64_t moved = kSlotBytes;
  for (std::size_t at = inlined; at < m.payload.size(); at += chunkBytes_) {
    const std::size_t n = std::min(chunkBytes_, m.payload.size() - at);
    MPI_Ibcast(m.payload.data() + at, int(n), MPI_BYTE, 0, comm, &request);
    seconds += mpi_.wait(request, what);
    moved += n;
  }
  const std::uint64_t got = fnv1a64(m.payload);
  if (got != checksum)
    throw Error(concat("rank ", mpi_.rank(), ": ", what, " arrived damaged (", m.payload.size(),
                       " bytes, checksum ", std::hex, got, " where rank 0 sent ", checksum,
                       "); stopping every rank rather than drawing different frames"));
  if (perFrame && m.kind == Kind::Packet) {
    stats_.broadcastBytes += moved;
    stats_.broadcastSeconds += seconds;
    stats_.maxBroadcastSeconds = std::max(stats_.maxBroadcastSeconds, seconds);
  } else if (m.kind == Kind::Grid || m.kind == Kind::Sparse) {
    ++stats_.grids;
    stats_.gridBytes += moved;
    stats_.gridSeconds += seconds;
  }
  return m;
}

void FrameBroadcaster::send(const FramePacket& packet) {
  FieldRefs refs;
  // Series steps for the ranks that cannot see the files: sent after the packet.
  std::vector<std::pair<std::uint64_t, std::shared_ptr<const VectorField>>> afterPacket;
  if (packet.fieldUpdate) {
    const std::optional<FieldSeriesRef>& series = packet.fieldUpdate->series;
    const bool bySteps = series_ && series.has_value();
    // A watched folder's steps that joined since: every reading rank's reader takes their files.
    for (; bySteps && announcing_ && announced_ < series->steps; ++announced_) {
      ByteWriter w;
      w.u32(std::uint32_t(announced_));
      w.str(announcing_->name(announced_));
      post(Kind::StepFile, w.bytes(), false);
    }
    refs.field = bySteps ? stepKey(series->first, series->firstFile)
                         : store_.identify(packet.fieldUpdate->field);
    refs.next = bySteps ? stepKey(series->second, series->secondFile)
                        : store_.identify(packet.fieldUpdate->next);
    FieldStore::Grids incoming;
    for (const auto& [hash, grid] : {std::pair{refs.field, packet.fieldUpdate->field},
                                     std::pair{refs.next, packet.fieldUpdate->next}}) {
      if (hash == 0 || store_.contains(hash) || incoming.count(hash)) continue;
      incoming[hash] = grid;
      if (bySteps) {
        if (blind_ != MPI_COMM_NULL) afterPacket.emplace_back(hash, grid);
        continue;
      }
      // The hash leads, so a receiver can check the grid that follows.
      ByteWriter w;
      w.u64(hash);
      w.raw(encodeField(*grid));
      post(Kind::Grid, w.bytes(), false);
    }
    const std::uint64_t used[2] = {refs.field, refs.next};
    store_.use(used, incoming);  // as every receiver will
    if (const auto& sparse = packet.fieldUpdate->sparse) {
      // The grid sent last is known by its hash: gigabytes are not hashed again.
      refs.sparse = sparse == sparse_ ? sparseHash_ : sparseHash(*sparse);
      if (refs.sparse != sparseHash_) {
        ByteWriter w;
        w.u64(refs.sparse);
        w.raw(std::as_bytes(sparse->words()));
        post(Kind::Sparse, w.bytes(), false);
        sparseHash_ = refs.sparse;
        sparse_ = sparse;
      }
    }
  }
  const std::vector<std::byte> bytes = encodePacket(packet, refs);
  post(Kind::Packet, bytes, true);
  for (const auto& [key, grid] : afterPacket) {
    ByteWriter w;
    w.u64(key);
    w.raw(encodeField(*grid));
    post(Kind::Grid, w.bytes(), false, blind_);
  }
  ++stats_.packets;
  stats_.packetBytes += bytes.size();
  stats_.maxPacketBytes = std::max<std::uint64_t>(stats_.maxPacketBytes, bytes.size());
  nextFrame_ = packet.frame + 1;
}

std::shared_ptr<const VectorField> FrameBroadcaster::seriesStep(std::uint32_t frame,
                                                                std::uint32_t step,
                                                                const FileIdentity& file,
                                                                std::uint64_t key) {
  if (!steps_) {
    // This rank cannot see the files: rank 0 sends the step after the packet.
    Message m = take(concat("step ", step, " of the series for frame ", frame, " from rank 0"),
                     false, blind_);
    ByteReader r(m.payload, "series step");  // take() checked the payload's checksum
    if (m.kind != Kind::Grid || r.u64("key") != key)
      throw Error(concat("rank ", mpi_.rank(), ": another message arrived where step ", step,
                         " of the series was expected"));
    return std::make_shared<const VectorField>(
        decodeField(r.raw(r.remaining(), "grid"), concat("series step ", step)));
  }
  const FileIdentity mine = steps_->identity(step);
  if (mine != file)
    throw Error(concat("rank ", mpi_.rank(), " (", mpi_.host(), "): ", stepName(step, *steps_),
                       " is ", mine.text(), " here but was ", file.text(),
                       " when rank 0 opened it; every rank must see the same files "
                       "(cluster.steps = \"broadcast\" sends them from rank 0)"));
  // Read by this rank's reader threads, which were asked for it (want); a
  // disk that stalls beyond cluster.timeout_s stops every rank, as a rank
  // that stops drawing does.
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  for (;;) {
    if (auto grid = steps_->get(step)) {
      ++stats_.stepsRead;
      stats_.stepSeconds += std::chrono::duration<double>(Clock::now() - start).count();
      return grid;
    }
    if (const std::string failure = steps_->failure(step); !failure.empty())
      throw Error(concat("rank ", mpi_.rank(), " (", mpi_.host(), ") could not read ",
                         stepName(step, *steps_), ", which rank 0 read: ", failure));
    if (std::chrono::duration<double>(Clock::now() - start).count() > mpi_.timeout())
      throw Error(concat("rank ", mpi_.rank(), " (", mpi_.host(), "): ", stepName(step, *steps_),
                         " was not read within ", mpi_.timeout(), " s (cluster.timeout_s)"));
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

void FrameBroadcaster::sendStop() {
  post(Kind::Stop, {}, false);  // not a frame: kept out of the per-frame figures
}

std::shared_ptr<const FramePacket> FrameBroadcaster::receive() {
  try {
    for (;;) {
      Message m = take(concat("the packet of frame ", nextFrame_, " from rank 0"), true);
      switch (m.kind) {
        case Kind::Stop:
          return nullptr;
        case Kind::Hashes:
          throw Error("a list of field hashes arrived where a packet was expected");
        case Kind::Grid: {
          ByteReader r(m.payload, "field grid");
          const std::uint64_t expected = r.u64("hash");
          const std::span<const std::byte> encoded = r.raw(r.remaining(), "grid");
          const std::uint64_t got = fnv1a64(encoded);
          if (got != expected)
            throw Error(concat("a field grid arrived damaged: hash ", std::hex, got,
                               ", rank 0 sent ", expected));
          incoming_[expected] = std::make_shared<const VectorField>(decodeField(encoded));
          log::debug("rank ", mpi_.rank(), ": field grid ", std::hex, expected, std::dec,
                     " arrived (", encoded.size(), " bytes)");
          continue;
        }
        case Kind::StepFile: {
          ByteReader r(m.payload, "watched step");  // take() checked the payload's checksum
          const std::uint32_t step = r.u32("step");
          const std::string file = r.str("file", 1 << 16);
          if (!steps_) continue;  // this rank gets the steps from rank 0
          if (step != steps_->size())
            throw Error(concat("rank ", mpi_.rank(), ": rank 0 announced step ", step,
                               " of its watched folder where step ", steps_->size(),
                               " was expected"));
          steps_->appendFile(file);
          continue;
        }
        case Kind::Sparse: {
          ByteReader r(m.payload, "sparse field grid");
          const std::uint64_t expected = r.u64("hash");
          const std::span<const std::byte> bytes = r.raw(r.remaining(), "words");
          const std::uint64_t got = fnv1a64(bytes);
          if (got != expected || bytes.size() % 4 != 0)
            throw Error(concat("a sparse field grid arrived damaged: hash ", std::hex, got,
                               ", rank 0 sent ", expected));
          std::vector<std::uint32_t> words(bytes.size() / 4);
          std::memcpy(words.data(), bytes.data(), bytes.size());
          sparse_ = std::make_shared<const SparseField>(std::move(words), "rank 0's sparse grid");
          sparseHash_ = expected;
          log::debug("rank ", mpi_.rank(), ": sparse field grid ", std::hex, expected, std::dec,
                     " arrived (", bytes.size(), " bytes)");
          continue;
        }
        case Kind::Packet: {
          FieldRefs refs;
          auto packet = std::make_shared<FramePacket>(decodePacket(m.payload, &refs));
          if (packet->fieldUpdate) {
            if (const std::optional<FieldSeriesRef>& s = packet->fieldUpdate->series;
                series_ && s) {
              // Read ahead as rank 0's playback does, then take the pair.
              if (steps_)
                steps_->want(FieldTimeline::aheadOrder(s->steps, steps_->capacity(),
                                                       {s->first, s->second, 0.0f}, s->backwards,
                                                       s->loop));
              for (const auto& [key, step, file] :
                   {std::tuple{refs.field, s->first, s->firstFile},
                    std::tuple{refs.next, s->second, s->secondFile}})
                if (key != 0 && !store_.contains(key) && !incoming_.count(key))
                  incoming_[key] = seriesStep(packet->frame, step, file, key);
              playing_ = s;
            } else {
              playing_.reset();
            }
            const std::uint64_t used[2] = {refs.field, refs.next};
            store_.use(used, incoming_);
            FieldUpdate update{.field = store_.find(refs.field),
                               .placement = packet->fieldUpdate->placement,
                               .next = store_.find(refs.next),
                               .series = packet->fieldUpdate->series,
                               .equation = packet->fieldUpdate->equation,
                               .range = packet->fieldUpdate->range};
            if (refs.sparse != 0) {
              if (refs.sparse != sparseHash_)
                throw Error(concat("the packet of frame ", packet->frame, " names sparse grid ",
                                   std::hex, refs.sparse, ", which did not arrive"));
              update.sparse = sparse_;
            }
            if (refs.colorGrid && update.field) {
              update.colorGrid = makeColorGrid(*update.field, *refs.colorGrid);
              if (update.next) update.nextColorGrid = makeColorGrid(*update.next, *refs.colorGrid);
              update.colorArray = *refs.colorGrid;
            }
            packet->fieldUpdate = std::make_shared<const FieldUpdate>(std::move(update));
          }
          incoming_.clear();
          // The step after the pair, if this rank's reader has it: its walls
          // upload it ahead of need (a hint, as on rank 0; it does not travel).
          if (steps_ && uploadAhead_ && playing_)
            if (const auto i = FieldTimeline::upcomingIndex(
                    playing_->steps, {playing_->first, playing_->second, 0.0f}, playing_->backwards,
                    playing_->loop))
              packet->upcomingField = steps_->get(*i);
          if (packet->frame != nextFrame_)
            throw Error(concat("the packet of frame ", packet->frame, " arrived where frame ",
                               nextFrame_, " was expected"));
          nextFrame_ = packet->frame + 1;
          ++stats_.packets;
          stats_.packetBytes += m.payload.size();
          stats_.maxPacketBytes = std::max<std::uint64_t>(stats_.maxPacketBytes, m.payload.size());
          return packet;
        }
      }
    }
  } catch (const Error& e) {
    // Walls are running: unwinding would leave them waiting. Stop every rank instead.
    mpi_.abort(e.what());
  }
}

bool FrameBroadcaster::pinLocal(const std::vector<std::shared_ptr<const VectorField>>& grids) {
  std::vector<std::uint64_t> mine;
  for (const auto& grid : grids)
    mine.push_back(store_.identify(grid));
  std::vector<std::uint64_t> theirs = mine;
  if (mpi_.rank() == 0) {
    ByteWriter w;
    w.u32(std::uint32_t(mine.size()));
    for (const std::uint64_t h : mine)
      w.u64(h);
    post(Kind::Hashes, w.bytes(), false);
  } else {
    try {
      const Message m = take("rank 0's field hashes", false);
      if (m.kind != Kind::Hashes) throw Error("a message other than the field hashes arrived");
      ByteReader r(m.payload, "field hashes");
      theirs.assign(r.u32("count"), 0);
      if (theirs.size() > 1u << 20) r.fail("count", "too many grids");
      for (std::uint64_t& h : theirs)
        h = r.u64("hash");
      r.finish();
    } catch (const Error& e) {
      mpi_.abort(e.what());
    }
  }
  const int same = theirs == mine ? 1 : 0;
  if (!same)
    log::warn("rank ", mpi_.rank(), " (", mpi_.host(), "): the field it read (", mine.size(),
              " grid(s)) differs from rank 0's (", theirs.size(), "); rank 0 will send its own");
  int all = 0;
  MPI_Request request;
  MPI_Iallreduce(&same, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD, &request);
  mpi_.wait(request, "every rank to compare the field it read");
  if (all)
    for (std::size_t i = 0; i < grids.size(); ++i)
      store_.pin(mine[i], grids[i]);
  else if (mpi_.rank() == 0)
    log::warn(
        "cluster: not every rank read the same field as rank 0; rank 0 broadcasts it instead");
  return all != 0;
}

}  // namespace sandstorm
