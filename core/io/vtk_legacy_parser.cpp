#include "core/io/vtk_legacy_parser.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>

#include "core/field/vector_field.h"
#include "core/io/ascii_numbers.h"
#include "core/io/budget_advice.h"
#include "core/util/error.h"
#include "core/util/page_buffer.h"
#include "core/util/progress_meter.h"

namespace sandstorm {

long long LegacyVtkData::pointCount() const {
  if (pointSet()) return (long long)(points.size() / 3);
  return dims[0] * dims[1] * dims[2];
}

long long LegacyVtkData::cellCount() const {
  if (type == Type::UnstructuredGrid) return cells.count();
  if (type == Type::PolyData) {
    long long n = 0;
    for (const LegacyCells& c : polyCells)
      n += c.count();
    return n;
  }
  long long cells = 1;
  for (long long n : dims)
    cells *= n > 1 ? n - 1 : 1;
  return cells;
}

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return out;
}

bool isSpace(char c) {
  return isAsciiSpace(c);
}

// The bytes of a legacy type in BINARY data; 0 for types refused.
int typeSize(const std::string& type) {
  static const std::pair<const char*, int> sizes[] = {
      {"unsigned_char", 1}, {"char", 1},         {"signed_char", 1},   {"unsigned_short", 2},
      {"short", 2},         {"unsigned_int", 4}, {"int", 4},           {"unsigned_long", 8},
      {"long", 8},          {"vtktypeint64", 8}, {"vtktypeuint64", 8}, {"vtkidtype", 8},
      {"float", 4},         {"double", 8}};
  for (const auto& [name, size] : sizes)
    if (type == name) return size;
  return 0;
}

// ASCII arrays this long are parsed over the cores (parseAsciiNumbers).
constexpr std::size_t kParallelValues = std::size_t{1} << 16;

class Parser {
 public:
  // `meter`, where given, hears of the bytes parsed; `pages`, where given,
  // holds `text`, and the parse gives its pages back as it passes them.
  Parser(std::string_view text, std::string file, std::size_t budget,
         ProgressMeter* meter = nullptr, PageBuffer* pages = nullptr)
      : text_(text), file_(std::move(file)), budget_(budget), meter_(meter), pages_(pages) {}

  // STRUCTURED_POINTS's frame: the header and the geometry up to the first
  // POINT_DATA or CELL_DATA, which must lie in the text (a prefix of the
  // file: a geometry that reaches its end may be cut inside a number).
  std::optional<VtkImageFrame> frame() {
    header();
    if (data_.type != LegacyVtkData::Type::StructuredPoints) return std::nullopt;
    geometry();
    skipSpace();
    if (at_ >= text_.size()) return std::nullopt;
    VtkImageFrame f;
    for (std::size_t a = 0; a < 3; ++a) {
      if (data_.dims[a] > (1LL << 30)) return std::nullopt;
      f.extent[2 * a] = 0;
      f.extent[2 * a + 1] = data_.dims[a] - 1;
      f.origin[a] = data_.origin[a];
      f.spacing[a] = data_.spacing[a];
    }
    return f;
  }

