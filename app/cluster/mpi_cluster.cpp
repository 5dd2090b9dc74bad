#include "app/cluster/mpi_cluster.h"

#include <algorithm>
#include <csignal>
#include <numeric>

#include "app/app.h"
#include "app/cluster/config_fingerprint.h"
#include "app/scene_setup.h"
#include "core/util/byte_reader.h"
#include "core/util/byte_writer.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

using Clock = std::chrono::steady_clock;

struct Hello {
  bool ok = true;
  std::string host;
  std::string message;
};

std::string encodeHello(const Hello& h) {
  ByteWriter w;
  w.boolean(h.ok);
  w.str(h.host);
  w.str(h.message);
  const std::vector<std::byte>& b = w.bytes();
  return std::string(reinterpret_cast<const char*>(b.data()), b.size());
}

Hello decodeHello(const std::string& s, int rank) {
  ByteReader r(std::as_bytes(std::span<const char>(s.data(), s.size())),
               concat("rank ", rank, "'s start-up record"));
  Hello h;
  h.ok = r.boolean("ok");
  h.host = r.str("host", 4096);
  h.message = r.str("message", 1 << 20);
  r.finish();
  return h;
}

// "out/hash.txt" on rank 2: "out/hash.rank2.txt"; "{rank}" in the name is replaced instead.
std::filesystem::path perRank(const std::filesystem::path& path, int rank) {
  std::string name = path.filename().string();
  if (const std::size_t at = name.find("{rank}"); at != std::string::npos)
    return path.parent_path() / name.replace(at, 6, std::to_string(rank));
  return path.parent_path() /
         concat(path.stem().string(), ".rank", rank, path.extension().string());
}

std::string ms(double seconds) {
  return concat(std::round(seconds * 1e6) / 1e3, " ms");
}

}  // namespace

MpiCluster::MpiCluster(MpiSession& mpi, ClusterOptions options) : mpi_(mpi), options_(options) {
  if (options_.debugRank < 0) options_.debugRank = mpi_.size() - 1;
}

std::vector<std::string> MpiCluster::gather(const std::string& record, const std::string& what) {
  const int size = mpi_.size();
  const int length = int(record.size());
  std::vector<int> lengths(std::size_t(size), 0);
  MPI_Request request;
  MPI_Iallgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD, &request);
  mpi_.wait(request, what);
  std::vector<int> offsets(std::size_t(size), 0);
  std::exclusive_scan(lengths.begin(), lengths.end(), offsets.begin(), 0);
  std::string all(std::size_t(offsets.back() + lengths.back()), '\0');
  MPI_Iallgatherv(record.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                  MPI_CHAR, MPI_COMM_WORLD, &request);
  mpi_.wait(request, what);
  std::vector<std::string> out;
  for (int r = 0; r < size; ++r)
    out.push_back(
        all.substr(std::size_t(offsets[std::size_t(r)]), std::size_t(lengths[std::size_t(r)])));
  return out;
}

