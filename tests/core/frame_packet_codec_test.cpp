// The cluster's wire format: every member of a FramePacket survives a round
// trip bit for bit (every kind of change and attribute value, the emitter of
// an add, the viewer, the field reference); field grids travel apart and are
// found by hash; truncated, corrupt or padded buffers are clear Errors.
#include "core/sim/frame_packet_codec.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "core/sim/field_store.h"
#include "core/sim/main_context.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

std::shared_ptr<const VectorField> grid(float scale, glm::ivec3 dims = {5, 4, 3}) {
  auto f = std::make_shared<VectorField>(Box{{-1, -2, 0}, {1, 2, 3}}, dims);
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        f->at(i, j, k) = scale * glm::vec3(i, j - 0.5f, std::sin(float(k)));
  return f;
}

Emitter oddEmitter() {
  Emitter e;
  e.shape = EmitterShape::Sphere;
  e.position = {1.5f, -2.25f, 0.125f};
  e.width = 2;
  e.depth = 3;
  e.height = 0.5f;
  e.radius = 0.75f;
  e.rate = 12345.5f;
  e.rateVariance = 17;
  e.lifetime = 3.5f;
  e.lifetimeVariance = 0.25f;
  e.velocity = {0.1f, -0.2f, 4};
  e.spread = 0.3f;
  e.enabled = false;
  e.kind = EmitterKind::Molecules;
  return e;
}

FramePacket fullPacket() {
  FramePacket p;
  p.frame = 4242;
  p.dt = 1.0f / 60.0f;
  p.simDt = 0.5f / 60.0f;
  p.time = 70.123456789012345;
  p.simTime = 35.0000000001;
  p.seed = 0xfedcba9876543210ull;
  p.reset = true;
  p.changes = {StateChange::set("sim.paused", true),
               StateChange::set("sim.maximum", 123456),
               StateChange::set("render.size", 0.1f + 1e-9f),
               StateChange::set("sim.gravity", glm::vec3(0.1f, -0.0f, -9.81f)),
               StateChange::set("sim.integrator", std::string("rk4")),
               StateChange::set("field.expression_z", std::string("0.1 + 0.05*x")),
               StateChange::addEmitter(oddEmitter()),
               StateChange::removeEmitter(3),
               StateChange::reset()};
  p.emission = {0, 7, 4000000000u};
  p.fieldUpdate = std::make_shared<const FieldUpdate>(
      FieldUpdate{.field = grid(1),
                  .placement = {.offset = {1, 2, 3},
                                .scale = 0.35f,
                                .rotation = glm::mat3(0, 1, 0, -1, 0, 0, 0, 0, 1)},
                  .next = grid(2),
                  .series = FieldSeriesRef{.steps = 1000,
                                           .first = 998,
                                           .second = 0,
                                           .firstFile = {true, 1600000084ull, -1234567890123ll},
                                           .secondFile = {},
                                           .backwards = false,
                                           .loop = true},
                  .range = {.minSpeed = 0.25f,
                            .maxSpeed = 9.5f,
                            .minVelocity = {-1, -2, -3},
                            .maxVelocity = {4, 5, 6},
                            .minScalar = 0.125f,
                            .maxScalar = 7.5f},
                  .colorGrid = grid(3),
                  .colorArray = "pressure"});
  p.viewer.head.position = {0.1f, 0.2f, 1.7f};
  p.viewer.head.right = {0, -1, 0};
  p.viewer.head.eyeSeparation = 0.063f;
  p.viewer.navigation.offset = {-1, 2.6f, 0};
  p.viewer.navigation.yawRadians = 0.3f;
  p.viewer.navigation.scale = 0.35f;
  p.fieldBlend = 0.625f;
  p.tracking.active = true;
  p.tracking.stale = true;
  p.tracking.trackerFrame = 987654321u;
  p.tracking.headTracked = true;
  p.tracking.head = {{0.1f, -0.2f, 1.65f}, glm::mat3(0.8f, 0.6f, 0, -0.6f, 0.8f, 0, 0, 0, 1)};
  p.tracking.wand = {.present = true,
                     .tracked = true,
                     .pose = {{0.3f, 0.4f, 1.1f}, glm::mat3(1, 0, 0, 0, 0, 1, 0, -1, 0)},
                     .buttons = 0x80000021u,
                     .joystick = {-0.5f, 1.0f}};
  p.wand = {.visible = true,
            .origin = {0.3f, 0.4f, 1.1f},
            .end = {0.3f, 1.5f, 1.1f},
            .target = WandTarget::Menu,
            .emitter = 3,
            .holding = true};
  return p;
}

