// Tracking on loopback: the receiver keeps the newest complete DTrack frame
// and survives every kind of bad datagram; a measurement that arrived before
// a frame starts is that frame's sample (by frame index, not by clock); and,
// end to end with sandstorm-tracker-sim, each wall's image follows the tracked
// head exactly as a fixed head at that pose would draw it, the wand clicks the
// menu, carries an emitter and sets the throttle, and recorded sessions
// replay without the tracker.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "app/menu/imgui_session.h"
#include "app/menu/menu_panel.h"
#include "app/tracking/dtrack_receiver.h"
#include "app/tracking/tracking_input.h"
#include "core/tracking/dtrack_writer.h"
#include "core/util/error.h"
#include "tests/app/tracked_run.h"

namespace sandstorm {
namespace {

using test::readLines;

// Sends to `to` (loopback by default) from `from` (any loopback address:
// Linux lets a socket take 127.0.0.2 as its own, a second host for the test).
class Sender {
 public:
  explicit Sender(int port, const char* to = "127.0.0.1", const char* from = nullptr)
      : fd_(::socket(AF_INET, SOCK_DGRAM, 0)) {
    to_.sin_family = AF_INET;
    to_.sin_port = htons(std::uint16_t(port));
    ::inet_pton(AF_INET, to, &to_.sin_addr);
    if (from) {
      sockaddr_in self{};
      self.sin_family = AF_INET;
      ::inet_pton(AF_INET, from, &self.sin_addr);
      EXPECT_EQ(::bind(fd_, reinterpret_cast<sockaddr*>(&self), sizeof self), 0) << from;
    }
  }
  ~Sender() { ::close(fd_); }
  void send(const std::string& datagram) {
    ::sendto(fd_, datagram.data(), datagram.size(), 0, reinterpret_cast<sockaddr*>(&to_),
             sizeof to_);
  }

