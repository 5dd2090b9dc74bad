// MpiSession: MPI for the lifetime of one object (MPI_Init_thread in the
// constructor, MPI_Finalize in the destructor), and the one place that waits
// for MPI requests.
//
// Every MPI call of Sandstorm happens on the main thread (MPI_THREAD_FUNNELED):
// render threads never touch MPI. Collectives are non-blocking (MPI_Ibcast,
// MPI_Iallreduce, ...) and complete through wait(), which polls MPI_Test
// against a deadline, so a rank that died or hangs cannot freeze the others:
// past the deadline, wait() names what it waited for and calls MPI_Abort,
// which makes mpirun stop every rank with a non-zero status. Rank 0 reports
// first: the other ranks wait a little longer before they give up.
#pragma once

#include <mpi.h>

#include <atomic>
#include <chrono>
#include <string>
#include <string_view>

namespace sandstorm {

class MpiSession {
 public:
  // Exit status of a run that MPI_Abort ends (mpirun passes it on).
  static constexpr int kAbortStatus = 3;

  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  // True when this process was started by mpirun (Open MPI, or a PMI launcher).
  static bool launchedByMpirun();

  int rank() const { return rank_; }
  int size() const { return size_; }
  const std::string& host() const { return host_; }

  void setTimeout(double seconds) { timeout_ = seconds; }
  double timeout() const { return timeout_; }
  // While this flag is set (SIGINT/SIGTERM: mpirun stops the job), waits end soon.
  void watchInterrupt(const std::atomic<bool>* flag) { interrupt_ = flag; }

  // Completes `request`; returns the seconds it took. `what` says what was
  // awaited ("the packet of frame 57"), for the message if it never completes.
  double wait(MPI_Request& request, std::string_view what);

  // Logs `message` (prefixed with this rank) and ends every rank. Never returns.
  [[noreturn]] void abort(std::string_view message);

 private:
  int rank_ = 0;
  int size_ = 1;
  std::string host_;
  double timeout_ = 120.0;  // start-up; the frame loop's is set once it begins
  const std::atomic<bool>* interrupt_ = nullptr;
};

}  // namespace sandstorm
