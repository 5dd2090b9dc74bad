#include "core/io/vtk_progress.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>

#include <algorithm>
#include <system_error>

#include "core/util/progress_meter.h"

namespace sandstorm {

namespace {

double fileSize(const std::filesystem::path& file) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  return ec ? 0.0 : double(size);
}

}  // namespace

VtkProgress::VtkProgress(vtkAlgorithm* reader, const std::filesystem::path& file)
    : VtkProgress(reader, "reading " + file.filename().string(), fileSize(file)) {}

VtkProgress::VtkProgress(vtkAlgorithm* algorithm, const std::string& what, double bytes)
    : algorithm_(algorithm),
      owned_(std::make_unique<ProgressMeter>(what, std::uint64_t(bytes), "bytes")),
      meter_(owned_.get()),
      bytes_(bytes) {
  observe();
}

VtkProgress::VtkProgress(vtkAlgorithm* algorithm, ProgressMeter& shared, double bytes)
    : algorithm_(algorithm), meter_(&shared), bytes_(bytes) {
  observe();
}

void VtkProgress::observe() {
  callback_ = vtkSmartPointer<vtkCallbackCommand>::New();
  callback_->SetClientData(this);
  callback_->SetCallback([](vtkObject*, unsigned long, void* self, void* data) {
    auto* me = static_cast<VtkProgress*>(self);
    const double fraction = std::clamp(data ? *static_cast<double*>(data) : 0.0, 0.0, 1.0);
    const double done = fraction * me->bytes_;
    const auto step = std::uint64_t(std::max(done - me->reported_, 0.0));
    if (step == 0) return;
    me->meter_->add(step);
    me->reported_ += double(step);
  });
  tag_ = algorithm_->AddObserver(vtkCommand::ProgressEvent, callback_);
}

VtkProgress::~VtkProgress() {
  algorithm_->RemoveObserver(tag_);
}

void VtkProgress::finish() {
  if (owned_) owned_->finish();
}

}  // namespace sandstorm
