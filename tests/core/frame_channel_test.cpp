// FrameChannel::waitFor: a wall that opened before its first packet waits for
// it a moment at a time (showing what it waits for in between) and sees the
// packet, or the channel's close, as soon as it comes.
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

}  // namespace
}  // namespace sandstorm
