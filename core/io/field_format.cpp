#include "core/io/field_format.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <utility>

#include "core/io/exodus_spread.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

FieldFormat xmlType(const std::string& head) {
  const auto tag = head.find("<VTKFile");
  if (tag == std::string::npos) return FieldFormat::Unknown;
  const auto type = head.find("type=\"", tag);
  if (type == std::string::npos) return FieldFormat::Unknown;
  const std::string rest = head.substr(type + 6);
  const auto starts = [&](const char* s) { return rest.rfind(s, 0) == 0; };
  static const std::pair<const char*, FieldFormat> kTypes[] = {
      {"ImageData\"", FieldFormat::VtkImageData},
      {"RectilinearGrid\"", FieldFormat::VtkRectilinearGrid},
      {"StructuredGrid\"", FieldFormat::VtkStructuredGrid},
      {"UnstructuredGrid\"", FieldFormat::VtkUnstructuredGrid},
      {"PolyData\"", FieldFormat::VtkPolyData},
      {"PImageData\"", FieldFormat::VtkPImageData},
      {"PRectilinearGrid\"", FieldFormat::VtkPRectilinearGrid},
      {"PStructuredGrid\"", FieldFormat::VtkPStructuredGrid},
      {"PUnstructuredGrid\"", FieldFormat::VtkPUnstructuredGrid},
      {"PPolyData\"", FieldFormat::VtkPPolyData},
      {"vtkMultiBlockDataSet\"", FieldFormat::VtkMultiBlock},
      {"Collection\"", FieldFormat::VtkCollection}};
  for (const auto& [name, format] : kTypes)
    if (starts(name)) return format;
  return FieldFormat::Unknown;
}

bool looksLikeFga(const std::string& head) {
  // Numbers separated by commas, the first line holding the three dimensions.
  std::size_t i = 0;
  while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i])))
    ++i;
  if (i == head.size()) return false;
  const auto eol = head.find('\n', i);
  const std::string line = head.substr(i, eol == std::string::npos ? std::string::npos : eol - i);
  if (std::count(line.begin(), line.end(), ',') < 2) return false;
  return std::all_of(line.begin(), line.end(), [](unsigned char c) {
    return std::isdigit(c) || c == ',' || c == '.' || c == '-' || c == '+' || c == 'e' ||
           c == 'E' || std::isspace(c);
  });
}

}  // namespace

bool looksLikeEnSightCase(const std::string& head) {
  std::size_t i = 0;
  while (i < head.size()) {  // comment lines (#) and blank lines before FORMAT
    while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i])))
      ++i;
    if (i < head.size() && head[i] == '#') {
      i = head.find('\n', i);
      if (i == std::string::npos) return false;
      continue;
    }
    break;
  }
  return head.compare(i, 6, "FORMAT") == 0;
}

// An OpenFOAM case: the folder, its .foam or .OpenFOAM file (ParaView's
// convention, any content), or its system/controlDict.
bool isOpenFoamCase(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    return std::filesystem::is_regular_file(path / "system" / "controlDict", ec);
  const std::string ext = lower(path.extension().string());
  return ext == ".foam" || ext == ".openfoam" || path.filename() == "controlDict";
}

FieldFormat containerFormat(const std::filesystem::path& path, const std::string& head) {
  const std::string ext = lower(path.extension().string());
  const bool hdf5 = head.rfind("\x89HDF\r\n\x1a\n", 0) == 0;
  const bool classic = head.size() >= 4 && head.compare(0, 3, "CDF") == 0 &&
                       (head[3] == 1 || head[3] == 2 || head[3] == 5);
  const FieldFormat named = formatForExtension(path);
  if (classic) {
    if (named == FieldFormat::ExodusII || named == FieldFormat::NetCdf) return named;
    // Exodus declares its dimensions first: num_nodes is in the first kilobyte.
    return head.find("num_nodes") != std::string::npos ? FieldFormat::ExodusII
                                                       : FieldFormat::NetCdf;
  }
  if (!hdf5) return FieldFormat::Unknown;
  if (named == FieldFormat::ExodusII || named == FieldFormat::NetCdf ||
      named == FieldFormat::Cgns || named == FieldFormat::VtkHdf)
    return named;
  return FieldFormat::Unknown;
}