bool MpiCluster::start(const AppConfig* config, const std::string& fingerprint,
                       const std::string& error) {
  if (config) mpi_.setTimeout(config->cluster.startupTimeoutSeconds);
  // Rank 0's fingerprint, so a rank with another configuration can say where it differs.
  std::uint64_t length = fingerprint.size();
  MPI_Request request;
  MPI_Ibcast(&length, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD, &request);
  mpi_.wait(request, "rank 0's configuration");
  std::string reference = root() ? fingerprint : std::string(std::size_t(length), '\0');
  MPI_Ibcast(reference.data(), int(length), MPI_CHAR, 0, MPI_COMM_WORLD, &request);
  mpi_.wait(request, "rank 0's configuration");

  Hello mine{error.empty(), mpi_.host(), error};
  if (mine.ok && !root() && fingerprint != reference && !reference.empty())
    mine = {false, mpi_.host(),
            concat("its configuration differs from rank 0's (every rank must read the same file "
                   "with the same "
                   "options); first difference, here | rank 0: ",
                   firstDifference(fingerprint, reference))};
  std::vector<Hello> hellos;
  const std::vector<std::string> records =
      gather(encodeHello(mine), "every rank to load the configuration");
  for (std::size_t r = 0; r < records.size(); ++r)
    hellos.push_back(decodeHello(records[r], int(r)));

  // From here on every rank decides alike, from the same records.
  bool ok = true;
  for (std::size_t r = 0; r < hellos.size(); ++r) {
    if (hellos[r].ok) continue;
    ok = false;
    // Rank 0's own failure is the news; the others' differences from its (empty) configuration are
    // not.
    if (root() && (r == 0 || hellos[0].ok))
      log::error("rank ", r, " (", hellos[r].host, "): ", hellos[r].message);
  }
  if (!ok) return false;

  const int size = mpi_.size();
  owner_.clear();
  std::vector<std::string> problems;
  for (const WallSpec& w : config->walls) {
    // Name the [cluster] entry that placed the wall, if one did (the wall may come from an
    // include).
    std::string where = concat(config->path.string(), ": wall '", w.name, "'");
    for (const ClusterSpec::Placement& p : config->cluster.placements)
      if (p.wall == w.name && (p.rank || !p.host.empty()))
        where = concat(p.where, " (wall '", w.name, "')");
    int owner = w.rank;
    if (config->cluster.roundRobin) {
      owner = int(owner_.size()) % size;
    } else if (!w.host.empty()) {
      const auto it = std::find_if(hellos.begin(), hellos.end(),
                                   [&](const Hello& h) { return h.host == w.host; });
      if (it == hellos.end()) {
        std::string hosts;
        for (int r = 0; r < size; ++r)
          hosts += concat(r ? ", " : "", r, "=", hellos[std::size_t(r)].host);
        problems.push_back(
            concat(where, ": host '", w.host, "' runs no rank; the ranks run on ", hosts));
        continue;
      }
      owner = int(it - hellos.begin());
    } else if (w.rank >= size) {
      problems.push_back(concat(where, ": rank ", w.rank, " does not exist; mpirun started ", size,
                                " rank", size == 1 ? "" : "s", " (0..", size - 1,
                                "): start more with -np, or change the wall's rank"));
      continue;
    }
    owner_.push_back(owner);
  }
  if (!problems.empty()) {
    if (root())
      for (const std::string& p : problems)
        log::error(p);
    return false;
  }

  readField_ = config->cluster.readField;
  readSteps_ = config->cluster.readSteps;
  fieldSpec_ = config->field;
  configFolder_ = config->folder;
  frameTimeout_ = config->cluster.timeoutSeconds;
  startupTimeout_ = config->cluster.startupTimeoutSeconds;
  broadcaster_ = std::make_unique<FrameBroadcaster>(
      mpi_, std::size_t(config->cluster.chunkKiB) * 1024, std::size_t(config->cluster.fieldCache));
  if (root()) broadcaster_->corruptAt(options_.corruptAtFrame);
  if (root()) {
    std::string plan;
    for (std::size_t i = 0; i < owner_.size(); ++i)
      plan += concat(i ? ", " : "", config->walls[i].name, " on ", owner_[i], " (",
                     hellos[std::size_t(owner_[i])].host, ")");
    log::info("cluster: ", size, " rank", size == 1 ? "" : "s", "; rank 0 (", mpi_.host(),
              ") is the main context; walls: ", plan);
    for (int r = 1; r < size; ++r)
      if (std::find(owner_.begin(), owner_.end(), r) == owner_.end())
        log::warn("cluster: rank ", r, " (", hellos[std::size_t(r)].host, ") drives no wall");
  }
  return true;
}

