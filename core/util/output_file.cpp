#include "core/util/output_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "core/util/error.h"

namespace sandstorm {
namespace {

std::string reason() {
  return errno ? std::strerror(errno) : "unknown error";
}

}  // namespace

void writeFile(const std::filesystem::path& path, std::span<const char> bytes,
               const std::string& what) {
  errno = 0;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw Error(concat(what, " ", path.string(), ": cannot open for writing: ", reason()));
  const std::size_t written = std::fwrite(bytes.data(), 1, bytes.size(), f);
  const int flushed = std::fflush(f);
  const int closed = std::fclose(f);
  if (written != bytes.size() || flushed != 0 || closed != 0)
    throw Error(concat(what, " ", path.string(), ": writing ", bytes.size(),
                       " bytes failed: ", reason(), " (is the disk full?)"));
}

void checkOutputFile(const std::filesystem::path& path, const std::string& what) {
  std::error_code ec;
  const std::filesystem::path folder =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(folder, ec))
    throw Error(
        concat(what, " ", path.string(), ": the folder ", folder.string(), " does not exist"));
  if (std::filesystem::is_directory(path, ec))
    throw Error(concat(what, " ", path.string(), ": is a folder; expected a file name"));
  const bool existed = std::filesystem::exists(path, ec);
  errno = 0;
  std::FILE* f = std::fopen(path.c_str(), existed ? "ab" : "wb");
  if (!f) throw Error(concat(what, " ", path.string(), ": cannot write there: ", reason()));
  std::fclose(f);
  if (!existed) std::filesystem::remove(path, ec);
}

void checkOutputDirectory(const std::filesystem::path& dir, const std::string& what) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw Error(concat(what, " ", dir.string(), ": cannot make the folder: ",
                       ec ? ec.message() : "a file of that name is in the way"));
  checkOutputFile(dir / ".sandstorm-write-test", what);
}

}  // namespace sandstorm
