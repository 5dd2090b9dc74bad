// FieldPlayer: a streamed field's playback waits for a step that is not read
// yet (the clock stands, the walls keep their pair and weight), a replay given
// the recorded waits plays the same packets whatever its disk does, and a step
// that cannot be read stops playback with its name while the run goes on.
#include "core/sim/field_player.h"

#include <gtest/gtest.h>

#include <set>

#include "core/sim/main_context.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// Steps whose reading the test controls: a step is in memory once `arrived`
// holds it; wait() reads it at once (a replay); `broken` ones never read.
class ScriptedSteps final : public FieldSteps {
 public:
  explicit ScriptedSteps(int n) {
    for (int i = 0; i < n; ++i) {
      auto f = std::make_shared<VectorField>(Box{{0, 0, 0}, {1, 1, 1}}, glm::ivec3(2));
      for (glm::vec3& v : f->values())
        v = glm::vec3(float(i));
      frames.push_back(f);
    }
  }
  void want(const std::vector<std::size_t>& order) override { wanted = order; }
  std::shared_ptr<const VectorField> get(std::size_t i) override {
    return arrived.count(i) ? frames[i] : nullptr;
  }
  std::shared_ptr<const VectorField> wait(std::size_t i) override {
    if (broken.count(i)) throw Error(failure(i));
    waited.insert(i);
    arrived.insert(i);
    return frames[i];
  }
  std::string failure(std::size_t i) const override {
    return broken.count(i) ? name(i) + ": truncated" : "";
  }
  std::string name(std::size_t i) const override { return "step_" + std::to_string(i) + ".vti"; }
  std::size_t capacity() const override { return 4; }
  std::size_t size() const override { return frames.size(); }
  std::vector<std::size_t> resident() const override { return {arrived.begin(), arrived.end()}; }
  FileIdentity identity(std::size_t i) const override {
    return {true, 1000 + i, std::int64_t(i) * 7};
  }

  std::vector<std::shared_ptr<const VectorField>> frames;
  std::set<std::size_t> arrived, waited, broken;
  std::vector<std::size_t> wanted;
};

struct Shown {
  int field = -1, next = -1;  // the pair a packet sent (-1: none)
  float blend = 0.0f;
  bool operator==(const Shown&) const = default;
};

// Runs `frames` packets; before frame f, `arrive(f)` may let steps arrive.
std::vector<Shown> play(MainContext& main, int frames, const std::function<void(int)>& arrive) {
  std::vector<Shown> out;
  for (int f = 0; f < frames; ++f) {
    arrive(f);
    const FramePacket p = main.next();
    Shown s;
    if (p.fieldUpdate) {
      s.field = int(p.fieldUpdate->field->values()[0].x);
      s.next = int(p.fieldUpdate->next->values()[0].x);
    }
    s.blend = p.fieldBlend;
    out.push_back(s);
  }
  return out;
}

MainContext::Options quarterSteps() {
  MainContext::Options o;
  o.fixedDt = 0.25f;  // four frames a step of 1 s
  return o;
}

ParticleState unlooped() {
  ParticleState s;
  s.field.loop = false;
  return s;
}

TEST(FieldPlayer, WaitsForAStepNotReadYetAndAReplayWaitsAtTheSameFrames) {
  auto steps = std::make_shared<ScriptedSteps>(5);
  MainContext live(unlooped(), FieldUpdate{}, quarterSteps());
  std::vector<std::uint32_t> waits;
  live.setFieldWaitListener([&](std::uint32_t f) { waits.push_back(f); });
  live.setFieldTimeline(FieldTimeline({0, 1, 2, 3, 4}, steps), FieldPlacement{});
  EXPECT_EQ(steps->waited, (std::set<std::size_t>{0, 1}));  // the start waits for its pair
  // Step 2 is read only before frame 6, step 3 at once.
  const std::vector<Shown> shown = play(live, 12, [&](int f) {
    if (f == 0) steps->arrived.insert(3);
    if (f == 6) steps->arrived.insert(2);
  });
  EXPECT_EQ(waits, (std::vector<std::uint32_t>{4, 5}));
  // Frames 4 and 5 keep the pair (0, 1) at its last weight; frame 6 starts (1, 2) at 0.
  EXPECT_EQ(shown[0], (Shown{0, 1, 0.0f}));
  EXPECT_EQ(shown[3], (Shown{-1, -1, 0.75f}));
  EXPECT_EQ(shown[4], (Shown{-1, -1, 0.75f}));
  EXPECT_EQ(shown[5], (Shown{-1, -1, 0.75f}));
  EXPECT_EQ(shown[6], (Shown{1, 2, 0.0f}));
  EXPECT_EQ(shown[7], (Shown{-1, -1, 0.25f}));
  EXPECT_EQ(shown[10], (Shown{2, 3, 0.0f}));
  // The read-ahead asks for the pair, then the steps after it.
  EXPECT_EQ(steps->wanted, (std::vector<std::size_t>{2, 3, 4}));

  // A replay whose disk is fast: told the waits, it shows exactly the same.
  auto fast = std::make_shared<ScriptedSteps>(5);
  MainContext replay(unlooped(), FieldUpdate{}, quarterSteps());
  replay.replayFieldWaits({4, 5});
  replay.setFieldTimeline(FieldTimeline({0, 1, 2, 3, 4}, fast), FieldPlacement{});
  EXPECT_EQ(play(replay, 12, [&](int f) { fast->arrived.insert(std::size_t(f % 5)); }), shown);
  // A replay whose disk is slower still reads what it needs (nothing arrives by itself).
  auto slow = std::make_shared<ScriptedSteps>(5);
  MainContext slowReplay(unlooped(), FieldUpdate{}, quarterSteps());
  slowReplay.replayFieldWaits({4, 5});
  slowReplay.setFieldTimeline(FieldTimeline({0, 1, 2, 3, 4}, slow), FieldPlacement{});
  EXPECT_EQ(play(slowReplay, 12, [](int) {}), shown);
  // Without the waits, the same steps play another sequence: the waits matter.
  auto other = std::make_shared<ScriptedSteps>(5);
  MainContext unrecorded(unlooped(), FieldUpdate{}, quarterSteps());
  unrecorded.replayFieldWaits({});
  unrecorded.setFieldTimeline(FieldTimeline({0, 1, 2, 3, 4}, other), FieldPlacement{});
  EXPECT_NE(play(unrecorded, 12, [](int) {}), shown);
}