 private:
  int fd_;
  sockaddr_in to_{};
};

TrackerFrame frameNumber(std::uint32_t n, float headX = 0.0f) {
  TrackerFrame f;
  f.frame = n;
  f.bodies.push_back({0, 1.0f, {headX, 0.0f, 1700.0f}, glm::mat3(1.0f)});
  return f;
}

// Waits (at most two seconds) until the receiver has taken `received` and dropped `dropped`.
bool waitFor(const TrackerSource& source, std::uint64_t received, std::uint64_t dropped = 0) {
  for (int i = 0; i < 400; ++i) {
    const TrackerStats s = source.stats();
    if (s.received >= received && s.dropped >= dropped) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

TEST(DTrackReceiver, KeepsTheNewestCompleteFrame) {
  DTrackReceiver receiver({.port = 0});
  EXPECT_FALSE(receiver.newest());  // nothing yet, and no waiting for it
  Sender sender(receiver.port());
  for (std::uint32_t n = 1; n <= 3; ++n)
    sender.send(writeDTrack(frameNumber(n, float(n))));
  ASSERT_TRUE(waitFor(receiver, 3));
  const auto newest = receiver.newest();
  ASSERT_TRUE(newest);
  EXPECT_EQ(*newest->frame.frame, 3u);
  EXPECT_EQ(newest->sequence, 3u);
  EXPECT_EQ(newest->frame.bodies[0].position.x, 3.0f);
}

TEST(DTrackReceiver, DropsAndCountsBadDatagramsAndKeepsTheLastGoodPose) {
  DTrackReceiver receiver({.port = 0});
  Sender sender(receiver.port());
  sender.send(writeDTrack(frameNumber(1, 10.0f)));
  ASSERT_TRUE(waitFor(receiver, 1));
  const std::string rot = "[1 0 0 0 1 0 0 0 1]";
  const std::vector<std::string> bad = {
      "fr 2\r\n6d 3 [0 1.000][10 20 30]" + rot,  // three announced, one sent
      "fr 2\r\n6d 1 [0 1.000][nan 20 30]" + rot,
      "fr 2\r\n6d 1 [0 1.000][inf 20 30]" + rot,
      "fr 2\r\n6d 1 [70000 1.000][10 20 30]" + rot,
      "fr 2\r\n6d 1 [0 1.000][10 20 30][1 0 0 0 1",  // truncated
      std::string("\x01\x02\x03\xfe\xff junk", 10),
      std::string(65507, 'x'),  // the largest UDP datagram: one 64 KiB line of junk
      "",
  };
  for (int round = 0; round < 25; ++round)
    for (const std::string& d : bad)
      sender.send(d);
  ASSERT_TRUE(waitFor(receiver, 1, 25 * bad.size()));
  sender.send(writeDTrack(frameNumber(3, 30.0f)));
  ASSERT_TRUE(waitFor(receiver, 2, 25 * bad.size()));
  const TrackerStats s = receiver.stats();
  EXPECT_EQ(s.received, 2u);
  EXPECT_EQ(s.dropped, 25u * bad.size());
  EXPECT_FALSE(s.lastError.empty());
  const auto newest = receiver.newest();
  ASSERT_TRUE(newest);
  EXPECT_EQ(*newest->frame.frame, 3u);  // no bad datagram touched the pose
  EXPECT_EQ(newest->frame.bodies[0].position, glm::vec3(30.0f, 0.0f, 1700.0f));
}

TEST(DTrackReceiver, APortInUseIsAClearErrorNamingThePort) {
  DTrackReceiver first({.port = 0});
  try {
    DTrackReceiver second({.port = first.port()});
    FAIL() << "a second receiver opened port " << first.port();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("UDP port " + std::to_string(first.port())),
              std::string::npos)
        << e.what();
  }
}

// tracking.sender: a datagram from a host not listed moves nothing.
TEST(DTrackReceiver, OnlyTheListedSenderMovesAnything) {
  DTrackReceiver receiver({.port = 0, .senders = {"127.0.0.1"}});
  Sender intruder(receiver.port(), "127.0.0.1", "127.0.0.2");
  for (std::uint32_t n = 1; n <= 20; ++n)
    intruder.send(writeDTrack(frameNumber(n, 999.0f)));
  for (int i = 0; i < 400 && receiver.stats().foreign < 20; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(receiver.stats().foreign, 20u);
  EXPECT_EQ(receiver.stats().received, 0u);
  EXPECT_FALSE(receiver.newest());
  Sender tracker(receiver.port(), "127.0.0.1", "127.0.0.1");
  tracker.send(writeDTrack(frameNumber(21, 5.0f)));
  ASSERT_TRUE(waitFor(receiver, 1));
  EXPECT_EQ(receiver.newest()->frame.bodies[0].position.x, 5.0f);
  intruder.send(writeDTrack(frameNumber(22, 999.0f)));
  for (int i = 0; i < 400 && receiver.stats().foreign < 21; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(receiver.stats().foreign, 21u);
  EXPECT_EQ(receiver.newest()->frame.bodies[0].position.x, 5.0f);  // still the tracker's
}

// tracking.interface: listens on that address alone; an address no interface
// has is a clear error naming the setting.
TEST(DTrackReceiver, ListensOnTheConfiguredInterfaceOnly) {
  DTrackReceiver receiver({.port = 0, .interfaceAddress = "127.0.0.2"});
  Sender elsewhere(receiver.port(), "127.0.0.1");
  elsewhere.send(writeDTrack(frameNumber(1)));
  Sender there(receiver.port(), "127.0.0.2");
  there.send(writeDTrack(frameNumber(2)));
  ASSERT_TRUE(waitFor(receiver, 1));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(receiver.stats().received, 1u);
  EXPECT_EQ(*receiver.newest()->frame.frame, 2u);
  try {
    DTrackReceiver nowhere({.port = 0, .interfaceAddress = "192.0.2.1"});  // TEST-NET-1
    FAIL() << "listened on an address no interface has";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("tracking] interface"), std::string::npos) << e.what();
  }
}

TEST(TrackingInput, AMeasurementThatArrivedBeforeAFrameIsThatFramesSample) {
  auto receiver = std::make_unique<DTrackReceiver>(DTrackReceiver::Options{.port = 0});
  const DTrackReceiver& source = *receiver;
  Sender sender(receiver->port());
  TrackingSpec spec;
  spec.source = TrackingSource::DTrack;
  TrackingInput input(spec, NavigationSpec{}, {}, std::move(receiver));
  EXPECT_FALSE(input.sample(0).active);  // before any measurement: the configured head
  for (std::uint32_t frame = 1; frame <= 20; ++frame) {
    sender.send(writeDTrack(frameNumber(500 + frame, 10.0f * float(frame))));
    ASSERT_TRUE(waitFor(source, frame));  // it arrived; frame `frame` starts now
    const TrackingSample s = input.sample(frame);
    EXPECT_TRUE(s.active);
    EXPECT_EQ(s.trackerFrame, 500 + frame);
    EXPECT_FLOAT_EQ(s.head.position.x, 0.01f * float(frame));
  }
}

// --- End to end, with sandstorm-tracker-sim --------------------------------

std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The `track` lines of a session log: frame -> the line's items.
std::map<std::uint32_t, std::map<std::string, std::string>> trackLines(
    const std::filesystem::path& log) {
  std::map<std::uint32_t, std::map<std::string, std::string>> out;
  for (const std::string& line : readLines(log)) {
    std::istringstream in(line);
    std::uint32_t frame;
    std::string verb;
    if (!(in >> frame >> verb) || verb != "track") continue;
    for (std::string item; in >> item;)
      out[frame][item.substr(0, item.find('='))] = item.substr(item.find('=') + 1);
  }
  return out;
}

std::vector<std::string> split(const std::string& s, char by) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, by);)
    out.push_back(part == "-0" ? "-0.0" : part);  // TOML reads "-0" as the integer 0
  return out;
}

const char* kWalkingHead = R"(loop = false
[[key]]
time = 0.0
head = [-0.4, -0.3, 1.6]
head_yaw_deg = 70.0
head_pitch_deg = -5.0
head_roll_deg = 3.0
wand_visible = false
[[key]]
time = 4.0
head = [0.5, 0.4, 1.8]
head_yaw_deg = 120.0
head_pitch_deg = 10.0
head_roll_deg = -4.0
)";

