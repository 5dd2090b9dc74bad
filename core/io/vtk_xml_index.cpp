#include "core/io/vtk_xml_index.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include <vtkCompositeDataSet.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkPartitionedDataSet.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLPPolyDataReader.h>
#include <vtkXMLPRectilinearGridReader.h>
#include <vtkXMLPStructuredGridReader.h>
#include <vtkXMLPUnstructuredGridReader.h>

#include "core/field/vector_field.h"
#include "core/io/budget_advice.h"
#include "core/io/parallel_image_reader.h"
#include "core/io/vtk_blocks.h"
#include "core/io/vtk_cell_check.h"
#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_xml_check.h"
#include "core/io/vtk_xml_pieces.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

namespace fs = std::filesystem;

// An index lists files; one larger than this is not an index.
constexpr std::uintmax_t kMaxIndexBytes = std::uintmax_t{64} << 20;

// The serial format a parallel file's pieces have.
FieldFormat pieceFormat(FieldFormat parallel) {
  switch (parallel) {
    case FieldFormat::VtkPImageData:
      return FieldFormat::VtkImageData;
    case FieldFormat::VtkPRectilinearGrid:
      return FieldFormat::VtkRectilinearGrid;
    case FieldFormat::VtkPStructuredGrid:
      return FieldFormat::VtkStructuredGrid;
    case FieldFormat::VtkPUnstructuredGrid:
      return FieldFormat::VtkUnstructuredGrid;
    case FieldFormat::VtkPPolyData:
      return FieldFormat::VtkPolyData;
    default:
      break;
  }
  return FieldFormat::Unknown;
}

bool singleDataset(FieldFormat f) {
  return f == FieldFormat::VtkImageData || f == FieldFormat::VtkRectilinearGrid ||
         f == FieldFormat::VtkStructuredGrid || f == FieldFormat::VtkUnstructuredGrid ||
         f == FieldFormat::VtkPolyData;
}

struct Entry {
  std::string label;   // "Piece 2", "block 'inlet'"
  std::string name;    // as the index writes it
  std::string extent;  // a structured piece's Extent, as the index gives it
};

// Every piece (Piece Source=) or dataset (DataSet file=) the index names, in order.
void listEntries(vtkXMLDataElement* e, bool multiblock, std::vector<Entry>& out, int& pieces) {
  for (int i = 0; i < e->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* child = e->GetNestedElement(i);
    const char* tag = child->GetName();
    if (!multiblock && std::strcmp(tag, "Piece") == 0) {
      ++pieces;
      const char* source = child->GetAttribute("Source");
      const char* extent = child->GetAttribute("Extent");
      out.push_back({concat("Piece ", pieces), source ? source : "", extent ? extent : ""});
    } else if (multiblock && std::strcmp(tag, "DataSet") == 0) {
      const char* file = child->GetAttribute("file");
      if (!file) continue;  // an empty block
      const char* name = child->GetAttribute("name");
      const char* index = child->GetAttribute("index");
      out.push_back({name ? concat("block '", name, "'")
                          : concat("block ", index ? index : std::to_string(out.size())),
                     file, ""});
    }
    if (multiblock) listEntries(child, multiblock, out, pieces);
  }
}

// A parallel file's declarations of its pieces' arrays (PPoints, PPointData,
// PCellData, PCoordinates), as the sections the pieces hold them in.
void listDeclarations(vtkXMLDataElement* top, std::vector<VtkXmlArray>& out) {
  for (int i = 0; i < top->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* section = top->GetNestedElement(i);
    const std::string name = section->GetName();
    if (name.size() < 2 || name[0] != 'P' || name == "Piece") continue;
    for (int j = 0; j < section->GetNumberOfNestedElements(); ++j) {
      // VTK makes an array of every element here, whatever its tag says.
      vtkXMLDataElement* a = section->GetNestedElement(j);
      VtkXmlArray d;
      d.section = name.substr(1);
      d.name = a->GetAttribute("Name") ? a->GetAttribute("Name") : "";
      d.type = a->GetAttribute("type") ? a->GetAttribute("type") : "";
      int components = 1;
      a->GetScalarAttribute("NumberOfComponents", components);
      d.components = std::uint64_t(std::max(components, 0));
      out.push_back(d);
    }
  }
}

struct Index {
  std::vector<Entry> entries;
  std::vector<VtkXmlArray> declared;  // a parallel file's
};