void MpiCluster::localize(AppConfig& config, AppOptions& options) {
  std::vector<WallSpec> mine;
  std::string menuWall;
  // The legend's wall in the whole configuration (the marked one, else the
  // menu's, else the first): marked on the rank that drives it, and no other.
  std::string legendWall = config.walls.empty() ? "" : config.walls.front().name;
  bool marked = false;
  for (const WallSpec& w : config.walls) {
    if (w.legend && !marked) legendWall = w.name;
    marked = marked || w.legend;
  }
  if (!marked)
    for (const WallSpec& w : config.walls)
      if (w.menu) {
        legendWall = w.name;
        break;
      }
  for (std::size_t i = 0; i < config.walls.size(); ++i) {
    if (config.walls[i].menu) menuWall = config.walls[i].name;
    if (owner_.at(i) == rank()) {
      mine.push_back(config.walls[i]);
      mine.back().legend = config.walls[i].name == legendWall;
    }
  }
  // Only the rank that drives the first wall dumps its particles, as a single process would.
  if (owner_.empty() || owner_[0] != rank()) options.dumpParticles.reset();
  if (options.hashLog) options.hashLog = perRank(*options.hashLog, rank());
  if (root()) {
    if (!menuWall.empty() && !config.menu.operatorWindow &&
        std::none_of(mine.begin(), mine.end(), [](const WallSpec& w) { return w.menu; }))
      log::warn("cluster: the menu runs on rank 0 only; wall '", menuWall,
                "' is on another rank, so it shows no menu (give rank 0 a [menu] operator_window)");
  } else {
    // The menu, recording and replay belong to the main context.
    config.menu.operatorWindow.reset();
    for (WallSpec& w : mine)
      w.menu = false;
    options.menuScript.reset();
    options.record.reset();
    options.replay.reset();
  }
  config.walls = std::move(mine);
  gate_ = std::make_unique<WallGate>(int(config.walls.size()));
}

bool MpiCluster::ready(const std::string& error) {
  ready_ = true;
  const std::vector<std::string> records =
      gather(encodeHello({error.empty(), mpi_.host(), error}), "every rank to open its walls");
  bool ok = true;
  for (std::size_t r = 0; r < records.size(); ++r) {
    const Hello h = decodeHello(records[r], int(r));
    if (h.ok) continue;
    ok = false;
    if (root()) log::error("rank ", r, " (", h.host, ") cannot start: ", h.message);
  }
  if (!ok && root()) log::error("cluster: stopping every rank before the first frame");
  return ok;
}

void MpiCluster::shareField(const FieldSource& field) {
  // Start-up waits allow cluster.startup_timeout_s (loading a field, opening windows); frames allow
  // timeout_s.
  struct FrameTimeout {
    MpiSession& mpi;
    double seconds;
    ~FrameTimeout() { mpi.setTimeout(seconds); }
  } frameTimeout{mpi_, frameTimeout_};
  if (readSteps_) {
    // Whether rank 0's field is a streamed series, or a watched folder's
    // (a series that grows on rank 0, its new steps announced to the
    // others): every rank takes part in sharing it.
    int series = root() && field.timeline && field.timeline->streamed() ? 1 : 0;
    MPI_Request request;
    MPI_Ibcast(&series, 1, MPI_INT, 0, MPI_COMM_WORLD, &request);
    mpi_.wait(request, "rank 0 to say what its field is");
    if (series) {
      shareSeries(field);
      if (root() && field.stream)
        broadcaster_->announceSteps(field.timeline->steps(), field.timeline->size());
      return;
    }
  }
  if (!readField_) return;
  std::vector<std::shared_ptr<const VectorField>> grids;
  if (field.timeline) {
    // A streamed series' steps in memory now (its first); later ones travel as they come.
    for (std::size_t i = 0; i < field.timeline->size(); ++i)
      if (auto frame = field.timeline->frame(i)) grids.push_back(std::move(frame));
  } else
    grids.push_back(field.update.field);
  if (broadcaster_->pinLocal(grids) && root())
    log::info("cluster: every rank read the same field (", grids.size(),
              " grid(s)); no grid travels");
}

