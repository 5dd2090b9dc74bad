#include "core/io/netcdf_lock.h"

namespace sandstorm {

std::unique_lock<std::mutex> lockNetcdfLibraries() {
  static std::mutex mutex;
  return std::unique_lock<std::mutex>(mutex);
}

}  // namespace sandstorm
