#include "core/io/openfoam_check.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <string>

#include "core/io/budget_advice.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kMaxCount = (std::uint64_t{1} << 31) - 1;  // OpenFOAM's 32-bit labels
constexpr int kMaxDepth = 64;

// Reads a file through zlib, which passes plain files through unchanged.
class GzStream {
 public:
  explicit GzStream(const fs::path& path) : file_(gzopen(path.c_str(), "rb")) {
    if (file_) gzbuffer(file_, 1 << 16);
  }
  ~GzStream() {
    if (file_) gzclose(file_);
  }
  GzStream(const GzStream&) = delete;
  GzStream& operator=(const GzStream&) = delete;
  bool open() const { return file_ != nullptr; }
  int peek() {
    if (at_ == end_ && !fill()) return -1;
    return static_cast<unsigned char>(buffer_[at_]);
  }
  int get() {
    const int c = peek();
    if (c >= 0) {
      ++at_;
      if (c == '\n') ++line_;
    }
    return c;
  }
  // Skips `n` bytes; false when the file ends first.
  bool skip(std::uint64_t n) {
    while (n > 0) {
      if (at_ == end_ && !fill()) return false;
      const std::uint64_t take = std::min<std::uint64_t>(n, end_ - at_);
      at_ += std::size_t(take);
      n -= take;
    }
    return true;
  }
  long line() const { return line_; }

 private:
  bool fill() {
    if (!file_) return false;
    const int n = gzread(file_, buffer_, sizeof buffer_);
    at_ = 0;
    end_ = n > 0 ? std::size_t(n) : 0;
    return end_ > 0;
  }
  gzFile file_;
  char buffer_[1 << 16];
  std::size_t at_ = 0, end_ = 0;
  long line_ = 1;
};

bool wordChar(int c) {
  return std::isalnum(c) || c == '_' || c == '<' || c == '>' || c == ':' || c == '.' || c == '-' ||
         c == '+' || c == '#' || c == '$' || c == '|' || c == '^' || c == '*' || c == '/' ||
         c == '\\' || c == '!' || c == '&' || c == '%' || c == '@' || c == '?' || c == '=' ||
         c == '~' || c == '`' || c == '\'' || c == ',';
}

class FoamScanner {
 public:
  FoamScanner(const fs::path& path, std::size_t budget)
      : in_(path), file_(path.string()), budget_(budget) {}

  const OpenFoamFacts& facts() const { return facts_; }

  void run() {
    if (!in_.open()) throw Error(concat(file_, ": cannot open the file for reading"));
    while (true) {
      skipSpace();
      const int c = in_.peek();
      if (c < 0) break;
      item(0);
    }
    if (braces_ != 0) fail("a '{' is never closed");
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(concat(file_, ":", in_.line(), ": ", what));
  }

