#include "core/io/vtk_xml_check.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/budget_advice.h"
#include "core/io/vtk_xml_payload.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr std::size_t kMaxTag = 1 << 20;  // bytes in one tag: far above any real one
constexpr std::size_t kMaxToken = 64;     // characters in one ascii value: far above any real one

// Reads a file byte by byte through a buffer; seeks for appended data.
class Scanner {
 public:
  explicit Scanner(const std::filesystem::path& path) : in_(path, std::ios::binary) {}
  bool ok() const { return bool(in_) || in_.eof(); }
  int get() {
    if (at_ == end_ && !fill()) return -1;
    ++position_;
    return static_cast<unsigned char>(buffer_[at_++]);
  }
  // The bytes read ahead and not taken yet (reading more if none are), for
  // taking many at once; consume(n) takes n of them.
  std::size_t available() {
    if (at_ == end_ && !fill()) return 0;
    return end_ - at_;
  }
  const std::uint8_t* data() const {
    return reinterpret_cast<const std::uint8_t*>(buffer_.data()) + at_;
  }
  void consume(std::size_t n) {
    at_ += n;
    position_ += n;
  }
  std::uint64_t position() const { return position_; }
  void seek(std::uint64_t position) {
    in_.clear();
    in_.seekg(std::streamoff(position));
    position_ = position;
    at_ = end_ = 0;
  }

 private:
  bool fill() {
    in_.read(buffer_.data(), std::streamsize(buffer_.size()));
    end_ = std::size_t(in_.gcount());
    at_ = 0;
    return end_ > 0;
  }
  std::ifstream in_;
  std::array<char, 1 << 16> buffer_{};
  std::size_t at_ = 0, end_ = 0;
  std::uint64_t position_ = 0;
};

struct Tag {
  std::string name;
  std::map<std::string, std::string> attributes;
  bool closing = false, selfClosing = false, special = false;  // special: <?..?>, <!..>
  bool quotedGreater = false;  // a '>' inside an attribute's value (legal XML)
  std::uint64_t end = 0;       // file position after '>'
};

int typeSize(const std::string& type) {
  if (type == "Int8" || type == "UInt8" || type == "Char") return 1;
  if (type == "Int16" || type == "UInt16") return 2;
  if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
  if (type == "Int64" || type == "UInt64" || type == "Float64") return 8;
  return 0;
}

int base64Value(int c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

bool isSpace(int c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// Decodes base64 four characters at a time, as VTK writes it: the header and
// the data of a compressed array are separate units, each padded with '='.
class Base64Decoder {
 public:
  // The bytes decoded so far into `out` (0 until a group of four is complete),
  // or -1 for a character that is not base64.
  int add(int c, std::uint8_t out[3]) {
    if (c == '=') {
      ++pad_;
    } else {
      const int v = base64Value(c);
      if (v < 0 || pad_ > 0) return -1;
      value_ = (value_ << 6) | std::uint32_t(v);
    }
    if (++count_ < 4) return 0;
    const int bytes = 3 - pad_;
    if (bytes < 1) return -1;
    value_ <<= 6 * pad_;
    for (int i = 0; i < bytes; ++i)
      out[i] = std::uint8_t(value_ >> (16 - 8 * i));
    count_ = pad_ = 0;
    value_ = 0;
    return bytes;
  }
  bool complete() const { return count_ == 0; }

 private:
  std::uint32_t value_ = 0;
  int count_ = 0, pad_ = 0;
};

// Whether an ascii token is a value of the array's type, as VTK's reader
// (operator>>) will take it: a finite number in the type's range.
bool asciiValueFits(std::string_view token, const std::string& type) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  const char* first = token.data();
  const char* last = first + token.size();
  const auto whole = [&](auto value) {
    const auto [end, ec] = std::from_chars(first, last, value);
    return ec == std::errc() && end == last;
  };
  if (type == "Float32" || type == "Float64") {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || end != last || !std::isfinite(v)) return false;
    return type == "Float64" || std::fabs(v) <= double(std::numeric_limits<float>::max());
  }
  if (type == "Int8" || type == "Char") return whole(std::int8_t{});
  if (type == "UInt8") return whole(std::uint8_t{});
  if (type == "Int16") return whole(std::int16_t{});
  if (type == "UInt16") return whole(std::uint16_t{});
  if (type == "Int32") return whole(std::int32_t{});
  if (type == "UInt32") return whole(std::uint32_t{});
  if (type == "Int64") return whole(std::int64_t{});
  return whole(std::uint64_t{});
}