template <class T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

void expectSameEmitter(const Emitter& a, const Emitter& b) {
  EXPECT_EQ(a.shape, b.shape);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.radius, b.radius);
  EXPECT_EQ(a.rate, b.rate);
  EXPECT_EQ(a.rateVariance, b.rateVariance);
  EXPECT_EQ(a.lifetime, b.lifetime);
  EXPECT_EQ(a.lifetimeVariance, b.lifetimeVariance);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.spread, b.spread);
  EXPECT_EQ(a.enabled, b.enabled);
  EXPECT_EQ(a.kind, b.kind);
}

TEST(FramePacketCodec, EveryMemberSurvivesARoundTrip) {
  const FramePacket p = fullPacket();
  FieldStore store;
  const FieldRefs refs{store.identify(p.fieldUpdate->field), store.identify(p.fieldUpdate->next),
                       0x5eed5a1234ull};
  FieldRefs got;
  const FramePacket q = decodePacket(encodePacket(p, refs), &got);
  EXPECT_EQ(q.frame, p.frame);
  EXPECT_TRUE(sameBits(q.dt, p.dt));
  EXPECT_TRUE(sameBits(q.simDt, p.simDt));
  EXPECT_TRUE(sameBits(q.time, p.time));
  EXPECT_TRUE(sameBits(q.simTime, p.simTime));
  EXPECT_EQ(q.seed, p.seed);
  EXPECT_EQ(q.reset, p.reset);
  ASSERT_EQ(q.changes.size(), p.changes.size());
  for (std::size_t i = 0; i < p.changes.size(); ++i) {
    SCOPED_TRACE(describe(p.changes[i]));
    EXPECT_EQ(q.changes[i].kind, p.changes[i].kind);
    EXPECT_EQ(q.changes[i].key, p.changes[i].key);
    EXPECT_EQ(q.changes[i].value, p.changes[i].value);
    EXPECT_EQ(q.changes[i].index, p.changes[i].index);
    expectSameEmitter(q.changes[i].emitter, p.changes[i].emitter);
  }
  EXPECT_EQ(q.changes[3].value.index(), 3u);  // the vec3 stayed a vec3 (not text)
  EXPECT_TRUE(std::signbit(std::get<glm::vec3>(q.changes[3].value).y));  // -0 stays -0: bits travel
  EXPECT_EQ(q.emission, p.emission);
  ASSERT_TRUE(q.fieldUpdate);
  EXPECT_EQ(got.field, refs.field);
  EXPECT_EQ(got.next, refs.next);
  EXPECT_EQ(got.sparse, refs.sparse);  // a sparse grid's hash; its words travel apart
  EXPECT_NE(got.field, got.next);
  EXPECT_EQ(got.colorGrid, std::optional<std::string>("pressure"));  // the receiver makes it
  EXPECT_FALSE(q.fieldUpdate->field);                                // grids travel apart
  EXPECT_EQ(q.fieldUpdate->placement.offset, p.fieldUpdate->placement.offset);
  EXPECT_EQ(q.fieldUpdate->placement.scale, p.fieldUpdate->placement.scale);
  EXPECT_EQ(q.fieldUpdate->placement.rotation, p.fieldUpdate->placement.rotation);
  EXPECT_EQ(q.fieldUpdate->range, p.fieldUpdate->range);
  EXPECT_EQ(q.fieldUpdate->series, p.fieldUpdate->series);  // steps and files, by name
  EXPECT_EQ(q.viewer.head.position, p.viewer.head.position);
  EXPECT_EQ(q.viewer.head.right, p.viewer.head.right);
  EXPECT_EQ(q.viewer.head.eyeSeparation, p.viewer.head.eyeSeparation);
  EXPECT_EQ(q.viewer.navigation.offset, p.viewer.navigation.offset);
  EXPECT_EQ(q.viewer.navigation.yawRadians, p.viewer.navigation.yawRadians);
  EXPECT_EQ(q.viewer.navigation.scale, p.viewer.navigation.scale);
  EXPECT_EQ(q.fieldBlend, p.fieldBlend);
  EXPECT_EQ(q.tracking, p.tracking);
  EXPECT_EQ(q.wand, p.wand);
  // Encoding the decoded packet gives the same bytes: nothing was lost.
  EXPECT_EQ(encodePacket(q, got), encodePacket(p, refs));
}