FieldFormat detectFieldFormat(const std::filesystem::path& path) {
  if (isOpenFoamCase(path)) return FieldFormat::OpenFoam;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(concat(path.string(), ": cannot open the file for reading"));
  std::string head(1024, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));

  if (head.rfind("# vtk DataFile", 0) == 0) return FieldFormat::VtkLegacy;
  // OpenVDB's magic number 0x56444220 ("VDB ") as a little-endian int64.
  static constexpr unsigned char kVdbMagic[8] = {0x20, 0x42, 0x44, 0x56, 0, 0, 0, 0};
  if (head.size() >= 8 && std::memcmp(head.data(), kVdbMagic, 8) == 0) return FieldFormat::OpenVdb;
  if (head.rfind("VF_V", 0) == 0 || head.rfind("VF_F", 0) == 0 || head.rfind("VF2X", 0) == 0)
    return FieldFormat::UnityVf;
  if (const FieldFormat xml = xmlType(head); xml != FieldFormat::Unknown) return xml;
  if (const FieldFormat c = containerFormat(path, head); c != FieldFormat::Unknown) return c;
  // CGNS's older ADF layout: "@(#)" (written with each byte's high bit set
  // by some versions), then its name.
  if (head.size() >= 24 && head.compare(4, 20, "ADF Database Version") == 0)
    return FieldFormat::Cgns;
  if (looksLikeEnSightCase(head)) return FieldFormat::EnSightGold;
  if (looksLikeFga(head)) return FieldFormat::UnrealFga;
  return FieldFormat::Unknown;
}

FieldFormat formatForExtension(const std::filesystem::path& path) {
  // One rank's file of a decomposed Exodus run: "out.e.4.0" is an "out.e".
  if (const std::optional<ExodusSpreadName> spread = parseExodusSpreadName(path);
      spread && formatForExtension(spread->base) == FieldFormat::ExodusII)
    return FieldFormat::ExodusII;
  const std::string ext = lower(path.extension().string());
  if (ext == ".vtk") return FieldFormat::VtkLegacy;
  if (ext == ".vti") return FieldFormat::VtkImageData;
  if (ext == ".vtr") return FieldFormat::VtkRectilinearGrid;
  if (ext == ".vts") return FieldFormat::VtkStructuredGrid;
  if (ext == ".vtu") return FieldFormat::VtkUnstructuredGrid;
  if (ext == ".vtp") return FieldFormat::VtkPolyData;
  if (ext == ".pvti") return FieldFormat::VtkPImageData;
  if (ext == ".pvtr") return FieldFormat::VtkPRectilinearGrid;
  if (ext == ".pvts") return FieldFormat::VtkPStructuredGrid;
  if (ext == ".pvtu") return FieldFormat::VtkPUnstructuredGrid;
  if (ext == ".pvtp") return FieldFormat::VtkPPolyData;
  if (ext == ".vtm") return FieldFormat::VtkMultiBlock;
  if (ext == ".pvd") return FieldFormat::VtkCollection;
  if (ext == ".e" || ext == ".exo" || ext == ".g" || ext == ".ex2" || ext == ".exii")
    return FieldFormat::ExodusII;
  if (ext == ".case") return FieldFormat::EnSightGold;
  if (ext == ".foam" || ext == ".openfoam") return FieldFormat::OpenFoam;
  if (ext == ".nc" || ext == ".nc4" || ext == ".cdf") return FieldFormat::NetCdf;
  if (ext == ".cgns") return FieldFormat::Cgns;
  if (ext == ".vtkhdf" || ext == ".hdf") return FieldFormat::VtkHdf;
  if (ext == ".vdb") return FieldFormat::OpenVdb;
  if (ext == ".fga") return FieldFormat::UnrealFga;
  if (ext == ".vf") return FieldFormat::UnityVf;
  return FieldFormat::Unknown;
}

bool hasFieldExtension(const std::filesystem::path& path) {
  return formatForExtension(path) != FieldFormat::Unknown;
}

bool namesOtherFiles(FieldFormat format) {
  switch (format) {
    case FieldFormat::VtkPImageData:
    case FieldFormat::VtkPRectilinearGrid:
    case FieldFormat::VtkPStructuredGrid:
    case FieldFormat::VtkPUnstructuredGrid:
    case FieldFormat::VtkPPolyData:
    case FieldFormat::VtkMultiBlock:
    case FieldFormat::VtkCollection:
      return true;
    default:
      return false;
  }
}