void MpiCluster::shareSeries(const FieldSource& field) {
  std::shared_ptr<FieldSteps> steps = field.timeline ? field.timeline->steps() : nullptr;
  // Whether the steps are read as halves (field.precision = "auto" asks this rank's GPUs).
  bool half = field.update.field && field.update.field->halfPrecision();
  std::string blind;  // why this rank cannot read the steps itself
  if (!root() && options_.blindToSteps && rank() == options_.debugRank) {
    steps.reset();
    blind = "--debug-blind-to-steps";
  } else if (!root() && !steps) {
    try {
      const FieldSource own = makeField(fieldSpec_, configFolder_);
      steps = own.timeline ? own.timeline->steps() : nullptr;
      half = own.update.field && own.update.field->halfPrecision();
      if (!steps) blind = "the field source reads as one grid here, not as a series";
    } catch (const Error& e) {
      blind = e.what();
    }
  }
  // Rank 0's files as it opened them: every reading rank must see the same.
  ByteWriter w;
  if (root()) {
    w.boolean(half);
    const std::uint32_t count = std::uint32_t(field.timeline->size());
    w.u32(count);
    for (std::uint32_t i = 0; i < count; ++i) {
      const FileIdentity f = steps->identity(i);
      w.boolean(f.present);
      w.u64(f.size);
      w.u64(std::uint64_t(f.modified));
    }
  }
  std::vector<std::byte> files = w.take();
  std::uint64_t length = files.size();
  MPI_Request request;
  MPI_Ibcast(&length, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD, &request);
  mpi_.wait(request, "rank 0's list of the series' files");
  files.resize(std::size_t(length));
  MPI_Ibcast(files.data(), int(length), MPI_BYTE, 0, MPI_COMM_WORLD, &request);
  mpi_.wait(request, "rank 0's list of the series' files");
  if (!root() && blind.empty()) {
    try {
      ByteReader r(files, "rank 0's list of the series' files");
      const bool theirHalf = r.boolean("precision");
      if (theirHalf != half)
        blind = concat("its steps read as ", half ? "16-bit floats" : "floats", " here and as ",
                       theirHalf ? "16-bit floats" : "floats",
                       " on rank 0 (field.precision = \"auto\" asks each machine's GPUs; "
                       "\"float\" or \"half\" makes them agree)");
      const std::uint32_t count = r.u32("count");
      for (std::uint32_t i = 0; i < count && blind.empty(); ++i) {
        FileIdentity theirs;
        theirs.present = r.boolean("present");
        theirs.size = r.u64("size");
        theirs.modified = std::int64_t(r.u64("time"));
        const FileIdentity mine = steps->identity(i);
        if (mine != theirs)
          blind = concat("step ", i, "'s file ", steps->name(i), " is ", mine.text(), " here and ",
                         theirs.text(), " on rank 0");
      }
      if (blind.empty()) {
        r.finish();
        if (steps->identity(count).present)
          blind = concat("its series has more steps than rank 0's ", count);
      }
    } catch (const Error& e) {
      blind = e.what();
    }
  }
  if (!blind.empty()) {
    steps.reset();
    log::warn("rank ", rank(), " (", mpi_.host(), ") cannot read the series' steps itself: ", blind,
              "; rank 0 sends them over MPI (slower: every rank that reads them from a shared "
              "file system spares the network)");
  }
  // Every rank's verdict, so that all agree who gets the steps over MPI.
  const int mine = blind.empty() ? 0 : 1;
  std::vector<int> verdicts(std::size_t(mpi_.size()), 0);
  MPI_Iallgather(&mine, 1, MPI_INT, verdicts.data(), 1, MPI_INT, MPI_COMM_WORLD, &request);
  mpi_.wait(request, "every rank to open the series");
  std::string readers = "0", blindRanks;
  for (int r = 1; r < mpi_.size(); ++r) {
    std::string& list = verdicts[std::size_t(r)] ? blindRanks : readers;
    list += concat(list.empty() ? "" : ", ", r);
  }
  MPI_Comm blindComm = MPI_COMM_NULL;
  if (!blindRanks.empty())
    MPI_Comm_split(MPI_COMM_WORLD, root() || mine ? 0 : MPI_UNDEFINED, rank(), &blindComm);
  if (root())
    log::info("cluster: the series' steps are read from disk by rank(s) ", readers,
              blindRanks.empty() ? "" : "; rank 0 sends them over MPI to rank(s) " + blindRanks);
  broadcaster_->readSeries(root() ? nullptr : steps, blindComm, fieldSpec_.uploadAhead);
}

void MpiCluster::fail(const std::string& error) {
  if (finished_) {
    log::error("rank ", rank(), ": ", error);
    return;
  }
  if (!ready_) {
    ready(error);
    return;
  }
  mpi_.abort(error);
}

void MpiCluster::send(const FramePacket& packet) {
  broadcaster_->send(packet);
}

void MpiCluster::sendStop() {
  broadcaster_->sendStop();
}

