// VtkMessageTrap: catches what VTK reports while one reader or filter runs, so
// that failures become sandstorm::Error instead of console noise and partial
// data.
//
// VTK readers rarely throw: they print an error (or, for short data, only a
// generic warning such as "Error reading binary data!") and return whatever
// they had. While a trap lives on a thread, every VTK message from that thread
// is recorded in it: error and warning events of the watched algorithms (via
// observers) and everything sent to vtkOutputWindow, which Sandstorm replaces
// once, process-wide, with one that forwards to log::debug (log::warn outside
// a trap). throwIfFailed() then throws with the messages.
#pragma once

#include <vtkAlgorithm.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sandstorm {

class VtkMessageTrap {
 public:
  explicit VtkMessageTrap(std::filesystem::path file);
  ~VtkMessageTrap();
  VtkMessageTrap(const VtkMessageTrap&) = delete;
  VtkMessageTrap& operator=(const VtkMessageTrap&) = delete;

  // Records the error and warning events of `algorithm` (and its executive).
  // The trap holds a reference to it, so it outlives the observers whatever the
  // order of destruction.
  void watch(vtkAlgorithm* algorithm);

  void record(std::string message, bool isError);
  bool failed() const { return !errors_.empty(); }
  const std::vector<std::string>& errors() const { return errors_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

  // Throws Error naming the file and `what` when VTK reported an error, or a
  // warning about reading data (VTK's only sign of truncated data).
  void throwIfFailed(const std::string& what) const;

  // Installs the forwarding output window (done by the constructor too).
  static void installOutputWindow();

 private:
  std::filesystem::path file_;
  std::vector<std::string> errors_;
  std::vector<std::string> warnings_;
  VtkMessageTrap* previous_;
  std::vector<std::pair<vtkSmartPointer<vtkAlgorithm>, unsigned long>> observers_;
};

}  // namespace sandstorm