TEST(FieldPlayer, AStepThatCannotBeReadStopsPlaybackAndTheRunGoesOn) {
  auto steps = std::make_shared<ScriptedSteps>(5);
  steps->broken.insert(2);
  MainContext main(unlooped(), FieldUpdate{}, quarterSteps());
  std::vector<std::uint32_t> waits;
  main.setFieldWaitListener([&](std::uint32_t f) { waits.push_back(f); });
  main.setFieldTimeline(FieldTimeline({0, 1, 2, 3, 4}, steps), FieldPlacement{});
  steps->arrived.insert(3);
  const std::vector<Shown> shown = play(main, 16, [](int) {});
  for (int f = 4; f < 16; ++f)
    EXPECT_EQ(shown[std::size_t(f)], (Shown{-1, -1, 0.75f})) << f;  // the last pair read, held
  EXPECT_TRUE(waits.empty());                                       // stopped, not waiting
  const FieldPlaybackStatus status = main.fieldStatus();
  EXPECT_NE(status.error.find("step_2.vti: truncated"), std::string::npos);
  EXPECT_EQ(status.first, 0u);
  EXPECT_TRUE(status.waitingFor.empty());
  // The same in a replay, where the step is waited for and fails.
  auto again = std::make_shared<ScriptedSteps>(5);
  again->broken.insert(2);
  MainContext replay(unlooped(), FieldUpdate{}, quarterSteps());
  replay.replayFieldWaits({});
  replay.setFieldTimeline(FieldTimeline({0, 1, 2, 3, 4}, again), FieldPlacement{});
  EXPECT_EQ(play(replay, 16, [](int) {}), shown);
}

TEST(FieldPlayer, ASecondStepThatCannotBeReadHoldsTheFirstAndAFirstStopsTheStart) {
  auto steps = std::make_shared<ScriptedSteps>(3);
  steps->broken.insert(1);
  MainContext main(unlooped(), FieldUpdate{}, quarterSteps());
  main.setFieldTimeline(FieldTimeline({0, 1, 2}, steps), FieldPlacement{});
  const std::vector<Shown> shown = play(main, 8, [](int) {});
  EXPECT_EQ(shown[0], (Shown{0, 0, 0.0f}));
  for (int f = 1; f < 8; ++f)
    EXPECT_EQ(shown[std::size_t(f)], (Shown{-1, -1, 0.0f})) << f;
  EXPECT_NE(main.fieldStatus().error.find("step_1.vti"), std::string::npos);
  auto first = std::make_shared<ScriptedSteps>(3);
  first->broken.insert(0);
  MainContext start(unlooped(), FieldUpdate{}, quarterSteps());
  EXPECT_THROW(start.setFieldTimeline(FieldTimeline({0, 1, 2}, first), FieldPlacement{}), Error);
}

TEST(FieldPlayer, TheStatusSaysWhatPlaybackWaitsForAndWhatIsInMemory) {
  auto steps = std::make_shared<ScriptedSteps>(5);
  MainContext main(unlooped(), FieldUpdate{}, quarterSteps());
  main.setFieldTimeline(FieldTimeline({0, 1, 2, 3, 4}, steps), FieldPlacement{});
  play(main, 5, [](int) {});
  const FieldPlaybackStatus status = main.fieldStatus();
  EXPECT_TRUE(status.streamed);
  EXPECT_EQ(status.steps, 5u);
  EXPECT_EQ(status.waitingFor, "step_2.vti");
  EXPECT_EQ(status.resident, (std::vector<std::size_t>{0, 1}));
  EXPECT_DOUBLE_EQ(status.time, 1.0);  // stood still at the step it waits for
}