  LegacyVtkData run() {
    header();
    geometry();
    while (skipSpace(), at_ < text_.size()) {
      const std::string key = keyword("POINT_DATA or CELL_DATA");
      if (key == "point_data")
        attributes(data_.pointData, data_.pointCount(), "POINT_DATA");
      else if (key == "cell_data")
        attributes(data_.cellData, data_.cellCount(), "CELL_DATA");
      else
        fail(concat("'", last_, "'; expected POINT_DATA or CELL_DATA"));
    }
    // An ASCII file cut inside its last number still parses ("12.5" -> "1"):
    // VTK's writers end every file with a newline, so one that ends in a value is truncated.
    if (!binary_ && !text_.empty() && !isSpace(text_.back())) {
      start_ = text_.size() - 1;
      fail(
          "the file ends inside a value, without the final newline; it is truncated (if it is "
          "complete, end it with a newline)");
    }
    return std::move(data_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(concat(file_, ":", line(), ": ", what));
  }
  long long line() const {
    const std::size_t from = std::min(released(), start_);
    return releasedLines_ +
           std::count(text_.begin() + long(from), text_.begin() + long(start_), '\n') + 1;
  }
  std::size_t released() const { return pages_ ? pages_->released() : 0; }

  // A whole line (without its end), from the current position.
  std::string_view readLine() {
    start_ = at_;
    const std::size_t end = text_.find('\n', at_);
    const std::size_t stop = end == std::string::npos ? text_.size() : end;
    std::string_view l(text_.data() + at_, stop - at_);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    at_ = end == std::string::npos ? text_.size() : end + 1;
    return l;
  }

  void skipSpace() {
    while (at_ < text_.size() && isSpace(text_[at_]))
      ++at_;
  }

  std::string_view token(const std::string& what) {
    return tokenFor([&] { return what; });
  }

  // `what()` names what was expected; it is only called to say so (an
  // array's millions of values each have a name of their own).
  template <class What>
  std::string_view tokenFor(const What& what) {
    skipSpace();
    start_ = at_;
    if (at_ >= text_.size()) fail(concat("the file ends; expected ", what()));
    while (at_ < text_.size() && !isSpace(text_[at_]))
      ++at_;
    last_.assign(text_.data() + start_, std::min<std::size_t>(at_ - start_, 40));
    return std::string_view(text_.data() + start_, at_ - start_);
  }

  std::string keyword(const std::string& what) { return lower(token(what)); }

  long long integer(const std::string& what, long long min, long long max) {
    const std::string_view t = token(what);
    long long v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size())
      fail(concat("'", last_, "'; expected ", what, " (a whole number)"));
    if (v < min || v > max) fail(concat(what, " is ", v, "; expected ", min, "..", max));
    return v;
  }

  double number(const std::string& what) {
    return numberFor([&] { return what; });
  }

  template <class What>
  double numberFor(const What& what) {
    const std::string_view t = tokenFor(what);
    double v = 0.0;
    if (!readAsciiNumber(t, v)) fail(concat("'", last_, "'; expected ", what(), " (a number)"));
    return v;
  }

  // The parse's progress: the bytes passed since the last report, once a MiB.
  void tick() {
    if (at_ - reported_ < (std::size_t{1} << 20)) return;
    if (meter_) meter_->add(at_ - reported_);
    reported_ = at_;
    release();
  }

  // Gives back the text's pages more than a MiB behind both the position and
  // the last token's start (the parse steps back a few bytes at most; error
  // messages count lines up to the token), counting their lines first.
  void release() {
    constexpr std::size_t kSlack = std::size_t{1} << 20, kStep = std::size_t{4} << 20;
    const std::size_t keep = std::min(at_, start_);
    if (!pages_ || keep < pages_->released() + kSlack + kStep) return;
    const std::size_t end = PageBuffer::pageFloor(keep - kSlack);
    releasedLines_ +=
        std::count(text_.begin() + long(pages_->released()), text_.begin() + long(end), '\n');
    pages_->releaseBefore(end);
  }

  // The rest of the current line must be empty (binary data starts on the next).
  void endOfLine(const std::string& after) {
    while (at_ < text_.size() && text_[at_] != '\n') {
      if (!isSpace(text_[at_]))
        fail(concat("unexpected '", text_.substr(at_, 20), "' after ", after));
      ++at_;
    }
    if (at_ < text_.size()) ++at_;
  }

  void header() {
    const std::string_view first = readLine();
    if (first.rfind("# vtk DataFile Version", 0) != 0)
      fail("this is not a legacy VTK file; expected '# vtk DataFile Version x.x' on line 1");
    // 5.x writes cells as OFFSETS and CONNECTIVITY, earlier versions as counted lists.
    version_ = std::atof(std::string(first.substr(22)).c_str());
    if (at_ >= text_.size()) fail("the file ends before its title line (line 2)");
    readLine();  // the title: anything
    const std::string mode = lower(token("ASCII or BINARY"));
    if (mode != "ascii" && mode != "binary")
      fail(concat("'", last_, "'; expected ASCII or BINARY on line 3"));
    binary_ = mode == "binary";
    if (keyword("DATASET") != "dataset") fail(concat("'", last_, "'; expected DATASET"));
    const std::string type = keyword("the dataset type");
    if (type == "structured_points")
      data_.type = LegacyVtkData::Type::StructuredPoints;
    else if (type == "rectilinear_grid")
      data_.type = LegacyVtkData::Type::RectilinearGrid;
    else if (type == "structured_grid")
      data_.type = LegacyVtkData::Type::StructuredGrid;
    else if (type == "unstructured_grid")
      data_.type = LegacyVtkData::Type::UnstructuredGrid;
    else if (type == "polydata")
      data_.type = LegacyVtkData::Type::PolyData;
    else
      fail(concat("DATASET ", last_,
                  " is not one Sandstorm reads; expected STRUCTURED_POINTS, RECTILINEAR_GRID, "
                  "STRUCTURED_GRID, UNSTRUCTURED_GRID or POLYDATA"));
  }

