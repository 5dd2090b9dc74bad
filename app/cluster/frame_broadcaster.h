// FrameBroadcaster: rank 0's frame packets, and the field grids they refer to,
// to every rank, over non-blocking MPI broadcasts (MpiSession::wait bounds
// every one). The bytes are the one wire format of core/sim/frame_packet_codec.h.
//
// Every message is one fixed-size slot (a header: kind, sequence number,
// length; then the first bytes of the payload), so a frame costs one
// broadcast; a longer payload (a field grid) follows in chunks of `chunkBytes`.
// A grid travels once per change: rank 0 and every rank keep FieldStores that
// agree, so a packet carries only the grids' hashes; every rank checks each
// grid it receives against its hash. A sparse grid (FieldUpdate::sparse)
// travels as its NanoVDB words when it changes, checked the same way.
//
// A streamed series (readSeries, cluster.steps = "read"): a grid that a packet
// names by its series step (FieldUpdate::series) is not sent. A rank that sees
// the series' files takes the step from its own reader, after checking that
// the file is the one rank 0 opened (size and modification time), and reads
// ahead as rank 0's playback does; a rank that cannot see them receives the
// grid after the packet, over a communicator of rank 0 and such ranks only.
// Stores are keyed by step and file then, so nobody hashes a step's bytes.
// A watched folder is such a series that grows: each step that joins rank
// 0's is announced, by its file, before the packet that first counts it, and
// every reading rank appends that file to its own reader (announceSteps).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/cluster/mpi_session.h"
#include "core/field/field_timeline.h"
#include "core/sim/field_store.h"
#include "core/sim/frame_packet.h"

namespace sandstorm {

class FrameBroadcaster {
 public:
  static constexpr std::size_t kSlotBytes = 512;

  struct Stats {
    std::uint64_t packets = 0;
    std::uint64_t packetBytes = 0;  // encoded packets (the codec's bytes)
    std::uint64_t maxPacketBytes = 0;
    std::uint64_t broadcastBytes = 0;  // what the per-frame broadcasts moved (slots and overflow)
    double broadcastSeconds = 0.0;     // waiting for per-frame broadcasts
    double maxBroadcastSeconds = 0.0;
    std::uint64_t grids = 0;  // field grids sent or received
    std::uint64_t gridBytes = 0;
    double gridSeconds = 0.0;
    std::uint64_t stepsRead = 0;  // series steps this rank took from its own reader
    double stepSeconds = 0.0;     // waiting for them
  };

  FrameBroadcaster(MpiSession& mpi, std::size_t chunkBytes, std::size_t fieldCache);

  // Rank 0: ships the grids the ranks lack, then the packet.
  void send(const FramePacket& packet);
  // Rank 0: tells every rank that no packet follows.
  void sendStop();
  // The other ranks: the next packet, its field grids attached; null when rank 0 stopped.
  std::shared_ptr<const FramePacket> receive();

  // Every rank, with the grids it read itself (cluster.field = "read"): when
  // every rank's hashes equal rank 0's, the grids are kept for good and never
  // travel; otherwise rank 0 sends its own. Returns whether they agreed.
  bool pinLocal(const std::vector<std::shared_ptr<const VectorField>>& grids);

  // Every rank, before the first frame, when rank 0's field is a streamed
  // series and cluster.steps = "read". `steps`: this rank's own reader of the
  // series (null on rank 0 and on ranks that cannot see its files). `blind`:
  // rank 0 and the ranks that cannot see them (MPI_COMM_NULL when there are
  // none, and on the other ranks).
  // `uploadAhead` (field.upload_ahead): packets to this rank's walls carry the
  // step after the pair from its own reader, as rank 0's own walls get it.
  void readSeries(std::shared_ptr<FieldSteps> steps, MPI_Comm blind, bool uploadAhead);
  // Rank 0, after readSeries, when the series is a watched folder's: the
  // steps after the first `known` are announced by file as they join `steps`.
  void announceSteps(std::shared_ptr<FieldSteps> steps, std::size_t known);

  const Stats& stats() const { return stats_; }
  // Fault injection for the tests: rank 0 damages the packet of `frame` after checksumming it.
  void corruptAt(int frame) { corruptFrame_ = frame; }

 private:
  enum class Kind : std::uint8_t {
    Packet = 1,
    Grid = 2,
    Stop = 3,
    Hashes = 4,
    Sparse = 5,
    StepFile = 6  // a watched folder's new step: its index and file
  };
  struct Message {
    Kind kind;
    std::vector<std::byte> payload;
  };

  void post(Kind kind, std::span<const std::byte> payload, bool perFrame,
            MPI_Comm comm = MPI_COMM_WORLD);
  Message take(const std::string& what, bool perFrame, MPI_Comm comm = MPI_COMM_WORLD);
  // A series step's grid on a receiving rank: from its own reader, or from rank 0 over blind_.
  std::shared_ptr<const VectorField> seriesStep(std::uint32_t frame, std::uint32_t step,
                                                const FileIdentity& file, std::uint64_t key);
  int corruptFrame_ = -1;

  MpiSession& mpi_;
  std::size_t chunkBytes_;
  FieldStore store_;
  FieldStore::Grids incoming_;  // grids that arrived for the next packet
  // The sparse grid (FieldUpdate::sparse) last sent or received, by its
  // sparseHash: a steady grid travels once.
  std::uint64_t sparseHash_ = 0;
  std::shared_ptr<const SparseField> sparse_;
  std::uint32_t sequence_ = 0;
  bool series_ = false;                // readSeries was called
  std::shared_ptr<FieldSteps> steps_;  // this rank's own reader of the series
  bool uploadAhead_ = false;
  std::optional<FieldSeriesRef> playing_;   // the pair the last series packet named
  std::shared_ptr<FieldSteps> announcing_;  // rank 0: a watched folder's steps
  std::size_t announced_ = 0;               // of them, those the ranks know
  MPI_Comm blind_ = MPI_COMM_NULL;
  std::uint32_t blindSequence_ = 0;  // messages on blind_
  std::uint32_t nextFrame_ = 0;      // for messages: the frame expected next
  Stats stats_;
};

}  // namespace sandstorm