  void skipSpace() {
    while (true) {
      const int c = in_.peek();
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
        in_.get();
      } else if (c == '/') {
        in_.get();
        const int d = in_.peek();
        if (d == '/') {
          while (in_.peek() >= 0 && in_.peek() != '\n')
            in_.get();
        } else if (d == '*') {
          in_.get();
          int previous = 0;
          while (true) {
            const int e = in_.get();
            if (e < 0) fail("a /* comment is never closed");
            if (previous == '*' && e == '/') break;
            previous = e;
          }
        } else {
          pending_ = '/';  // a word starting with '/'
          return;
        }
      } else {
        return;
      }
    }
  }

  std::string word() {
    std::string w;
    if (pending_) {
      w.push_back(char(pending_));
      pending_ = 0;
    }
    while (wordChar(in_.peek()) && w.size() < 4096)
      w.push_back(char(in_.get()));
    return w;
  }

  void string() {
    in_.get();  // the opening quote
    while (true) {
      const int c = in_.get();
      if (c < 0) fail("a string is never closed");
      if (c == '\\') {
        in_.get();
        continue;
      }
      if (c == '"') return;
    }
  }

  static bool integer(const std::string& w) {
    return !w.empty() && w.size() <= 19 &&
           std::all_of(w.begin(), w.end(), [](unsigned char c) { return std::isdigit(c); });
  }

  // One item at top level or inside a group; returns whether it counts as an
  // element of a list (a dictionary's braces belong to the keyword before).
  bool item(int depth) {
    if (depth > kMaxDepth) fail("lists nested too deep");
    skipSpace();
    const int c = pending_ ? pending_ : in_.peek();
    if (c == '"') {
      string();
      return true;
    }
    if (c == '(') {
      in_.get();
      group(depth + 1, ')');
      return true;
    }
    if (c == '{') {
      in_.get();
      ++braces_;
      group(depth + 1, '}');
      --braces_;
      return false;
    }
    if (c == '[') {  // dimensions [0 1 -1 0 0 0 0]
      in_.get();
      group(depth + 1, ']');
      return true;
    }
    if (c == ';' || c == ')' || c == '}' || c == ']') {
      if (c == ';') {
        in_.get();
        inInternalField_ = false;
        return false;
      }
      fail(concat("an unmatched '", char(c), "'"));
    }
    const std::string w = word();
    if (w.empty()) fail(concat("unexpected byte ", c));
    if (w == "FoamFile") {
      header();
      return false;
    }
    if (integer(w)) {
      const std::uint64_t value = std::strtoull(w.c_str(), nullptr, 10);
      skipSpace();
      const int next = in_.peek();
      if (next == '(' || next == '{') {
        if (depth == 0) facts_.lists.push_back({value, 0});
        if (depth == 1 && !facts_.lists.empty())
          facts_.lists.back().minInner = std::min(facts_.lists.back().minInner, value);
        if (inInternalField_) facts_.internalField = value;
        inInternalField_ = false;
        list(value, next == '{', depth);
        lastType_.clear();
        return true;
      }
      if (depth > 0 && !facts_.lists.empty())
        facts_.lists.back().maxLabel = std::max(facts_.lists.back().maxLabel, value);
      if (lastWord_ == "nFaces") facts_.patches.push_back({0, value});
      if (lastWord_ == "startFace" && !facts_.patches.empty()) facts_.patches.back().first = value;
    }
    if (w.rfind("List<", 0) == 0) lastType_ = w.substr(5, w.size() - 6);
    if (w == "internalField") inInternalField_ = true;
    lastWord_ = w;
    return true;
  }

  // Items up to `close`.
  void group(int depth, char close) {
    while (true) {
      skipSpace();
      const int c = pending_ ? pending_ : in_.peek();
      if (c < 0) fail(concat("the file ends before a '", close, "'"));
      if (c == close) {
        in_.get();
        return;
      }
      item(depth);
    }
  }

  void header() {
    skipSpace();
    if (in_.get() != '{') fail("expected '{' after FoamFile");
    std::string key;
    while (true) {
      skipSpace();
      const int c = in_.peek();
      if (c < 0) fail("the FoamFile header is never closed");
      if (c == '}') {
        in_.get();
        return;
      }
      if (c == ';') {
        in_.get();
        key.clear();
        continue;
      }
      if (c == '"') {
        string();
        continue;
      }
      const std::string w = word();
      if (w.empty()) fail(concat("unexpected byte ", c, " in the FoamFile header"));
      if (key.empty()) {
        key = w;
      } else if (key == "format") {
        binary_ = w == "binary";
      } else if (key == "class") {
        class_ = w;
      } else if (key == "arch") {
        if (w.find("label=64") != std::string::npos) label_ = 8;
        if (w.find("scalar=32") != std::string::npos) scalar_ = 4;
      }
    }
  }

  // Bytes a binary element of this list takes; 0 when unknown.
  int elementSize() const {
    static const std::map<std::string, int> kScalars{
        {"scalar", 1}, {"vector", 3}, {"sphericalTensor", 1}, {"symmTensor", 6}, {"tensor", 9}};
    if (lastType_ == "label") return label_;
    if (const auto it = kScalars.find(lastType_); it != kScalars.end()) return it->second * scalar_;
    if (class_ == "labelList" || class_ == "faceCompactList" || class_ == "cellList") return label_;
    if (class_ == "vectorField" || class_ == "pointField") return 3 * scalar_;
    if (class_ == "scalarField") return scalar_;
    return 0;
  }

  void list(std::uint64_t count, bool uniform, int depth) {
    if (count > kMaxCount)
      fail(concat("a list of ", count, " elements; OpenFOAM counts in 31 bits"));
    if (double(count) * 24.0 > double(budget_))
      fail(concat("a list of ", count,
                  " elements, beyond the memory budget (field.memory_budget) of ", budget_,
                  " bytes", raiseBudget(double(count) * 24.0)));
    const char open = char(in_.get()), close = open == '(' ? ')' : '}';
    // A binary file writes lists of fixed-size elements as raw bytes; lists
    // of anything else (a boundary's dictionaries) as text.
    if (const int size = binary_ && !uniform ? elementSize() : 0; size > 0) {
      // Labels are read, for the mesh's cross-checks; other values skipped.
      const bool labels = (lastType_ == "label" ||
                           (lastType_.empty() && size == label_ && class_ != "scalarField")) &&
                          depth == 0 && !facts_.lists.empty();
      const bool complete =
          labels ? readLabels(count, facts_.lists.back()) : in_.skip(count * std::uint64_t(size));
      if (!complete)
        fail(concat("a binary list of ", count, " elements of ", size,
                    " bytes runs past the end of the file (truncated)"));
      if (in_.get() != ')') fail(concat("a binary list of ", count, " elements does not close"));
      return;
    }
    if (uniform) {
      group(depth + 1, close);
      return;
    }
    std::uint64_t items = 0;
    while (true) {
      skipSpace();
      const int c = pending_ ? pending_ : in_.peek();
      if (c < 0) fail(concat("the file ends inside a list of ", count, " elements"));
      if (c == close) {
        in_.get();
        break;
      }
      if (item(depth + 1)) ++items;
      if (items > count)
        fail(concat("a list of ", count, " elements holds more (the count is wrong)"));
    }
    if (items != count)
      fail(concat("a list of ", count, " elements holds ", items, " (the count is wrong)"));
  }

  // `count` binary labels into `list`'s facts; false when the file ends first.
  bool readLabels(std::uint64_t count, OpenFoamFacts::List& list) {
    std::int64_t previous = 0;
    for (std::uint64_t i = 0; i < count; ++i) {
      std::uint64_t v = 0;
      for (int b = 0; b < label_; ++b) {
        const int c = in_.get();
        if (c < 0) return false;
        v |= std::uint64_t(c) << (8 * b);  // LSB, as the arch says
      }
      const std::int64_t label =
          label_ == 4 ? std::int64_t(std::int32_t(std::uint32_t(v))) : std::int64_t(v);
      list.maxLabel = std::max(list.maxLabel, label < 0 ? ~std::uint64_t(0) : std::uint64_t(label));
      if (i == 0)
        list.first = label;
      else
        list.minStep = std::min(list.minStep, label - previous);
      list.last = previous = label;
    }
    return true;
  }

  GzStream in_;
  std::string file_;
  std::size_t budget_;
  OpenFoamFacts facts_;
  std::string lastWord_;
  bool inInternalField_ = false;
  int pending_ = 0;
  int braces_ = 0;
  bool binary_ = false;
  std::string class_, lastType_;
  int label_ = 4, scalar_ = 8;
};

