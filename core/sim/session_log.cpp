#include "core/sim/session_log.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <sstream>

#include "core/util/error.h"

namespace sandstorm {
namespace {

void number(std::string& out, float v) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  out.append(buffer, ec == std::errc() ? end : buffer);
}

void numbers(std::string& out, std::initializer_list<float> values) {
  bool first = true;
  for (const float v : values) {
    if (!first) out += ',';
    number(out, v);
    first = false;
  }
}

// Values print without spaces ("1,2,3", names as encodeName writes them) so
// a line splits on whitespace, and floats as the shortest text that reads
// back as the same float, so a replay sets exactly what was recorded.
std::string compact(const AttributeValue& value) {
  if (const auto* name = std::get_if<std::string>(&value)) return encodeName(*name);
  std::string s;
  if (const auto* f = std::get_if<float>(&value)) {
    number(s, *f);
    return s;
  }
  if (const auto* v = std::get_if<glm::vec3>(&value)) {
    numbers(s, {v->x, v->y, v->z});
    return s;
  }
  return toString(value);
}

void pose(std::string& out, const TrackedPose& p) {
  const glm::mat3& a = p.axes;
  numbers(out, {p.position.x, p.position.y, p.position.z, a[0][0], a[0][1], a[0][2], a[1][0],
                a[1][1], a[1][2], a[2][0], a[2][1], a[2][2]});
}

// Comma-separated floats, exactly `count` of them.
std::vector<float> floats(const std::string& text, std::size_t count, const std::string& what) {
  std::vector<float> out;
  std::size_t at = 0;
  while (at <= text.size()) {
    std::size_t comma = text.find(',', at);
    if (comma == std::string::npos) comma = text.size();
    float v = 0.0f;
    const char* first = text.data() + at;
    const char* last = text.data() + comma;
    const auto [end, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || end != last || !std::isfinite(v))
      throw Error(concat(what, ": expected ", count, " comma-separated numbers, got '", text, "'"));
    out.push_back(v);
    at = comma + 1;
    if (out.size() > count) break;
  }
  if (out.size() != count)
    throw Error(concat(what, ": expected ", count, " comma-separated numbers, got ", out.size()));
  return out;
}

TrackedPose pose(const std::vector<float>& v, std::size_t at) {
  TrackedPose p;
  p.position = {v[at], v[at + 1], v[at + 2]};
  for (int i = 0; i < 9; ++i)
    p.axes[i / 3][i % 3] = v[at + 3 + std::size_t(i)];
  return p;
}

bool flag(const std::string& text, const std::string& what) {
  if (text == "0") return false;
  if (text == "1") return true;
  throw Error(concat(what, ": expected 0 or 1, got '", text, "'"));
}

TrackingSample parseTracking(std::istringstream& words) {
  TrackingSample s;
  s.active = true;
  std::string pair;
  bool frame = false, stale = false, head = false, wand = false;
  while (words >> pair) {
    const std::size_t eq = pair.find('=');
    if (eq == std::string::npos) throw Error("expected name=value after track, got '" + pair + "'");
    const std::string key = pair.substr(0, eq), value = pair.substr(eq + 1);
    if (key == "frame") {
      std::uint32_t f = 0;
      const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), f);
      if (ec != std::errc() || end != value.data() + value.size())
        throw Error("track frame: expected the tracker's frame number, got '" + value + "'");
      s.trackerFrame = f;
      frame = true;
    } else if (key == "stale") {
      s.stale = flag(value, "track stale");
      stale = true;
    } else if (key == "head") {
      if (value != "-") {
        s.head = pose(floats(value, 12, "track head"), 0);
        s.headTracked = true;
      }
      head = true;
    } else if (key == "wand") {
      if (value != "-") {
        const std::vector<float> v = floats(value, 17, "track wand");
        if (v[0] != 0.0f && v[0] != 1.0f) throw Error("track wand: expected present 0 or 1 first");
        if (v[1] != 0.0f && v[1] != 1.0f) throw Error("track wand: expected tracked 0 or 1 second");
        s.wand.present = v[0] == 1.0f;
        s.wand.tracked = v[1] == 1.0f;
        s.wand.pose = pose(v, 2);
        if (!(v[14] >= 0.0f && v[14] <= 4294967295.0f && v[14] == std::floor(v[14])))
          throw Error("track wand: expected the buttons as a whole number");
        s.wand.buttons = std::uint32_t(v[14]);
        s.wand.joystick = {v[15], v[16]};
      }
      wand = true;
    } else {
      throw Error("track: unknown item '" + key + "'; expected frame, stale, head and wand");
    }
  }
  if (!frame || !stale || !head || !wand)
    throw Error("track: expected frame=, stale=, head= and wand=");
  return s;
}

}  // namespace

