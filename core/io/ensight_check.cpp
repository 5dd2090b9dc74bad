#include "core/io/ensight_check.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <type_traits>

#include "core/io/budget_advice.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxCaseBytes = 1 << 20;
constexpr std::size_t kMaxLine = 255;  // VTK's EnSight readers read lines into 256 bytes

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return {};
  const std::size_t b = s.find_last_not_of(" \t\r\n");
  return s.substr(a, b - a + 1);
}

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;)
    out.push_back(w);
  return out;
}

bool isInteger(const std::string& w) {
  return !w.empty() && w.size() < 10 &&
         std::all_of(w.begin(), w.end(), [](unsigned char c) { return std::isdigit(c); });
}

// Nodes an element of an EnSight Gold type has; 0 for nsided/nfaced, -1 unknown.
int nodesPer(std::string type) {
  if (type.rfind("g_", 0) == 0) type = type.substr(2);
  static const std::map<std::string, int> kTypes{
      {"point", 1},      {"bar2", 2},   {"bar3", 3},     {"tria3", 3},    {"tria6", 6},
      {"quad4", 4},      {"quad8", 8},  {"tetra4", 4},   {"tetra10", 10}, {"pyramid5", 5},
      {"pyramid13", 13}, {"penta6", 6}, {"penta15", 15}, {"hexa8", 8},    {"hexa20", 20},
      {"nsided", 0},     {"nfaced", 0}};
  const auto it = kTypes.find(type);
  return it == kTypes.end() ? -1 : it->second;
}

// One part's sizes, for its variables.
struct Part {
  std::uint64_t nodes = 0;
  std::map<std::string, std::uint64_t> elements;  // by type
};

// Reads a geometry or variable file: C binary words of 80 characters and
// 32-bit numbers (either byte order), or ascii lines.
class EnSightFile {
 public:
  // A geometry file says whether it is binary; a variable file is as its geometry (`binary`).
  EnSightFile(const fs::path& path, std::size_t budget, int binary = -1)
      : file_(path.string()), budget_(budget) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(concat(file_, ": cannot open the file for reading"));
    std::ostringstream s;
    s << in.rdbuf();
    bytes_ = s.str();
    binary_ = binary < 0 ? bytes_.rfind("C Binary", 0) == 0 : binary == 1;
    if (bytes_.rfind("Fortran Binary", 0) == 0)
      fail("Fortran binary EnSight files are not read; write C binary or ascii");
  }
  bool binary() const { return binary_; }
  std::size_t mark() const { return at_; }
  void reset(std::size_t at) { at_ = at; }
  bool done() {
    if (binary_) return at_ >= bytes_.size();
    while (at_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[at_])))
      ++at_;
    return at_ >= bytes_.size();
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(concat(file_, ": ", what,
                       binary_ ? concat(" (byte ", at_, ")") : concat(" (line ", line(), ")")));
  }

  // An 80-character word (binary) or a line (ascii), trimmed.
  std::string text(const std::string& what) {
    if (binary_) {
      if (at_ + 80 > bytes_.size()) fail(concat("the file ends where ", what, " should be"));
      std::string s = bytes_.substr(at_, 80);
      at_ += 80;
      return trim(s.substr(0, s.find('\0')));
    }
    if (at_ >= bytes_.size()) fail(concat("the file ends where ", what, " should be"));
    const std::size_t eol = bytes_.find('\n', at_);
    std::string s = bytes_.substr(at_, eol == std::string::npos ? std::string::npos : eol - at_);
    if (s.size() > kMaxLine)
      fail(concat("a line of ", s.size(), " characters, past VTK's ", kMaxLine));
    at_ = eol == std::string::npos ? bytes_.size() : eol + 1;
    return trim(s);
  }

  // A count: a 32-bit integer (binary) or the line's first number (ascii).
  std::uint64_t count(const std::string& what) {
    long long v = 0;
    if (binary_) {
      if (at_ + 4 > bytes_.size()) fail(concat("the file ends where ", what, " should be"));
      std::uint32_t w;
      std::memcpy(&w, bytes_.data() + at_, 4);
      if (!order_) order_ = w < (1u << 30) ? 1 : 2;  // little-endian unless that looks absurd
      if (order_ == 2) w = __builtin_bswap32(w);
      at_ += 4;
      v = std::int32_t(w);
    } else {
      const std::vector<std::string> w = words(text(what));
      if (w.empty() || !isInteger(w[0])) fail(concat("expected ", what, " (a count)"));
      v = std::atoll(w[0].c_str());
    }
    if (v < 0) fail(concat(what, " is ", v, "; expected a count"));
    if (double(v) * 12.0 > double(budget_))
      fail(concat(what, " ", v, " is beyond the memory budget (field.memory_budget) of ", budget_,
                  " bytes", raiseBudget(double(v) * 12.0)));
    return std::uint64_t(v);
  }

  // Skips `n` numbers (binary: 4 bytes each; ascii: n lines of `perLine`).
  void skip(std::uint64_t n, const std::string& what, std::uint64_t perLine = 1) {
    if (binary_) {
      if (double(n) * 4.0 > double(bytes_.size() - at_))
        fail(concat(what, ": ", n, " values need ", n * 4, " bytes; ", bytes_.size() - at_,
                    " are left (truncated, or the count is wrong)"));
      at_ += std::size_t(n * 4);
      return;
    }
    const std::uint64_t lines = perLine > 0 ? (n + perLine - 1) / perLine : 0;
    for (std::uint64_t i = 0; i < lines; ++i) {
      if (at_ >= bytes_.size())
        fail(concat(what, ": ", n, " values, but the file ends after ", i * perLine));
      const std::size_t eol = bytes_.find('\n', at_);
      const std::size_t end = eol == std::string::npos ? bytes_.size() : eol;
      if (end - at_ > kMaxLine)
        fail(concat(what, ": a line of ", end - at_, " characters, past VTK's ", kMaxLine));
      at_ = eol == std::string::npos ? bytes_.size() : eol + 1;
    }
  }

  // The sum of `n` counts (an nsided element's nodes), each read.
  std::uint64_t sum(std::uint64_t n, const std::string& what) {
    if (binary_ && double(n) * 4.0 > double(bytes_.size() - at_))
      fail(concat(what, ": ", n, " counts run past the end of the file"));
    std::uint64_t total = 0;
    for (std::uint64_t i = 0; i < n; ++i)
      total += count(what);
    return total;
  }

 private:
  long line() const {
    return long(std::count(bytes_.begin(), bytes_.begin() + long(at_), '\n')) + 1;
  }
  std::string file_;
  std::size_t budget_;
  std::string bytes_;
  std::size_t at_ = 0;
  bool binary_ = false;
  int order_ = 0;  // 1 little-endian, 2 big
};