Index parseIndex(const fs::path& path, FieldFormat format) {
  const std::string file = path.string();
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw Error(concat(file, ": cannot read its size: ", ec.message()));
  if (size > kMaxIndexBytes)
    throw Error(concat(file, ": ", size, " bytes; an index of pieces or blocks is far smaller"));
  VtkMessageTrap trap(path);
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(file.c_str());
  const int ok = parser->Parse();
  trap.throwIfFailed("parsing the XML");
  vtkXMLDataElement* root = parser->GetRootElement();
  if (!ok || !root) throw Error(concat(file, ": is not well-formed XML"));
  const bool multiblock = format == FieldFormat::VtkMultiBlock;
  vtkXMLDataElement* top =
      root->GetNumberOfNestedElements() > 0 ? root->GetNestedElement(0) : nullptr;
  if (std::strcmp(root->GetName(), "VTKFile") != 0 || !top)
    throw Error(concat(file, ": expected a <VTKFile> holding the dataset's element"));
  Index index;
  int pieces = 0;
  listEntries(top, multiblock, index.entries, pieces);
  if (index.entries.empty())
    throw Error(concat(file, ": names no ",
                       multiblock ? "block file (DataSet file=...)" : "piece (Piece Source=...)"));
  if (!multiblock) listDeclarations(top, index.declared);
  return index;
}

// VTK's parallel readers copy each piece's arrays into arrays made as the
// index declares them: a piece that holds one of another type or shape (or
// none) would be copied out of bounds.
void checkPieceArrays(const std::string& where, const std::vector<VtkXmlArray>& declared,
                      const std::vector<VtkXmlArray>& held) {
  std::size_t coordinate = 0;
  for (const VtkXmlArray& d : declared) {
    const VtkXmlArray* match = nullptr;
    if (d.section == "Points") {
      for (const VtkXmlArray& h : held)
        if (h.section == "Points") match = &h;
    } else if (d.section == "Coordinates") {
      std::size_t n = 0;
      for (const VtkXmlArray& h : held)
        if (h.section == "Coordinates" && n++ == coordinate) match = &h;
      ++coordinate;
    } else {
      for (const VtkXmlArray& h : held)
        if (h.section == d.section && h.name == d.name) match = &h;
    }
    const std::string what = concat(d.section, d.name.empty() ? "" : " '" + d.name + "'");
    if (!match) throw Error(concat(where, " holds no ", what, " array, which the index declares"));
    if (match->type != d.type || match->components != d.components)
      throw Error(concat(where, ": its ", what, " array is ", match->type, " x ", match->components,
                         "; the index declares ", d.type, " x ", d.components));
  }
}

// The entry's file, checked to be a regular file inside the index's folder tree.
fs::path resolve(const fs::path& index, const Entry& e) {
  const std::string where = concat(index.string(), ": ", e.label);
  if (e.name.empty()) throw Error(concat(where, " names no file"));
  const fs::path named(e.name);
  const fs::path base = index.parent_path();
  // An index named without a folder has an empty parent: the working directory.
  const fs::path absoluteBase = base.empty() ? fs::current_path() : fs::absolute(base);
  const fs::path relative =
      named.is_absolute()
          ? named.lexically_normal().lexically_relative(absoluteBase.lexically_normal())
          : named.lexically_normal();
  if (relative.empty() || *relative.begin() == "..")
    throw Error(concat(where, " names '", e.name, "', outside the folder of ",
                       index.filename().string(), "; pieces and blocks live beside it or below"));
  const fs::path target = base / relative;
  std::error_code ec;
  if (!fs::exists(target, ec))
    throw Error(concat(where, " names '", e.name, "': no such file (", target.string(), ")"));
  if (!fs::is_regular_file(target, ec))
    throw Error(concat(where, " names '", e.name, "': not a regular file"));
  if (fs::equivalent(target, index, ec)) throw Error(concat(where, " names the index itself"));
  return target;
}

struct Leaf {
  fs::path file;
  std::string where;                  // "run.pvtu: Piece 2 (run_1.vtu)"
  std::string name;                   // "Piece 2 (run_1.vtu)"
  std::vector<VtkXmlArray> declared;  // what its parallel index declares
  std::string extent;                 // the Extent the index gives a structured piece
};

