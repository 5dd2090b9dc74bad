#include "core/io/field_info.h"

#include <iomanip>
#include <sstream>

#include "core/io/field_statistics.h"

namespace sandstorm {
namespace {

std::string vec(const glm::vec3& v) {
  std::ostringstream os;
  os << std::setprecision(6) << v.x << " " << v.y << " " << v.z;
  return os.str();
}

}  // namespace

std::string describeField(const std::string& file, const VectorField& f, const LoadReport& report) {
  std::ostringstream out;
  const FieldStatistics s = computeStatistics(f);
  const glm::ivec3 d = f.dims();
  out << "file:        " << file << "\n"
      << "format:      " << report.format << "\n";
  for (const std::string& block : report.blocks)
    out << "block:       " << block << "\n";
  if (report.times.size() > 1)
    out << "time steps:  " << report.times.size() << ", t = " << report.times.front() << " .. "
        << report.times.back() << " s (this is the first)\n";
  if (report.cells > 0 || report.points > 0)
    out << "cells:       " << report.cells << " cells, " << report.points << " points\n";
  out << "contents:    ";
  for (std::size_t i = 0; i < report.available.size(); ++i)
    out << (i ? ", " : "") << report.available[i];
  out << "\n"
      << "loaded:      " << report.arrayName << "\n";
  if (report.sourceDims != glm::ivec3(0))
    out << "file grid:   " << report.sourceDims.x << " x " << report.sourceDims.y << " x "
        << report.sourceDims.z << "\n";
  out << "dims:        " << d.x << " x " << d.y << " x " << d.z << " (" << f.pointCount()
      << " points" << (report.resampled ? ", resampled" : "") << ")\n"
      << "bounds:      " << vec(f.bounds().min) << " .. " << vec(f.bounds().max) << " m\n"
      << "spacing:     " << vec(f.spacing()) << " m\n"
      << "magnitude:   min " << s.minMagnitude << "  max " << s.maxMagnitude << "  mean "
      << s.meanMagnitude << "\n"
      << "zero:        " << s.zero << " vectors\n"
      << "NaN/Inf:     " << report.nonFinite << " vectors (replaced by zero)\n"
      << "outside:     " << f.invalidCount()
      << " points outside the file's cells (vtkValidPointMask)\n"
      << "scalars:     " << f.scalarNames() << "\n";
  for (const std::string& note : report.notes)
    out << "note:        " << note << "\n";
  return out.str();
}

}  // namespace sandstorm
