#include "core/io/vtk_legacy_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <sstream>

#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkNew.h>
#include <vtkRectilinearGrid.h>
#include <vtkRectilinearGridReader.h>
#include <vtkStructuredGrid.h>
#include <vtkStructuredGridReader.h>
#include <vtkStructuredPoints.h>
#include <vtkStructuredPointsReader.h>

#include "core/field/vector_field.h"
#include "core/io/vtk_message_trap.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

struct Header {
  std::string dataset;  // STRUCTURED_POINTS, ...
  bool binary = false;
  long long dims[3] = {0, 0, 0};
  bool hasDims = false;
};

// Walks the header lines up to the first data block.
Header readHeader(const std::string& text, const std::string& file) {
  Header h;
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  auto next = [&]() -> bool {
    while (std::getline(in, line)) {
      ++lineNo;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (lineNo <= 2 || line.find_first_not_of(" \t") != std::string::npos) return true;
    }
    return false;
  };
  if (!next() || line.rfind("# vtk DataFile", 0) != 0)
    throw Error(concat(file, ": line 1 is not '# vtk DataFile Version x.x'"));
  if (!next()) throw Error(concat(file, ": ends before its title line (line 2)"));
  if (!next()) throw Error(concat(file, ": ends before the ASCII/BINARY line (line 3)"));
  const std::string mode = upper(line.substr(0, line.find_first_of(" \t")));
  if (mode != "ASCII" && mode != "BINARY")
    throw Error(concat(file, ":", lineNo, ": '", line, "'; expected ASCII or BINARY"));
  h.binary = mode == "BINARY";
  if (!next()) throw Error(concat(file, ": ends before its DATASET line"));
  {
    std::istringstream words(line);
    std::string key, type;
    words >> key >> type;
    if (upper(key) != "DATASET")
      throw Error(concat(file, ":", lineNo, ": '", line, "'; expected 'DATASET <type>'"));
    h.dataset = upper(type);
    if (h.dataset != "STRUCTURED_POINTS" && h.dataset != "RECTILINEAR_GRID" &&
        h.dataset != "STRUCTURED_GRID")
      throw Error(concat(file, ":", lineNo, ": DATASET ", type,
                         " is not a grid; expected STRUCTURED_POINTS, RECTILINEAR_GRID or "
                         "STRUCTURED_GRID"));
  }
  while (next()) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    key = upper(key);
    if (key == "DIMENSIONS") {
      for (long long& d : h.dims)
        if (!(words >> d))
          throw Error(concat(file, ":", lineNo, ": '", line, "'; expected DIMENSIONS nx ny nz"));
      for (int a = 0; a < 3; ++a)
        if (h.dims[a] <= 0)
          throw Error(concat(file, ":", lineNo, ": DIMENSIONS along ", "xyz"[a], " is ", h.dims[a],
                             "; expected a positive point count"));
      h.hasDims = true;
    } else if (key == "SPACING" || key == "ASPECT_RATIO") {
      double s[3];
      for (double& v : s)
        if (!(words >> v))
          throw Error(concat(file, ":", lineNo, ": '", line, "'; expected ", key, " sx sy sz"));
      for (int a = 0; a < 3; ++a)
        if (!(s[a] > 0.0) && !(h.hasDims && h.dims[a] == 1))
          throw Error(concat(file, ":", lineNo, ": ", key, " along ", "xyz"[a], " is ", s[a],
                             "; expected a positive spacing"));
    } else if (key == "ORIGIN" || key == "FIELD") {
      continue;
    } else {
      break;  // the first data block: the scan below checks its count
    }
  }
  if (!h.hasDims) throw Error(concat(file, ": no DIMENSIONS line before the data"));
  return h;
}

