// Runs the sandstorm binary as a child process, for tests of the command line
// and of what separate processes compute.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace sandstorm::test {

struct ProcessResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

inline std::filesystem::path scratchDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("sandstorm-test-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Runs a shell command line (append 2>&1 to catch stderr too) to its end.
inline ProcessResult runCommand(const std::string& cmd) {
  ProcessResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe))
    r.output += buffer;
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// `env`: variable assignments for the child ("MESA_GL_VERSION_OVERRIDE=3.3").
inline ProcessResult runSandstorm(const std::string& args, const std::string& env = "") {
  return runCommand(std::string("cd '") + SANDSTORM_SOURCE_DIR + "' && " + env + " '" +
                    SANDSTORM_BINARY + "' " + args + " 2>&1");
}

// Windows under a virtual X server (scripts/setup installs xvfb-run).
inline const std::string kXvfb = "xvfb-run -a -s '-screen 0 1280x1024x24' ";

inline bool haveXvfb() {
  return std::system("command -v xvfb-run >/dev/null 2>&1") == 0;
}

inline ProcessResult runUnderXvfb(const std::string& args) {
  return runCommand(std::string("cd '") + SANDSTORM_SOURCE_DIR + "' && " + kXvfb + "'" +
                    SANDSTORM_BINARY + "' " + args + " 2>&1");
}

inline std::vector<std::string> readLines(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

// A file's bytes; "" when it cannot be read.
inline std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace sandstorm::test
