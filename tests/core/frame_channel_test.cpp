// FrameChannel::waitFor: a wall that opened before its first packet waits for
// it a moment at a time (showing what it waits for in between) and sees the
// packet, the channel's close, or the field offered ahead of the packet, as
// soon as it comes.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "core/sim/frame_channel.h"

namespace sandstorm {
namespace {

using namespace std::chrono_literals;

std::shared_ptr<const FramePacket> packet(std::uint32_t frame) {
  auto p = std::make_shared<FramePacket>();
  p->frame = frame;
  return p;
}

TEST(FrameChannel, WaitForTimesOutUntilThePacketComesThenTakeHasIt) {
  FrameChannel channel(2);
  EXPECT_FALSE(channel.waitFor(0, 20ms));
  std::thread publisher([&] {
    std::this_thread::sleep_for(50ms);
    channel.publish(packet(0));
  });
  int waits = 0;
  while (!channel.waitFor(0, 5ms))
    ++waits;
  publisher.join();
  EXPECT_GT(waits, 0);  // it came only after the publisher's sleep
  // Each consumer has it; after the first one takes it, the second still does.
  const auto first = channel.take(0);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->frame, 0u);
  EXPECT_FALSE(channel.waitFor(0, 1ms));  // consumer 0 took everything there was
  EXPECT_TRUE(channel.waitFor(1, 1ms));
  EXPECT_EQ(channel.take(1)->frame, 0u);
}

TEST(FrameChannel, WaitForAnswersAtOnceWhenTheChannelCloses) {
  FrameChannel channel(1);
  std::thread closer([&] {
    std::this_thread::sleep_for(30ms);
    channel.close();
  });
  const auto before = std::chrono::steady_clock::now();
  EXPECT_TRUE(channel.waitFor(0, 10s));
  EXPECT_LT(std::chrono::steady_clock::now() - before, 5s);  // woken by the close, not the timeout
  closer.join();
  EXPECT_EQ(channel.take(0), nullptr);
}

// The field packet 0 is to carry, offered before it (AppRun::takeField): it
// wakes a waiting wall, each consumer takes it once, and publishing packet 0
// lets it go (the channel would otherwise hold a grid for the whole run).
TEST(FrameChannel, AnOfferedFieldWakesEachWallOnceAndGoesWithPacketZero) {
  FrameChannel channel(2);
  EXPECT_EQ(channel.takeOfferedField(0), nullptr);
  auto field = std::make_shared<FieldUpdate>();
  const std::weak_ptr<const FieldUpdate> held = field;
  std::thread offerer([&] {
    std::this_thread::sleep_for(30ms);
    channel.offerField(field);
  });
  const auto before = std::chrono::steady_clock::now();
  EXPECT_TRUE(channel.waitFor(0, 10s));
  EXPECT_LT(std::chrono::steady_clock::now() - before, 5s);  // woken by the offer
  offerer.join();
  EXPECT_EQ(channel.takeOfferedField(0), field);
  EXPECT_EQ(channel.takeOfferedField(0), nullptr);  // once
  EXPECT_FALSE(channel.waitFor(0, 1ms));            // nothing more for consumer 0
  EXPECT_TRUE(channel.waitFor(1, 1ms));             // consumer 1 has not taken it
  field.reset();
  channel.publish(packet(0));
  EXPECT_EQ(channel.takeOfferedField(1), nullptr);  // a hint before packet 0 only
  EXPECT_TRUE(held.expired());
  EXPECT_EQ(channel.take(1)->frame, 0u);
}

}  // namespace
}  // namespace sandstorm
