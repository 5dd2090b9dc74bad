#include "core/sim/main_context.h"

#include <gtest/gtest.h>

#include "core/util/error.h"

namespace sandstorm {
namespace {

MainContext::Options fixed() {
  MainContext::Options o;
  o.fixedDt = 0.02f;
  o.seed = 11;
  return o;
}

TEST(MainContext, ChangesTakeEffectAtTheNextPacket) {
  MainContext main(ParticleState{}, FieldUpdate{}, fixed());
  const FramePacket p0 = main.next();
  EXPECT_EQ(p0.frame, 0u);
  EXPECT_TRUE(p0.fieldUpdate);  // packet 0 always carries the field
  EXPECT_TRUE(p0.changes.empty());

  main.set("render.size", 0.3f);
  main.set("Maximum", 1234.0f);
  EXPECT_FLOAT_EQ(main.state().render.size, ParticleState{}.render.size);  // not yet
  const FramePacket p1 = main.next();
  ASSERT_EQ(p1.changes.size(), 2u);
  EXPECT_EQ(p1.changes[1].key, "sim.maximum");  // canonical key travels
  EXPECT_FALSE(p1.fieldUpdate);
  EXPECT_EQ(main.state().sim.maximum, 1234);

  // A replica that applies the packets holds the same state.
  ParticleState replica = main.initialState();
  for (const FramePacket* p : {&p0, &p1})
    for (const StateChange& c : p->changes)
      applyChange(replica, c);
  EXPECT_FLOAT_EQ(replica.render.size, 0.3f);
  EXPECT_EQ(replica.sim.maximum, 1234);
}

TEST(MainContext, ValidatesAgainstPendingRequests) {
  MainContext main(ParticleState{}, FieldUpdate{}, fixed());
  EXPECT_THROW(main.set("emitter.1.rate", 10.0f), Error);
  main.addEmitter(Emitter{});
  EXPECT_NO_THROW(main.set("emitter.1.rate", 10.0f));  // valid once the queued add applies
  EXPECT_THROW(main.set("render.size", std::string("x")), Error);
  const FramePacket p = main.next();
  EXPECT_EQ(p.changes.size(), 2u);
  EXPECT_EQ(p.emission.size(), 2u);
}

TEST(MainContext, ScheduledChangesLandOnTheirFrame) {
  MainContext main(ParticleState{}, FieldUpdate{}, fixed());
  main.schedule(3, StateChange::set("render.size", 0.5f));
  for (std::uint32_t f = 0; f < 5; ++f) {
    const FramePacket p = main.next();
    EXPECT_EQ(p.changes.size(), f == 3 ? 1u : 0u) << "frame " << f;
  }
}

TEST(MainContext, PauseStopsTimeAndEmission) {
  ParticleState s;
  s.emitters[0].rate = 1e4f;
  MainContext main(s, FieldUpdate{}, fixed());
  FramePacket p = main.next();
  EXPECT_FLOAT_EQ(p.simDt, 0.02f);
  EXPECT_GT(p.emission[0], 0u);
  main.set("sim.paused", true);
  p = main.next();
  EXPECT_FLOAT_EQ(p.simDt, 0.0f);
  EXPECT_EQ(p.emission[0], 0u);
  main.set("sim.paused", false);
  main.set("sim.time_scale", 0.5f);
  p = main.next();
  EXPECT_FLOAT_EQ(p.simDt, 0.01f);
}

TEST(MainContext, MaximumIsCappedAtTheBufferLimitWithAMessage) {
  MainContext::Options o = fixed();
  o.capacityLimit = 50000;
  MainContext main(ParticleState{}, FieldUpdate{}, o);
  const AttributeResult r = main.set("sim.maximum", 80000);
  EXPECT_EQ(std::get<int>(r.applied), 50000);
  EXPECT_NE(r.warning.find("capped to 50000"), std::string::npos) << r.warning;
  main.next();
  EXPECT_EQ(main.state().sim.maximum, 50000);
}

TEST(MainContext, AFixedStepIsTakenAsGiven) {
  MainContext::Options o;
  o.fixedDt = 0.25f;  // longer than maxDt, which only bounds measured stalls
  MainContext main(ParticleState{}, FieldUpdate{}, o);
  EXPECT_FLOAT_EQ(main.next().dt, 0.25f);
  EXPECT_DOUBLE_EQ(main.next().time, 0.25);
}

TEST(MainContext, RecordsEveryChangeWithItsFrame) {
  MainContext main(ParticleState{}, FieldUpdate{}, fixed());
  std::vector<std::pair<std::uint32_t, std::string>> log;
  main.setChangeListener(
      [&](std::uint32_t f, const StateChange& c) { log.emplace_back(f, describe(c)); });
  main.next();
  main.set("render.size", 0.5f);
  main.next();
  main.next();
  main.removeEmitter(0);
  main.next();
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log[0], std::make_pair(1u, std::string("render.size = 0.5")));
  EXPECT_EQ(log[1], std::make_pair(3u, std::string("remove emitter 0")));
}

}  // namespace
}  // namespace sandstorm
