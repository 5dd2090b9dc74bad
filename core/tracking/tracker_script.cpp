#include "core/tracking/tracker_script.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <toml.hpp>

#include "core/util/error.h"
#include "core/util/toml_text.h"

namespace sandstorm {

glm::mat3 bodyRotation(float yawDeg, float pitchDeg, float rollDeg) {
  const float y = glm::radians(yawDeg - 90.0f), p = glm::radians(pitchDeg),
              r = glm::radians(rollDeg);
  const glm::mat3 yaw(std::cos(y), std::sin(y), 0, -std::sin(y), std::cos(y), 0, 0, 0, 1);
  const glm::mat3 pitch(1, 0, 0, 0, std::cos(p), std::sin(p), 0, -std::sin(p), std::cos(p));
  const glm::mat3 roll(std::cos(r), 0, -std::sin(r), 0, 1, 0, std::sin(r), 0, std::cos(r));
  return yaw * pitch * roll;
}

TrackerScript TrackerScript::builtIn() {
  TrackerScript s;
  // 24 s round a circle of 0.6 m about the CAVE's centre, eyes at 1.7 m,
  // looking ahead and about; the wand held ahead and below, sweeping.
  const int steps = 24;
  for (int i = 0; i <= steps; ++i) {
    const double t = i;
    const float a = float(2.0 * M_PI * i / steps);
    TrackerKey k;
    k.time = t;
    k.head = {0.6f * std::cos(a), 0.6f * std::sin(a) - 0.2f, 1.7f + 0.05f * std::sin(3.0f * a)};
    k.headYawDeg = 90.0f + 35.0f * std::sin(2.0f * a);
    k.headPitchDeg = -8.0f + 6.0f * std::cos(a);
    k.headRollDeg = 4.0f * std::sin(a);
    const float wy = glm::radians(90.0f + 35.0f * std::sin(2.0f * a) + 25.0f * std::sin(5.0f * a));
    k.wand = k.head + glm::vec3(0.35f * std::cos(wy), 0.35f * std::sin(wy), -0.45f);
    k.wandYawDeg = glm::degrees(wy);
    k.wandPitchDeg = 12.0f * std::sin(4.0f * a);
    k.buttons = (i % 6 == 2) ? 4u : (i % 6 == 4 ? 8u : 0u);
    s.keys.push_back(k);
  }
  s.loop = true;
  return s;
}

namespace {

class KeyReader {
 public:
  explicit KeyReader(std::string name) : name_(std::move(name)) {}

  [[noreturn]] void fail(const toml::value& v, const std::string& key,
                         const std::string& what) const {
    const auto line = v.location().line();
    throw Error(concat(name_, line > 0 ? concat(":", line) : std::string(), ": ", key, ": ", what));
  }
  double number(const toml::value& v, const std::string& key) const {
    if (v.is_integer()) return double(v.as_integer());
    if (v.is_floating() && std::isfinite(v.as_floating())) return v.as_floating();
    fail(v, key, "expected a finite number");
  }
  template <int N>
  glm::vec<N, float> vec(const toml::value& v, const std::string& key) const {
    if (!v.is_array() || v.as_array().size() != std::size_t(N))
      fail(v, key, concat("expected ", N, " numbers [..]"));
    glm::vec<N, float> out;
    for (int i = 0; i < N; ++i)
      out[i] = float(number(v.as_array()[std::size_t(i)], key));
    return out;
  }
  bool flag(const toml::value& v, const std::string& key) const {
    if (!v.is_boolean()) fail(v, key, "expected true or false");
    return v.as_boolean();
  }
  int integer(const toml::value& v, const std::string& key, long long lo, long long hi) const {
    if (!v.is_integer() || v.as_integer() < lo || v.as_integer() > hi)
      fail(v, key, concat("expected an integer in ", lo, "..", hi));
    return int(v.as_integer());
  }

