#include "core/field/field_timeline.h"

#include <gtest/gtest.h>

#include "core/sim/main_context.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

std::vector<std::shared_ptr<const VectorField>> frames(int n) {
  std::vector<std::shared_ptr<const VectorField>> out;
  for (int i = 0; i < n; ++i) {
    auto f = std::make_shared<VectorField>(Box{{0, 0, 0}, {1, 1, 1}}, glm::ivec3(2));
    for (glm::vec3& v : f->values())
      v = glm::vec3(float(i));
    out.push_back(f);
  }
  return out;
}

TEST(FieldTimeline, FindsTheFramesAroundATimeAndTheWeight) {
  const FieldTimeline t({0.0, 1.0, 3.0}, frames(3));
  const auto at = [&](double time, bool loop) { return t.at(time, loop); };
  EXPECT_EQ(at(-1.0, false).first, 0u);
  EXPECT_EQ(at(-1.0, false).second, 1u);
  EXPECT_FLOAT_EQ(at(-1.0, false).weight, 0.0f);
  EXPECT_EQ(at(0.25, false).first, 0u);
  EXPECT_EQ(at(0.25, false).second, 1u);
  EXPECT_FLOAT_EQ(at(0.25, false).weight, 0.25f);
  EXPECT_EQ(at(2.0, false).first, 1u);
  EXPECT_FLOAT_EQ(at(2.0, false).weight, 0.5f);
  EXPECT_EQ(at(9.0, false).first, 2u);  // held at the end
  EXPECT_EQ(at(9.0, false).second, 2u);
  // Looping: the period is 3 s of frames plus one average step (1.5 s) back to the first.
  EXPECT_EQ(at(3.75, true).first, 2u);
  EXPECT_EQ(at(3.75, true).second, 0u);
  EXPECT_FLOAT_EQ(at(3.75, true).weight, 0.5f);
  EXPECT_EQ(at(4.5 + 0.25, true).second, 1u);  // wrapped into the next period
  EXPECT_FLOAT_EQ(at(4.5 + 0.25, true).weight, 0.25f);
}

TEST(FieldTimeline, RefusesMismatchedFrames) {
  auto f = frames(2);
  f.push_back(std::make_shared<VectorField>(Box{{0, 0, 0}, {2, 1, 1}}, glm::ivec3(2)));
  EXPECT_THROW(FieldTimeline({0, 1, 2}, f), Error);
  EXPECT_THROW(FieldTimeline({0, 0}, frames(2)), Error);
  EXPECT_THROW(FieldTimeline({0}, frames(2)), Error);
}

// A step off the first's grid is named by what differs: its points per axis,
// or (the same points) its bounds, digits enough to tell them apart.
TEST(FieldTimeline, AStepOffTheGridSaysWhetherItsPointsOrItsBoundsDiffer) {
  const auto message = [](std::shared_ptr<const VectorField> step) {
    FieldTimeline t({0.0, 1.0}, frames(2));
    try {
      t.append(2.0, std::move(step));
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(std::make_shared<VectorField>(Box{{0, 0, 0}, {1, 1, 1}}, glm::ivec3(3, 2, 2))),
            "the step at 2 s has a 3x2x2 grid, not the first step's 2x2x2; expected every step "
            "on the same grid");
  EXPECT_EQ(
      message(std::make_shared<VectorField>(Box{{0, 0, 0}, {1, 1, 1.0000001f}}, glm::ivec3(2))),
      "the step at 2 s has bounds [0,0,0]..[1,1,1.00000012] m, not the first step's "
      "[0,0,0]..[1,1,1] m; expected every step on the same grid");
  EXPECT_EQ(message(frames(3)[2]), "no error");
}

TEST(FieldTimeline, TheMainContextSendsAFrameOnceAndTheWeightEveryFrame) {
  MainContext::Options o;
  o.fixedDt = 0.25f;
  MainContext main(ParticleState{}, FieldUpdate{}, o);
  main.setFieldTimeline(FieldTimeline({0.0, 1.0, 2.0}, frames(3)), FieldPlacement{});
  std::vector<int> updates;
  std::vector<float> blends;
  for (int f = 0; f < 9; ++f) {
    const FramePacket p = main.next();
    updates.push_back(p.fieldUpdate ? int(p.fieldUpdate->field->values()[0].x) : -1);
    blends.push_back(p.fieldBlend);
  }
  // Frames 0-3 blend 0 -> 1, 4-7 blend 1 -> 2, 8 wraps into 2 -> 0: a new pair travels only at 0, 4
  // and 8.
  EXPECT_EQ(updates, (std::vector<int>{0, -1, -1, -1, 1, -1, -1, -1, 2}));
  EXPECT_FLOAT_EQ(blends[1], 0.25f);
  EXPECT_FLOAT_EQ(blends[6], 0.5f);
  main.set("field.paused", true);
  const float held = main.next().fieldBlend;
  EXPECT_FLOAT_EQ(main.next().fieldBlend, held);
}

TEST(FieldTimeline, AppendsFramesThatFollowAndShareTheGrid) {
  FieldTimeline t({0.0, 1.0}, frames(2));
  t.append(2.5, frames(3)[2]);
  EXPECT_EQ(t.size(), 3u);
  EXPECT_EQ(t.time(2), 2.5);
  EXPECT_THROW(t.append(2.5, frames(1)[0]), Error);  // not after the last
  EXPECT_THROW(
      t.append(3.0, std::make_shared<VectorField>(Box{{0, 0, 0}, {2, 1, 1}}, glm::ivec3(2))),
      Error);
  EXPECT_THROW(t.append(3.0, nullptr), Error);
  EXPECT_EQ(t.size(), 3u);  // nothing half-applied
}

// A growing field: each appended frame comes into use at the next packet
// with field.follow (the newest frame, unblended), and only the new frame travels.
TEST(FieldTimeline, FollowingAGrowingFieldShowsEachNewFrameAtTheNextPacket) {
  MainContext::Options o;
  o.fixedDt = 0.25f;
  ParticleState s;
  s.field.follow = true;
  MainContext main(s, FieldUpdate{}, o);
  auto all = frames(4);
  main.setFieldTimeline(FieldTimeline({0.0}, {all[0]}), FieldPlacement{});
  FramePacket p = main.next();
  ASSERT_TRUE(p.fieldUpdate);
  EXPECT_EQ(p.fieldUpdate->field->values()[0].x, 0.0f);
  EXPECT_FALSE(main.next().fieldUpdate);  // nothing new
  for (int k = 1; k < 4; ++k) {
    main.appendFieldFrame(double(k), all[std::size_t(k)]);
    p = main.next();
    ASSERT_TRUE(p.fieldUpdate) << k;
    EXPECT_EQ(p.fieldUpdate->field->values()[0].x, float(k));
    EXPECT_EQ(p.fieldBlend, 0.0f);
    EXPECT_FALSE(main.next().fieldUpdate);
  }
  EXPECT_EQ(main.fieldFrames(), 4u);
  // A frame that does not fit is refused; the field stays.
  EXPECT_THROW(main.appendFieldFrame(
                   9.0, std::make_shared<VectorField>(Box{{0, 0, 0}, {2, 2, 2}}, glm::ivec3(2))),
               Error);
  EXPECT_EQ(main.fieldFrames(), 4u);
  EXPECT_FALSE(main.next().fieldUpdate);
  // Without a timeline there is nothing to grow.
  MainContext still(s, FieldUpdate{.field = all[0]}, o);
  EXPECT_THROW(still.appendFieldFrame(1.0, all[1]), Error);
}

}  // namespace
}  // namespace sandstorm
