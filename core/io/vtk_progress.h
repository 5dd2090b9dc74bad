// VtkProgress: a VTK reader's or writer's progress events shown as
// ProgressMeter lines (bytes, the rate, the time left), so that opening or
// writing a large file says how far it is rather than going quiet for half a
// minute. Work that ends within a second says nothing.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include <vtkSmartPointer.h>

class vtkAlgorithm;
class vtkCallbackCommand;

namespace sandstorm {

class ProgressMeter;

class VtkProgress {
 public:
  // `what`: "reading wind.vti"; `bytes`: what the whole work moves.
  VtkProgress(vtkAlgorithm* algorithm, const std::string& what, double bytes);
  // Reading `file`: its size.
  VtkProgress(vtkAlgorithm* reader, const std::filesystem::path& file);
  // One of several readers at once adding to `shared` (`bytes`: this one's
  // share); the meter's owner finishes it.
  VtkProgress(vtkAlgorithm* algorithm, ProgressMeter& shared, double bytes);
  ~VtkProgress();
  VtkProgress(const VtkProgress&) = delete;
  VtkProgress& operator=(const VtkProgress&) = delete;

  // The work is over: the total time, if anything was said (an owned meter).
  void finish();

 private:
  void observe();

  vtkAlgorithm* algorithm_;
  unsigned long tag_ = 0;
  vtkSmartPointer<vtkCallbackCommand> callback_;
  std::unique_ptr<ProgressMeter> owned_;
  ProgressMeter* meter_ = nullptr;
  double bytes_ = 0.0, reported_ = 0.0;
};

}  // namespace sandstorm