 private:
  std::string name_;
};

}  // namespace

TrackerScript TrackerScript::parse(const std::string& text, const std::string& name) {
  checkTomlText(text, name);
  toml::value root;
  try {
    std::istringstream in(text);
    root = toml::parse(in, name);
  } catch (const toml::syntax_error& e) {
    throw Error(concat(name, ": TOML syntax error:\n", e.what()));
  }
  const KeyReader r(name);
  TrackerScript s;
  bool haveKeys = false;
  for (const auto& [key, value] : root.as_table()) {
    if (key == "loop") {
      s.loop = r.flag(value, key);
    } else if (key == "head_body") {
      s.headBody = r.integer(value, key, 0, 9999);
    } else if (key == "wand_flystick") {
      s.wandFlystick = r.integer(value, key, 0, 9999);
    } else if (key == "key") {
      if (!value.is_array()) r.fail(value, key, "expected [[key]] tables");
      haveKeys = true;
      for (const toml::value& t : value.as_array()) {
        if (!t.is_table()) r.fail(t, key, "expected a table");
        TrackerKey k = s.keys.empty() ? TrackerKey{} : s.keys.back();  // unset items hold
        bool timed = false;
        for (const auto& [item, v] : t.as_table()) {
          const std::string where = "key." + item;
          if (item == "time")
            k.time = r.number(v, where), timed = true;
          else if (item == "head")
            k.head = r.vec<3>(v, where);
          else if (item == "head_yaw_deg")
            k.headYawDeg = float(r.number(v, where));
          else if (item == "head_pitch_deg")
            k.headPitchDeg = float(r.number(v, where));
          else if (item == "head_roll_deg")
            k.headRollDeg = float(r.number(v, where));
          else if (item == "wand")
            k.wand = r.vec<3>(v, where);
          else if (item == "wand_yaw_deg")
            k.wandYawDeg = float(r.number(v, where));
          else if (item == "wand_pitch_deg")
            k.wandPitchDeg = float(r.number(v, where));
          else if (item == "buttons")
            k.buttons = std::uint32_t(r.integer(v, where, 0, 0x7fffffff));
          else if (item == "joystick") {
            k.joystick = r.vec<2>(v, where);
            if (std::abs(k.joystick.x) > 1.0f || std::abs(k.joystick.y) > 1.0f)
              r.fail(v, where, "expected two numbers in -1..1");
          } else if (item == "head_visible")
            k.headVisible = r.flag(v, where);
          else if (item == "wand_visible")
            k.wandVisible = r.flag(v, where);
          else
            r.fail(v, where,
                   "unknown key; expected time, head, head_yaw_deg, head_pitch_deg, "
                   "head_roll_deg, wand, wand_yaw_deg, wand_pitch_deg, buttons, joystick, "
                   "head_visible, wand_visible");
        }
        if (!timed) r.fail(t, "key.time", "missing: every keyframe needs a time");
        if (!s.keys.empty() && !(k.time > s.keys.back().time))
          r.fail(t, "key.time", "expected times that increase");
        for (int a = 0; a < 3; ++a)
          if (std::abs(k.head[a]) > 100.0f || std::abs(k.wand[a]) > 100.0f)
            r.fail(t, "key.head/wand", "expected positions within 100 m of the tracker's origin");
        s.keys.push_back(k);
      }
    } else {
      r.fail(value, key, "unknown key; expected loop, head_body, wand_flystick or [[key]]");
    }
  }
  if (!haveKeys || s.keys.empty()) throw Error(concat(name, ": expected at least one [[key]]"));
  return s;
}

TrackerScript TrackerScript::load(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(concat(path.string(), ": cannot open the tracker path"));
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str(), path.string());
}

TrackerKey TrackerScript::sampleKeys(double seconds) const {
  const double start = keys.front().time, end = keys.back().time;
  double t = seconds + start;
  if (loop && end > start) t = start + std::fmod(seconds, end - start);
  t = std::clamp(t, start, end);
  const auto next = std::upper_bound(keys.begin(), keys.end(), t,
                                     [](double x, const TrackerKey& k) { return x < k.time; });
  if (next == keys.begin()) return keys.front();
  if (next == keys.end()) return keys.back();
  const TrackerKey& a = *(next - 1);
  const TrackerKey& b = *next;
  const float w = float((t - a.time) / (b.time - a.time));
  TrackerKey k = a;  // buttons, joystick and visibility hold
  k.time = t;
  k.head = glm::mix(a.head, b.head, w);
  k.headYawDeg = glm::mix(a.headYawDeg, b.headYawDeg, w);
  k.headPitchDeg = glm::mix(a.headPitchDeg, b.headPitchDeg, w);
  k.headRollDeg = glm::mix(a.headRollDeg, b.headRollDeg, w);
  k.wand = glm::mix(a.wand, b.wand, w);
  k.wandYawDeg = glm::mix(a.wandYawDeg, b.wandYawDeg, w);
  k.wandPitchDeg = glm::mix(a.wandPitchDeg, b.wandPitchDeg, w);
  return k;
}

TrackerFrame TrackerScript::at(double seconds, std::uint32_t frame) const {
  const TrackerKey k = sampleKeys(seconds);
  TrackerFrame f;
  f.frame = frame;
  f.timestamp = std::fmod(seconds, 86400.0);
  if (k.headVisible)
    f.bodies.push_back(TrackedBody{headBody, 1.0f, k.head * 1000.0f,
                                   bodyRotation(k.headYawDeg, k.headPitchDeg, k.headRollDeg)});
  TrackedFlystick w;
  w.id = wandFlystick;
  w.quality = k.wandVisible ? 1.0f : -1.0f;
  if (k.wandVisible) {
    w.position = k.wand * 1000.0f;
    w.rotation = bodyRotation(k.wandYawDeg, k.wandPitchDeg, 0.0f);
  }
  w.buttonCount = 6;  // a Flystick2: six buttons and a joystick
  w.buttons = k.buttons & 0x3fu;
  w.controllerCount = 2;
  w.controllers[0] = k.joystick.x;
  w.controllers[1] = k.joystick.y;
  f.flysticks.push_back(w);
  return f;
}

}  // namespace sandstorm
