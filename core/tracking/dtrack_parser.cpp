#include "core/tracking/dtrack_parser.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "core/util/error.h"

namespace sandstorm {

const TrackedBody* TrackerFrame::body(int id) const {
  const auto it =
      std::find_if(bodies.begin(), bodies.end(), [id](const TrackedBody& b) { return b.id == id; });
  return it == bodies.end() ? nullptr : &*it;
}

const TrackedFlystick* TrackerFrame::flystick(int id) const {
  const auto it = std::find_if(flysticks.begin(), flysticks.end(),
                               [id](const TrackedFlystick& f) { return f.id == id; });
  return it == flysticks.end() ? nullptr : &*it;
}

namespace {

using L = DTrackLimits;

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// One line of a datagram: words and [bracketed blocks] read left to right.
// Every failure names the line, its type and the item being read.
class LineReader {
 public:
  LineReader(std::string_view text, int number) : text_(text), number_(number) {}

  void setType(std::string_view type) { type_ = type; }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(concat("DTrack datagram line ", number_, type_.empty() ? "" : " ('", type_,
                       type_.empty() ? "" : "')", ": ", what));
  }

  std::string_view word(const std::string& what) {
    skipSpace();
    if (at_ >= text_.size()) fail(concat("truncated: expected ", what));
    if (text_[at_] == '[') fail(concat("expected ", what, ", got a [block]"));
    const std::size_t start = at_;
    while (at_ < text_.size() && !isSpace(text_[at_]) && text_[at_] != '[')
      ++at_;
    return text_.substr(start, at_ - start);
  }

  // The numbers inside the next [ ... ], as text; `what` names the block.
  const std::vector<std::string_view>& block(const std::string& what) {
    skipSpace();
    if (at_ >= text_.size()) fail(concat("truncated: expected the ", what, " block [...]"));
    if (text_[at_] != '[') fail(concat("expected the ", what, " block [...], got '", rest(), "'"));
    const std::size_t close = text_.find(']', at_);
    if (close == std::string_view::npos)
      fail(concat("truncated: the ", what, " block has no closing ']'"));
    const std::string_view inside = text_.substr(at_ + 1, close - at_ - 1);
    if (inside.find('[') != std::string_view::npos)
      fail(concat("the ", what, " block has no closing ']' before the next '['"));
    at_ = close + 1;
    tokens_.clear();
    std::size_t i = 0;
    while (i < inside.size()) {
      while (i < inside.size() && isSpace(inside[i]))
        ++i;
      const std::size_t start = i;
      while (i < inside.size() && !isSpace(inside[i]))
        ++i;
      if (i > start) tokens_.push_back(inside.substr(start, i - start));
    }
    return tokens_;
  }

  // The next block, which must hold exactly `count` numbers.
  const std::vector<std::string_view>& block(const std::string& what, std::size_t count) {
    const std::vector<std::string_view>& t = block(what);
    if (t.size() != count)
      fail(concat("the ", what, " block: expected ", count, " numbers, got ", t.size()));
    return t;
  }

  void finish() {
    skipSpace();
    if (at_ < text_.size()) fail(concat("unexpected '", rest(), "' after the last block"));
  }

  long long integer(std::string_view token, const std::string& what, long long min,
                    long long max) const {
    long long v = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (ec != std::errc() || end != token.data() + token.size())
      fail(concat(what, ": expected an integer, got '", token, "'"));
    if (v < min || v > max)
      fail(concat(what, ": expected an integer in ", min, "..", max, ", got ", v));
    return v;
  }

  double real(std::string_view token, const std::string& what) const {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (ec != std::errc() || end != token.data() + token.size())
      fail(concat(what, ": expected a number, got '", token, "'"));
    if (!std::isfinite(v)) fail(concat(what, ": expected a finite number, got '", token, "'"));
    return v;
  }

  float coordinate(std::string_view token, const std::string& what) const {
    const double v = real(token, what);
    if (std::abs(v) > double(L::kMaxCoordinate))
      fail(concat(what, ": ", v, " mm is beyond any room (limit ", L::kMaxCoordinate, " mm)"));
    return float(v);
  }

 private:
  void skipSpace() {
    while (at_ < text_.size() && isSpace(text_[at_]))
      ++at_;
  }
  std::string rest() const {
    const std::string_view r = text_.substr(at_, 24);
    return std::string(r) + (at_ + 24 < text_.size() ? "..." : "");
  }

