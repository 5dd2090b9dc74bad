// GridPrefetch: a time-varying field's coming frame uploaded ahead of need.
// What it hands over must hold the frame's values exactly (read back from the
// GPU and compared with the field), whether it was copied over several frames
// or finished on the spot; a frame it does not prepare is never handed over.
// Each test runs with the grid as a buffer and as a texture, copied by the
// test's thread and by an upload thread (a second context of the test's).
// That particles moved through a series with it match the CPU twin is
// ParticleBackendTest.TimeVaryingFieldsBlendTheSameOnBothSides.
#include "contexts/particles/grid_prefetch.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <chrono>
#include <thread>
#include <vector>

#include "core/util/error.h"
#include "core/util/half_float.h"
#include "tests/contexts/gl_test.h"

namespace sandstorm {
namespace {

struct Case {
  GpuField::Storage storage;
  bool uploadThread;
};

class GridPrefetchTest : public GlTest, public ::testing::WithParamInterface<Case> {
 protected:
  void SetUp() override {
    if (GetParam().uploadThread)
      uploads_ = std::make_unique<UploadThread>(
          std::make_unique<EglContext>(EglContext::Options{.share = context().get()}));
  }
  static GpuField::Storage storage() { return GetParam().storage; }
  UploadThread* uploads() const { return uploads_.get(); }

 private:
  std::unique_ptr<UploadThread> uploads_;
};

std::shared_ptr<const VectorField> frame(float seed, bool masked = false, bool half = false) {
  auto f = std::make_shared<VectorField>(Box{{0, 0, 0}, {1, 2, 3}}, glm::ivec3(7, 5, 9));
  for (std::size_t i = 0; i < f->pointCount(); ++i)
    f->values()[i] = glm::vec3(seed + 0.25f * float(i), -float(i % 7), seed * float(i % 3));
  if (masked) {
    std::vector<std::uint8_t> valid(f->pointCount(), 1);
    valid[11] = 0;
    f->setValidity(valid);
  }
  if (half) f->roundToHalf();
  return f;
}

// The grid's points as the GPU holds them (xyz, and the mask in w).
std::vector<glm::vec4> readBack(const GpuField& grid, std::size_t points) {
  std::vector<glm::vec4> out(points);
  if (grid.storage() == GpuField::Storage::HalfBuffer) {  // four halves a point
    grid.bind(GpuField::Slot::Current);
    GLint buffer = 0;
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 14, &buffer);
    std::vector<std::uint16_t> halves(points * 4);
    glGetNamedBufferSubData(GLuint(buffer), 0, GLsizeiptr(points * 8), halves.data());
    for (std::size_t i = 0; i < points; ++i)
      for (int c = 0; c < 4; ++c)
        out[i][c] = halfToFloat(halves[i * 4 + std::size_t(c)]);
  } else if (grid.storage() == GpuField::Storage::Buffer) {
    grid.bind(GpuField::Slot::Current);
    GLint buffer = 0;
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 14, &buffer);
    glGetNamedBufferSubData(GLuint(buffer), 0, GLsizeiptr(points * sizeof(glm::vec4)), out.data());
  } else {
    grid.bindTexture(3);
    glActiveTexture(GL_TEXTURE3);
    GLint texture = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_3D, &texture);
    glGetTextureImage(GLuint(texture), 0, GL_RGBA, GL_FLOAT, GLsizei(points * sizeof(glm::vec4)),
                      out.data());
    glActiveTexture(GL_TEXTURE0);
  }
  return out;
}

void expectHolds(const GpuField& grid, const VectorField& f) {
  const std::vector<glm::vec4> texels = readBack(grid, f.pointCount());
  for (std::size_t i = 0; i < f.pointCount(); ++i) {
    ASSERT_EQ(glm::vec3(texels[i]), f.values()[i]) << "point " << i;
    ASSERT_EQ(texels[i].w, f.hasValidity() && f.validity()[i] == 0 ? 0.0f : 1.0f) << "point " << i;
  }
}