// The case's time folders (names that are numbers), in time order.
std::vector<fs::path> timeFolders(const fs::path& root) {
  std::vector<std::pair<double, fs::path>> times;
  std::error_code ec;
  for (auto it = fs::directory_iterator(root, ec); !ec && it != fs::directory_iterator();
       it.increment(ec)) {
    if (!it->is_directory(ec)) continue;
    const std::string name = it->path().filename().string();
    char* end = nullptr;
    const double t = std::strtod(name.c_str(), &end);
    if (!name.empty() && end == name.c_str() + name.size()) times.push_back({t, it->path()});
  }
  std::sort(times.begin(), times.end());
  std::vector<fs::path> out;
  for (const auto& t : times)
    out.push_back(t.second);
  return out;
}

void addFiles(const fs::path& folder, std::vector<fs::path>& out, int depth) {
  std::error_code ec;
  for (auto it = fs::directory_iterator(folder, ec); !ec && it != fs::directory_iterator();
       it.increment(ec)) {
    if (it->is_regular_file(ec))
      out.push_back(it->path());
    else if (depth > 0 && it->is_directory(ec))
      addFiles(it->path(), out, depth - 1);
  }
}

}  // namespace

OpenFoamFacts checkOpenFoamFile(const fs::path& file, std::size_t memoryBudget) {
  FoamScanner scanner(file, memoryBudget);
  scanner.run();
  return scanner.facts();
}

