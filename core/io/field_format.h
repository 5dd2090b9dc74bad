// FieldFormat: the kinds of field file loadField() reads, recognised by their
// content (magic bytes, header), not their name; where one container holds
// several formats (NetCDF holds Exodus meshes and CF fields, HDF5 holds
// NetCDF-4, CGNS and VTKHDF) the content decides what it can and the
// extension the rest. An OpenFOAM case is a folder (or its .foam file, or its
// system/controlDict).
//
// detectFieldFormat() reads at most the first kilobyte. checkExtension()
// throws when a file's extension names another format than its content
// ("wind.vti is a legacy VTK file ..."); an unknown extension is accepted.
#pragma once

#include <filesystem>
#include <string>

namespace sandstorm {

enum class FieldFormat {
  Unknown,
  VtkLegacy,             // .vtk
  VtkImageData,          // .vti
  VtkRectilinearGrid,    // .vtr
  VtkStructuredGrid,     // .vts
  VtkUnstructuredGrid,   // .vtu
  VtkPolyData,           // .vtp
  VtkPImageData,         // .pvti (pieces of image data)
  VtkPRectilinearGrid,   // .pvtr
  VtkPStructuredGrid,    // .pvts
  VtkPUnstructuredGrid,  // .pvtu
  VtkPPolyData,          // .pvtp
  VtkMultiBlock,         // .vtm
  VtkCollection,         // .pvd (a time series of the above)
  ExodusII,              // .e .exo .g .ex2 (NetCDF inside)
  EnSightGold,           // .case
  OpenFoam,              // a case folder, its .foam file or its system/controlDict
  NetCdf,                // .nc (NetCDF CF)
  Cgns,                  // .cgns
  VtkHdf,                // .vtkhdf .hdf
  OpenVdb,               // .vdb
  UnrealFga,             // .fga
  UnityVf,               // .vf
};

// Throws Error when the file cannot be opened; Unknown when nothing matches.
FieldFormat detectFieldFormat(const std::filesystem::path& path);
// The format an extension names (case-insensitive); Unknown for others.
FieldFormat formatForExtension(const std::filesystem::path& path);
// Whether the extension names a format loadField() reads (case-insensitive).
bool hasFieldExtension(const std::filesystem::path& path);
// Whether files of this format name other files (parallel pieces, blocks).
bool namesOtherFiles(FieldFormat format);
// "legacy VTK file", "VTK XML image data (.vti)", ...
std::string describe(FieldFormat format);
// The formats, for messages: "a legacy VTK (.vtk), VTK XML (.vti ...) ... file".
std::string knownFormats();
// Throws Error when the extension names a known format other than `content`.
void checkExtension(const std::filesystem::path& path, FieldFormat content);

}  // namespace sandstorm