  // POINTS, cells and their types: an unstructured grid's or polydata's geometry.
  void pointSetGeometry() {
    bool points = false, cells = false, types = false;
    std::array<bool, 4> lists{};
    static const char* kLists[4] = {"vertices", "lines", "polygons", "triangle_strips"};
    const bool grid = data_.type == LegacyVtkData::Type::UnstructuredGrid;
    while (skipSpace(), at_ < text_.size()) {
      const std::size_t before = at_;
      const std::string key = keyword("the dataset's geometry");
      if (key == "point_data" || key == "cell_data") {
        at_ = before;
        break;
      }
      if (key == "points") {
        if (points) fail("a second POINTS");
        points = true;
        const long long n = integer("POINTS count", 0, 1LL << 40);
        if (double(n) * 12.0 > double(budget_))
          fail(concat("POINTS ", n, " exceed the memory budget (field.memory_budget) of ", budget_,
                      " bytes", raiseBudget(double(n) * 12.0)));
        const std::string type = keyword("the points' type");
        data_.points = values(type, 3 * n, "POINTS");
      } else if (key == "field") {
        token("the field data's name");
        std::vector<LegacyArray> discard;
        fieldArrays(discard, std::nullopt);
      } else if (grid && key == "cells") {
        if (cells) fail("a second CELLS");
        cells = true;
        data_.cells = cellList("CELLS");
      } else if (grid && key == "cell_types") {
        if (types) fail("a second CELL_TYPES");
        types = true;
        const long long n = integer("CELL_TYPES count", 0, 1LL << 40);
        if (cells && n != data_.cells.count())
          fail(concat("CELL_TYPES ", n, " but CELLS lists ", data_.cells.count(),
                      " cells; expected the counts to agree"));
        for (double t : values("int", n, "CELL_TYPES")) {
          if (t < 0 || t > 255) fail(concat("cell type ", t, "; expected a VTK cell type, 0..255"));
          data_.cellTypes.push_back(int(t));
        }
      } else if (!grid &&
                 std::find(std::begin(kLists), std::end(kLists), key) != std::end(kLists)) {
        const std::size_t list =
            std::size_t(std::find(std::begin(kLists), std::end(kLists), key) - std::begin(kLists));
        if (lists[list]) fail(concat("a second ", last_));
        lists[list] = true;
        data_.polyCells[list] = cellList(last_);
      } else {
        fail(concat("'", last_, "' in the ", lower(datasetName()), " geometry; expected POINTS, ",
                    grid ? "CELLS, CELL_TYPES" : "VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS",
                    ", FIELD, POINT_DATA or CELL_DATA"));
      }
      metadata();
    }
    if (!points) fail("no POINTS in the dataset");
    if (grid && cells != types)
      fail(cells ? "CELLS without CELL_TYPES" : "CELL_TYPES without CELLS");
    if (grid && data_.cellTypes.size() != std::size_t(data_.cells.count()))
      fail(concat("CELL_TYPES lists ", data_.cellTypes.size(), " types for ", data_.cells.count(),
                  " cells"));
    const long long count = data_.pointCount();
    auto checkIds = [&](const LegacyCells& c, const std::string& what) {
      for (std::int64_t id : c.connectivity)
        if (id < 0 || id >= count)
          fail(concat(what, " names point ", id, "; the POINTS are 0..", count - 1));
    };
    checkIds(data_.cells, "CELLS");
    for (std::size_t l = 0; l < 4; ++l)
      checkIds(data_.polyCells[l], kLists[l]);
  }

