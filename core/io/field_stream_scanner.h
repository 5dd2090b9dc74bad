// FieldStreamScanner: which steps of a field that a running simulation writes
// are complete, looked at again and again (FieldStream polls it). The source
// is either
//   - a folder: its field files (any format loadField reads, .pvd aside; hidden
//     names and .tmp/.part files left alone; where a step is an index beside
//     its pieces, .pvtu or .vtm, only the indexes) in name order; step k of them
//     gets the time k * `interval`. A file is complete once two looks at
//     least `settle` seconds apart found it with the same non-zero size and
//     modification time (a file still being written grows between them; a
//     writer that pauses longer than `settle` mid-file is caught half-written,
//     and the step fails to load and is skipped). One that appears with a name
//     before the newest step's is skipped, with a message;
//   - a .pvd collection: its entries in time order, those after the newest
//     step's time. An entry is complete once the .pvd lists it and its file
//     has kept its size over two looks (simulations write the entry after
//     the file, and its file has settled as above). A .pvd being rewritten that does not parse is
//     looked at again next time; an entry whose file stays missing for `patience` looks is skipped,
//     with a message, and so is a time of several parts (read only unwatched:
//     loadFieldParts).
// A step is reported once. Not thread-safe: one owner polls it.
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace sandstorm {

class FieldStreamScanner {
 public:
  struct Step {
    double time = 0.0;
    std::filesystem::path file;
  };

  FieldStreamScanner(std::filesystem::path source, double interval = 1.0, int patience = 50,
                     double settle = 0.0);

  // Whether `source` is watched as a folder (else a .pvd).
  bool folder() const { return folder_; }

  // One look: the steps that became complete since the last one, in order.
  // `messages` gets a line for each step skipped.
  std::vector<Step> poll(std::vector<std::string>& messages);
  // Steps a poll reported that the caller did not take (the start takes the
  // first complete step; those found with it follow): the next poll reports
  // them first.
  void putBack(std::vector<Step> steps);

 private:
  struct Seen {
    std::uintmax_t size = 0;
    std::filesystem::file_time_type written;
    int looks = 0;                                // in a row with this size and time
    std::chrono::steady_clock::time_point since;  // first seen so
  };

  std::vector<Step> pollFolder(std::vector<std::string>& messages);
  std::vector<Step> pollPvd(std::vector<std::string>& messages);
  // Whether `file` has looked the same (and non-empty) twice in a row now.
  bool settled(const std::filesystem::path& file);

  std::filesystem::path source_;
  bool folder_;
  double interval_;
  int patience_;
  double settle_;
  std::map<std::filesystem::path, Seen> seen_;
  std::optional<std::filesystem::path> newestFile_;  // a folder's newest step
  std::optional<double> newestTime_;                 // a .pvd's newest step
  int folderSteps_ = 0;
  std::map<std::filesystem::path, int> missing_;  // .pvd entries without their file yet
  std::vector<Step> back_;                        // put back, for the next poll
};

}  // namespace sandstorm