// Checks each counted keyword at the start of a line: its count must match the
// grid and fit in the file.
void checkCounts(const std::string& text, const Header& h, const std::string& file) {
  const long long points = h.dims[0] * h.dims[1] * h.dims[2];
  struct Rule {
    const char* key;
    long long expected;
    int components;
  };
  const Rule rules[] = {{"POINT_DATA", points, 0},
                        {"POINTS", points, 3},
                        {"X_COORDINATES", h.dims[0], 1},
                        {"Y_COORDINATES", h.dims[1], 1},
                        {"Z_COORDINATES", h.dims[2], 1}};
  for (const Rule& rule : rules) {
    const std::string key = std::string("\n") + rule.key + " ";
    for (auto at = text.find(key); at != std::string::npos; at = text.find(key, at + 1)) {
      const char* first = text.data() + at + key.size();
      const char* last = text.data() + std::min(text.size(), at + key.size() + 24);
      long long count = -1;
      const auto [end, ec] = std::from_chars(first, last, count);
      if (ec != std::errc() || (end < last && *end != ' ' && *end != '\n' && *end != '\r'))
        continue;  // not a header line (bytes inside binary data)
      const long long line = std::count(text.begin(), text.begin() + long(at) + 1, '\n') + 1;
      if (count != rule.expected)
        throw Error(concat(file, ":", line, ": ", rule.key, " ", count, " but DIMENSIONS ",
                           h.dims[0], " ", h.dims[1], " ", h.dims[2], " make ", rule.expected,
                           "; expected the counts to agree"));
      // Each value takes at least 4 bytes in BINARY and 2 ("0 ") in ASCII.
      const long long minBytes = count * std::max(rule.components, 1) * (h.binary ? 4 : 2);
      if (minBytes > static_cast<long long>(text.size() - at))
        throw Error(concat(file, ":", line, ": ", rule.key, " ", count,
                           " needs more data than the file holds (", text.size(),
                           " bytes); the file is truncated"));
    }
  }
}

template <class Reader>
vtkSmartPointer<vtkDataSet> run(const std::filesystem::path& path, const char* what) {
  VtkMessageTrap trap(path);
  vtkNew<Reader> reader;
  trap.watch(reader);
  reader->SetFileName(path.string().c_str());
  reader->ReadAllVectorsOn();
  reader->ReadAllScalarsOn();
  reader->ReadAllFieldsOn();
  reader->Update();
  trap.throwIfFailed(concat("reading the ", what));
  if (reader->GetErrorCode() != 0)
    throw Error(concat(path.string(), ": VTK's legacy reader failed with error code ",
                       reader->GetErrorCode()));
  vtkSmartPointer<vtkDataSet> out = reader->GetOutput();
  if (!out || out->GetNumberOfPoints() <= 0)
    throw Error(concat(path.string(), ": VTK read no points from the ", what));
  return out;
}

}  // namespace

vtkSmartPointer<vtkDataSet> readVtkLegacy(const std::filesystem::path& path,
                                          const LoadOptions& options) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(concat(file, ": cannot open the file for reading"));
  const auto size = std::filesystem::file_size(path);
  // The whole file is scanned when it is not too large to hold; the header alone otherwise.
  const std::size_t scanned =
      std::min<std::uintmax_t>(size, std::max<std::size_t>(options.memoryBudget, 1 << 20));
  std::string text(scanned, '\0');
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(std::size_t(in.gcount()));

  const Header h = readHeader(text.substr(0, std::min<std::size_t>(text.size(), 4096)), file);
  const double points = double(h.dims[0]) * double(h.dims[1]) * double(h.dims[2]);
  if (points > double(VectorField::kMaxPoints) || points * 12.0 > double(options.memoryBudget))
    throw Error(concat(file, ": DIMENSIONS ", h.dims[0], " ", h.dims[1], " ", h.dims[2], " = ",
                       points, " points exceed the memory budget of ", options.memoryBudget,
                       " bytes (12 per point, at most ", VectorField::kMaxPoints, " points)"));
  if (text.size() == size) checkCounts(text, h, file);
  // An ASCII file cut inside its last number still parses ("12.5" -> "1"): VTK's
  // writers end every file with a newline, so a file that ends in a digit is
  // taken as truncated.
  if (!h.binary && !text.empty() && text.size() == size &&
      !std::isspace(static_cast<unsigned char>(text.back())))
    throw Error(concat(file,
                       ": ends inside a value, without the final newline; the file is "
                       "truncated (if it is complete, end it with a newline)"));
  text = {};

  if (h.dataset == "STRUCTURED_POINTS")
    return run<vtkStructuredPointsReader>(path, "legacy VTK structured points");
  if (h.dataset == "RECTILINEAR_GRID")
    return run<vtkRectilinearGridReader>(path, "legacy VTK rectilinear grid");
  return run<vtkStructuredGridReader>(path, "legacy VTK structured grid");
}

}  // namespace sandstorm