  // A point id, offset or count read as a number: a whole number from 0 up
  // to 2^53 (past that a double cannot hold it), checked before it becomes
  // an integer. Ids are held to the POINTS later.
  std::int64_t index(double v, const std::string& what) {
    if (!(v >= 0.0 && v < 9007199254740992.0) || v != std::floor(v))
      fail(concat(what, ": ", v, " is not a point index (a whole number from 0)"));
    return std::int64_t(v);
  }

  // A cell list: "n size" then n counted cells (up to 4.2), or "offsets
  // connectivity" then OFFSETS and CONNECTIVITY arrays (5.x).
  LegacyCells cellList(const std::string& what) {
    LegacyCells cells;
    const long long n = integer(concat(what, " count"), 0, 1LL << 40);
    const long long size = integer(concat(what, " size"), 0, 1LL << 40);
    if (double(n + size) * 8.0 > double(budget_))
      fail(concat(what, " ", n, " ", size, " exceed the memory budget (field.memory_budget) of ",
                  budget_, " bytes", raiseBudget(double(n + size) * 8.0)));
    if (version_ >= 5.0) {
      if (keyword("OFFSETS") != "offsets") fail(concat("'", last_, "'; expected OFFSETS"));
      const std::vector<double> offsets = values(keyword("the offsets' type"), n, "OFFSETS");
      if (keyword("CONNECTIVITY") != "connectivity")
        fail(concat("'", last_, "'; expected CONNECTIVITY"));
      const std::vector<double> connectivity =
          values(keyword("the connectivity's type"), size, "CONNECTIVITY");
      if (n == 0) {
        if (size != 0) fail(concat(what, ": no offsets for ", size, " point ids"));
        return cells;
      }
      if (offsets.front() != 0.0)
        fail(concat(what, ": the first offset is ", offsets.front(), "; expected 0"));
      cells.offsets.clear();
      for (std::size_t i = 0; i < offsets.size(); ++i) {
        if (i > 0 && offsets[i] < offsets[i - 1])
          fail(concat(what, ": offset ", i, " (", offsets[i], ") is below the one before it"));
        cells.offsets.push_back(index(offsets[i], concat(what, " offset ", i)));
      }
      if (offsets.back() != double(size))
        fail(concat(what, ": the last offset is ", offsets.back(), " but CONNECTIVITY holds ", size,
                    " ids"));
      cells.connectivity.reserve(connectivity.size());
      for (const double id : connectivity)
        cells.connectivity.push_back(index(id, concat(what, " CONNECTIVITY")));
      return cells;
    }
    const std::vector<double> list = values("int", size, what);
    cells.offsets.reserve(std::size_t(n) + 1);
    std::size_t at = 0;
    for (long long c = 0; c < n; ++c) {
      if (at >= list.size())
        fail(concat(what, ": ", c, " of ", n, " cells fill its size of ", size, " values"));
      const double k = double(index(list[at++], concat(what, ": cell ", c, "'s point count")));
      if (k > double(list.size() - at))
        fail(concat(what, ": cell ", c, " has ", k, " points; only ", list.size() - at,
                    " values of its size are left"));
      for (std::size_t i = 0; i < std::size_t(k); ++i)
        cells.connectivity.push_back(index(list[at++], what));
      cells.offsets.push_back(std::int64_t(cells.connectivity.size()));
    }
    if (at != list.size())
      fail(concat(what, ": its ", n, " cells take ", at, " of the ", size,
                  " values its size says; expected them to agree"));
    return cells;
  }