  std::string_view text_;
  int number_;
  std::string_view type_;
  std::size_t at_ = 0;
  std::vector<std::string_view> tokens_;
};

int itemCount(LineReader& r, const std::string& what) {
  return int(r.integer(r.word(what), what, 0, L::kMaxItems));
}

// Position: three numbers, or DTrack1's six (with Euler angles, which the matrix supersedes).
glm::vec3 position(LineReader& r, const std::string& item) {
  const std::vector<std::string_view>& t = r.block(item + " position");
  if (t.size() != 3 && t.size() != 6)
    r.fail(concat(item, " position block: expected 3 numbers (or 6 with angles), got ", t.size()));
  glm::vec3 p;
  for (int i = 0; i < 3; ++i)
    p[i] = r.coordinate(t[std::size_t(i)], item + " position");
  for (std::size_t i = 3; i < t.size(); ++i)
    r.real(t[i], item + " angle");
  return p;
}

// Nine numbers, column by column. A tracked item's matrix must be a rotation;
// an untracked Flystick's is all zeros, and becomes the identity.
glm::mat3 rotation(LineReader& r, const std::string& item, bool tracked) {
  const std::vector<std::string_view>& t = r.block(item + " rotation", 9);
  glm::mat3 m;
  for (int i = 0; i < 9; ++i) {
    const double v = r.real(t[std::size_t(i)], item + " rotation");
    if (std::abs(v) > 1.5) r.fail(concat(item, " rotation: entry ", v, " is not in -1..1"));
    m[i / 3][i % 3] = float(v);
  }
  if (!tracked) return glm::mat3(1.0f);
  const glm::mat3 gram = glm::transpose(m) * m;
  float worst = 0.0f;
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, std::abs(gram[c][k] - (c == k ? 1.0f : 0.0f)));
  if (worst > 0.02f || glm::determinant(m) <= 0.0f)
    r.fail(concat(item, " rotation: not a rotation matrix (|R^T R - I| = ", worst,
                  ", det = ", glm::determinant(m), ")"));
  return m;
}

float quality(LineReader& r, std::string_view token, const std::string& item) {
  const double q = r.real(token, item + " quality");
  if (q < -1.0 || q > 1.0) r.fail(concat(item, " quality: expected -1..1, got ", q));
  return float(q);
}

template <class T>
void checkUnique(LineReader& r, const std::vector<T>& items, int id, const std::string& kind) {
  for (const T& other : items)
    if (other.id == id) r.fail(concat(kind, " id ", id, " appears twice"));
}

std::string itemName(const char* kind, int i, int count) {
  return concat(kind, " ", i + 1, " of ", count);
}

void readBodies(LineReader& r, TrackerFrame& f) {
  const int count = itemCount(r, "the number of bodies");
  for (int i = 0; i < count; ++i) {
    const std::string item = itemName("body", i, count);
    TrackedBody b;
    const auto& head = r.block(item + " id/quality", 2);
    b.id = int(r.integer(head[0], item + " id", 0, L::kMaxId));
    b.quality = quality(r, head[1], item);
    checkUnique(r, f.bodies, b.id, "body");
    b.position = position(r, item);
    b.rotation = rotation(r, item, true);
    f.bodies.push_back(b);
  }
}

void readFlysticksV1(LineReader& r, TrackerFrame& f) {
  const int count = itemCount(r, "the number of Flysticks");
  for (int i = 0; i < count; ++i) {
    const std::string item = itemName("Flystick", i, count);
    TrackedFlystick s;
    const auto& head = r.block(item + " id/quality/buttons", 3);
    s.id = int(r.integer(head[0], item + " id", 0, L::kMaxId));
    s.quality = quality(r, head[1], item);
    s.buttons = std::uint32_t(r.integer(head[2], item + " buttons", 0, 0xffffffffLL));
    s.buttonCount = 8;
    checkUnique(r, f.flysticks, s.id, "Flystick");
    const glm::vec3 p = position(r, item);
    s.position = s.tracked() ? p : glm::vec3(0.0f);
    s.rotation = rotation(r, item, s.tracked());
    f.flysticks.push_back(s);
  }
}

