// Writing the files a run produces (screenshots, particle dumps, logs) so
// that a failure is an Error naming the path and the reason, never a
// silently short file: writeFile() checks every write and the close (a full
// disk shows only there). checkOutputFile() and checkOutputDirectory() try
// the path before a run starts, so a bad one stops the run before anything
// is computed.
#pragma once

#include <filesystem>
#include <span>
#include <string>

namespace sandstorm {

// Writes `bytes` to `path` (replacing it). Throws Error "what path: reason".
void writeFile(const std::filesystem::path& path, std::span<const char> bytes,
               const std::string& what);

// Whether `path` can be written: its folder exists and a file can be made
// there (or the existing file opened for writing); nothing is left behind.
// Throws Error "what path: reason".
void checkOutputFile(const std::filesystem::path& path, const std::string& what);

// Makes `dir` (and its parents) and checks that files can be made in it.
void checkOutputDirectory(const std::filesystem::path& dir, const std::string& what);

}  // namespace sandstorm