  void geometry() {
    if (data_.pointSet()) {
      pointSetGeometry();
      return;
    }
    bool dims = false, origin = false, spacing = false;
    std::array<bool, 3> coordinates{};
    bool points = false;
    while (skipSpace(), at_ < text_.size()) {
      const std::size_t before = at_;
      const std::string key = keyword("the dataset's geometry");
      if (key == "point_data" || key == "cell_data") {
        at_ = before;
        break;
      }
      if (key == "dimensions") {
        if (dims) fail("a second DIMENSIONS");
        for (int a = 0; a < 3; ++a) {
          const std::string what = concat("DIMENSIONS along ", "xyz"[a]);
          const long long n = integer(what, -(1LL << 62), 1LL << 31);
          if (n < 1) fail(concat(what, " is ", n, "; expected a positive point count"));
          data_.dims[std::size_t(a)] = n;
        }
        const double n = double(data_.dims[0]) * double(data_.dims[1]) * double(data_.dims[2]);
        if (n > double(VectorField::kMaxPoints) || n * 12.0 > double(budget_))
          fail(concat("DIMENSIONS ", data_.dims[0], " ", data_.dims[1], " ", data_.dims[2], " = ",
                      n, " points exceed the memory budget (field.memory_budget) of ", budget_,
                      " bytes (12 per point, at most ", VectorField::kMaxPoints, " points)",
                      n > double(VectorField::kMaxPoints) ? std::string() : raiseBudget(n * 12.0)));
        dims = true;
      } else if (key == "field") {
        token("the field data's name");
        std::vector<LegacyArray> discard;
        fieldArrays(discard, std::nullopt);
      } else if (data_.type == LegacyVtkData::Type::StructuredPoints &&
                 (key == "origin" || key == "spacing" || key == "aspect_ratio")) {
        const bool isOrigin = key == "origin";
        if (isOrigin ? origin : spacing) fail(concat("a second ", lower(last_)));
        (isOrigin ? origin : spacing) = true;
        const std::string name =
            isOrigin ? "ORIGIN" : (key == "spacing" ? "SPACING" : "ASPECT_RATIO");
        for (int a = 0; a < 3; ++a) {
          const double v = number(concat(name, " along ", "xyz"[a]));
          if (!std::isfinite(v)) fail(concat(name, " along ", "xyz"[a], " is ", v));
          if (!isOrigin && !(v > 0.0) && !(dims && data_.dims[std::size_t(a)] == 1))
            fail(concat(name, " along ", "xyz"[a], " is ", v, "; expected a positive spacing"));
          (isOrigin ? data_.origin : data_.spacing)[std::size_t(a)] = v;
        }
      } else if (data_.type == LegacyVtkData::Type::RectilinearGrid &&
                 (key == "x_coordinates" || key == "y_coordinates" || key == "z_coordinates")) {
        const int a = key[0] - 'x';
        if (!dims) fail(concat(lower(last_), " before DIMENSIONS"));
        if (coordinates[std::size_t(a)]) fail(concat("a second ", key));
        coordinates[std::size_t(a)] = true;
        const long long n = integer(concat(key, " count"), 0, 1LL << 31);
        if (n != data_.dims[std::size_t(a)])
          fail(concat(key, " ", n, " but DIMENSIONS make ", data_.dims[std::size_t(a)], " along ",
                      "xyz"[a], "; expected the counts to agree"));
        const std::string type = keyword("the coordinates' type");
        data_.coordinates[std::size_t(a)] = values(type, n, key);
      } else if (data_.type == LegacyVtkData::Type::StructuredGrid && key == "points") {
        if (!dims) fail("POINTS before DIMENSIONS");
        if (points) fail("a second POINTS");
        points = true;
        const long long n = integer("POINTS count", 0, 1LL << 40);
        if (n != data_.pointCount())
          fail(concat("POINTS ", n, " but DIMENSIONS make ", data_.pointCount(),
                      "; expected the counts to agree"));
        const std::string type = keyword("the points' type");
        data_.points = values(type, 3 * n, "POINTS");
      } else {
        fail(concat("'", last_, "' in the ", lower(datasetName()), " geometry; expected DIMENSIONS",
                    data_.type == LegacyVtkData::Type::StructuredPoints
                        ? ", ORIGIN, SPACING"
                        : (data_.type == LegacyVtkData::Type::RectilinearGrid
                               ? ", X_COORDINATES, Y_COORDINATES, Z_COORDINATES"
                               : ", POINTS"),
                    ", FIELD, POINT_DATA or CELL_DATA"));
      }
      metadata();
    }
    if (!dims) fail("no DIMENSIONS in the dataset");
    if (data_.type == LegacyVtkData::Type::RectilinearGrid)
      for (int a = 0; a < 3; ++a)
        if (!coordinates[std::size_t(a)]) fail(concat("no ", "XYZ"[a], "_COORDINATES"));
    if (data_.type == LegacyVtkData::Type::StructuredGrid && !points) fail("no POINTS");
  }