struct Array {
  std::string where;
  std::string cellList;  // "offsets" or "connectivity" of a piece's cells; empty for others
  std::string key;       // the piece and section the cell list belongs to
  std::string type;
  int size = 0;
  std::uint64_t components = 1;
  std::optional<std::uint64_t> declaredTuples;
  std::optional<std::uint64_t> expectedTuples;
  std::string format;
  std::uint64_t offset = 0;
  std::uint64_t asciiValues = 0;
};

class Checker {
 public:
  Checker(std::filesystem::path path, std::size_t budget)
      : path_(std::move(path)), file_(path_.string()), in_(path_), budget_(budget) {}

  VtkXmlSummary summary() const { return {totalBytes_, declared_, extents_, raw_}; }

  // The tags up to the ImageData (or PImageData) element: its frame, or none.
  std::optional<VtkImageFrame> imageFrame() {
    if (!in_.ok()) return std::nullopt;
    std::string type;
    while (const std::optional<Tag> tag = next()) {
      if (tag->special) continue;
      if (tag->closing) return std::nullopt;
      if (tag->name == "VTKFile") {
        const auto it = tag->attributes.find("type");
        if (it == tag->attributes.end() ||
            (it->second != "ImageData" && it->second != "PImageData"))
          return std::nullopt;
        type = it->second;
        sawFile_ = true;
        continue;
      }
      if (!sawFile_ || tag->name != type) return std::nullopt;
      return frameOf(*tag);
    }
    return std::nullopt;
  }

