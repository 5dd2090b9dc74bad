// FrameStageTimer: the GPU time a frame spends in each stage (the particle
// update, the scene, the particles, the post pass), summed over the frame's
// views, from GL_TIMESTAMP queries around each stage read back a few frames
// later: measuring never waits for the GPU. (Timestamps, not GL_TIME_ELAPSED:
// llvmpipe starts some elapsed-time queries at zero.) One per wall, on the
// wall's thread.
//   timer.begin(Stage::Scene); ...draw...; timer.end();   // any number a frame
//   timer.endFrame();
//   if (auto t = timer.latest()) ... (*t)[Stage::Scene] ms
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "contexts/gl/objects.h"

namespace sandstorm::gl {

class FrameStageTimer {
 public:
  enum Stage { Update = 0, Scene = 1, Particles = 2, Post = 3 };
  static constexpr int kStages = 4;
  using Times = std::array<double, kStages>;  // ms

  void begin(Stage stage);
  void end();
  void endFrame();
  // The newest frame whose measurements are all in; nullopt before the first.
  const std::optional<Times>& latest() const { return latest_; }

 private:
  static constexpr int kFrames = 4;     // frames in flight before a slot is reused
  static constexpr int kPerFrame = 12;  // stage measurements a frame (views x stages)
  struct Frame {
    std::array<Query, kPerFrame> starts, ends;
    std::array<Stage, kPerFrame> stages{};
    int used = 0;
    bool closed = false;
  };
  void harvest();

  std::array<Frame, kFrames> frames_;
  int current_ = 0;
  bool open_ = false;
  std::optional<Times> latest_;
};

}  // namespace sandstorm::gl
