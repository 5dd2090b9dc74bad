#include "core/sim/session_log.h"

#include <gtest/gtest.h>

#include "core/util/error.h"

namespace sandstorm {
namespace {

TEST(SessionLog, FormatsAndParsesEveryKindOfChange) {
  Emitter e;
  e.shape = EmitterShape::Disc;
  e.position = {1, -2, 0.5f};
  e.rate = 2500;
  const std::vector<StateChange> changes = {StateChange::set("emitter.0.rate", 50000.0f),
                                            StateChange::set("sim.gravity", glm::vec3(0, 0, -3)),
                                            StateChange::set("render.mode", std::string("points")),
                                            StateChange::addEmitter(e),
                                            StateChange::removeEmitter(1),
                                            StateChange::reset()};
  std::string text;
  for (std::size_t i = 0; i < changes.size(); ++i)
    text += std::to_string(10 * i) + " " + formatChange(changes[i]) + "\n";
  const std::vector<ScheduledChange> parsed = parseSessionLog(text, "log");
  ASSERT_EQ(parsed.size(), changes.size());
  for (std::size_t i = 0; i < changes.size(); ++i) {
    EXPECT_EQ(parsed[i].frame, 10u * i);
    EXPECT_EQ(describe(parsed[i].change), describe(changes[i]));
  }
  EXPECT_EQ(parsed[3].change.emitter.shape, EmitterShape::Disc);
  EXPECT_EQ(parsed[3].change.emitter.position, e.position);
  EXPECT_EQ(parsed[3].change.emitter.rate, 2500.0f);
}

TEST(SessionLog, BadLinesNameTheirLine) {
  const auto errorOf = [](const std::string& text) {
    try {
      parseSessionLog(text, "s.log");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(
      errorOf("# c\n5 set render.size 0.1\nx set a b\n").find("s.log:3: expected a frame number"),
      std::string::npos);
  EXPECT_NE(errorOf("5 set render.sise 1\n").find("s.log:1: unknown attribute 'render.sise'"),
            std::string::npos);
  EXPECT_NE(errorOf("5 jump\n").find("s.log:1: unknown change 'jump'"), std::string::npos);
  EXPECT_NE(errorOf("9 reset\n5 reset\n").find("s.log:2: frame 5 comes after frame 9"),
            std::string::npos);
  EXPECT_NE(errorOf("5 set sim.maximum lots\n").find("s.log:1"), std::string::npos);
}

}  // namespace
}  // namespace sandstorm