  std::string datasetName() const {
    switch (data_.type) {
      case LegacyVtkData::Type::StructuredPoints:
        return "STRUCTURED_POINTS";
      case LegacyVtkData::Type::RectilinearGrid:
        return "RECTILINEAR_GRID";
      case LegacyVtkData::Type::StructuredGrid:
        return "STRUCTURED_GRID";
      case LegacyVtkData::Type::UnstructuredGrid:
        return "UNSTRUCTURED_GRID";
      case LegacyVtkData::Type::PolyData:
        break;
    }
    return "POLYDATA";
  }

  // `count` values of `type`: ASCII numbers, or BINARY big-endian words
  // starting on the next line; as double, or as float (rounded from the
  // double: the same floats VTK's float arrays took of them before).
  std::vector<double> values(const std::string& type, long long count, const std::string& what) {
    const std::size_t n = checkValues(type, count, what);
    std::vector<double> out(n);
    readValues(out.data(), n, type, what);
    return out;
  }
  // An attribute array: float unless its type is double (`asFloat`: float whatever its type).
  void arrayValues(LegacyArray& a, const std::string& type, long long count,
                   const std::string& what, bool asFloat = false) {
    a.singlePrecision = asFloat || type != "double";
    const std::size_t n = checkValues(type, count, what, a.singlePrecision ? 4 : 8);
    if (a.singlePrecision) {
      a.floats = std::make_unique_for_overwrite<float[]>(n);
      a.floatCount = n;
      readValues(a.floats.get(), n, type, what);
    } else {
      a.values.resize(n);
      readValues(a.values.data(), n, type, what);
    }
  }
  // Checks that `count` values of `type`, held in `held` bytes each once
  // read, fit in the budget, and in the bytes left (before anything is
  // allocated for them); returns the count.
  std::size_t checkValues(const std::string& type, long long count, const std::string& what,
                          int held = 8) {
    const int size = typeSize(type);
    if (size == 0)
      fail(concat(what, ": data type '", last_,
                  "' is not a number type Sandstorm reads (unsigned_char .. double; bit and "
                  "string arrays are not supported)"));
    if (count < 0 || double(count) * held > double(budget_))
      fail(concat(what, ": ", count, " values exceed the memory budget (field.memory_budget) of ",
                  budget_, " bytes",
                  count < 0 ? std::string() : raiseBudget(double(count) * held)));
    const std::size_t n = std::size_t(count);
    if (binary_) {
      endOfLine(concat(what, "'s type"));
      const double bytes = double(n) * double(size);
      if (bytes > double(text_.size() - at_))
        fail(concat(what, ": ", n, " values of ", size, " bytes need ", bytes, " bytes; ",
                    text_.size() - at_, " are left; the file is truncated"));
    } else if (double(n) * 2.0 - 1.0 > double(text_.size() - at_)) {
      fail(concat(what, ": ", n, " values cannot fit in the ", text_.size() - at_,
                  " bytes left; the file is truncated"));
    }
    return n;
  }
  // Reads the n values checkValues allowed into `out`.
  template <class T>
  void readValues(T* out, std::size_t n, const std::string& type, const std::string& what) {
    const int size = typeSize(type);
    if (!binary_) {
      std::size_t i = 0;
      if (n >= kParallelValues) {  // over the cores, up to any bad token
        const AsciiScan scan = parseAsciiNumbers<T>(text_, at_, n, out, [&](std::size_t offset) {
          at_ = start_ = offset;
          tick();
        });
        i = scan.parsed;
        at_ = start_ = scan.end;
      }
      for (; i < n; ++i) {
        out[i] = T(numberFor([&] { return concat(what, " value ", i + 1, " of ", n); }));
        tick();
      }
      return;
    }
    const auto* p = reinterpret_cast<const unsigned char*>(text_.data() + at_);
    const bool isFloat = type == "float" || type == "double";
    const bool isSigned = type == "char" || type == "signed_char" || type == "short" ||
                          type == "int" || type == "long" || type == "vtktypeint64" ||
                          type == "vtkidtype";
    for (std::size_t i = 0; i < n; ++i, p += size) {
      std::uint64_t word = 0;
      for (int b = 0; b < size; ++b)
        word = (word << 8) | p[b];
      double v;
      if (isFloat)
        v = size == 4 ? double(std::bit_cast<float>(std::uint32_t(word)))
                      : std::bit_cast<double>(word);
      else if (isSigned)
        v = double(std::int64_t(word << (64 - 8 * size)) >> (64 - 8 * size));
      else
        v = double(word);
      out[i] = T(v);
      if ((i & 0xfffff) == 0xfffff) {  // the text behind given back as the array fills
        at_ += std::size_t{0x100000} * std::size_t(size);
        start_ = at_;  // a message from here on names the line the parse is at
        tick();
      }
    }
    at_ = std::size_t(p - reinterpret_cast<const unsigned char*>(text_.data()));
    tick();
  }