void readFlysticksV2(LineReader& r, TrackerFrame& f) {
  itemCount(r, "the number of calibrated Flysticks");
  const int count = itemCount(r, "the number of Flysticks");
  for (int i = 0; i < count; ++i) {
    const std::string item = itemName("Flystick", i, count);
    TrackedFlystick s;
    const auto& head = r.block(item + " id/quality/buttons/controllers", 4);
    s.id = int(r.integer(head[0], item + " id", 0, L::kMaxId));
    s.quality = quality(r, head[1], item);
    s.buttonCount = int(r.integer(head[2], item + " button count", 0, L::kMaxButtons));
    s.controllerCount = int(r.integer(head[3], item + " controller count", 0, L::kMaxControllers));
    checkUnique(r, f.flysticks, s.id, "Flystick");
    const auto& p = r.block(item + " position", 3);
    for (int a = 0; a < 3; ++a)
      s.position[a] = r.coordinate(p[std::size_t(a)], item + " position");
    if (!s.tracked()) s.position = glm::vec3(0.0f);
    s.rotation = rotation(r, item, s.tracked());
    const int words = (s.buttonCount + 31) / 32;
    const auto& input =
        r.block(item + " buttons/controllers", std::size_t(words + s.controllerCount));
    for (int w = 0; w < words; ++w) {
      const auto bits = std::uint32_t(
          r.integer(input[std::size_t(w)], item + " buttons", -0x80000000LL, 0xffffffffLL));
      if (w == 0) s.buttons = bits;
    }
    if (s.buttonCount < 32) s.buttons &= (1u << unsigned(s.buttonCount)) - 1u;
    for (int c = 0; c < s.controllerCount; ++c) {
      const double v = r.real(input[std::size_t(words + c)], item + " controller");
      if (v < -1.0001 || v > 1.0001)
        r.fail(concat(item, " controller ", c, ": expected -1..1, got ", v));
      if (c < TrackedFlystick::kMaxControllers) s.controllers[std::size_t(c)] = float(v);
    }
    s.controllerCount = std::min(s.controllerCount, TrackedFlystick::kMaxControllers);
    f.flysticks.push_back(s);
  }
}

void readMarkers(LineReader& r, TrackerFrame& f) {
  const int count = itemCount(r, "the number of markers");
  for (int i = 0; i < count; ++i) {
    const std::string item = itemName("marker", i, count);
    TrackedMarker m;
    const auto& head = r.block(item + " id/quality", 2);
    m.id = int(r.integer(head[0], item + " id", 0, 999999));
    m.quality = quality(r, head[1], item);
    checkUnique(r, f.markers, m.id, "marker");
    const auto& p = r.block(item + " position", 3);
    for (int a = 0; a < 3; ++a)
      m.position[a] = r.coordinate(p[std::size_t(a)], item + " position");
    f.markers.push_back(m);
  }
}

void checkText(std::string_view d) {
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto c = static_cast<unsigned char>(d[i]);
    if ((c < 0x20 || c > 0x7e) && c != '\n' && c != '\r' && c != '\t')
      throw Error(concat("DTrack datagram: byte 0x", std::hex, int(c), std::dec, " at offset ", i,
                         " is not text; not a DTrack ASCII datagram"));
  }
}

}  // namespace

TrackerFrame parseDTrack(std::string_view d) {
  if (d.size() > L::kMaxDatagram)
    throw Error(
        concat("DTrack datagram: ", d.size(), " bytes exceed the limit of ", L::kMaxDatagram));
  while (!d.empty() && d.back() == '\0')
    d.remove_suffix(1);  // some senders end the text with NULs
  checkText(d);
  TrackerFrame f;
  std::vector<std::string_view> seen;
  int number = 0;
  bool any = false;
  for (std::size_t start = 0; start <= d.size();) {
    std::size_t end = d.find('\n', start);
    if (end == std::string_view::npos) end = d.size();
    const std::string_view line = d.substr(start, end - start);
    start = end + 1;
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    any = true;
    LineReader r(line, number);
    const std::string_view type = r.word("a line type");
    if (type.size() > 16 || !std::all_of(type.begin(), type.end(), [](char c) {
          return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
        }))
      r.fail(concat("'", type.substr(0, 24), type.size() > 24 ? "...'" : "'",
                    " is not a DTrack line type (lower-case letters and digits)"));
    r.setType(type);
    if (std::find(seen.begin(), seen.end(), type) != seen.end())
      r.fail("a second line of this type in one datagram");
    seen.push_back(type);
    if (type == "fr") {
      f.frame =
          std::uint32_t(r.integer(r.word("the frame counter"), "frame counter", 0, 0xffffffffLL));
    } else if (type == "ts") {
      const double t = r.real(r.word("the timestamp"), "timestamp");
      if (t < 0.0 || t > 1.0e7) r.fail(concat("timestamp: expected 0..1e7 s, got ", t));
      f.timestamp = t;
    } else if (type == "6dcal") {
      itemCount(r, "the number of calibrated bodies");
    } else if (type == "6d") {
      readBodies(r, f);
    } else if (type == "6df") {
      readFlysticksV1(r, f);
    } else if (type == "6df2") {
      readFlysticksV2(r, f);
    } else if (type == "3d") {
      readMarkers(r, f);
    } else {
      ++f.skippedLines;  // another DTrack output (6di, 6dmt, gl, ...): not read
      continue;
    }
    r.finish();
  }
  if (!any) throw Error("DTrack datagram: empty (no lines)");
  return f;
}

}  // namespace sandstorm
