// MpiCluster: cluster mode on MPI (ClusterLink). Rank 0 is the main context;
// every rank drives the walls whose `rank` (or `host`) names it.
//
// Start-up (start(), before App::run): rank 0 broadcasts its configuration
// fingerprint; every rank gathers every rank's host, fingerprint verdict and
// set-up error; walls assigned to ranks that do not exist are errors. All of
// it is decided identically on every rank, so all stop together, and rank 0
// reports. Frames: FrameBroadcaster for packets and grids, WallGate plus an
// MPI_Iallreduce for the swap barrier. Every MPI call stays on the main
// thread; every wait is bounded (MpiSession::wait).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cluster/cluster_link.h"
#include "app/cluster/frame_broadcaster.h"
#include "app/cluster/mpi_session.h"
#include "app/cluster/wall_gate.h"

namespace sandstorm {

class MpiCluster final : public ClusterLink {
 public:
  MpiCluster(MpiSession& mpi, ClusterOptions options);

  // Collective: false when any rank failed to set up, read another
  // configuration, or a wall names a rank or host that is not there (rank 0
  // has said which). `config` is null where loading failed (`error` says why).
  bool start(const AppConfig* config, const std::string& fingerprint, const std::string& error);
  // An error escaped App::run: before ready() every rank hears of it and all
  // stop cleanly; later, the job is aborted.
  void fail(const std::string& error);

  bool root() const override { return mpi_.rank() == 0; }
  int rank() const override { return mpi_.rank(); }
  void localize(AppConfig& config, AppOptions& options) override;
  bool makesField() const override { return root() || readField_; }
  bool ready(const std::string& error) override;
  void shareField(const FieldSource& field) override;
  void watchInterrupt(const std::atomic<bool>* flag) override { mpi_.watchInterrupt(flag); }
  void send(const FramePacket& packet) override;
  void sendStop() override;
  std::shared_ptr<const FramePacket> receive() override;
  void drawn(int wall, std::uint32_t frame) override;
  Verdict swap(std::uint32_t frame, int stop, const std::function<bool()>& wallFailed) override;
  void finish() override;

 private:
  // Every rank's record; returns them all (the same on every rank).
  std::vector<std::string> gather(const std::string& record, const std::string& what);
  // cluster.steps = "read" with a streamed series on rank 0: which ranks read
  // its steps themselves; the others get them over MPI (FrameBroadcaster::readSeries).
  void shareSeries(const FieldSource& field);
  void misbehave(std::uint32_t frame);

  MpiSession& mpi_;
  ClusterOptions options_;
  std::vector<int> owner_;  // per configured wall: the rank that drives it
  bool readField_ = false;
  bool readSteps_ = true;
  FieldSpec fieldSpec_;  // to open the series on ranks that did not load the field
  std::filesystem::path configFolder_;
  double frameTimeout_ = 10.0;     // cluster.timeout_s, from the first frame on
  double startupTimeout_ = 120.0;  // cluster.startup_timeout_s, until frame 0 was drawn everywhere
  bool ready_ = false;
  bool finished_ = false;
  std::unique_ptr<FrameBroadcaster> broadcaster_;
  std::unique_ptr<WallGate> gate_;
  std::uint64_t swaps_ = 0;
  double swapSeconds_ = 0.0, maxSwapSeconds_ = 0.0, drawWaitSeconds_ = 0.0;
};

}  // namespace sandstorm
