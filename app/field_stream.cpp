#include "app/field_stream.h"

#include <chrono>

#include "core/io/field_loader.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

FieldStream::FieldStream(std::shared_ptr<FieldStreamScanner> scanner, LoadOptions options,
                         std::function<std::uint32_t()> frameNow)
    : scanner_(std::move(scanner)), options_(std::move(options)), frameNow_(std::move(frameNow)) {
  thread_ = std::thread([this] { run(); });
}

FieldStream::~FieldStream() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

std::shared_ptr<const VectorField> FieldStream::load(const std::filesystem::path& file,
                                                     const LoadOptions& options) {
  // The readers say what they replaced (NaN or Inf values), naming the array.
  return std::make_shared<const VectorField>(loadField(file, options));
}

void FieldStream::run() {
  // A file found complete is read at once; the folder is looked at again
  // every few milliseconds (a step comes into use at the frame after it is read).
  constexpr auto kLookEvery = std::chrono::milliseconds(10);
  while (!stop_) {
    std::vector<std::string> messages;
    std::vector<FieldStreamScanner::Step> steps;
    try {
      steps = scanner_->poll(messages);
    } catch (const std::exception& e) {
      messages.push_back(concat("the field source: ", e.what()));
    }
    for (const std::string& m : messages)
      log::warn("field stream: ", m);
    for (const FieldStreamScanner::Step& s : steps) {
      const std::uint32_t frame = frameNow_();
      try {
        Step step{s.time, s.file, load(s.file, options_), frame};
        std::lock_guard lock(mutex_);
        ready_.push_back(std::move(step));
      } catch (const std::exception& e) {
        log::warn("field stream: the step at t = ", s.time, " s (", s.file.string(),
                  ") was skipped: ", e.what(), "; the last good field stays");
      }
    }
    std::this_thread::sleep_for(kLookEvery);
  }
}

std::vector<FieldStream::Step> FieldStream::take() {
  std::lock_guard lock(mutex_);
  std::vector<Step> out;
  out.swap(ready_);
  return out;
}

}  // namespace sandstorm
