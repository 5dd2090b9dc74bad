#include "app/cluster/mpi_session.h"

#include <cstdlib>
#include <optional>
#include <thread>

#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

using Clock = std::chrono::steady_clock;

void check(int code, const char* call) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw Error(concat(call, " failed: ", std::string(text, std::size_t(length))));
}

}  // namespace

MpiSession::MpiSession() {
  int provided = 0;
  check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  // Errors come back as codes (and become messages) rather than killing the job silently.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  char name[MPI_MAX_PROCESSOR_NAME] = {};
  int length = 0;
  MPI_Get_processor_name(name, &length);
  host_.assign(name, std::size_t(length));
  if (provided < MPI_THREAD_FUNNELED)
    log::warn("rank ", rank_, ": MPI gives thread level ", provided,
              "; MPI calls stay on the main thread anyway");
}

MpiSession::~MpiSession() {
  MPI_Finalize();
}

bool MpiSession::launchedByMpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (const char* v = std::getenv(name); v && *v) return true;
  return false;
}

double MpiSession::wait(MPI_Request& request, std::string_view what) {
  const Clock::time_point start = Clock::now();
  // Rank 0 gives up first, so the message that explains the stop is its own.
  const double limit = rank_ == 0 ? timeout_ : timeout_ + 2.0;
  const Clock::time_point deadline =
      start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limit));
  std::optional<Clock::time_point> interruptedAt;
  for (int spins = 0;; ++spins) {
    int done = 0;
    const int code = MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (code != MPI_SUCCESS) {
      char text[MPI_MAX_ERROR_STRING];
      int length = 0;
      MPI_Error_string(code, text, &length);
      abort(concat("MPI failed while waiting for ", what, ": ",
                   std::string(text, std::size_t(length))));
    }
    if (done) return std::chrono::duration<double>(Clock::now() - start).count();
    const Clock::time_point now = Clock::now();
    if (now > deadline)
      abort(concat("no answer within ", limit, " s while waiting for ", what,
                   ": a rank died or hangs (cluster.timeout_s); stopping every rank"));
    if (interrupt_ && *interrupt_) {
      // mpirun signals every rank when it stops the job (a rank died, Ctrl-C):
      // a collective that did not complete by now never will.
      if (!interruptedAt)
        interruptedAt = now;
      else if (now - *interruptedAt > std::chrono::milliseconds(500))
        abort(concat(
            "mpirun is stopping the job (a rank died, or Ctrl-C) while this rank waited for ",
            what));
    }
    // Spin briefly (the answer is usually microseconds away), then sleep: the
    // render threads on this machine need the cores more than we do.
    if (spins < 200)
      std::this_thread::yield();
    else
      std::this_thread::sleep_for(std::chrono::microseconds(spins < 2000 ? 50 : 500));
  }
}

void MpiSession::abort(std::string_view message) {
  log::error(message, " (rank ", rank_, " on ", host_, ")");
  MPI_Abort(MPI_COMM_WORLD, kAbortStatus);
  std::_Exit(kAbortStatus);  // MPI_Abort does not return; should it, leave anyway
}

}  // namespace sandstorm
