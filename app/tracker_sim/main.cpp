// sandstorm-tracker-sim: sends ART DTrack datagrams over UDP from a scripted
// path (core/tracking/tracker_script.h), as a DTrack2/DTrack3 controller
// would: a head walking round the CAVE and a wand sweeping and pressing
// buttons, at a chosen rate, with optional dropouts, jitter and malformed
// datagrams. Try the tracked CAVE without a tracker:
//
//   build/sandstorm-tracker-sim --port 5000 &
//   build/sandstorm --config config/cave4-tracked-desktop.toml
#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <random>
#include <thread>

#include <CLI/CLI.hpp>

#include "app/cli_unknown_option.h"
#include "app/tracker_sim/malformed_datagrams.h"
#include "core/tracking/dtrack_writer.h"
#include "core/tracking/tracker_script.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace {

std::atomic<bool> interrupted{false};
void onInterrupt(int) {
  interrupted = true;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace sandstorm;
  CLI::App cli{"sandstorm-tracker-sim: an ART DTrack stand-in sending scripted datagrams over UDP"};
  int port = 0;
  std::string host = "127.0.0.1", pathFile, format = "6df2";
  double rate = 60.0, duration = 0.0, dropout = 0.0, jitter = 0.0, malformed = 0.0;
  unsigned seed = 1;
  std::uint32_t firstFrame = 1;
  bool print = false;
  cli.add_option("--port", port, "UDP port to send to (Sandstorm's tracking.port)")
      ->required()
      ->check(CLI::Range(1, 65535));
  cli.add_option("--host", host, "Host to send to (default 127.0.0.1)");
  cli.add_option("--rate", rate, "Datagrams per second (DTrack: 60..300)")
      ->check(CLI::Range(1.0, 1000.0));
  cli.add_option("--duration", duration, "Seconds to send, then exit (0: until Ctrl-C)")
      ->check(CLI::Range(0.0, 1e7));
  cli.add_option("--path", pathFile, "A path file (TOML keyframes); default: the built-in walk")
      ->check(CLI::ExistingFile);
  cli.add_option("--dropout", dropout, "Chance that a frame's datagram is lost (0..1)")
      ->check(CLI::Range(0.0, 1.0));
  cli.add_option("--jitter", jitter, "Noise on every position, standard deviation in mm")
      ->check(CLI::Range(0.0, 1000.0));
  cli.add_option("--malformed", malformed,
                 "Share of datagrams replaced by malformed ones (0..1): a storm to survive")
      ->check(CLI::Range(0.0, 1.0));
  cli.add_option("--format", format, "Flystick lines: 6df2 (DTrack2 and later) or 6df (older)")
      ->check(CLI::IsMember({"6df2", "6df"}));
  cli.add_option("--seed", seed, "Seed of the dropouts, jitter and malformed datagrams");
  cli.add_option("--first-frame", firstFrame, "The first frame counter (fr) sent");
  cli.add_flag("--print", print, "Write the datagrams to stdout as well");
  if (const std::string unknown = unknownOption(cli, argc, argv); !unknown.empty()) {
    log::error(unknown);
    return 2;
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli.exit(e);
  }

  try {
    const TrackerScript script =
        pathFile.empty() ? TrackerScript::builtIn() : TrackerScript::load(pathFile);
    addrinfo hints{};
    hints.ai_family = AF_INET;
    hints.ai_socktype = SOCK_DGRAM;
    addrinfo* target = nullptr;
    if (const int e = getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &target))
      throw Error(concat("--host ", host, ": ", gai_strerror(e)));
    const int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (fd < 0) throw Error("cannot open a UDP socket");

    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> chance(0.0, 1.0);
    std::normal_distribution<float> noise(0.0f, float(jitter));
    const FlystickFormat flysticks = format == "6df" ? FlystickFormat::V1 : FlystickFormat::V2;
    log::info("sending DTrack datagrams to ", host, ":", port, " at ", rate, " Hz",
              duration > 0 ? concat(" for ", duration, " s") : std::string(" until Ctrl-C"),
              pathFile.empty() ? " (the built-in walk)" : " (" + pathFile + ")");

    const auto start = std::chrono::steady_clock::now();
    const auto period = std::chrono::duration<double>(1.0 / rate);
    std::uint64_t sent = 0, lost = 0, bad = 0;
    for (std::uint64_t i = 0; !interrupted; ++i) {
      const double t = double(i) / rate;
      if (duration > 0.0 && t >= duration) break;
      std::this_thread::sleep_until(
          start + std::chrono::duration_cast<std::chrono::nanoseconds>(period * double(i)));
      TrackerFrame frame = script.at(t, firstFrame + std::uint32_t(i));
      if (jitter > 0.0) {
        for (TrackedBody& b : frame.bodies)
          b.position += glm::vec3(noise(random), noise(random), noise(random));
        for (TrackedFlystick& f : frame.flysticks)
          if (f.tracked()) f.position += glm::vec3(noise(random), noise(random), noise(random));
      }
      if (dropout > 0.0 && chance(random) < dropout) {
        ++lost;
        continue;
      }
      std::string datagram = writeDTrack(frame, flysticks);
      if (malformed > 0.0 && chance(random) < malformed) {
        datagram = malformDatagram(datagram, random);
        ++bad;
      }
      if (print) std::fwrite(datagram.data(), 1, datagram.size(), stdout);
      if (::sendto(fd, datagram.data(), datagram.size(), 0, target->ai_addr, target->ai_addrlen) >=
          0)
        ++sent;
    }
    ::close(fd);
    freeaddrinfo(target);
    log::info("sent ", sent, " datagrams (", bad, " malformed), ", lost, " dropped on purpose");
    return 0;
  } catch (const Error& e) {
    log::error(e.what());
    return 1;
  }
}