TEST(TrackedCave, EachWallShowsWhatAFixedHeadAtTheTrackedPoseShows) {
  const auto dir = test::scratchDir("tracked-head");
  const int port = test::freeUdpPort();
  const auto config = test::trackedConfig(dir, "tests/data/tracked.toml", port);
  const auto path = test::writeFile(dir / "walk.toml", kWalkingHead);
  const auto r = test::runTracked(
      "--config " + config.string() + " --frames 122 --screenshot-every 40 --screenshot " +
          (dir / "tracked").string() + " --record " + (dir / "session.log").string() +
          " --hash-log " + (dir / "hashes.txt").string(),
      "--port " + std::to_string(port) + " --rate 250 --duration 60 --path " + path.string(), dir);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto tracks = trackLines(dir / "session.log");
  ASSERT_FALSE(tracks.empty()) << r.output << r.simOutput;
  int compared = 0;
  std::set<std::string> fronts;
  for (const std::uint32_t frame : {40u, 80u, 120u}) {
    const auto at = tracks.upper_bound(frame);
    if (at == tracks.begin()) continue;  // no measurement by then (a slow start)
    const auto& items = std::prev(at)->second;
    const std::vector<std::string> head = split(items.at("head"), ',');
    ASSERT_EQ(head.size(), 12u) << items.at("head");
    // The same scene with a fixed head at that pose (its right vector as written, bit for bit).
    const auto fixed = dir / ("fixed" + std::to_string(frame));
    test::writeFile(dir / "fixed.toml",
                    std::string("include = \"") + SANDSTORM_SOURCE_DIR +
                        "/tests/data/tracked.toml\"\n[tracking]\nsource = \"none\"\n[head]\n"
                        "mode = \"fixed\"\nposition = [" +
                        head[0] + ", " + head[1] + ", " + head[2] + "]\nright = [" + head[3] +
                        ", " + head[4] + ", " + head[5] + "]\n");
    const auto still =
        test::runSandstorm("--config " + (dir / "fixed.toml").string() + " --frames " +
                           std::to_string(frame + 1) + " --screenshot " + fixed.string());
    ASSERT_EQ(still.exitCode, 0) << still.output;
    for (const std::string wall : {"front", "left", "right", "floor"}) {
      const std::string tracked =
          readBytes(dir / "tracked" / (wall + "_" + std::to_string(frame) + ".png"));
      ASSERT_FALSE(tracked.empty()) << wall << " " << frame;
      EXPECT_TRUE(tracked == readBytes(fixed / (wall + ".png")))
          << wall << " at frame " << frame << " differs from a fixed head at the tracked pose";
    }
    fronts.insert(readBytes(dir / "tracked" / ("front_" + std::to_string(frame) + ".png")));
    ++compared;
  }
  EXPECT_GE(compared, 2) << r.output;
  EXPECT_EQ(fronts.size(), std::size_t(compared));  // the head moved: every image differs
  // The walls hold the same particles every frame.
  std::map<std::string, std::set<std::string>> perFrame;
  for (const std::string& line : readLines(dir / "hashes.txt")) {
    std::istringstream in(line);
    std::string frame, wall, count, hash;
    in >> frame >> wall >> count >> hash;
    perFrame[frame].insert(hash);
  }
  EXPECT_EQ(perFrame.size(), 122u);
  for (const auto& [frame, hashes] : perFrame)
    EXPECT_EQ(hashes.size(), 1u) << "walls differ at frame " << frame;
}