  void run() {
    if (!in_.ok()) fail(file_ + ": cannot open");
    std::error_code ec;
    fileSize_ = std::uint64_t(std::filesystem::file_size(path_, ec));
    while (true) {
      const std::optional<Tag> tag = next();
      if (!tag) break;
      if (tag->special) continue;
      if (tag->closing) {
        if (stack_.empty() || stack_.back() != tag->name)
          fail(concat(file_, ": the closing tag </", tag->name, "> does not match ",
                      stack_.empty() ? "anything" : "<" + stack_.back() + ">"));
        stack_.pop_back();
        continue;
      }
      open(*tag);
      if (!tag->selfClosing) stack_.push_back(tag->name);
      if (tag->name == "AppendedData") {
        appended(*tag);
        break;  // raw bytes follow: the XML is over
      }
    }
    if (sawFile_ && !stack_.empty() && !appendedSeen_)
      fail(concat(file_, ": truncated: <", stack_.back(), "> is never closed"));
    endPiece();
    for (Array& a : appendedArrays_)
      checkAppended(a);
    checkCellLists();
    if (totalBytes_ > 2.0 * double(budget_))
      fail(concat(file_, ": its arrays need ", totalBytes_, " bytes together, beyond twice the ",
                  "memory budget (field.memory_budget) of ", budget_, " bytes",
                  raiseBudget(totalBytes_ / 2.0)));
    // Points no piece holds would be silent garbage (and VTK's structured
    // readers leak the arrays they were filling when pieces leave gaps).
    if (wholeExtent_ && covered_ && *covered_ != *wholeExtent_)
      fail(concat(file_, ": the pieces' extents cover ", (*covered_)[0], "..", (*covered_)[1], " ",
                  (*covered_)[2], "..", (*covered_)[3], " ", (*covered_)[4], "..", (*covered_)[5],
                  " of the WholeExtent '", wholeText_, "': points without data"));
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { throw Error(message); }

  std::optional<Tag> next() {
    int c;
    while ((c = in_.get()) >= 0 && c != '<') {
      if (!isSpace(c) && stack_.empty() && !sawFile_ && c != 0xEF && c != 0xBB && c != 0xBF)
        fail(concat(file_, ": not XML: text before the first tag"));
    }
    if (c < 0) return std::nullopt;
    Tag t;
    std::string text;
    char quote = 0;
    while ((c = in_.get()) >= 0) {
      if (quote) {
        if (c == quote) quote = 0;
        if (c == '>') t.quotedGreater = true;
      } else if (c == '"' || c == '\'') {
        quote = char(c);
      } else if (c == '>') {
        break;
      }
      text.push_back(char(c));
      if (text.size() > kMaxTag)
        fail(concat(file_, ": a tag longer than ", kMaxTag, " bytes at byte ", in_.position()));
      if (text.size() == 3 && text == "!--") {  // a comment: skip to -->
        int a = 0, b = 0;
        while ((c = in_.get()) >= 0 && !(a == '-' && b == '-' && c == '>'))
          a = b, b = c;
        t.special = true;
        return t;
      }
    }
    if (c < 0) fail(concat(file_, ": truncated inside a tag ('<", text.substr(0, 40), "')"));
    t.end = in_.position();
    if (!text.empty() && (text[0] == '?' || text[0] == '!')) {
      t.special = true;
      return t;
    }
    std::size_t i = 0;
    if (!text.empty() && text[0] == '/') t.closing = true, ++i;
    const std::size_t nameStart = i;
    while (i < text.size() && !isSpace(text[i]) && text[i] != '/')
      ++i;
    t.name = text.substr(nameStart, i - nameStart);
    if (t.name.empty()) fail(concat(file_, ": a tag without a name at byte ", t.end));
    if (!text.empty() && text.back() == '/') t.selfClosing = true, text.pop_back();
    while (i < text.size()) {
      while (i < text.size() && isSpace(text[i]))
        ++i;
      if (i >= text.size()) break;
      const std::size_t eq = text.find('=', i);
      if (eq == std::string::npos) break;
      std::string key = text.substr(i, eq - i);
      while (!key.empty() && isSpace(key.back()))
        key.pop_back();
      std::size_t v = eq + 1;
      while (v < text.size() && isSpace(text[v]))
        ++v;
      if (v >= text.size() || (text[v] != '"' && text[v] != '\''))
        fail(concat(file_, ": <", t.name, "> attribute ", key, ": expected a quoted value"));
      const std::size_t close = text.find(text[v], v + 1);
      if (close == std::string::npos)
        fail(concat(file_, ": <", t.name, "> attribute ", key, ": unterminated value"));
      t.attributes[key] = text.substr(v + 1, close - v - 1);
      i = close + 1;
    }
    return t;
  }

  std::uint64_t whole(const std::string& text, const std::string& what) const {
    std::uint64_t v = 0;
    const char* first = text.data();
    while (first < text.data() + text.size() && isSpace(*first))
      ++first;
    const auto [end, ec] = std::from_chars(first, text.data() + text.size(), v);
    if (ec != std::errc() || end == first)
      fail(concat(file_, ": ", what, ": expected a whole number, got '", text.substr(0, 40), "'"));
    return v;
  }

  void open(const Tag& t) {
    if (t.name == "VTKFile") {
      sawFile_ = true;
      const auto header = t.attributes.find("header_type");
      if (header != t.attributes.end()) {
        if (header->second == "UInt64")
          headerSize_ = 8;
        else if (header->second != "UInt32")
          fail(concat(file_, ": VTKFile header_type '", header->second,
                      "': expected UInt32 or UInt64"));
      }
      const auto order = t.attributes.find("byte_order");
      bigEndian_ = order != t.attributes.end() && order->second == "BigEndian";
      const auto compressor = t.attributes.find("compressor");
      compressor_ = vtkCompressorNamed(
          compressor == t.attributes.end() ? std::string() : compressor->second, file_);
    } else if (t.attributes.count("WholeExtent") && stack_.size() == 1) {
      wholeText_ = t.attributes.at("WholeExtent");
      wholeExtent_ = parseExtent(wholeText_, t.name + " WholeExtent");
    } else if (t.name == "Piece") {
      endPiece();
      ++piece_;
      dims_.reset();
      points_.reset();
      cells_.reset();
      kindCells_.clear();
      sawPoints_ = false;
      coordinate_ = 0;
      const auto extent = t.attributes.find("Extent");
      if (extent != t.attributes.end()) {
        const std::string what = concat("Piece ", piece_, " Extent");
        const std::array<long long, 6> e = parseExtent(extent->second, what);
        extents_.push_back(e);
        for (int i = 0; i < 6 && wholeExtent_; i += 2) {
          const auto& w = *wholeExtent_;
          if (e[std::size_t(i)] < w[std::size_t(i)] ||
              e[std::size_t(i + 1)] > w[std::size_t(i + 1)])
            fail(concat(file_, ": ", what, " '", extent->second, "' reaches outside the ",
                        "WholeExtent '", wholeText_, "' along ", "xyz"[i / 2]));
        }
        // What the pieces cover together: it must be the whole extent.
        if (!covered_) covered_ = e;
        for (int i = 0; i < 6; i += 2) {
          (*covered_)[std::size_t(i)] = std::min((*covered_)[std::size_t(i)], e[std::size_t(i)]);
          (*covered_)[std::size_t(i + 1)] =
              std::max((*covered_)[std::size_t(i + 1)], e[std::size_t(i + 1)]);
        }
        std::array<std::uint64_t, 3> n{};
        for (int a = 0; a < 3; ++a) {
          const long long count = e[std::size_t(2 * a + 1)] - e[std::size_t(2 * a)] + 1;
          if (count < 1 || count > (1LL << 31))
            fail(concat(file_, ": Piece ", piece_, " Extent '", extent->second, "' along ",
                        "xyz"[a], " holds ", count, " points"));
          n[std::size_t(a)] = std::uint64_t(count);
        }
        dims_ = n;
      } else {
        unstructuredPiece(t);
      }
    } else if (t.name == "Coordinates") {
      coordinate_ = 0;
    } else if (t.name == "DataArray") {
      dataArray(t);
    }
  }

  // Exactly `n` finite numbers, or none.
  template <std::size_t n>
  static std::optional<std::array<double, n>> numbers(const std::string& text) {
    std::array<double, n> out{};
    const char* p = text.data();
    const char* end = p + text.size();
    for (double& v : out) {
      while (p < end && isSpace(*p))
        ++p;
      const auto [q, ec] = std::from_chars(p, end, v);
      if (ec != std::errc() || !std::isfinite(v)) return std::nullopt;
      p = q;
    }
    while (p < end && isSpace(*p))
      ++p;
    if (p != end) return std::nullopt;
    return out;
  }

  std::optional<VtkImageFrame> frameOf(const Tag& t) const {
    const auto attribute = [&](const char* key) -> const std::string* {
      const auto it = t.attributes.find(key);
      return it == t.attributes.end() ? nullptr : &it->second;
    };
    const std::string* whole = attribute("WholeExtent");
    if (!whole) return std::nullopt;
    VtkImageFrame f;
    f.extent = parseExtent(*whole, "ImageData WholeExtent");
    for (int a = 0; a < 3; ++a) {
      const long long points = f.extent[2 * a + 1] - f.extent[2 * a] + 1;
      if (points < 1 || points > (1LL << 30)) return std::nullopt;
    }
    if (const std::string* origin = attribute("Origin")) {
      const auto o = numbers<3>(*origin);
      if (!o) return std::nullopt;
      f.origin = *o;
    }
    if (const std::string* spacing = attribute("Spacing")) {
      const auto s = numbers<3>(*spacing);
      if (!s) return std::nullopt;
      f.spacing = *s;
    }
    for (int a = 0; a < 3; ++a)
      if (f.extent[2 * a + 1] > f.extent[2 * a] && !(f.spacing[std::size_t(a)] > 0.0))
        return std::nullopt;
    if (const std::string* direction = attribute("Direction")) {
      const auto d = numbers<9>(*direction);
      if (!d) return std::nullopt;
      for (std::size_t i = 0; i < 9; ++i)
        if ((*d)[i] != (i % 4 == 0 ? 1.0 : 0.0)) return std::nullopt;
    }
    return f;
  }

  std::array<long long, 6> parseExtent(const std::string& text, const std::string& what) const {
    std::array<long long, 6> e{};
    const char* p = text.data();
    const char* end = p + text.size();
    for (long long& v : e) {
      while (p < end && isSpace(*p))
        ++p;
      const auto [q, ec] = std::from_chars(p, end, v);
      if (ec != std::errc())
        fail(concat(file_, ": ", what, " '", text.substr(0, 80), "': expected six whole numbers"));
      if (v < -(1LL << 40) || v > (1LL << 40))
        fail(concat(file_, ": ", what, " '", text.substr(0, 80), "': ", v,
                    " is far outside any grid"));
      p = q;
    }
    return e;
  }

  // A .vtu or .vtp piece's counts: each within the budget, as VTK allocates
  // them before it reads a byte of the arrays.
  void unstructuredPiece(const Tag& t) {
    auto count = [&](const char* key) -> std::optional<std::uint64_t> {
      const auto it = t.attributes.find(key);
      if (it == t.attributes.end()) return std::nullopt;
      const std::uint64_t n = whole(it->second, concat("Piece ", piece_, " ", key));
      if (double(n) * 12.0 > double(budget_))
        fail(concat(file_, ": Piece ", piece_, " ", key, " ", n,
                    " is beyond what the memory budget (field.memory_budget) of ", budget_,
                    " bytes holds", raiseBudget(double(n) * 12.0)));
      return n;
    };
    points_ = count("NumberOfPoints");
    cells_ = count("NumberOfCells");
    for (const char* kind : {"Verts", "Lines", "Strips", "Polys"})
      if (const auto n = count(concat("NumberOf", kind).c_str())) {
        kindCells_[kind] = *n;
        cells_ = cells_.value_or(0) + *n;
      }
  }

  // A piece that claims points must hold them: VTK would allocate them and
  // leave them unset.
  void endPiece() {
    if (points_ && *points_ > 0 && !sawPoints_)
      fail(concat(file_, ": Piece ", piece_, " has NumberOfPoints ", *points_,
                  " but no Points array"));
  }

  std::optional<std::uint64_t> expectedTuples(const std::string& name) {
    const std::string section = stack_.empty() ? "" : stack_.back();
    if (!dims_) {
      if (section == "PointData" || section == "Points") return points_;
      if (section == "CellData") return cells_;
      if (section == "Cells" && (name == "offsets" || name == "types" || name == "faceoffsets"))
        return cells_;
      if (kindCells_.count(section) && name == "offsets") return kindCells_.at(section);
      return std::nullopt;
    }
    if (dims_) {
      const auto& n = *dims_;
      if (section == "PointData" || section == "Points") return n[0] * n[1] * n[2];
      if (section == "CellData") {
        std::uint64_t cells = 1;
        for (std::uint64_t k : n)
          cells *= k > 1 ? k - 1 : 1;
        return cells;
      }
      if (section == "Coordinates" && coordinate_ < 3) return n[coordinate_];
    }
    return std::nullopt;
  }

  void dataArray(const Tag& t) {
    Array a;
    const auto attribute = [&](const char* key) {
      const auto it = t.attributes.find(key);
      return it == t.attributes.end() ? std::string() : it->second;
    };
    const std::string section = stack_.empty() ? "?" : stack_.back();
    const std::string name = attribute("Name");
    a.where = concat(file_, ": Piece ", std::max(piece_, 1), " ", section, " DataArray",
                     name.empty() ? std::string() : " '" + name + "'");
    a.type = attribute("type");
    a.size = typeSize(a.type);
    if (a.size == 0)
      fail(concat(a.where, ": type '", a.type,
                  "' is not a numeric type (Int8..UInt64, Float32, Float64)"));
    if (t.attributes.count("NumberOfComponents")) {
      a.components = whole(attribute("NumberOfComponents"), a.where + " NumberOfComponents");
      if (a.components < 1 || a.components > 0x7fffffffULL)
        fail(concat(a.where, ": NumberOfComponents ", a.components, ": expected 1..2147483647"));
    }
    if (t.attributes.count("NumberOfTuples"))
      a.declaredTuples = whole(attribute("NumberOfTuples"), a.where + " NumberOfTuples");
    declared_.push_back({section, name, a.type, a.components});
    static const char* kCellSections[] = {"Cells", "Verts", "Lines", "Strips", "Polys"};
    if ((name == "offsets" || name == "connectivity") &&
        std::find(std::begin(kCellSections), std::end(kCellSections), section) !=
            std::end(kCellSections)) {
      a.cellList = name;
      a.key = concat("Piece ", std::max(piece_, 1), " ", section);
      cellLists_[a.key].where = concat(file_, ": ", a.key);
    }
    a.expectedTuples = expectedTuples(name);
    if (section == "Points") sawPoints_ = true;
    if (section == "Coordinates") ++coordinate_;
    if (a.declaredTuples && a.expectedTuples && *a.declaredTuples != *a.expectedTuples)
      fail(concat(a.where, ": NumberOfTuples ", *a.declaredTuples, ", but the piece's ",
                  dims_ ? "extent gives " : "counts give ", *a.expectedTuples));
    const std::optional<std::uint64_t> known =
        a.declaredTuples ? a.declaredTuples : a.expectedTuples;
    const std::uint64_t tuples = known.value_or(0);
    const double bytes = double(tuples) * double(a.components) * double(a.size);
    if (bytes > double(budget_))
      fail(concat(a.where, ": ", tuples, " tuples x ", a.components, " components x ", a.size,
                  " bytes = ", bytes, " bytes, beyond the memory budget (field.memory_budget) of ",
                  budget_, " bytes", raiseBudget(bytes)));
    totalBytes_ += bytes;
    a.format = attribute("format");
    if (a.format.empty()) a.format = "ascii";
    if (a.format == "appended") {
      a.offset = whole(attribute("offset"), a.where + " offset");
      appendedArrays_.push_back(a);
      return;
    }
    if (a.format != "ascii" && a.format != "binary")
      fail(concat(a.where, ": format '", a.format, "': expected ascii, binary or appended"));
    // VTK finds an array's inline data after the first '>' past the tag's
    // start, quoted or not, and would decode an attribute's tail as the data.
    if (t.quotedGreater)
      fail(concat(a.where,
                  ": an attribute value holds '>' (write it as &gt;): VTK would read "
                  "the inline data from inside the tag"));
    if (t.selfClosing) {
      if (tuples * a.components > 0)
        fail(concat(a.where, ": no data for ", tuples * a.components, " values"));
      return;
    }
    const std::uint64_t words = tuples * a.components;
    if (a.format == "ascii") {
      asciiOffsets_.clear();
      readAscii(a);
      if (!a.cellList.empty()) {
        CellList& list = cellLists_[a.key];
        if (a.cellList == "connectivity") {
          list.connectivity = a.asciiValues / a.components;
        } else {
          list.haveOffsets = true;
          list.offsets = std::move(asciiOffsets_);
        }
      }
      if (known && a.asciiValues != words)
        fail(concat(a.where, ": holds ", a.asciiValues, " ascii values; ", tuples, " tuples x ",
                    a.components, " components need ", words,
                    " (the extent and the data disagree)"));
      return;
    }
    VtkXmlPayload payload(format(), a.where, needed(a), needText(a));
    std::vector<std::uint8_t> decoded;
    if (a.cellList == "offsets") payload.capture(&decoded);
    readBase64(a, payload);
    payload.finish();
    noteCellList(a, payload, decoded);
  }

  // What VTK will build the cells from: the connectivity's length and the
  // offsets' values (VTK sizes the connectivity by the last offset).
  void noteCellList(const Array& a, const VtkXmlPayload& payload,
                    const std::vector<std::uint8_t>& bytes) {
    if (a.cellList.empty()) return;
    CellList& list = cellLists_[a.key];
    if (a.cellList == "connectivity") {
      list.connectivity = payload.declaredBytes() / std::uint64_t(a.size * a.components);
      return;
    }
    list.haveOffsets = true;
    list.offsets = integers(bytes, a);
  }

  std::vector<std::int64_t> integers(const std::vector<std::uint8_t>& bytes, const Array& a) const {
    if (a.type.rfind("Float", 0) == 0)
      fail(concat(a.where, ": offsets of type ", a.type, "; expected whole numbers"));
    std::vector<std::int64_t> out;
    const std::size_t n = bytes.size() / std::size_t(a.size);
    out.reserve(n);
    const bool isSigned = a.type.rfind("Int", 0) == 0 || a.type == "Char";
    for (std::size_t i = 0; i < n; ++i) {
      std::uint64_t w = 0;
      for (int b = 0; b < a.size; ++b) {
        const std::uint64_t byte = bytes[i * std::size_t(a.size) + std::size_t(b)];
        w |= byte << (8 * (bigEndian_ ? a.size - 1 - b : b));
      }
      const int shift = 64 - 8 * a.size;
      out.push_back(isSigned && shift > 0 ? std::int64_t(w << shift) >> shift : std::int64_t(w));
    }
    return out;
  }

  void checkCellLists() const {
    for (const auto& [key, list] : cellLists_) {
      if (!list.haveOffsets || list.offsets.empty()) continue;
      std::int64_t previous = 0;
      for (std::size_t i = 0; i < list.offsets.size(); ++i) {
        if (list.offsets[i] < previous)
          fail(concat(list.where, ": offset ", i, " (", list.offsets[i],
                      ") is below the one before it"));
        previous = list.offsets[i];
      }
      const std::uint64_t length = list.connectivity.value_or(0);
      if (std::uint64_t(previous) != length)
        fail(concat(list.where, ": the last offset is ", previous, " but the connectivity holds ",
                    length, " point ids"));
    }
  }

  VtkPayloadFormat format() const {
    return {headerSize_, bigEndian_, compressor_, std::uint64_t(budget_)};
  }

  static std::string needText(const Array& a) {
    const std::optional<std::uint64_t> bytes = needed(a);
    if (!bytes) return {};
    return concat(*bytes / (a.components * std::uint64_t(a.size)), " tuples x ", a.components,
                  " components need ", *bytes, " (", a.size, " bytes each)");
  }

  static std::optional<std::uint64_t> needed(const Array& a) {
    const std::optional<std::uint64_t> known =
        a.declaredTuples ? a.declaredTuples : a.expectedTuples;
    if (!known) return std::nullopt;
    return *known * a.components * std::uint64_t(a.size);
  }

  // Inline data runs up to the next '<' (a nested element or the closing
  // tag), which is put back for the tag reader.
  void readAscii(Array& a) {
    std::string token;
    int c;
    do {
      c = in_.get();
      if (c >= 0 && c != '<' && !isSpace(c)) {
        if (token.size() < kMaxToken) token.push_back(char(c));
        continue;
      }
      if (token.empty()) continue;
      ++a.asciiValues;
      if (a.cellList == "offsets" && asciiValueFits(token, a.type))
        asciiOffsets_.push_back(std::strtoll(token.c_str(), nullptr, 10));
      if (!asciiValueFits(token, a.type))
        fail(concat(a.where, ": ascii value ", a.asciiValues, " ('", token.substr(0, 40),
                    "') is not ", a.type == "Float32" || a.type == "Float64" ? "a finite " : "an ",
                    a.type, " number"));
      token.clear();
    } while (c >= 0 && c != '<');
    endInline(a, c);
  }

  // Decoded bytes go to the payload a batch at a time, each batch no more
  // than it wants next, so no character is read beyond the one it ends with.
  struct DecodedBatch {
    std::array<std::uint8_t, 4096> bytes;
    std::size_t size = 0;
    bool full(const VtkXmlPayload& p) const {
      return size + 3 > bytes.size() || size >= p.wanted();
    }
    void flush(VtkXmlPayload& p) {
      p.push(bytes.data(), size);
      size = 0;
    }
  };

  void readBase64(const Array& a, VtkXmlPayload& payload) {
    Base64Decoder decoder;
    DecodedBatch batch;
    int c;
    bool started = false;
    while ((c = in_.get()) >= 0 && c != '<') {
      if (isSpace(c) && started) {
        batch.flush(payload);
        if (!payload.complete()) whitespaceInside(a);
      }
      if (isSpace(c) || payload.complete()) continue;
      started = true;
      decode(a, c, "inline binary", decoder, batch, payload);
    }
    batch.flush(payload);
    endInline(a, c);
  }

  // One base64 character into the batch; a full batch goes to the payload.
  void decode(const Array& a, int c, const char* what, Base64Decoder& decoder, DecodedBatch& batch,
              VtkXmlPayload& payload) {
    const int n = decoder.add(c, batch.bytes.data() + batch.size);
    if (n < 0)
      fail(
          concat(a.where, ": the ", what, " data is not valid base64 (byte ", in_.position(), ")"));
    batch.size += std::size_t(n);
    if (batch.full(payload)) batch.flush(payload);
  }

  // VTK's reader decodes base64 four characters at a time, straight from the
  // file: a space or line break inside an array's data breaks it halfway.
  [[noreturn]] void whitespaceInside(const Array& a) {
    fail(concat(a.where, ": whitespace inside the base64 data (byte ", in_.position(),
                "); VTK's reader takes an array's base64 as one unbroken run"));
  }

  void endInline(const Array& a, int c) {
    if (c < 0) fail(concat(a.where, ": truncated: the file ends inside the array's data"));
    in_.seek(in_.position() - 1);
  }

  void appended(const Tag& t) {
    appendedSeen_ = true;
    const auto encoding = t.attributes.find("encoding");
    base64Appended_ = encoding != t.attributes.end() && encoding->second == "base64";
    if (encoding != t.attributes.end() && encoding->second != "base64" && encoding->second != "raw")
      fail(concat(file_, ": AppendedData encoding '", encoding->second,
                  "': expected raw or base64"));
    int c;
    while ((c = in_.get()) >= 0 && isSpace(c)) {
    }
    if (c != '_') fail(concat(file_, ": AppendedData: expected '_' before the data"));
    appendedStart_ = in_.position();
    // The section ends at the last </AppendedData> (raw bytes may hold anything before it).
    appendedEnd_ = fileSize_;
    const std::uint64_t tail = std::min<std::uint64_t>(fileSize_ - appendedStart_, 4096);
    std::ifstream in(path_, std::ios::binary);
    in.seekg(std::streamoff(fileSize_ - tail));
    std::string end(tail, '\0');
    in.read(end.data(), std::streamsize(tail));
    const std::size_t close = end.rfind("</AppendedData>");
    if (close != std::string::npos) appendedEnd_ = fileSize_ - tail + close;
  }

  void checkAppended(const Array& a) {
    if (!appendedSeen_)
      fail(concat(a.where, ": format appended, but the file has no AppendedData"));
    const std::uint64_t at = appendedStart_ + a.offset;
    if (at > appendedEnd_ || a.offset > appendedEnd_)
      fail(concat(a.where, ": offset ", a.offset, " lies beyond the appended data (",
                  appendedEnd_ - appendedStart_, " bytes)"));
    VtkXmlPayload payload(format(), a.where, needed(a), needText(a));
    std::vector<std::uint8_t> bytes;
    if (a.cellList == "offsets") payload.capture(&bytes);
    in_.seek(at);
    if (base64Appended_) {
      Base64Decoder decoder;
      DecodedBatch batch;
      while (!payload.complete() && in_.position() < appendedEnd_) {
        const int c = in_.get();
        if (c < 0) break;
        if (isSpace(c)) {
          batch.flush(payload);
          if (!payload.complete()) whitespaceInside(a);
          break;
        }
        decode(a, c, "appended base64", decoder, batch, payload);
      }
      batch.flush(payload);
    } else {
      while (!payload.complete() && in_.position() < appendedEnd_) {
        // Uncompressed data needs no look: skip over what the file holds of it.
        if (const std::uint64_t skip = payload.skippable(); skip > 0) {
          const std::uint64_t n = std::min(skip, appendedEnd_ - in_.position());
          in_.seek(in_.position() + n);
          payload.skipped(n);
          continue;
        }
        const std::size_t n =
            std::size_t(std::min<std::uint64_t>(in_.available(), appendedEnd_ - in_.position()));
        if (n == 0) break;
        in_.consume(payload.push(in_.data(), n));
      }
    }
    payload.finish();
    noteCellList(a, payload, bytes);
    if (!base64Appended_ && compressor_ == VtkCompressor::None &&
        bigEndian_ == (std::endian::native == std::endian::big))
      raw_.push_back({a.offset, at + std::uint64_t(headerSize_), payload.declaredBytes()});
  }

  std::filesystem::path path_;
  std::string file_;
  Scanner in_;
  std::size_t budget_;
  std::uint64_t fileSize_ = 0;
  std::vector<std::string> stack_;
  bool sawFile_ = false, bigEndian_ = false;
  VtkCompressor compressor_ = VtkCompressor::None;
  int headerSize_ = 4;
  int piece_ = 0;
  std::optional<std::array<std::uint64_t, 3>> dims_;
  std::optional<std::array<long long, 6>> wholeExtent_;
  std::optional<std::array<long long, 6>> covered_;  // the pieces' extents together
  std::string wholeText_;
  std::optional<std::uint64_t> points_, cells_;     // an unstructured piece's counts
  std::map<std::string, std::uint64_t> kindCells_;  // a .vtp piece's Verts, Lines, ...
  bool sawPoints_ = false;
  std::size_t coordinate_ = 0;
  double totalBytes_ = 0.0;
  struct CellList {
    std::string where;
    std::optional<std::uint64_t> connectivity;
    std::vector<std::int64_t> offsets;
    bool haveOffsets = false;
  };
  std::map<std::string, CellList> cellLists_;
  std::vector<std::int64_t> asciiOffsets_;
  std::vector<VtkXmlArray> declared_;
  std::vector<std::array<long long, 6>> extents_;
  std::vector<Array> appendedArrays_;
  std::vector<VtkXmlRawArray> raw_;
  bool appendedSeen_ = false, base64Appended_ = false;
  std::uint64_t appendedStart_ = 0, appendedEnd_ = 0;
};

}  // namespace

std::optional<VtkImageFrame> readVtkImageFrame(const std::filesystem::path& path) {
  try {
    return Checker(path, 0).imageFrame();
  } catch (const Error&) {
    return std::nullopt;  // the read says what is wrong
  }
}

VtkXmlSummary checkVtkXml(const std::filesystem::path& path, std::size_t memoryBudget) {
  Checker checker(path, memoryBudget);
  checker.run();
  return checker.summary();
}

}  // namespace sandstorm