// VTK copies a structured piece into the place its index's Extent gives it,
// sized by the piece file's own: the two must be one.
// Returns the extent; none for a piece without one (unstructured).
std::optional<std::array<long long, 6>> checkPieceExtent(const Leaf& leaf,
                                                         const VtkXmlSummary& summary) {
  if (leaf.extent.empty()) return std::nullopt;
  std::array<long long, 6> e{};
  std::istringstream in(leaf.extent);
  for (long long& v : e)
    if (!(in >> v))
      throw Error(concat(leaf.where, ": the index's Extent '", leaf.extent.substr(0, 60),
                         "' is not six whole numbers"));
  if (summary.extents.size() != 1 || summary.extents.front() != e)
    throw Error(concat(leaf.where, ": the index gives it the Extent '", leaf.extent,
                       "', but the file holds ",
                       summary.extents.size() == 1 ? "another" : "not exactly one piece's"));
  return e;
}

// The union of the pieces' extents: the grid the pieces make together, and
// the resampled grid's unless field.resolution names another (the budget is
// held against that grid, by the extractor, and against the pieces' arrays,
// above).
glm::ivec3 wholeDims(const std::string& file,
                     const std::vector<std::array<long long, 6>>& extents) {
  std::array<long long, 6> whole = extents.front();
  for (const auto& e : extents)
    for (int a = 0; a < 3; ++a) {
      whole[2 * a] = std::min(whole[2 * a], e[2 * a]);
      whole[2 * a + 1] = std::max(whole[2 * a + 1], e[2 * a + 1]);
    }
  glm::ivec3 dims;
  for (int a = 0; a < 3; ++a) {
    const long long n = whole[2 * a + 1] - whole[2 * a] + 1;
    if (n <= 0 || n > (1ll << 30))
      throw Error(concat(file, ": its pieces' extents span ", whole[2 * a], "..", whole[2 * a + 1],
                         " along ", "xyz"[a], "; expected 1 to 2^30 points"));
    dims[a] = int(n);
  }
  return dims;
}

// A parallel file of several structured or unstructured pieces: read at once
// (vtk_xml_pieces.h), not merged.
bool readsPiecesAtOnce(FieldFormat format, std::size_t pieces) {
  return pieces > 1 &&
         (format == FieldFormat::VtkPRectilinearGrid || format == FieldFormat::VtkPStructuredGrid ||
          format == FieldFormat::VtkPUnstructuredGrid || format == FieldFormat::VtkPPolyData);
}

// The index's files, checked, into `leaves`.
void collect(const fs::path& path, FieldFormat format, std::vector<Leaf>& leaves) {
  const Index index = parseIndex(path, format);
  for (const Entry& e : index.entries) {
    const fs::path target = resolve(path, e);
    const FieldFormat kind = detectFieldFormat(target);
    const std::string where = concat(path.string(), ": ", e.label, " (", e.name, ")");
    if (format == FieldFormat::VtkMultiBlock && !singleDataset(kind))
      throw Error(concat(where, " is a ", describe(kind),
                         "; a .vtm's blocks are .vti, .vtr, .vts, .vtu or .vtp files (VTK "
                         "reads no index inside a .vtm: nest blocks in <Block> elements)"));
    if (format != FieldFormat::VtkMultiBlock && kind != pieceFormat(format))
      throw Error(concat(where, " is a ", describe(kind), "; the pieces of a ", describe(format),
                         " are each a ", describe(pieceFormat(format))));
    leaves.push_back({target, where, concat(e.label, " (", e.name, ")"), index.declared, e.extent});
  }
}

// A structured reader's whole extent, within the budget before it allocates.
void checkWholeExtent(vtkAlgorithm* reader, const std::string& file, const LoadOptions& options) {
  vtkInformation* info = reader->GetOutputInformation(0);
  if (!info || !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
    throw Error(concat(file, ": declares no WholeExtent"));
  int e[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), e);
  double points = 1.0;
  for (int a = 0; a < 3; ++a) {
    const long long n = (long long)e[2 * a + 1] - e[2 * a] + 1;
    if (n <= 0)
      throw Error(concat(file, ": WholeExtent along ", "xyz"[a], " is ", e[2 * a], "..",
                         e[2 * a + 1], "; expected at least one point"));
    points *= double(n);
  }
  if (points > double(VectorField::kMaxPoints) || points * 12.0 > double(options.memoryBudget))
    throw Error(concat(
        file, ": WholeExtent holds ", points,
        " points, beyond the memory budget (field.memory_budget) of ", options.memoryBudget,
        " bytes",
        points > double(VectorField::kMaxPoints) ? std::string() : raiseBudget(points * 12.0)));
}