std::string formatTracking(const TrackingSample& s) {
  std::string out = concat("track frame=", s.trackerFrame, " stale=", s.stale ? 1 : 0, " head=");
  if (s.headTracked)
    pose(out, s.head);
  else
    out += '-';
  out += " wand=";
  if (s.wand.present || s.wand.tracked) {
    out += concat(s.wand.present ? 1 : 0, ",", s.wand.tracked ? 1 : 0, ",");
    pose(out, s.wand.pose);
    out += concat(",", s.wand.buttons, ",");
    numbers(out, {s.wand.joystick.x, s.wand.joystick.y});
  } else {
    out += '-';
  }
  return out;
}

std::string formatNavigation(const Navigation& n) {
  std::string out = "navigate ";
  numbers(out, {n.offset.x, n.offset.y, n.offset.z, n.yawRadians, n.scale});
  return out;
}

std::string formatChange(const StateChange& c) {
  switch (c.kind) {
    case StateChange::Kind::Set:
      return "set " + c.key + " " + compact(c.value);
    case StateChange::Kind::RemoveEmitter:
      return concat("remove-emitter ", c.index);
    case StateChange::Kind::Reset:
      return "reset";
    case StateChange::Kind::AddEmitter: {
      ParticleState holder;
      holder.emitters = {c.emitter};
      std::string line = "add-emitter";
      for (const AttributeInfo& info : AttributeTable::instance().entries()) {
        if (!info.perEmitter()) continue;
        line += ' ';
        line += info.key.substr(10);  // after "emitter.*."
        line += '=';
        line += compact(info.get(holder, 0));
      }
      return line;
    }
  }
  return "?";
}

SessionLog parseSession(const std::string& text, const std::string& name) {
  const AttributeTable& table = AttributeTable::instance();
  SessionLog log;
  std::vector<ScheduledChange>& changes = log.changes;
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  std::uint32_t lastFrame = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string where = concat(name, ":", lineNo, ": ");
    std::istringstream words(line);
    std::string frameText, verb;
    if (!(words >> frameText) || frameText.starts_with("#")) continue;
    std::uint32_t frame = 0;
    const auto [end, ec] =
        std::from_chars(frameText.data(), frameText.data() + frameText.size(), frame);
    if (ec != std::errc() || end != frameText.data() + frameText.size())
      throw Error(where + "expected a frame number first, got '" + frameText + "'");
    if (frame < lastFrame)
      throw Error(where + concat("frame ", frame, " comes after frame ", lastFrame));
    lastFrame = frame;
    if (!(words >> verb))
      throw Error(where +
                  "expected set, add-emitter, remove-emitter, reset, track, navigate, field, "
                  "field-step or field-wait after the frame");
    try {
      if (verb == "set") {
        std::string key, value, extra;
        if (!(words >> key >> value) || (words >> extra))
          throw Error("expected 'set KEY VALUE' (vectors as x,y,z)");
        changes.push_back(
            {frame, StateChange::set(table.canonical(key),
                                     table.validate(key, table.parse(key, value)).applied)});
      } else if (verb == "add-emitter") {
        ParticleState holder;
        std::string pair;
        while (words >> pair) {
          const std::size_t eq = pair.find('=');
          if (eq == std::string::npos)
            throw Error("expected name=value pairs after add-emitter, got '" + pair + "'");
          const std::string key = "emitter.0." + pair.substr(0, eq);
          table.set(holder, key, table.parse(key, pair.substr(eq + 1)));
        }
        changes.push_back({frame, StateChange::addEmitter(holder.emitters[0])});
      } else if (verb == "remove-emitter") {
        int index = -1;
        if (!(words >> index) || index < 0) throw Error("expected 'remove-emitter INDEX'");
        changes.push_back({frame, StateChange::removeEmitter(index)});
      } else if (verb == "reset") {
        changes.push_back({frame, StateChange::reset()});
      } else if (verb == "track") {
        log.tracking.push_back({frame, parseTracking(words)});
      } else if (verb == "field") {
        std::string source, extra;
        if (!(words >> source) || (words >> extra))
          throw Error("expected 'field SOURCE' (analytic:NAME, or a file path without spaces)");
        log.fields.push_back({frame, source});
      } else if (verb == "field-step") {
        std::string time, file, extra;
        if (!(words >> time >> file) || (words >> extra))
          throw Error("expected 'field-step TIME FILE' (a file path without spaces)");
        char* end = nullptr;
        const double t = std::strtod(time.c_str(), &end);
        if (end != time.c_str() + time.size() || !std::isfinite(t))
          throw Error("field-step: expected a time in seconds, got '" + time + "'");
        log.fieldSteps.push_back({frame, t, file});
      } else if (verb == "field-wait") {
        std::string extra;
        if (words >> extra) throw Error("expected 'field-wait' alone after the frame");
        log.fieldWaits.insert(frame);
      } else if (verb == "navigate") {
        std::string values, extra;
        if (!(words >> values) || (words >> extra))
          throw Error("expected 'navigate OFFSET_X,OFFSET_Y,OFFSET_Z,YAW,SCALE'");
        const std::vector<float> v = floats(values, 5, "navigate");
        if (!(v[4] > 0.0f)) throw Error("navigate: expected a positive scale");
        log.navigation.push_back({frame, Navigation{{v[0], v[1], v[2]}, v[3], v[4]}});
      } else {
        throw Error("unknown change '" + verb +
                    "'; expected set, add-emitter, remove-emitter, reset, track, navigate, field, "
                    "field-step or field-wait");
      }
    } catch (const Error& e) {
      const std::string what = e.what();
      throw Error(what.starts_with(name) ? what : where + what);
    }
  }
  return log;
}