TEST(FramePacketCodec, NaNAndInfinityTravelAsBits) {
  FramePacket p;
  p.dt = std::numeric_limits<float>::infinity();
  p.fieldBlend = std::bit_cast<float>(0x7fc01234u);  // a NaN with a payload
  const FramePacket q = decodePacket(encodePacket(p));
  EXPECT_TRUE(std::isinf(q.dt));
  EXPECT_EQ(std::bit_cast<std::uint32_t>(q.fieldBlend), 0x7fc01234u);
  EXPECT_FALSE(q.fieldUpdate);
}

TEST(FramePacketCodec, APacketsSizeDoesNotDependOnTheFieldOrTheParticles) {
  FramePacket p = fullPacket();
  const std::size_t small = encodePacket(p).size();
  p.fieldUpdate =
      std::make_shared<const FieldUpdate>(FieldUpdate{.field = grid(1, {64, 64, 64}),
                                                      .series = p.fieldUpdate->series,
                                                      .colorGrid = grid(3, {64, 64, 64}),
                                                      .colorArray = "pressure"});
  EXPECT_EQ(encodePacket(p).size(), small);
  // A frame of the identity scene (one emitter, no change) is about a hundred bytes.
  FramePacket plain;
  plain.emission = {150};
  EXPECT_LT(encodePacket(plain).size(), 128u);
}

TEST(FramePacketCodec, PacketsOfAMainContextRoundTrip) {
  ParticleState state;
  MainContext::Options options;
  options.fixedDt = 0.02f;
  MainContext main(state, FieldUpdate{.field = grid(1)}, options);
  main.set("emitter.0.rate", 5000.0f);
  main.addEmitter(oddEmitter());
  for (int i = 0; i < 5; ++i) {
    const FramePacket p = main.next();
    FieldStore store;
    const FieldRefs refs{p.fieldUpdate ? store.identify(p.fieldUpdate->field) : 0};
    const std::vector<std::byte> bytes = encodePacket(p, refs);
    EXPECT_EQ(encodePacket(decodePacket(bytes), refs), bytes) << "frame " << i;
  }
}

TEST(FramePacketCodec, FieldGridsRoundTripAndHashByContent) {
  const std::shared_ptr<const VectorField> a = grid(1);
  const std::vector<std::byte> bytes = encodeField(*a);
  const VectorField b = decodeField(bytes);
  EXPECT_EQ(b.dims(), a->dims());
  EXPECT_EQ(b.bounds().min, a->bounds().min);
  EXPECT_EQ(b.bounds().max, a->bounds().max);
  EXPECT_EQ(b.indexScale(), a->indexScale());
  ASSERT_EQ(b.pointCount(), a->pointCount());
  EXPECT_EQ(std::memcmp(b.values().data(), a->values().data(), a->values().size_bytes()), 0);
  EXPECT_EQ(fieldHash(b), fieldHash(*a));
  EXPECT_NE(fieldHash(*grid(1.0001f)), fieldHash(*a));
}