std::shared_ptr<const FramePacket> MpiCluster::receive() {
  return broadcaster_->receive();
}

void MpiCluster::drawn(int wall, std::uint32_t frame) {
  gate_->drawn(wall, frame);
}

void MpiCluster::misbehave(std::uint32_t frame) {
  if (rank() != options_.debugRank) return;
  if (int(frame) == options_.dieAtFrame) {
    log::warn("rank ", rank(), ": --debug-die-at-frame ", frame, ": dying now");
    std::raise(SIGKILL);
  }
  if (int(frame) == options_.hangAtFrame) {
    log::warn("rank ", rank(), ": --debug-hang-at-frame ", frame, ": hanging now");
    std::raise(SIGSTOP);
  }
}

ClusterLink::Verdict MpiCluster::swap(std::uint32_t frame, int stop,
                                      const std::function<bool()>& wallFailed) {
  misbehave(frame);
  // Frame 0 is when walls compile their shaders and upload the field: it gets the start-up bound.
  mpi_.setTimeout(frame == 0 ? startupTimeout_ : frameTimeout_);
  const Clock::time_point start = Clock::now();
  const auto limit =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(mpi_.timeout()));
  switch (gate_->wait(frame, start + limit, wallFailed)) {
    case WallGate::Result::Drawn:
      break;
    case WallGate::Result::Stopped:
      stop |= kFailed;
      break;
    case WallGate::Result::TimedOut:
      mpi_.abort(concat("this rank's walls did not finish frame ", frame, " within ",
                        mpi_.timeout(), " s (cluster.timeout_s); stopping every rank"));
  }
  drawWaitSeconds_ += std::chrono::duration<double>(Clock::now() - start).count();
  // The swap barrier: an all-reduce, so it also tells every rank who wants to stop and why.
  const int local[3] = {stop & kClosed ? 1 : 0, stop & kInterrupted ? 1 : 0,
                        stop & kFailed ? rank() + 1 : 0};
  int all[3] = {0, 0, 0};
  MPI_Request request;
  MPI_Iallreduce(local, all, 3, MPI_INT, MPI_MAX, MPI_COMM_WORLD, &request);
  const double seconds =
      mpi_.wait(request, concat("every rank to draw frame ", frame, " (the swap barrier)"));
  ++swaps_;
  swapSeconds_ += seconds;
  maxSwapSeconds_ = std::max(maxSwapSeconds_, seconds);
  mpi_.setTimeout(frameTimeout_);
  if (all[0] == 0 && all[1] == 0 && all[2] == 0) return {};
  if (root()) {
    if (all[2])
      log::error("cluster: rank ", all[2] - 1, " failed at frame ", frame,
                 " (its message is above); stopping every rank");
    else if (all[1])
      log::info("cluster: interrupted at frame ", frame, "; stopping every rank");
    else
      log::info("cluster: a window was closed at frame ", frame, "; stopping every rank");
  }
  return {false, all[2] != 0};
}

void MpiCluster::finish() {
  finished_ = true;
  if (!options_.stats || !broadcaster_) return;
  const FrameBroadcaster::Stats& s = broadcaster_->stats();
  const double packets = double(std::max<std::uint64_t>(s.packets, 1));
  const double swaps = double(std::max<std::uint64_t>(swaps_, 1));
  log::info("cluster stats, rank ", rank(), " of ", mpi_.size(), " (", mpi_.host(),
            "): ", s.packets, " packets, ", double(s.packetBytes) / packets, " B/packet (max ",
            s.maxPacketBytes, " B), ", double(s.broadcastBytes) / packets,
            " B/frame broadcast; broadcast ", ms(s.broadcastSeconds / packets), "/frame (max ",
            ms(s.maxBroadcastSeconds), "); swap barrier ", ms(swapSeconds_ / swaps), "/frame (max ",
            ms(maxSwapSeconds_), "); waiting for own walls ", ms(drawWaitSeconds_ / swaps),
            "/frame; field grids: ", s.grids, " (", s.gridBytes, " B, ", ms(s.gridSeconds),
            "); series steps read here: ", s.stepsRead, " (waited ", ms(s.stepSeconds), ")");
}

}  // namespace sandstorm