template <class Reader>
vtkSmartPointer<vtkDataObject> read(const fs::path& path, const LoadOptions& options,
                                    const std::string& what, bool structured,
                                    const std::function<void(Reader&)>& prepare = {}) {
  const std::string file = path.string();
  VtkMessageTrap trap(path);
  vtkNew<Reader> reader;
  if (prepare) prepare(*reader);
  trap.watch(reader);
  reader->SetFileName(file.c_str());
  reader->UpdateInformation();
  trap.throwIfFailed(concat("reading the structure of the ", what));
  if (structured) checkWholeExtent(reader, file, options);
  reader->Update();
  trap.throwIfFailed(concat("reading the ", what));
  vtkSmartPointer<vtkDataObject> out = reader->GetOutputDataObject(0);
  if (!out) throw Error(concat(file, ": VTK read no ", what));
  return out;
}

}  // namespace

std::vector<fs::path> vtkXmlIndexFiles(const fs::path& path, FieldFormat format) {
  std::vector<fs::path> files;
  std::vector<Leaf> leaves;
  collect(path, format, leaves);
  for (const Leaf& l : leaves)
    files.push_back(l.file);
  return files;
}

vtkSmartPointer<vtkDataObject> readVtkXmlIndex(const fs::path& path, FieldFormat format,
                                               const LoadOptions& options, LoadReport& report) {
  const std::string file = path.string();
  std::vector<Leaf> files;
  collect(path, format, files);
  double bytes = 0.0;
  std::vector<std::pair<fs::path, std::vector<VtkXmlRawArray>>> raw;  // each file's raw arrays
  std::vector<std::array<long long, 6>> extents;
  for (const Leaf& f : files) {
    VtkXmlSummary summary = checkVtkXml(f.file, options.memoryBudget);
    checkPieceArrays(f.where, f.declared, summary.arrays);
    if (const auto e = checkPieceExtent(f, summary)) extents.push_back(*e);
    bytes += summary.bytes;
    raw.emplace_back(f.file, std::move(summary.raw));
  }
  if (bytes > 2.0 * double(options.memoryBudget))
    throw Error(concat(file, ": its ", files.size(), " files' arrays need ", bytes,
                       " bytes together, beyond twice the memory budget (field.memory_budget) of ",
                       options.memoryBudget, " bytes", raiseBudget(bytes / 2.0)));
  vtkSmartPointer<vtkDataObject> out;
  if (readsPiecesAtOnce(format, files.size())) {
    const bool structured =
        format == FieldFormat::VtkPRectilinearGrid || format == FieldFormat::VtkPStructuredGrid;
    if (structured && extents.size() == files.size()) report.sourceDims = wholeDims(file, extents);
    std::vector<VtkXmlPiece> pieces;
    for (const Leaf& f : files)
      pieces.push_back({f.file, f.where, f.name});
    out = readVtkXmlPieces(pieces, pieceFormat(format),
                           concat("reading ", path.filename().string()), options.showProgress);
    report.notes.push_back(
        concat(files.size(), " pieces read at once and resampled together (not merged)"));
    return out;
  }
  switch (format) {
    case FieldFormat::VtkPImageData:
      out = read<ParallelImageReader>(path, options, "parallel image data", true,
                                      [&](ParallelImageReader& reader) {
                                        for (auto& [piece, arrays] : raw)
                                          reader.addPieceRawArrays(piece, std::move(arrays));
                                      });
      break;
    case FieldFormat::VtkPRectilinearGrid:
      out = read<vtkXMLPRectilinearGridReader>(path, options, "parallel rectilinear grid", true);
      break;
    case FieldFormat::VtkPStructuredGrid:
      out = read<vtkXMLPStructuredGridReader>(path, options, "parallel structured grid", true);
      break;
    case FieldFormat::VtkPUnstructuredGrid:
      out = read<vtkXMLPUnstructuredGridReader>(path, options, "parallel unstructured grid", false);
      break;
    case FieldFormat::VtkPPolyData:
      out = read<vtkXMLPPolyDataReader>(path, options, "parallel polydata", false);
      break;
    case FieldFormat::VtkMultiBlock:
      out = read<vtkXMLMultiBlockDataReader>(path, options, "multiblock dataset", false);
      break;
    default:
      throw Error(concat(file, ": readVtkXmlIndex() got a ", describe(format)));
  }
  for (const VtkBlock& b : vtkBlocks(out))
    checkVtkCells(b.data, b.name.empty() ? file : concat(file, ": ", b.name));
  if (format != FieldFormat::VtkMultiBlock)
    report.notes.push_back(files.size() == 1 ? std::string("its one piece read")
                                             : concat(files.size(), " pieces merged"));
  return out;
}

}  // namespace sandstorm