std::map<long long, Part> checkGeometry(const fs::path& path, std::size_t budget, bool& binary) {
  EnSightFile f(path, budget);
  binary = f.binary();
  if (f.binary()) f.text("'C Binary'");
  f.text("the first description line");
  f.text("the second description line");
  const std::string nodeIds = lower(f.text("'node id ...'"));
  const std::string elementIds = lower(f.text("'element id ...'"));
  if (nodeIds.rfind("node id", 0) != 0 || elementIds.rfind("element id", 0) != 0)
    f.fail("expected the 'node id' and 'element id' lines after the two description lines");
  const bool nodeIdsGiven =
      nodeIds.find("given") != std::string::npos || nodeIds.find("ignore") != std::string::npos;
  const bool elementIdsGiven = elementIds.find("given") != std::string::npos ||
                               elementIds.find("ignore") != std::string::npos;
  std::map<long long, Part> parts;
  std::string next = f.done() ? "" : lower(f.text("'part' or 'extents'"));
  if (next.rfind("extents", 0) == 0) {
    f.skip(6, "the extents", 2);
    next = f.done() ? "" : lower(f.text("'part'"));
  }
  while (!next.empty()) {
    if (next.rfind("part", 0) != 0) f.fail(concat("'", next.substr(0, 40), "'; expected 'part'"));
    const long long number = (long long)f.count("the part number");
    Part& part = parts[number];
    const std::string where = concat("part ", number);
    f.text(where + "'s description");
    const std::string shape = lower(f.text(where + ": 'coordinates' or 'block'"));
    if (shape.rfind("coordinates", 0) == 0) {
      part.nodes = f.count(where + "'s node count");
      if (nodeIdsGiven) f.skip(part.nodes, where + "'s node ids");
      f.skip(3 * part.nodes, where + "'s coordinates");
    } else if (shape.rfind("block", 0) == 0) {
      if (shape.find("with_ghost") != std::string::npos)
        f.fail(concat(where, ": blocks with ghosts are not read"));
      std::uint64_t n[3];
      if (f.binary()) {
        for (auto& v : n)
          v = f.count(where + "'s block dimensions");
      } else {
        const std::vector<std::string> w = words(f.text(where + "'s block dimensions"));
        if (w.size() < 3 || !isInteger(w[0]) || !isInteger(w[1]) || !isInteger(w[2]))
          f.fail(concat(where, ": expected the block's i j k"));
        for (int a = 0; a < 3; ++a)
          n[a] = std::strtoull(w[std::size_t(a)].c_str(), nullptr, 10);
      }
      part.nodes = n[0] * n[1] * n[2];
      if (double(n[0]) * double(n[1]) * double(n[2]) * 12.0 > double(budget))
        f.fail(concat(where, ": a block of ", n[0], " x ", n[1], " x ", n[2],
                      " nodes is beyond the memory budget (field.memory_budget)",
                      raiseBudget(double(n[0]) * double(n[1]) * double(n[2]) * 12.0)));
      part.elements["block"] = std::max<std::uint64_t>(n[0], 1) * std::max<std::uint64_t>(n[1], 1) *
                               std::max<std::uint64_t>(n[2], 1);
      if (shape.find("uniform") != std::string::npos)
        f.skip(6, where + "'s origin and spacing");
      else if (shape.find("rectilinear") != std::string::npos)
        f.skip(n[0] + n[1] + n[2], where + "'s coordinates");
      else
        f.skip(3 * part.nodes, where + "'s coordinates");
      if (shape.find("iblanked") != std::string::npos) f.skip(part.nodes, where + "'s iblanking");
    } else {
      f.fail(concat(where, ": '", shape.substr(0, 40), "'; expected 'coordinates' or 'block'"));
    }
    // Element sections up to the next part.
    while (!f.done()) {
      next = lower(f.text(where + "'s element type or the next 'part'"));
      if (next.rfind("part", 0) == 0) break;
      const std::string type = words(next).empty() ? next : words(next)[0];
      const int per = nodesPer(type);
      if (per < 0)
        f.fail(concat(where, ": element type '", type.substr(0, 40),
                      "' is not one of EnSight Gold's"));
      const std::uint64_t count = f.count(concat(where, "'s ", type, " count"));
      part.elements[type] += count;
      if (elementIdsGiven) f.skip(count, concat(where, "'s ", type, " ids"));
      // Ascii writes an element (or a face) a line, binary its nodes one after another.
      if (type.find("nsided") != std::string::npos) {
        const std::uint64_t nodes = f.sum(count, concat(where, "'s nsided node counts"));
        f.binary() ? f.skip(nodes, concat(where, "'s nsided connectivity"))
                   : f.skip(count, concat(where, "'s nsided connectivity"));
      } else if (type.find("nfaced") != std::string::npos) {
        const std::uint64_t faces = f.sum(count, concat(where, "'s nfaced face counts"));
        const std::uint64_t nodes = f.sum(faces, concat(where, "'s nfaced node counts"));
        f.binary() ? f.skip(nodes, concat(where, "'s nfaced connectivity"))
                   : f.skip(faces, concat(where, "'s nfaced connectivity"));
      } else {
        f.skip(count * std::uint64_t(per), concat(where, "'s ", type, " connectivity"),
               std::uint64_t(per));
      }
      next.clear();
    }
    if (f.done() && next.rfind("part", 0) != 0) next.clear();
  }
  if (parts.empty()) f.fail("the geometry holds no part");
  return parts;
}

