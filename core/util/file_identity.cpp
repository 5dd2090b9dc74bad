#include "core/util/file_identity.h"

#include <chrono>
#include <cstdio>
#include <ctime>

namespace sandstorm {

FileIdentity FileIdentity::of(const std::filesystem::path& file) {
  std::error_code ec;
  FileIdentity out;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec) return out;
  const std::filesystem::file_time_type time = std::filesystem::last_write_time(file, ec);
  if (ec) return out;
  out.present = true;
  out.size = std::uint64_t(size);
  out.modified =
      std::chrono::duration_cast<std::chrono::nanoseconds>(time.time_since_epoch()).count();
  return out;
}

std::string FileIdentity::text() const {
  if (!present) return "not found";
  using namespace std::chrono;
  const std::filesystem::file_time_type time{
      duration_cast<std::filesystem::file_time_type::duration>(nanoseconds(modified))};
  const auto utc = time_point_cast<nanoseconds>(file_clock::to_sys(time));
  const std::time_t seconds = system_clock::to_time_t(time_point_cast<system_clock::duration>(utc));
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char when[32];
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S", &tm);
  const long long nanos =
      (utc.time_since_epoch() % std::chrono::nanoseconds(std::chrono::seconds(1))).count();
  char text[96];
  std::snprintf(text, sizeof text, "%llu bytes, modified %s.%09lld UTC",
                static_cast<unsigned long long>(size), when,
                nanos < 0 ? nanos + 1000000000 : nanos);
  return text;
}

}  // namespace sandstorm
