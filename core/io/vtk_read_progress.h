// VtkReadProgress: a VTK reader's progress events shown as ProgressMeter
// lines (the file's bytes, the rate, the time left), so that opening a large
// file says how far it is rather than going quiet for half a minute. Work
// that ends within a second says nothing.
#pragma once

#include <filesystem>
#include <memory>

#include <vtkSmartPointer.h>

class vtkAlgorithm;
class vtkCallbackCommand;

namespace sandstorm {

class ProgressMeter;

class VtkReadProgress {
 public:
  VtkReadProgress(vtkAlgorithm* reader, const std::filesystem::path& file);
  ~VtkReadProgress();
  VtkReadProgress(const VtkReadProgress&) = delete;
  VtkReadProgress& operator=(const VtkReadProgress&) = delete;

  // Reading is over: the total time, if anything was said.
  void finish();

 private:
  vtkAlgorithm* reader_;
  unsigned long tag_ = 0;
  vtkSmartPointer<vtkCallbackCommand> callback_;
  std::unique_ptr<ProgressMeter> meter_;
  double bytes_ = 0.0, reported_ = 0.0;
};

}  // namespace sandstorm
