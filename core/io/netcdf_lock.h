// lockNetcdfLibraries(): the NetCDF, HDF5 and CGNS libraries keep
// process-wide state (NetCDF-C's table of open files, the CGNS library's,
// an HDF5 built without its thread-safe option) and are not safe to call
// from two threads at once. A series is read by several reader threads, so
// the readers of the files inside them (Exodus II, NetCDF CF, CGNS, VTKHDF)
// take turns: loadField holds this lock while one reads (VTK's reader and
// Sandstorm's checks), not while the result is resampled.
#pragma once

#include <mutex>

namespace sandstorm {

std::unique_lock<std::mutex> lockNetcdfLibraries();

}  // namespace sandstorm