int componentsOf(const std::string& kind) {
  if (kind.rfind("scalar", 0) == 0) return 1;
  if (kind.rfind("vector", 0) == 0) return 3;
  if (kind.rfind("tensor symm", 0) == 0) return 6;
  if (kind.rfind("tensor asym", 0) == 0) return 9;
  return 0;
}

void checkVariable(const fs::path& path, const std::string& kind,
                   const std::map<long long, Part>& parts, std::size_t budget, bool binary) {
  EnSightFile f(path, budget, binary ? 1 : 0);
  const int components = componentsOf(kind);
  const bool perNode = kind.find("per node") != std::string::npos;
  f.text("the description");
  while (!f.done()) {
    const std::string word = lower(f.text("'part'"));
    if (word.rfind("part", 0) != 0) f.fail(concat("'", word.substr(0, 40), "'; expected 'part'"));
    const long long number = (long long)f.count("the part number");
    const auto it = parts.find(number);
    if (it == parts.end()) f.fail(concat("part ", number, " is not in the geometry"));
    const std::string where = concat("part ", number);
    if (perNode) {
      const std::string shape = lower(f.text(where + ": 'coordinates' or 'block'"));
      if (shape.rfind("coordinates", 0) != 0 && shape.rfind("block", 0) != 0)
        f.fail(concat(where, ": expected 'coordinates' or 'block'"));
      f.skip(it->second.nodes * std::uint64_t(components), where + "'s values");
      continue;
    }
    // Per element: a section for each element type the part has.
    while (!f.done()) {
      const std::size_t before = f.mark();
      const std::string type = lower(f.text(where + "'s element type"));
      if (type.rfind("part", 0) == 0) {
        f.reset(before);
        break;
      }
      const std::string name = words(type).empty() ? type : words(type)[0];
      const auto e = it->second.elements.find(name);
      if (e == it->second.elements.end())
        f.fail(concat(where, " has no '", name.substr(0, 40), "' elements in the geometry"));
      f.skip(e->second * std::uint64_t(components), concat(where, "'s ", name, " values"));
    }
  }
}