std::uint64_t checkOpenFoamMesh(const fs::path& root, std::size_t memoryBudget) {
  const fs::path mesh = root / "constant" / "polyMesh";
  auto read = [&](const char* name) {
    fs::path p = mesh / name;
    std::error_code ec;
    if (!fs::exists(p, ec) && fs::exists(mesh / (std::string(name) + ".gz"), ec))
      p = mesh / (std::string(name) + ".gz");
    if (!fs::exists(p, ec)) throw Error(concat(p.string(), ": the mesh has no ", name));
    return std::pair(p.string(), checkOpenFoamFile(p, memoryBudget));
  };
  const auto [pointsFile, points] = read("points");
  const auto [facesFile, faces] = read("faces");
  const auto [ownerFile, owner] = read("owner");
  const auto [neighbourFile, neighbour] = read("neighbour");
  const auto [boundaryFile, boundary] = read("boundary");
  auto first = [](const OpenFoamFacts& f, const std::string& file, const char* what) {
    if (f.lists.empty()) throw Error(concat(file, ": no list of ", what));
    return f.lists.front();
  };
  const std::uint64_t nPoints = first(points, pointsFile, "points").count;
  std::uint64_t nFaces = 0;
  if (faces.lists.size() == 2) {  // faceCompactList: offsets, then the points of every face
    const OpenFoamFacts::List& offsets = faces.lists[0];
    nFaces = offsets.count > 0 ? offsets.count - 1 : 0;
    if (offsets.count > 0 &&
        (offsets.first != 0 || offsets.last != std::int64_t(faces.lists[1].count) ||
         (offsets.count > 1 && offsets.minStep < 3)))
      throw Error(concat(facesFile, ": the faces' offsets must run from 0 to the ",
                         faces.lists[1].count, " face points, each face at least 3 of them"));
    if (nFaces > 0 && faces.lists[1].maxLabel >= nPoints)
      throw Error(concat(facesFile, ": a face names point ", faces.lists[1].maxLabel,
                         "; the points are 0..", nPoints - 1));
  } else {
    const OpenFoamFacts::List list = first(faces, facesFile, "faces");
    nFaces = list.count;
    if (nFaces > 0 && list.minInner < 3)
      throw Error(concat(facesFile, ": a face of ", list.minInner, " points; expected 3 or more"));
    if (nFaces > 0 && list.maxLabel >= nPoints)
      throw Error(concat(facesFile, ": a face names point ", list.maxLabel, "; the points are 0..",
                         nPoints - 1));
  }
  const OpenFoamFacts::List owners = first(owner, ownerFile, "owners");
  if (owners.count != nFaces)
    throw Error(concat(ownerFile, ": ", owners.count, " owners for ", nFaces, " faces"));
  // OpenFOAM counts the cells as the largest owner plus one; each has a face.
  const std::uint64_t nCells = nFaces > 0 ? owners.maxLabel + 1 : 0;
  if (nCells > nFaces)
    throw Error(concat(ownerFile, ": owner ", owners.maxLabel, " names a cell beyond the ", nFaces,
                       " faces' cells"));
  const OpenFoamFacts::List neighbours = first(neighbour, neighbourFile, "neighbours");
  if (neighbours.count > nFaces || (neighbours.count > 0 && neighbours.maxLabel >= nCells))
    throw Error(concat(neighbourFile, ": ", neighbours.count, " neighbours up to cell ",
                       neighbours.maxLabel, " for ", nFaces, " faces and ", nCells, " cells"));
  for (const auto& [start, count] : boundary.patches)
    if (start + count > nFaces)
      throw Error(concat(boundaryFile, ": a patch of faces ", start, "..", start + count,
                         " past the ", nFaces, " faces"));
  return nCells;
}

std::vector<OpenFoamRoot> openFoamFilesToRead(const fs::path& caseDir, bool decomposed,
                                              std::size_t timeStep) {
  std::vector<OpenFoamRoot> roots;
  std::error_code ec;
  if (decomposed) {
    for (auto it = fs::directory_iterator(caseDir, ec); !ec && it != fs::directory_iterator();
         it.increment(ec))
      if (it->is_directory(ec) && it->path().filename().string().rfind("processor", 0) == 0)
        roots.push_back({it->path(), {}});
    std::sort(roots.begin(), roots.end(),
              [](const OpenFoamRoot& a, const OpenFoamRoot& b) { return a.root < b.root; });
  } else {
    roots.push_back({caseDir, {}});
  }
  for (OpenFoamRoot& r : roots) {
    const std::vector<fs::path> times = timeFolders(r.root);
    if (timeStep < times.size()) addFiles(times[timeStep], r.fields, 1);
  }
  return roots;
}

}  // namespace sandstorm