// Where the menu's Reset button is on the front wall of tracked-menu.toml, in room metres.
glm::vec3 resetButtonInTheRoom() {
  MainContext main(ParticleState{}, FieldUpdate{}, MainContext::Options{});
  ImGuiSession session(nullptr, {400, 300});
  MenuPanel panel(main, {}, nullptr);
  for (int i = 0; i < 3; ++i) {  // auto-sized windows settle in a frame or two
    session.begin(1.0f / 60.0f);
    panel.build(MenuStats{});
    session.end();
  }
  const MenuPanel::Rect button = panel.rects().at("button:reset");
  const glm::vec2 pixel = 0.5f * (button.min + button.max);
  const glm::vec2 uv(pixel.x / 400.0f, 1.0f - pixel.y / 300.0f);
  return glm::vec3(-1.5f + 3.0f * uv.x, 1.5f, 3.0f * uv.y);
}

// A path file: the wand at `from` pointing at `to`; `keys` adds buttons and moves.
std::string aimedPath(const glm::vec3& from, const glm::vec3& to, const std::string& keys) {
  const glm::vec3 d = glm::normalize(to - from);
  std::ostringstream out;
  out.precision(9);
  out << "loop = false\n[[key]]\ntime = 0.0\nhead = [0.0, -0.5, 1.7]\nwand = [" << from.x << ", "
      << from.y << ", " << from.z << "]\nwand_yaw_deg = " << glm::degrees(std::atan2(d.y, d.x))
      << "\nwand_pitch_deg = " << glm::degrees(std::asin(d.z)) << "\n"
      << keys;
  return out.str();
}

TEST(TrackedWand, AClickThroughTheRayResetsEveryWallAtTheRecordedFrame) {
  const auto dir = test::scratchDir("tracked-click");
  const int port = test::freeUdpPort();
  const auto config = test::trackedConfig(dir, "tests/data/tracked-menu.toml", port);
  // Press the trigger (button 0) for 0.3 s, every 0.8 s from 1 s to 9 s
  // after the tracker starts (an app slow to start on a busy machine still
  // sees some).
  std::string clicks;
  for (int k = 0; k < 11; ++k)
    clicks += "[[key]]\ntime = " + std::to_string(1.0 + 0.8 * k) +
              "\nbuttons = 1\n[[key]]\ntime = " + std::to_string(1.3 + 0.8 * k) + "\nbuttons = 0\n";
  const auto path = test::writeFile(dir / "click.toml",
                                    aimedPath({0.2f, 0.0f, 1.2f}, resetButtonInTheRoom(), clicks));
  const auto r = test::runTracked(
      "--config " + config.string() + " --frames 300 --record " + (dir / "session.log").string() +
          " --hash-log " + (dir / "hashes.txt").string(),
      "--port " + std::to_string(port) + " --rate 250 --duration 60 --path " + path.string(), dir);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::vector<std::uint32_t> resets;
  for (const std::string& line : readLines(dir / "session.log"))
    if (line.ends_with(" reset")) resets.push_back(std::uint32_t(std::stoul(line)));
  ASSERT_FALSE(resets.empty()) << "no click reached the menu\n" << r.output;
  // Every wall dropped its particles at that frame (only that frame's newborn are left).
  std::map<std::pair<std::uint32_t, std::string>, std::size_t> counts;
  for (const std::string& line : readLines(dir / "hashes.txt")) {
    std::istringstream in(line);
    std::uint32_t frame;
    std::string wall;
    std::size_t count;
    in >> frame >> wall >> count;
    counts[{frame, wall}] = count;
  }
  for (const std::string wall : {"front", "floor"}) {
    const std::size_t before = counts.at({resets[0] - 1, wall}),
                      after = counts.at({resets[0], wall});
    EXPECT_GT(before, 1000u) << wall;
    EXPECT_LT(after, before / 4) << wall << " at frame " << resets[0];
  }
  // The session replays without the tracker: the same particles every frame.
  const auto replay = test::runSandstorm("--config " + config.string() + " --frames 300 --replay " +
                                         (dir / "session.log").string() + " --hash-log " +
                                         (dir / "replayed.txt").string());
  ASSERT_EQ(replay.exitCode, 0) << replay.output;
  EXPECT_EQ(replay.output.find("listening for DTrack"), std::string::npos) << replay.output;
  EXPECT_EQ(readLines(dir / "replayed.txt"), readLines(dir / "hashes.txt"));
}

