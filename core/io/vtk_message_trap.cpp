#include "core/io/vtk_message_trap.h"

#include <mutex>

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

thread_local VtkMessageTrap* activeTrap = nullptr;

// "ERROR: In file.cxx, line 455\nvtkReader (0x55..): Number of points ..." ->
// "Number of points ...".
std::string clean(const char* text) {
  std::string s = text ? text : "";
  if (const auto at = s.rfind("): "); at != std::string::npos) s = s.substr(at + 3);
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\r'))
    s.pop_back();
  std::size_t i = 0;
  while (i < s.size() && (s[i] == ' ' || s[i] == '\n'))
    ++i;
  return s.substr(i);
}

// VTK's warnings that mean data went missing (its legacy readers warn, not
// fail, when the data is shorter than declared).
bool warningMeansFailure(const std::string& s) {
  return s.find("rror") != std::string::npos || s.find("Premature") != std::string::npos ||
         s.find("mismatch") != std::string::npos;
}

void deliver(const char* text, bool isError) {
  std::string message = clean(text);
  if (message.empty()) return;
  if (activeTrap) {
    activeTrap->record(std::move(message), isError);
  } else if (isError) {
    log::warn("VTK: ", message);
  } else {
    log::debug("VTK: ", message);
  }
}

class ForwardingOutputWindow : public vtkOutputWindow {
 public:
  static ForwardingOutputWindow* New();
  vtkTypeMacro(ForwardingOutputWindow, vtkOutputWindow)
  void DisplayText(const char* text) override { deliver(text, false); }
  void DisplayErrorText(const char* text) override { deliver(text, true); }
  void DisplayWarningText(const char* text) override { deliver(text, false); }
  void DisplayGenericWarningText(const char* text) override { deliver(text, false); }
  void DisplayDebugText(const char*) override {}
};
vtkStandardNewMacro(ForwardingOutputWindow)

    void onEvent(vtkObject*, unsigned long event, void* clientData, void* callData) {
  auto* trap = static_cast<VtkMessageTrap*>(clientData);
  trap->record(clean(static_cast<const char*>(callData)), event == vtkCommand::ErrorEvent);
}

}  // namespace

void VtkMessageTrap::installOutputWindow() {
  static std::once_flag once;
  std::call_once(once, [] {
    vtkNew<ForwardingOutputWindow> window;
    vtkOutputWindow::SetInstance(window);
  });
}

VtkMessageTrap::VtkMessageTrap(std::filesystem::path file)
    : file_(std::move(file)), previous_(activeTrap) {
  installOutputWindow();
  activeTrap = this;
}

VtkMessageTrap::~VtkMessageTrap() {
  for (auto& [algorithm, tag] : observers_)
    algorithm->RemoveObserver(tag);
  activeTrap = previous_;
}

void VtkMessageTrap::watch(vtkAlgorithm* algorithm) {
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(onEvent);
  callback->SetClientData(this);
  const vtkSmartPointer<vtkAlgorithm> held(algorithm);
  observers_.emplace_back(held, algorithm->AddObserver(vtkCommand::ErrorEvent, callback));
  observers_.emplace_back(held, algorithm->AddObserver(vtkCommand::WarningEvent, callback));
}

void VtkMessageTrap::record(std::string message, bool isError) {
  log::debug("VTK (", file_.string(), "): ", message);
  if (isError || warningMeansFailure(message)) {
    errors_.push_back(std::move(message));
  } else {
    warnings_.push_back(std::move(message));
  }
}

void VtkMessageTrap::throwIfFailed(const std::string& what) const {
  if (errors_.empty()) return;
  std::string list;
  for (const std::string& e : errors_) {
    if (list.find(e) != std::string::npos) continue;  // VTK often repeats itself
    if (!list.empty()) list += "; ";
    list += e;
  }
  throw Error(concat(file_.string(), ": ", what, " failed (the file is damaged, truncated or not ",
                     "what it claims to be); VTK says: ", list));
}

}  // namespace sandstorm
