// Runs sandstorm with a tracker: sandstorm first, then, once it listens on its
// port, sandstorm-tracker-sim sending to that port (so the simulator's script
// starts with sandstorm's first frames); both end with sandstorm. Also: a free
// UDP port on loopback, and a configuration that includes a tracked test
// configuration with that port.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "tests/app/run_process.h"

namespace sandstorm::test {

inline int freeUdpPort() {
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
  socklen_t n = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &n);
  ::close(fd);
  return ntohs(a.sin_port);
}

// dir/run.toml: `base` (relative to the source tree) with [tracking] port = port, then `extra`.
inline std::filesystem::path trackedConfig(const std::filesystem::path& dir,
                                           const std::string& base, int port,
                                           const std::string& extra = "") {
  const std::filesystem::path path = dir / "run.toml";
  std::ofstream out(path);
  out << "include = \"" << SANDSTORM_SOURCE_DIR << "/" << base << "\"\n"
      << extra << "\n[tracking]\nport = " << port << "\n";
  return path;
}

inline std::filesystem::path writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

struct TrackedResult {
  int exitCode = -1;
  std::string output;  // sandstorm's
  std::string simOutput;
};

// `command`: a whole shell command line that runs sandstorm (with 2>&1), e.g. through mpirun.
inline TrackedResult runTrackedCommand(const std::string& command, const std::string& simArgs,
                                       const std::filesystem::path& dir) {
  TrackedResult r;
  FILE* app = popen(command.c_str(), "r");
  if (!app) return r;
  const std::filesystem::path pidFile = dir / "sim.pid", simLog = dir / "sim.log";
  bool started = false;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, app)) {
    r.output += buffer;
    // The tracker starts once the app listens and its walls are ready (their
    // shaders compiled), so its scripted times count from the first frames.
    if (!started && r.output.find("listening for DTrack") != std::string::npos &&
        r.output.find("frames begin") != std::string::npos) {
      started = true;
      const std::string sim = std::string("cd '") + SANDSTORM_SOURCE_DIR + "' && ('" +
                              SANDSTORM_TRACKER_SIM + "' " + simArgs + " > '" + simLog.string() +
                              "' 2>&1 & echo $! > '" + pidFile.string() + "')";
      std::system(sim.c_str());
    }
  }
  const int status = pclose(app);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (started) {
    std::ifstream pid(pidFile);
    int id = 0;
    if (pid >> id && id > 0) ::kill(id, SIGTERM);
    std::ifstream log(simLog);
    r.simOutput.assign(std::istreambuf_iterator<char>(log), {});
  }
  return r;
}

inline TrackedResult runTracked(const std::string& args, const std::string& simArgs,
                                const std::filesystem::path& dir) {
  return runTrackedCommand(std::string("cd '") + SANDSTORM_SOURCE_DIR + "' && '" +
                               SANDSTORM_BINARY + "' " + args + " 2>&1",
                           simArgs, dir);
}

}  // namespace sandstorm::test