TEST(TrackedWand, GrabCarriesEmitterZeroByTheWandsDisplacement) {
  const auto dir = test::scratchDir("tracked-grab");
  const int port = test::freeUdpPort();
  const auto config = test::trackedConfig(dir, "tests/data/tracked.toml", port);
  // Emitter 0 sits at world (0, 0, 0.05): room (-1, 2.6, 0.0175) through the navigation.
  const glm::vec3 from{-1.0f, 1.2f, 1.0f};
  const auto path =
      test::writeFile(dir / "grab.toml",
                      aimedPath(from, {-1.0f, 2.6f, 0.0175f},
                                "[[key]]\ntime = 0.8\nbuttons = 2\n"              // grab (button 1)
                                "[[key]]\ntime = 1.2\nwand = [-1.0, 1.2, 1.0]\n"  // hold still
                                "[[key]]\ntime = 2.0\nwand = [-0.7, 1.2, 1.2]\n"  // carry it
                                "[[key]]\ntime = 2.4\nbuttons = 0\n"              // let go
                                "[[key]]\ntime = 3.0\nwand = [0.0, 0.0, 1.0]\n"));  // and move away
  const auto r = test::runTracked(
      "--config " + config.string() + " --frames 400 --record " + (dir / "session.log").string(),
      "--port " + std::to_string(port) + " --rate 250 --duration 60 --path " + path.string(), dir);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string last;
  for (const std::string& line : readLines(dir / "session.log"))
    if (line.find("set emitter.0.position") != std::string::npos) last = line;
  ASSERT_FALSE(last.empty()) << r.output;
  const std::vector<std::string> xyz = split(last.substr(last.rfind(' ') + 1), ',');
  ASSERT_EQ(xyz.size(), 3u);
  // (0.3, 0, 0.2) m in the room is that over 0.35 in the world.
  EXPECT_NEAR(std::stof(xyz[0]), 0.3f / 0.35f, 1e-3f) << last;
  EXPECT_NEAR(std::stof(xyz[1]), 0.0f, 1e-3f) << last;
  EXPECT_NEAR(std::stof(xyz[2]), 0.05f + 0.2f / 0.35f, 1e-3f) << last;
}

TEST(TrackedWand, TiltingTheWandUpRaisesTheHelicoptersThrottle) {
  const auto dir = test::scratchDir("tracked-tilt");
  const int port = test::freeUdpPort();
  const auto config = test::trackedConfig(dir, "tests/data/tracked.toml", port);
  // Held level for a second, then tilted 50 degrees up (towards the user).
  const auto path = test::writeFile(
      dir / "tilt.toml",
      "loop = false\n[[key]]\ntime = 0.0\nwand = [0.0, 0.0, 1.2]\n[[key]]\ntime = 1.0\n"
      "wand_pitch_deg = 0.0\n[[key]]\ntime = 1.2\nwand_pitch_deg = 50.0\n");
  const auto r = test::runTracked(
      "--config " + config.string() +
          " --frames 300 --set helicopter.enabled=true --set helicopter.throttle=0.5 --record " +
          (dir / "session.log").string(),
      "--port " + std::to_string(port) + " --rate 250 --duration 60 --path " + path.string(), dir);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::vector<float> throttles;
  for (const std::string& line : readLines(dir / "session.log"))
    if (line.find("set helicopter.throttle") != std::string::npos)
      throttles.push_back(std::stof(line.substr(line.rfind(' ') + 1)));
  ASSERT_GE(throttles.size(), 3u) << r.output;
  for (std::size_t i = 1; i < throttles.size(); ++i)
    EXPECT_GT(throttles[i], throttles[i - 1]);  // up, a step at a time
  EXPECT_GT(throttles.back(), 0.55f);
}