TEST(FieldPlayer, PacketsNameTheStepAfterThePairInTheDirectionOfPlayOnceItIsInMemory) {
  // What walls upload ahead of need (FramePacket::upcomingField): the step
  // after the pair forwards, before it backwards, around a loop; none while
  // it is not read, at the end of an unlooped series, or when asked not to.
  const auto upcoming = [](MainContext& main, int frames) {
    std::vector<int> out;
    for (int f = 0; f < frames; ++f) {
      const FramePacket p = main.next();
      out.push_back(p.upcomingField ? int(p.upcomingField->values()[0].x) : -1);
    }
    return out;
  };
  const auto play = [&](bool loop, float speed, const std::set<std::size_t>& arrived,
                        bool uploadAhead = true) {
    auto steps = std::make_shared<ScriptedSteps>(4);
    ParticleState s;
    s.field.loop = loop;
    s.field.speed = speed;
    MainContext::Options o = quarterSteps();
    o.uploadAhead = uploadAhead;
    MainContext main(s, FieldUpdate{}, o);
    steps->arrived = arrived;
    main.setFieldTimeline(FieldTimeline({0, 1, 2, 3}, steps), FieldPlacement{});
    return upcoming(main, 16);
  };
  const std::set<std::size_t> all{0, 1, 2, 3};
  // Forwards, four frames a step: pairs (0,1) (1,2) (2,3), then held at the end.
  EXPECT_EQ(play(false, 1.0f, all),
            (std::vector<int>{2, 2, 2, 2, 3, 3, 3, 3, -1, -1, -1, -1, -1, -1, -1, -1}));
  // Looping: (2,3) is followed by (3,0), then (0,1).
  EXPECT_EQ(play(true, 1.0f, all),
            (std::vector<int>{2, 2, 2, 2, 3, 3, 3, 3, 0, 0, 0, 0, 1, 1, 1, 1}));
  // Backwards around the loop from t = 0: (0,1) at the start, then (3,0),
  // (2,3), (1,2), (0,1).
  EXPECT_EQ(play(true, -1.0f, all),
            (std::vector<int>{3, 2, 2, 2, 2, 1, 1, 1, 1, 0, 0, 0, 0, 3, 3, 3}));
  // Step 2 never read: nothing to upload ahead while the pair (0,1) plays.
  EXPECT_EQ(play(false, 1.0f, {0, 1, 3})[0], -1);
  EXPECT_EQ(play(true, 1.0f, all, false), std::vector<int>(16, -1));
}

TEST(FieldPlayer, PacketsNameThePairByStepAndFileAndHowToReadAhead) {
  // What a cluster rank reading the series itself goes by (FieldUpdate::series):
  // the pair's steps are those the packet's grids are, their files are the
  // reader's, and reading ahead from the packet asks for what rank 0 asked.
  for (const float speed : {1.0f, -1.0f}) {
    SCOPED_TRACE(speed);
    auto steps = std::make_shared<ScriptedSteps>(5);
    steps->arrived = {0, 1, 2, 3, 4};
    ParticleState s;
    s.field.loop = true;
    s.field.speed = speed;
    MainContext main(s, FieldUpdate{}, quarterSteps());
    main.setFieldTimeline(FieldTimeline({0, 1, 2, 3, 4}, steps), FieldPlacement{});
    int updates = 0;
    for (int f = 0; f < 24; ++f) {
      const FramePacket p = main.next();
      if (!p.fieldUpdate) continue;
      ++updates;
      ASSERT_TRUE(p.fieldUpdate->series);
      const FieldSeriesRef& r = *p.fieldUpdate->series;
      EXPECT_EQ(r.steps, 5u);
      EXPECT_EQ(int(r.first), int(p.fieldUpdate->field->values()[0].x));
      EXPECT_EQ(int(r.second), int(p.fieldUpdate->next->values()[0].x));
      EXPECT_EQ(r.firstFile, steps->identity(r.first));
      EXPECT_EQ(r.secondFile, steps->identity(r.second));
      EXPECT_EQ(r.backwards, speed < 0.0f);
      EXPECT_TRUE(r.loop);
      EXPECT_EQ(FieldTimeline::aheadOrder(r.steps, steps->capacity(), {r.first, r.second, 0.0f},
                                          r.backwards, r.loop),
                steps->wanted);
    }
    EXPECT_GE(updates, 5);  // the first pair, then a new one every four frames
  }
  // Frames held in memory are named by their grids only.
  MainContext held(ParticleState{}, FieldUpdate{}, quarterSteps());
  auto frame = std::make_shared<VectorField>(Box{{0, 0, 0}, {1, 1, 1}}, glm::ivec3(2));
  held.setFieldTimeline(FieldTimeline({0, 1}, {frame, frame}), FieldPlacement{});
  const FramePacket p = held.next();
  ASSERT_TRUE(p.fieldUpdate);
  EXPECT_FALSE(p.fieldUpdate->series);
}

}  // namespace
}  // namespace sandstorm
