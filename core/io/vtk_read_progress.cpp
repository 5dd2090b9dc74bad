#include "core/io/vtk_read_progress.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>

#include <algorithm>
#include <system_error>

#include "core/util/progress_meter.h"

namespace sandstorm {

VtkReadProgress::VtkReadProgress(vtkAlgorithm* reader, const std::filesystem::path& file)
    : reader_(reader) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  bytes_ = ec ? 0.0 : double(size);
  meter_ = std::make_unique<ProgressMeter>("reading " + file.filename().string(),
                                           std::uint64_t(bytes_), "bytes");
  callback_ = vtkSmartPointer<vtkCallbackCommand>::New();
  callback_->SetClientData(this);
  callback_->SetCallback([](vtkObject*, unsigned long, void* self, void* data) {
    auto* me = static_cast<VtkReadProgress*>(self);
    const double fraction = std::clamp(data ? *static_cast<double*>(data) : 0.0, 0.0, 1.0);
    const double done = fraction * me->bytes_;
    const auto step = std::uint64_t(std::max(done - me->reported_, 0.0));
    if (step == 0) return;
    me->meter_->add(step);
    me->reported_ += double(step);
  });
  tag_ = reader_->AddObserver(vtkCommand::ProgressEvent, callback_);
}

VtkReadProgress::~VtkReadProgress() {
  reader_->RemoveObserver(tag_);
}

void VtkReadProgress::finish() {
  meter_->finish();
}

}  // namespace sandstorm
