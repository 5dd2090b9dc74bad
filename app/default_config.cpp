#include "app/default_config.h"

#include <system_error>

namespace sandstorm {

std::filesystem::path defaultConfig(std::string_view name) {
  const std::filesystem::path relative = std::filesystem::path("config") / name;
  std::error_code ec;
  if (std::filesystem::is_regular_file(relative, ec)) return relative;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec)
    for (const std::filesystem::path& dir : {exe.parent_path(), exe.parent_path().parent_path()})
      if (std::filesystem::is_regular_file(dir / relative, ec)) return dir / relative;
  const std::filesystem::path source = std::filesystem::path(SANDSTORM_SOURCE_DIR) / relative;
  if (std::filesystem::is_regular_file(source, ec)) return source;
  return relative;
}

}  // namespace sandstorm