std::string filled(const std::string& name, long long number) {
  const std::size_t first = name.find('*');
  if (first == std::string::npos) return name;
  const std::size_t last = name.find_first_not_of('*', first);
  const std::size_t width = (last == std::string::npos ? name.size() : last) - first;
  std::string digits = std::to_string(number);
  if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
  return name.substr(0, first) + digits + (last == std::string::npos ? "" : name.substr(last));
}

fs::path inside(const EnSightCase& c, const std::string& name, const std::string& what) {
  const fs::path named(name);
  const fs::path relative = named.lexically_normal();
  if (named.is_absolute() || relative.empty() || *relative.begin() == "..")
    throw Error(concat(c.folder.string(), ": the case names ", what, " '", name,
                       "', outside the case's folder"));
  const fs::path path = c.folder / relative;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw Error(concat(path.string(), ": ", what, " named by the case: no such file"));
  return path;
}

}  // namespace

EnSightCase parseEnSightCase(const fs::path& caseFile) {
  const std::string file = caseFile.string();
  std::error_code ec;
  if (fs::file_size(caseFile, ec) > kMaxCaseBytes)
    throw Error(concat(file, ": larger than a case file can be"));
  std::ifstream in(caseFile, std::ios::binary);
  if (!in) throw Error(concat(file, ": cannot open the file for reading"));
  EnSightCase c;
  c.folder = caseFile.parent_path().empty() ? fs::path(".") : caseFile.parent_path();
  std::string section, line, pendingKey;
  int lineNumber = 0;
  long long steps = -1, start = 0, increment = 1;
  int timeSet = 0;
  std::vector<int> usedTimeSets;
  bool gold = false;
  std::vector<double> times;
  std::vector<long long> numbers;
  auto fail = [&](const std::string& what) {
    throw Error(concat(file, ":", lineNumber, ": ", what));
  };
  while (std::getline(in, line)) {
    ++lineNumber;
    // VTK's reader reads lines into 256 bytes and never gets past a longer one.
    if (line.size() > kMaxLine)
      fail(concat("a line of ", line.size(), " characters; EnSight's are at most ", kMaxLine));
    // A case file is text: VTK's reader stops a line at a zero byte and would
    // take what is left for another format.
    for (const char ch : line)
      if (static_cast<unsigned char>(ch) < 0x20 && ch != '\t' && ch != '\r')
        fail(concat("a control character (byte ", int(static_cast<unsigned char>(ch)),
                    "); a case file is text"));
    line = trim(line.substr(0, line.find('#')));
    if (line.empty()) continue;
    const std::string low = lower(line);
    if (low == "format" || low == "geometry" || low == "variable" || low == "time") {
      section = low;
      pendingKey.clear();
      continue;
    }
    if (low == "file" || low == "material" || low == "block_continuation" || low == "scripts")
      fail(concat("a ", line,
                  " section: not read (single-file transient cases, materials and "
                  "scripts are not supported)"));
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos &&
        !(section == "time" && (pendingKey == "time values" || pendingKey == "filename numbers")))
      fail(concat("'", line.substr(0, 40),
                  "'; expected a section (FORMAT, GEOMETRY, VARIABLE, "
                  "TIME) or 'key: value'"));
    if (section.empty()) fail("a line before the FORMAT section");
    // VTK's reader matches keys word for word: one space between words, no tabs.
    if (colon != std::string::npos) {
      const std::string raw = trim(line.substr(0, colon));
      if (raw.find('\t') != std::string::npos || raw.find("  ") != std::string::npos)
        fail(concat("'", raw.substr(0, 40), "': a key's words are one space apart"));
    }
    std::string key = colon == std::string::npos ? pendingKey : lower(trim(line.substr(0, colon)));
    const std::string value = colon == std::string::npos ? line : trim(line.substr(colon + 1));
    // VTK's reader loops for ever on a key it does not know in these sections.
    if (section == "format" && key != "type")
      fail(concat("'", key.substr(0, 40), "' in the FORMAT section; expected type"));
    if (section == "geometry" && key != "model")
      fail(concat("'", key.substr(0, 40),
                  "' in the GEOMETRY section; expected model (measured, match and boundary "
                  "geometry are not read)"));
    if (section == "format") {
      if (key == "type") gold = words(lower(value)) == std::vector<std::string>{"ensight", "gold"};
    } else if (section == "geometry") {
      if (key == "model") {
        std::vector<std::string> w = words(value);
        if (!w.empty() && isInteger(w.front())) {
          usedTimeSets.push_back(std::atoi(w.front().c_str()));
          w.erase(w.begin());
        }
        while (!w.empty() && isInteger(w.front()))
          w.erase(w.begin());
        if (w.empty()) fail("model: expected its file name");
        c.geometry = w.front();
      }
    } else if (section == "variable") {
      if (key.find("constant per case") != std::string::npos) continue;
      std::vector<std::string> w = words(value);
      if (!w.empty() && isInteger(w.front()) && w.size() > 2) {
        usedTimeSets.push_back(std::atoi(w.front().c_str()));
        w.erase(w.begin());
      }
      while (!w.empty() && isInteger(w.front()) && w.size() > 2)
        w.erase(w.begin());
      if (w.size() < 2) fail(concat("variable '", key, "': expected a description and a file"));
      if (componentsOf(key) == 0 || (key.find("per node") == std::string::npos &&
                                     key.find("per element") == std::string::npos))
        fail(concat("variable kind '", key,
                    "' is not read; expected scalar, vector or tensor per "
                    "node or per element"));
      c.variables.push_back({key, w[1]});
    } else if (section == "time") {
      auto numbersIn = [&](auto& out) {
        for (const std::string& w : words(value)) {
          char* end = nullptr;
          const double v = std::strtod(w.c_str(), &end);
          if (end != w.c_str() + w.size() || !std::isfinite(v))
            fail(concat("'", w, "' in the time section is not a number"));
          out.push_back(typename std::decay_t<decltype(out)>::value_type(v));
          if (out.size() > 1000000) fail("more than a million time steps");
        }
      };
      if (key == "time set") {
        timeSet = std::atoi(value.c_str());
        if (timeSet != 1) fail(concat("time set ", value, ": only one time set (1) is read"));
      } else if (key == "number of steps") {
        steps = std::atoll(value.c_str());
        if (steps < 1 || steps > 1000000)
          fail(concat("number of steps ", value, "; expected 1..1000000"));
      } else if (key == "filename start number") {
        start = std::atoll(value.c_str());
      } else if (key == "filename increment") {
        increment = std::atoll(value.c_str());
      } else if (key == "time values") {
        numbersIn(times);
      } else if (key == "filename numbers") {
        numbersIn(numbers);
      }
    }
    pendingKey = key;
  }
  for (int used : usedTimeSets)
    if (used != 1 || steps < 1)
      throw Error(
          concat(file, ": a file of time set ", used, ", which the TIME section does not define"));
  if (!gold)
    throw Error(concat(file,
                       ": not an EnSight Gold case (FORMAT type: ensight gold); EnSight 6 "
                       "is not read"));
  if (c.geometry.empty()) throw Error(concat(file, ": no GEOMETRY model file"));
  if (steps > 0) {
    if (times.size() != std::size_t(steps))
      throw Error(concat(file, ": number of steps ", steps, " but ", times.size(), " time values"));
    for (std::size_t i = 1; i < times.size(); ++i)
      if (!(times[i] > times[i - 1]))
        throw Error(concat(file, ": time value ", times[i], " does not come after ", times[i - 1]));
    c.times = times;
    if (!numbers.empty() && numbers.size() != std::size_t(steps))
      throw Error(concat(file, ": ", numbers.size(), " filename numbers for ", steps, " steps"));
    for (long long i = 0; i < steps; ++i)
      c.fileNumbers.push_back(numbers.empty() ? start + i * increment : numbers[std::size_t(i)]);
  }
  return c;
}

void checkEnSightStep(const EnSightCase& c, std::size_t step, std::size_t memoryBudget) {
  const long long number = step < c.fileNumbers.size() ? c.fileNumbers[step] : 0;
  const fs::path geometry = inside(c, filled(c.geometry, number), "the geometry");
  bool binary = false;
  const std::map<long long, Part> parts = checkGeometry(geometry, memoryBudget, binary);
  for (const EnSightCase::Variable& v : c.variables)
    checkVariable(inside(c, filled(v.file, number), "a variable"), v.kind, parts, memoryBudget,
                  binary);
}

}  // namespace sandstorm