  // Skips an array's METADATA block: "METADATA", then lines up to an empty one.
  void metadata() {
    const std::size_t before = at_;
    skipSpace();
    if (at_ + 8 > text_.size() || lower(std::string_view(text_.data() + at_, 8)) != "metadata") {
      at_ = before;
      return;
    }
    token("METADATA");
    endOfLine("METADATA");
    while (at_ < text_.size()) {
      const std::string_view l = readLine();
      if (l.find_first_not_of(" \t\r") == std::string_view::npos) return;
    }
  }

  void attributes(std::vector<LegacyArray>& out, long long expected, const char* section) {
    const long long n = integer(concat(section, " count"), 0, 1LL << 40);
    if (n != expected && data_.pointSet())
      fail(concat(section, " ", n, " but the dataset has ", expected,
                  std::string(section) == "POINT_DATA" ? " points" : " cells",
                  "; expected the counts to agree"));
    if (n != expected)
      fail(concat(section, " ", n, " but DIMENSIONS ", data_.dims[0], " ", data_.dims[1], " ",
                  data_.dims[2], " make ", expected, "; expected the counts to agree"));
    while (skipSpace(), at_ < text_.size()) {
      const std::size_t before = at_;
      const std::string key = keyword(concat("an attribute of ", section));
      LegacyArray a;
      a.kind = key;
      if (key == "point_data" || key == "cell_data") {
        at_ = before;
        return;
      }
      if (key == "scalars") {
        a.name = arrayName(out, "the scalars' name");
        const std::string type = keyword("the scalars' type");
        a.components = 1;
        // An optional component count, then LOOKUP_TABLE on its own line.
        std::string next = keyword("LOOKUP_TABLE or the component count");
        if (next != "lookup_table") {
          long long c = 0;
          const auto [end, ec] = std::from_chars(next.data(), next.data() + next.size(), c);
          if (ec != std::errc() || end != next.data() + next.size() || c < 1 || c > 4)
            fail(concat("'", last_, "'; expected the scalars' component count (1..4)"));
          a.components = int(c);
          next = keyword("LOOKUP_TABLE");
        }
        if (next != "lookup_table") fail(concat("'", last_, "'; expected LOOKUP_TABLE"));
        token("the lookup table's name");
        arrayValues(a, type, n * a.components, "SCALARS " + a.name);
        out.push_back(std::move(a));
      } else if (key == "vectors" || key == "normals") {
        a.name = arrayName(out, "the array's name");
        const std::string type = keyword("the array's type");
        a.components = 3;
        arrayValues(a, type, n * 3, lower(key) + " " + a.name);
        out.push_back(std::move(a));
      } else if (key == "tensors" || key == "tensors6") {
        a.name = arrayName(out, "the tensors' name");
        const std::string type = keyword("the tensors' type");
        a.components = key == "tensors" ? 9 : 6;
        arrayValues(a, type, n * a.components, "TENSORS " + a.name);
        out.push_back(std::move(a));
      } else if (key == "texture_coordinates") {
        a.name = arrayName(out, "the texture coordinates' name");
        a.components = int(integer("the texture coordinates' dimension", 1, 3));
        const std::string type = keyword("the texture coordinates' type");
        arrayValues(a, type, n * a.components, "TEXTURE_COORDINATES " + a.name, true);
        out.push_back(std::move(a));
      } else if (key == "color_scalars") {
        a.name = arrayName(out, "the colour scalars' name");
        a.components = int(integer("the colour scalars' value count", 1, 4));
        arrayValues(a, binary_ ? "unsigned_char" : "float", n * a.components,
                    "COLOR_SCALARS " + a.name, true);
        out.push_back(std::move(a));
      } else if (key == "lookup_table") {
        token("the lookup table's name");
        const long long size = integer("the lookup table's size", 0, 1 << 24);
        values(binary_ ? "unsigned_char" : "float", size * 4, "LOOKUP_TABLE");
      } else if (key == "field") {
        token("the field data's name");
        fieldArrays(out, n);
        continue;  // each array had its own METADATA
      } else {
        fail(concat("'", last_, "' in ", section,
                    "; expected SCALARS, COLOR_SCALARS, LOOKUP_TABLE, VECTORS, NORMALS, "
                    "TEXTURE_COORDINATES, TENSORS or FIELD"));
      }
      metadata();
    }
  }

