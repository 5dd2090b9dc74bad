#include "core/io/field_format.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <utility>

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

FieldFormat detectFieldFormat(const std::filesystem::path& path) {
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
  if (looksLikeFga(head)) return FieldFormat::UnrealFga;
  return FieldFormat::Unknown;
}

FieldFormat formatForExtension(const std::filesystem::path& path) {
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
         ".pvtu .pvtp, multiblock .vtm, collection .pvd), OpenVDB (.vdb), Unreal (.fga) or "
         "Unity (.vf) file";
}

void checkExtension(const std::filesystem::path& path, FieldFormat content) {
  const FieldFormat named = formatForExtension(path);
  if (named == FieldFormat::Unknown || named == content) return;
  if (content == FieldFormat::Unknown)
    throw Error(concat(path.string(), " is not a ", describe(named),
                       ": its first bytes match no format Sandstorm reads"));
  throw Error(concat(path.string(), " is a ", describe(content), ", not a ", describe(named),
                     " as its extension says; rename it to match its content"));
}

}  // namespace sandstorm
