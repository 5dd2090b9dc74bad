// readNetcdfCf(): a NetCDF file following the CF conventions (.nc: a
// climate, weather or ocean model's output) read by VTK's vtkNetCDFCFReader
// at options.timeStep: the variables on the grid of the flow (u, v, w, or
// what options.arrayName names, or the eastward/northward/upward components
// by their CF standard_name), on the grid their coordinate variables give,
// its time steps in report.times.
//
// Axes (x fastest: the last dimension, then y, then z) are converted to
// metres where the file's units allow:
// - longitude and latitude in degrees (units degrees_east/degrees_north, or
//   standard_name longitude/latitude): metres on a plane tangent at the
//   grid's middle latitude (x = R cos(lat0) lon, y = R lat in radians,
//   R = 6371 km), fine for regions up to a few hundred kilometres;
// - a vertical axis in m or km (negated where positive = "down", a depth);
// - other vertical axes (pressure, sigma, model levels) are kept as the file
//   gives them, and a note says so (field.scale or a configuration's
//   placement sets their size).
// The NetCDF header is checked before the reader runs (readNetcdfHeader) and
// the variables read are held to the memory budget. Throws Error naming the
// file and what was wrong.
#pragma once

#include <filesystem>

#include <vtkSmartPointer.h>

#include "core/io/load_options.h"

class vtkDataObject;

namespace sandstorm {

vtkSmartPointer<vtkDataObject> readNetcdfCf(const std::filesystem::path& path, LoadOptions& options,
                                            LoadReport& report);

}  // namespace sandstorm