std::string describe(FieldFormat format) {
  switch (format) {
    case FieldFormat::VtkLegacy:
      return "legacy VTK file (.vtk)";
    case FieldFormat::VtkImageData:
      return "VTK XML image data file (.vti)";
    case FieldFormat::VtkRectilinearGrid:
      return "VTK XML rectilinear grid file (.vtr)";
    case FieldFormat::VtkStructuredGrid:
      return "VTK XML structured grid file (.vts)";
    case FieldFormat::VtkUnstructuredGrid:
      return "VTK XML unstructured grid file (.vtu)";
    case FieldFormat::VtkPolyData:
      return "VTK XML polydata file (.vtp)";
    case FieldFormat::VtkPImageData:
      return "VTK XML parallel image data file (.pvti)";
    case FieldFormat::VtkPRectilinearGrid:
      return "VTK XML parallel rectilinear grid file (.pvtr)";
    case FieldFormat::VtkPStructuredGrid:
      return "VTK XML parallel structured grid file (.pvts)";
    case FieldFormat::VtkPUnstructuredGrid:
      return "VTK XML parallel unstructured grid file (.pvtu)";
    case FieldFormat::VtkPPolyData:
      return "VTK XML parallel polydata file (.pvtp)";
    case FieldFormat::VtkMultiBlock:
      return "VTK XML multiblock file (.vtm)";
    case FieldFormat::VtkCollection:
      return "ParaView data collection (.pvd)";
    case FieldFormat::ExodusII:
      return "Exodus II file (.e)";
    case FieldFormat::EnSightGold:
      return "EnSight Gold case (.case)";
    case FieldFormat::OpenFoam:
      return "OpenFOAM case";
    case FieldFormat::NetCdf:
      return "NetCDF file (.nc)";
    case FieldFormat::Cgns:
      return "CGNS file (.cgns)";
    case FieldFormat::VtkHdf:
      return "VTKHDF file (.vtkhdf)";
    case FieldFormat::OpenVdb:
      return "OpenVDB file (.vdb)";
    case FieldFormat::UnrealFga:
      return "Unreal FGA vector field (.fga)";
    case FieldFormat::UnityVf:
      return "Unity volume file (.vf)";
    case FieldFormat::Unknown:
      break;
  }
  return "file of unknown format";
}

std::string knownFormats() {
  return "a legacy VTK (.vtk), VTK XML (.vti .vtr .vts .vtu .vtp, parallel .pvti .pvtr .pvts "
         ".pvtu .pvtp, multiblock .vtm, collection .pvd), Exodus II (.e .exo .g), EnSight Gold "
         "(.case), OpenFOAM (a case folder, .foam, controlDict), NetCDF CF (.nc), CGNS (.cgns), "
         "VTKHDF (.vtkhdf .hdf), OpenVDB (.vdb), Unreal (.fga) or Unity (.vf) file";
}

namespace {

// "a" or "an" before a format's description, as it is read aloud ("an
// OpenVDB file", "an Unreal FGA", "a Unity volume file").
std::string withArticle(const std::string& what) {
  const bool vowel = !what.empty() &&
                     (std::strchr("AEIOaeio", what[0]) != nullptr || what.rfind("Unreal", 0) == 0);
  return (vowel ? "an " : "a ") + what;
}

}  // namespace

void checkExtension(const std::filesystem::path& path, FieldFormat content) {
  const FieldFormat named = formatForExtension(path);
  if (named == FieldFormat::Unknown || named == content) return;
  std::error_code ec;
  if (content == FieldFormat::Unknown && std::filesystem::file_size(path, ec) == 0 && !ec)
    throw Error(concat(path.string(), " is empty: expected ", withArticle(describe(named))));
  if (content == FieldFormat::Unknown)
    throw Error(concat(path.string(), " is not ", withArticle(describe(named)),
                       ": its first bytes match no format Sandstorm reads"));
  throw Error(concat(path.string(), " is ", withArticle(describe(content)), ", not ",
                     withArticle(describe(named)),
                     " as its extension says; rename it to match its content"));
}

}  // namespace sandstorm