// advance(wanted) once a frame until the frame is ready; the frames it took.
int advanceUntilReady(GridPrefetch& prefetch, const std::shared_ptr<const VectorField>& wanted) {
  for (int frames = 1; frames <= 2000; ++frames) {
    prefetch.advance(wanted);
    if (prefetch.ready() == wanted) return frames;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return -1;
}

TEST_P(GridPrefetchTest, AComingFrameIsCopiedOverSeveralFramesAndHandedOverWhole) {
  for (const bool half : {false, true})
    for (const bool masked : {false, true}) {
      SCOPED_TRACE(concat(masked ? "masked" : "unmasked", half ? ", half" : ""));
      const std::shared_ptr<const VectorField> f = frame(1.5f, masked, half);
      // Two z layers a frame at most: the nine layers take five frames' copies.
      const std::size_t texel = storage() == GpuField::Storage::Buffer ? (half ? 8 : 16)
                                : half                                 ? (masked ? 8 : 6)
                                                                       : (masked ? 16 : 12);
      const std::size_t layerBytes = 7 * 5 * texel;
      GridPrefetch prefetch(storage(), uploads(), 2 * layerBytes);
      const int frames = advanceUntilReady(prefetch, f);
      ASSERT_GT(frames, 0) << "never ready";
      // (An upload thread copies the frame at once.)
      if (!uploads()) {
        EXPECT_GE(frames, 5);
      }
      GpuField target(storage());
      target.upload(*frame(-3.0f));
      ASSERT_TRUE(prefetch.takeInto(target, f));
      EXPECT_EQ(target.holds(), f);
      EXPECT_EQ(target.storage(), storage() == GpuField::Storage::Buffer && half
                                      ? GpuField::Storage::HalfBuffer
                                      : storage());
      expectHolds(target, *f);
      EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
}

// A series: each frame taken while the next is wanted, so the two staging
// buffers take turns; every frame handed over holds its own values.
TEST_P(GridPrefetchTest, FramesOneAfterAnotherAreEachHandedOverWithTheirOwnValues) {
  for (const bool half : {false, true}) {
    SCOPED_TRACE(half ? "half" : "float");
    std::vector<std::shared_ptr<const VectorField>> frames;
    for (int i = 0; i < 6; ++i)
      frames.push_back(frame(float(i) + 0.5f, i % 2 == 1, half));
    GridPrefetch prefetch(storage(), uploads(),
                          1);  // a layer a frame: some are finished on the spot
    GpuField target(storage());
    for (std::size_t i = 0; i < frames.size(); ++i) {
      prefetch.advance(frames[i]);
      prefetch.advance(frames[i]);
      ASSERT_TRUE(prefetch.takeInto(target, frames[i])) << "frame " << i;
      // The next is wanted at once: it starts in the other staging buffer.
      if (i + 1 < frames.size()) prefetch.advance(frames[i + 1]);
      expectHolds(target, *frames[i]);
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
}

TEST_P(GridPrefetchTest, AFrameWantedBeforeItIsOnTheGpuIsFinishedOnTheSpot) {
  const std::shared_ptr<const VectorField> f = frame(2.0f);
  GridPrefetch prefetch(storage(), uploads(), 1);  // a layer a frame
  prefetch.advance(f);                             // the worker starts writing
  EXPECT_EQ(prefetch.ready(), nullptr);
  GpuField target(storage());
  ASSERT_TRUE(prefetch.takeInto(target, f));
  expectHolds(target, *f);
}

TEST_P(GridPrefetchTest, OnlyTheFrameItPreparesIsHandedOver) {
  const std::shared_ptr<const VectorField> f = frame(1.0f), g = frame(4.0f), h = frame(1.0f);
  GridPrefetch prefetch(storage(), uploads());
  GpuField target(storage());
  EXPECT_FALSE(prefetch.takeInto(target, f));  // nothing prepared yet
  ASSERT_GT(advanceUntilReady(prefetch, f), 0);
  // Another frame, even one of equal values, is not this one.
  EXPECT_FALSE(prefetch.takeInto(target, h));
  EXPECT_EQ(target.holds(), nullptr);
  // Wanting another frame prepares it in place of the first, in the same staging.
  ASSERT_GT(advanceUntilReady(prefetch, g), 0);
  EXPECT_FALSE(prefetch.takeInto(target, f));
  ASSERT_TRUE(prefetch.takeInto(target, g));
  expectHolds(target, *g);
}

TEST_P(GridPrefetchTest, TheGridGivenBackIsHandedOverAgainWhenWanted) {
  // Playback turned round: the frame the target held before is wanted again.
  const std::shared_ptr<const VectorField> f = frame(1.0f), g = frame(4.0f);
  GridPrefetch prefetch(storage(), uploads());
  GpuField target(storage());
  target.show(f);
  ASSERT_GT(advanceUntilReady(prefetch, g), 0);
  ASSERT_TRUE(prefetch.takeInto(target, g));
  EXPECT_EQ(prefetch.ready(), f);
  GpuField other(storage());
  ASSERT_TRUE(prefetch.takeInto(other, f));
  expectHolds(other, *f);
  expectHolds(target, *g);
}

TEST_P(GridPrefetchTest, AFrameBeyondTheStagingLimitIsNotStagedAndPrefetchingEnds) {
  const std::shared_ptr<const VectorField> f = frame(1.0f);  // 315 points: 5040 bytes as vec4
  GridPrefetch prefetch(storage(), uploads(), GridPrefetch::kCopyBytesPerFrame, 5000);
  for (int i = 0; i < 5; ++i)
    prefetch.advance(f);
  EXPECT_EQ(prefetch.ready(), nullptr);
  GpuField target(storage());
  EXPECT_FALSE(prefetch.takeInto(target, f));
  // It stays off: a smaller frame is not staged either (the series' frames share one grid).
  auto small = std::make_shared<VectorField>(Box{{0, 0, 0}, {1, 1, 1}}, glm::ivec3(2));
  prefetch.advance(small);
  prefetch.advance(small);
  EXPECT_EQ(prefetch.ready(), nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

INSTANTIATE_TEST_SUITE_P(Storages, GridPrefetchTest,
                         ::testing::Values(Case{GpuField::Storage::Buffer, false},
                                           Case{GpuField::Storage::Texture, false},
                                           Case{GpuField::Storage::Buffer, true},
                                           Case{GpuField::Storage::Texture, true}),
                         [](const auto& info) {
                           return std::string(info.param.storage == GpuField::Storage::Buffer
                                                  ? "Buffer"
                                                  : "Texture") +
                                  (info.param.uploadThread ? "ByAnUploadThread" : "");
                         });

}  // namespace
}  // namespace sandstorm
