#include "core/sim/session_log.h"

#include <algorithm>
#include <charconv>
#include <sstream>

#include "core/util/error.h"

namespace sandstorm {
namespace {

// Values print without spaces ("1,2,3") so a line splits on whitespace.
std::string compact(const AttributeValue& value) {
  std::string s = toString(value);
  if (std::holds_alternative<glm::vec3>(value)) std::replace(s.begin(), s.end(), ' ', ',');
  return s;
}

}  // namespace

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

std::vector<ScheduledChange> parseSessionLog(const std::string& text, const std::string& name) {
  const AttributeTable& table = AttributeTable::instance();
  std::vector<ScheduledChange> changes;
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
      throw Error(where + "expected set, add-emitter, remove-emitter or reset after the frame");
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
      } else {
        throw Error("unknown change '" + verb +
                    "'; expected set, add-emitter, remove-emitter or reset");
      }
    } catch (const Error& e) {
      const std::string what = e.what();
      throw Error(what.starts_with(name) ? what : where + what);
    }
  }
  return changes;
}

std::vector<ScheduledChange> readSessionLog(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw Error(concat(path.string(), ": cannot open the session log"));
  std::ostringstream text;
  text << in.rdbuf();
  return parseSessionLog(text.str(), path.string());
}

SessionRecorder::SessionRecorder(const std::filesystem::path& path) : out_(path), path_(path) {
  if (!out_) throw Error(concat(path.string(), ": cannot open for recording"));
  out_ << "# Sandstorm session log: frame, then the change that took effect at that frame\n";
}

void SessionRecorder::record(std::uint32_t frame, const StateChange& change) {
  std::lock_guard lock(mutex_);
  out_ << frame << " " << formatChange(change) << "\n";
  out_.flush();
}

}  // namespace sandstorm