  // An array's name, one the section has not used: VTK keeps only the last
  // of two arrays of one name, so the first would vanish unsaid.
  std::string arrayName(const std::vector<LegacyArray>& out, const char* what) {
    std::string name(token(what));
    for (const LegacyArray& a : out)
      if (a.name == name)
        fail(concat("a second array named '", name,
                    "'; the arrays of a section need names of their own"));
    return name;
  }

  // FIELD name n: n arrays "name components tuples type" + values. With
  // `tuples`, every array must have that many (attribute data).
  void fieldArrays(std::vector<LegacyArray>& out, std::optional<long long> tuples) {
    const long long arrays = integer("the field's array count", 0, 4096);
    for (long long i = 0; i < arrays; ++i) {
      LegacyArray a;
      a.kind = "FIELD";
      a.name = arrayName(out, "a field array's name");
      a.components = int(integer(concat("field array '", a.name, "' components"), 1, 4096));
      const long long n = integer(concat("field array '", a.name, "' tuples"), 0, 1LL << 40);
      if (tuples && n != *tuples)
        fail(concat("field array '", a.name, "' has ", n, " tuples; the section has ", *tuples));
      const std::string type = keyword(concat("field array '", a.name, "' type"));
      arrayValues(a, type, n * a.components, "field array '" + a.name + "'");
      metadata();
      if (tuples) out.push_back(std::move(a));
    }
  }

  std::string_view text_;
  std::string file_;
  std::size_t budget_;
  ProgressMeter* meter_;
  PageBuffer* pages_;
  long long releasedLines_ = 0;  // the lines of the text given back
  std::size_t reported_ = 0;
  std::size_t at_ = 0, start_ = 0;
  std::string last_;
  bool binary_ = false;
  double version_ = 0.0;
  LegacyVtkData data_;
};

}  // namespace

std::optional<VtkImageFrame> readVtkLegacyFrame(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string text(kLegacyFrameBytes, '\0');
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(std::size_t(in.gcount()));
  try {
    // No budget: the header's counts are the read's to judge; the prefix
    // bounds what this parse holds (every array is checked against the bytes left).
    return Parser(text, path.string(), std::numeric_limits<std::size_t>::max()).frame();
  } catch (const Error&) {
    return std::nullopt;  // the read says what is wrong
  }
}

LegacyVtkData parseVtkLegacy(const std::filesystem::path& path, std::size_t memoryBudget) {
  const std::string file = path.string();
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw Error(concat(file, ": cannot read its size: ", ec.message()));
  // ASCII takes at least two bytes a value and BINARY four: a file larger than
  // four times the budget holds more than the budget allows.
  if (double(size) > 4.0 * double(memoryBudget) + 65536.0)
    throw Error(
        concat(file, ": ", size,
               " bytes, more than a grid within the memory budget (field.memory_budget) of ",
               memoryBudget, " bytes can take", raiseBudget((double(size) - 65536.0) / 4.0)));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(concat(file, ": cannot open the file for reading"));
  PageBuffer text(std::size_t(size), file);
  std::size_t done = 0;
  {
    ProgressMeter reading("reading " + path.filename().string(), size, "bytes");
    constexpr std::size_t kChunk = std::size_t{16} << 20;
    while (done < text.size() && in) {
      in.read(text.data() + done, std::streamsize(std::min(kChunk, text.size() - done)));
      done += std::size_t(in.gcount());
      reading.add(std::uint64_t(in.gcount()));
    }
    reading.finish();
  }
  // The parse's own meter: ASCII values parse at tens of MB/s, far below a disk's read.
  ProgressMeter parsing("parsing " + path.filename().string(), done, "bytes");
  LegacyVtkData data =
      Parser(text.view().substr(0, done), file, memoryBudget, &parsing, &text).run();
  parsing.finish();
  return data;
}

}  // namespace sandstorm
