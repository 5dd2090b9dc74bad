// FieldStream: the steps of a field a running simulation writes (a folder,
// or a .pvd that grows: FieldStreamScanner says when each is complete), read
// on a thread of their own so the frame loop never waits for a file. Each
// frame the main thread takes the steps read since the last one and appends
// them to the main context's timeline (AppRun), so every wall gets a step at
// the same frame. A step that does not load (half-written beyond repair,
// malformed, another grid) is skipped with a warning naming the file; the
// last good field stays and the run goes on.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "core/field/vector_field.h"
#include "core/io/field_stream_scanner.h"
#include "core/io/load_options.h"

namespace sandstorm {

class FieldStream {
 public:
  struct Step {
    double time = 0.0;
    std::filesystem::path file;
    std::shared_ptr<const VectorField> field;
    std::uint32_t completeAt = 0;  // the frame during which the file was found complete
  };

  // `frameNow`: the main context's next frame (to stamp steps with). Starts the thread.
  FieldStream(std::shared_ptr<FieldStreamScanner> scanner, LoadOptions options,
              std::function<std::uint32_t()> frameNow);
  ~FieldStream();
  FieldStream(const FieldStream&) = delete;
  FieldStream& operator=(const FieldStream&) = delete;

  // The steps read since the last call, in order (main thread).
  std::vector<Step> take();

  // Loads one step's file (the thread's work; a replay does it on the main
  // thread). Throws Error naming the file.
  static std::shared_ptr<const VectorField> load(const std::filesystem::path& file,
                                                 const LoadOptions& options);

 private:
  void run();

  std::shared_ptr<FieldStreamScanner> scanner_;
  LoadOptions options_;
  std::function<std::uint32_t()> frameNow_;
  std::mutex mutex_;
  std::vector<Step> ready_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace sandstorm