// DTrack lists every Flystick in every datagram; an occluded one with
// quality -1, its buttons and joystick still live. Recorded: untracked from
// the first such datagram on, every frame alike, with the joystick as sent,
// and the user flies on (navigate lines) while the wand is hidden.
TEST(TrackedWand, AHiddenWandIsUntrackedAtOnceAndItsJoystickStillFlies) {
  const auto dir = test::scratchDir("tracked-hidden");
  const int port = test::freeUdpPort();
  const auto config = test::trackedConfig(dir, "tests/data/tracked.toml", port);
  const auto path = test::writeFile(
      dir / "hidden.toml",
      "loop = false\n[[key]]\ntime = 0.0\nwand = [0.0, 0.0, 1.2]\n"
      "[[key]]\ntime = 2.0\nwand_visible = false\njoystick = [0.0, 1.0]\nbuttons = 4\n");
  // Hidden 2 s after the tracker starts (an app slow to start still sees it
  // tracked first); 300 frames at the tracked configs' 60 a second.
  const auto r = test::runTracked(
      "--config " + config.string() + " --frames 300 --record " + (dir / "session.log").string(),
      "--port " + std::to_string(port) + " --rate 250 --duration 60 --path " + path.string(), dir);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  int tracked = 0, hidden = 0, flownWhileHidden = 0;
  bool wasHidden = false;
  for (const std::string& line : readLines(dir / "session.log")) {
    if (line.find(" navigate ") != std::string::npos && wasHidden) ++flownWhileHidden;
    const std::size_t at = line.find(" wand=");
    if (at == std::string::npos) continue;
    const std::string value = line.substr(at + 6, line.find(' ', at + 6) - at - 6);
    if (value == "-") continue;
    const std::vector<std::string> v = split(value, ',');
    ASSERT_EQ(v.size(), 17u) << line;
    const bool isTracked = v[1] == "1";
    const bool joystickForward = std::stof(v[16]) == 1.0f;
    if (joystickForward) {  // sent only with the wand hidden
      wasHidden = true;
      ++hidden;
      EXPECT_FALSE(isTracked) << "a hidden wand recorded as tracked: " << line;
      EXPECT_EQ(v[0], "1") << line;   // present: its radio is heard
      EXPECT_EQ(v[14], "4") << line;  // its buttons as sent
    } else {
      EXPECT_FALSE(wasHidden) << "the joystick fell back to zero: " << line;
      if (isTracked) ++tracked;
    }
  }
  EXPECT_GT(tracked, 10);
  EXPECT_GT(hidden, 30);
  EXPECT_GT(flownWhileHidden, 10) << "the joystick of a hidden wand did not fly";
}

TEST(TrackedCave, AMalformedDatagramStormLeavesItRunning) {
  const auto dir = test::scratchDir("tracked-storm");
  const int port = test::freeUdpPort();
  const auto config = test::trackedConfig(dir, "tests/data/tracked.toml", port);
  const auto r = test::runTracked(
      "--config " + config.string() + " --frames 150",
      "--port " + std::to_string(port) + " --rate 300 --duration 60 --malformed 0.6", dir);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::size_t at = r.output.find("frames received, ");
  ASSERT_NE(at, std::string::npos) << r.output;
  EXPECT_NE(r.output.find("tracking: dropped a datagram"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find(" 0 dropped"), std::string::npos) << r.output;
}

TEST(TrackedCave, NoTrackerAtAllNeitherHangsNorStopsTheRun) {
  const auto dir = test::scratchDir("tracked-silent");
  const auto config = test::trackedConfig(dir, "tests/data/tracked.toml", test::freeUdpPort());
  const auto r = test::runSandstorm("--config " + config.string() + " --frames 30");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(
      r.output.find("0 frames received, 0 dropped, 0 from other hosts dropped, none measured"),
      std::string::npos)
      << r.output;
}

TEST(TrackedCave, APortInUseStopsTheStartNamingThePort) {
  DTrackReceiver holder({.port = 0});
  const auto dir = test::scratchDir("tracked-port");
  const auto config = test::trackedConfig(dir, "tests/data/tracked.toml", holder.port());
  const auto r = test::runSandstorm("--config " + config.string() + " --frames 5");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("UDP port " + std::to_string(holder.port())), std::string::npos)
      << r.output;
}

TEST(TrackedCave, ReplayAsASourceNeedsARecordedSession) {
  const auto dir = test::scratchDir("tracked-replay-source");
  const auto config = test::trackedConfig(dir, "tests/data/tracked.toml", 5000, "");
  test::writeFile(dir / "replay.toml", "include = \"run.toml\"\n[tracking]\nsource = \"replay\"\n");
  const auto r = test::runSandstorm("--config " + (dir / "replay.toml").string() + " --frames 5");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("--replay"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sandstorm