TEST(FramePacketCodec, AGridsScalarArraysTravelWithIt) {
  VectorField a = *grid(1);
  std::vector<float> t(a.pointCount()), p(a.pointCount());
  for (std::size_t i = 0; i < t.size(); ++i) {
    t[i] = 280.0f + 0.5f * float(i);
    p[i] = -float(i * i);
  }
  a.addScalars("temperature", t);
  a.addScalars("p", p);
  const std::vector<std::byte> bytes = encodeField(a);
  const VectorField b = decodeField(bytes);
  ASSERT_EQ(b.scalars().size(), 2u);
  EXPECT_EQ(b.scalars()[0].name, "temperature");
  EXPECT_EQ(b.scalars()[0].values, t);
  EXPECT_EQ(b.scalars()[1].name, "p");
  EXPECT_EQ(b.scalars()[1].values, p);
  EXPECT_NE(fieldHash(a), fieldHash(*grid(1)));  // the arrays are part of the grid's identity
  for (std::size_t n = 0; n < bytes.size(); ++n)
    try {
      decodeField(std::span(bytes).first(n));
      ADD_FAILURE() << "a grid cut to " << n << " bytes decoded";
    } catch (const Error&) {
    }
}

void expectError(std::span<const std::byte> bytes, bool packet, const std::string& expected) {
  try {
    if (packet)
      decodePacket(bytes);
    else
      decodeField(bytes);
    ADD_FAILURE() << "no error; expected one mentioning '" << expected << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

TEST(FramePacketCodec, AHalfPrecisionGridTravelsAsHalvesExactly) {
  VectorField a = *grid(1.37f);
  const std::size_t floatBytes = encodeField(a).size();
  a.roundToHalf();
  const std::vector<std::byte> bytes = encodeField(a);
  EXPECT_EQ(bytes.size(), floatBytes - 6 * a.pointCount() + 0);
  const VectorField b = decodeField(bytes);
  EXPECT_TRUE(b.halfPrecision());
  ASSERT_EQ(b.pointCount(), a.pointCount());
  const std::span<const glm::vec3> sent =
      std::as_const(a).values();  // reading keeps the halves' mark
  EXPECT_EQ(std::memcmp(b.values().data(), sent.data(), sent.size_bytes()), 0);
  EXPECT_EQ(fieldHash(b), fieldHash(a));
  EXPECT_NE(fieldHash(a), fieldHash(*grid(1.37f)));
  for (std::size_t n = 0; n < bytes.size(); ++n)  // every truncation refused
    EXPECT_THROW(decodeField(std::span(bytes).first(n)), Error) << n << " bytes";
  std::vector<std::byte> infinite = bytes;
  infinite[43] = std::byte{0x00};  // the first vector's x: 0x7c00, a half infinity
  infinite[44] = std::byte{0x7c};
  expectError(infinite, false, "not finite");
}

TEST(FramePacketCodec, EveryTruncationIsAClearError) {
  FieldStore store;
  const FramePacket p = fullPacket();
  const std::vector<std::byte> bytes =
      encodePacket(p, {store.identify(p.fieldUpdate->field), store.identify(p.fieldUpdate->next)});
  for (std::size_t n = 0; n < bytes.size(); ++n)
    expectError(std::span(bytes).first(n), true, "truncated");
  const std::vector<std::byte> field = encodeField(*grid(1));
  for (std::size_t n = 0; n < 40; ++n)
    expectError(std::span(field).first(n), false, "truncated");
  expectError(std::span(field).first(field.size() - 1), false, "bytes of vectors");
}

TEST(FramePacketCodec, ASeriesStepBeyondTheSeriesIsRefused) {
  FramePacket p = fullPacket();
  FieldUpdate update = *p.fieldUpdate;
  update.series->second = 1000;  // of steps 0..999
  p.fieldUpdate = std::make_shared<const FieldUpdate>(update);
  expectError(encodePacket(p), true, "steps 998 and 1000 of a series of 1000");
}

TEST(FramePacketCodec, CorruptBuffersAreClearErrors) {
  const std::vector<std::byte> good = encodePacket(fullPacket());
  auto with = [&](std::size_t at, std::uint8_t value) {
    std::vector<std::byte> b = good;
    b.at(at) = std::byte{value};
    return b;
  };
  expectError(with(0, 'X'), true, "not a frame packet");
  expectError(with(4, 13), true, "version 13");
  expectError(with(42, 7), true, "reset");  // the reset flag: 0 or 1
  expectError(with(46, 0xff), true,
              "change count");  // a huge count is refused before any allocation
  expectError(with(47, 9), true, "change.kind");
  std::vector<std::byte> padded = good;
  padded.push_back(std::byte{0});
  expectError(padded, true, "unexpected bytes");
  expectError(encodeField(*grid(1)), true, "not a frame packet");  // a grid is not a packet
  expectError(good, false, "not a field grid");

  std::vector<std::byte> field = encodeField(*grid(1));
  field[30] = std::byte{0xff};  // dims.x = -1 (little-endian, high byte)
  field[31] = std::byte{0xff};
  field[32] = std::byte{0xff};
  field[33] = std::byte{0xff};
  expectError(field, false, "expected positive dims");
  field = encodeField(*grid(1));
  field[42] = std::byte{2};  // after magic, version, bounds and dims: the half flag, 0 or 1
  expectError(field, false, "half precision");
}

TEST(FieldStore, SenderAndReceiverHoldTheSameGridsWithoutTalking) {
  // A timeline of five frames played as (0,1), (1,2), ... (4,0): the sender ships
  // a grid only when the mirror says the receiver lacks it.
  std::vector<std::shared_ptr<const VectorField>> frames;
  for (int i = 0; i < 5; ++i)
    frames.push_back(grid(float(i + 1)));
  FieldStore sender(3), receiver(3);
  int shipped = 0;
  for (int round = 0; round < 3; ++round) {
    for (int i = 0; i < 5; ++i) {
      const std::uint64_t used[2] = {sender.identify(frames[std::size_t(i)]),
                                     sender.identify(frames[std::size_t((i + 1) % 5)])};
      FieldStore::Grids incoming;
      for (int u = 0; u < 2; ++u)
        if (!sender.contains(used[u])) {
          incoming[used[u]] = std::make_shared<VectorField>(
              decodeField(encodeField(*frames[std::size_t((i + u) % 5)])));
          ++shipped;
        }
      sender.use(
          used,
          incoming);  // the sender's mirror (it could hold its own grids; the same calls suffice)
      receiver.use(used, incoming);
      for (const std::uint64_t h : used) {
        ASSERT_TRUE(receiver.contains(h));
        EXPECT_EQ(fieldHash(*receiver.find(h)), h);
      }
      EXPECT_EQ(receiver.size(), sender.size());
    }
  }
  EXPECT_EQ(shipped,
            2 + 4 + 5 + 5);  // the first round needs every frame; each later wrap only the new ones
  EXPECT_LE(receiver.size(), 3u);
}

TEST(FieldStore, AMissingGridIsAClearError) {
  FieldStore store;
  const std::uint64_t h[1] = {0x1234};
  try {
    store.use(h, {});
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("1234"), std::string::npos) << e.what();
  }
}

TEST(FieldStore, PinnedGridsStayAndHashesAreCachedPerGrid) {
  FieldStore store(2);
  const auto pinned = grid(9);
  store.pin(store.identify(pinned), pinned);
  for (int i = 0; i < 6; ++i) {
    const auto g = grid(float(i + 1));
    const std::uint64_t h[1] = {store.identify(g)};
    store.use(h, {{h[0], g}});
  }
  EXPECT_TRUE(store.contains(fieldHash(*pinned)));
  EXPECT_EQ(store.size(), 3u);
}

}  // namespace
}  // namespace sandstorm