std::vector<ScheduledChange> parseSessionLog(const std::string& text, const std::string& name) {
  return parseSession(text, name).changes;
}

SessionLog readSession(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw Error(concat(path.string(), ": cannot open the session log"));
  std::ostringstream text;
  text << in.rdbuf();
  return parseSession(text.str(), path.string());
}

std::vector<ScheduledChange> readSessionLog(const std::filesystem::path& path) {
  return readSession(path).changes;
}

SessionRecorder::SessionRecorder(const std::filesystem::path& path) : out_(path), path_(path) {
  if (!out_) throw Error(concat("--record ", path.string(), ": cannot open for recording"));
  out_ << "# Sandstorm session log: frame, then the change that took effect at that frame\n";
}

void SessionRecorder::record(std::uint32_t frame, const StateChange& change) {
  std::lock_guard lock(mutex_);
  out_ << frame << " " << formatChange(change) << "\n";
  out_.flush();
  checkWritten();
}

void SessionRecorder::checkWritten() {
  if (!out_ && !error_)
    error_ =
        concat("--record ", path_.string(), ": writing the session log failed (is the disk full?)");
}

std::optional<std::string> SessionRecorder::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

void SessionRecorder::recordTracking(std::uint32_t frame, const TrackingSample& sample) {
  std::lock_guard lock(mutex_);
  if (lastTracking_ && *lastTracking_ == sample) return;
  lastTracking_ = sample;
  out_ << frame << " " << formatTracking(sample) << "\n";
  out_.flush();
  checkWritten();
}

void SessionRecorder::recordField(std::uint32_t frame, const std::string& source) {
  std::lock_guard lock(mutex_);
  out_ << frame << " field " << source << "\n";
  out_.flush();
  checkWritten();
}

void SessionRecorder::recordFieldStep(std::uint32_t frame, double time, const std::string& file) {
  std::lock_guard lock(mutex_);
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", time);
  out_ << frame << " field-step " << text << " " << file << "\n";
  out_.flush();
  checkWritten();
}

void SessionRecorder::recordFieldWait(std::uint32_t frame) {
  std::lock_guard lock(mutex_);
  out_ << frame << " field-wait\n";
  out_.flush();
  checkWritten();
}

void SessionRecorder::recordNavigation(std::uint32_t frame, const Navigation& navigation) {
  std::lock_guard lock(mutex_);
  if (lastNavigation_ && lastNavigation_->offset == navigation.offset &&
      lastNavigation_->yawRadians == navigation.yawRadians &&
      lastNavigation_->scale == navigation.scale)
    return;
  lastNavigation_ = navigation;
  out_ << frame << " " << formatNavigation(navigation) << "\n";
  out_.flush();
  checkWritten();
}

}  // namespace sandstorm
