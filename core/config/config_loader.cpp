// Reads AppConfig from TOML (toml11). Every key is checked; unknown keys,
// wrong types and bad values throw Error with "file:line: key: what was expected".
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include <toml.hpp>

#include "core/config/app_config.h"
#include "core/config/byte_size.h"
#include "core/config/config_sets.h"
#include "core/config/pvx_import.h"
#include "core/sim/attribute_table.h"
#include "core/tracking/ipv4_address.h"
#include "core/util/error.h"
#include "core/util/nearest_name.h"
#include "core/util/toml_text.h"

namespace sandstorm {
namespace {

// How a --set's setting is named in its errors (applyConfigSets): "--set key=value".
constexpr std::string_view kSetLabel = "--set ";

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  std::string at(const toml::value& v) const {
    const toml::source_location loc = v.location();
    return loc.line() > 0 && !commandLine() ? concat(file_, ":", loc.line()) : file_;
  }

  // A --set's setting (applyConfigSets): no file whose lines to name, and
  // files it names are relative to the folder the program started in.
  bool commandLine() const { return file_.starts_with(kSetLabel); }

  [[noreturn]] void fail(const toml::value& v, const std::string& key,
                         const std::string& what) const {
    throw Error(concat(at(v), ": ", key, ": ", what));
  }

  // fail() at the line of the key in `table` that `key` names (its last part;
  // of "run.near/far", near or else far), or at the table's where it has none:
  // a bad value is then named at its own line, not its section's.
  [[noreturn]] void failKey(const toml::value& table, const std::string& key,
                            const std::string& what) const {
    const std::string last = key.substr(key.rfind('.') + 1);
    for (std::size_t from = 0; from <= last.size();) {
      const std::size_t to = std::min(last.find('/', from), last.size());
      if (const toml::value* v = find(table, last.substr(from, to - from))) fail(*v, key, what);
      from = to + 1;
    }
    fail(table, key, what);
  }

  void checkKeys(const toml::value& table, const std::string& path,
                 const std::set<std::string>& known) const {
    for (const auto& [key, value] : table.as_table()) {
      if (known.count(key)) continue;
      std::string list;
      for (const std::string& k : known)
        list += (list.empty() ? "" : ", ") + k;
      const std::string meant =
          didYouMean(key, std::vector<std::string>(known.begin(), known.end()));
      fail(value, path.empty() ? key : path + "." + key,
           "unknown key" + meant + "; expected one of: " + list);
    }
  }

  const toml::value* find(const toml::value& table, const std::string& key) const {
    const auto& t = table.as_table();
    const auto it = t.find(key);
    return it == t.end() ? nullptr : &it->second;
  }

  const toml::value& require(const toml::value& table, const std::string& key,
                             const std::string& path) const {
    const toml::value* v = find(table, key);
    if (!v) throw Error(concat(at(table), ": ", path, ": missing required key '", key, "'"));
    return *v;
  }

  double number(const toml::value& v, const std::string& key) const {
    if (v.is_integer()) return double(v.as_integer());
    if (v.is_floating() && std::isfinite(v.as_floating())) return v.as_floating();
    fail(v, key, v.is_floating() ? "expected a finite number" : "expected a number");
  }

  // A number kept as a float: within float's range (a double beyond it has no
  // float to become).
  float single(const toml::value& v, const std::string& key) const {
    const double n = number(v, key);
    if (std::abs(n) > double(std::numeric_limits<float>::max()))
      fail(v, key, "expected a number within +-3.4e38");
    return float(n);
  }

  // A window's position or size in pixels: two numbers each within [min, max]
  // (checked before they become integers).
  glm::ivec2 pixels(const toml::value& table, const std::string& key, const std::string& path,
                    glm::ivec2 fallback, int min, int max) const {
    const toml::value* v = find(table, key);
    if (!v) return fallback;
    const std::string where = path + "." + key;
    if (!v->is_array() || v->as_array().size() != 2) fail(*v, where, "expected 2 numbers [..]");
    glm::ivec2 out;
    for (int i = 0; i < 2; ++i) {
      const double n = number(v->as_array()[std::size_t(i)], where);
      if (n < min || n > max)
        fail(*v, where, concat("expected ", min, "..", max, " pixels each way"));
      out[i] = int(n);
    }
    return out;
  }

  float real(const toml::value& table, const std::string& key, const std::string& path,
             float fallback) const {
    const toml::value* v = find(table, key);
    return v ? single(*v, path + "." + key) : fallback;
  }

  int integer(const toml::value& table, const std::string& key, const std::string& path,
              int fallback, int min, int max) const {
    const toml::value* v = find(table, key);
    if (!v) return fallback;
    if (!v->is_integer()) fail(*v, path + "." + key, "expected an integer");
    const auto i = v->as_integer();
    if (i < min || i > max)
      fail(*v, path + "." + key, concat("expected an integer in ", min, "..", max, ", got ", i));
    return int(i);
  }

  bool boolean(const toml::value& table, const std::string& key, const std::string& path,
               bool fallback) const {
    const toml::value* v = find(table, key);
    if (!v) return fallback;
    if (!v->is_boolean()) fail(*v, path + "." + key, "expected true or false");
    return v->as_boolean();
  }

  std::string string(const toml::value& table, const std::string& key, const std::string& path,
                     const std::string& fallback) const {
    const toml::value* v = find(table, key);
    if (!v) return fallback;
    if (!v->is_string()) fail(*v, path + "." + key, "expected a string");
    return v->as_string().str;
  }

  template <int N>
  glm::vec<N, float> vec(const toml::value& v, const std::string& key) const {
    if (!v.is_array() || v.as_array().size() != std::size_t(N))
      fail(v, key, concat("expected ", N, " numbers [..]"));
    glm::vec<N, float> out;
    for (int i = 0; i < N; ++i)
      out[i] = single(v.as_array()[std::size_t(i)], key);
    return out;
  }

  template <int N>
  glm::vec<N, float> vec(const toml::value& table, const std::string& key, const std::string& path,
                         glm::vec<N, float> fallback) const {
    const toml::value* v = find(table, key);
    return v ? vec<N>(*v, path + "." + key) : fallback;
  }

  template <class E>
  E choice(const toml::value& table, const std::string& key, const std::string& path, E fallback,
           const std::vector<std::pair<std::string, E>>& choices) const {
    const toml::value* v = find(table, key);
    if (!v) return fallback;
    std::string list;
    for (const auto& [name, e] : choices) {
      if (v->is_string() && v->as_string().str == name) return e;
      list += (list.empty() ? "" : ", ") + name;
    }
    fail(*v, path + "." + key, "expected one of: " + list);
  }

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

// A TOML value as an attribute value; the table then checks type and range.
AttributeValue attributeValue(const Reader& r, const toml::value& v, const std::string& key) {
  if (v.is_boolean()) return v.as_boolean();
  if (v.is_integer()) {
    const std::int64_t n = v.as_integer();
    if (n < -2000000000 || n > 2000000000) {
      r.fail(v, key, AttributeTable::instance().lookup(key).outsideRange(std::to_string(n)));
    }
    return int(n);
  }
  if (v.is_floating()) return r.single(v, key);
  if (v.is_string()) return v.as_string().str;
  if (v.is_array()) return r.vec<3>(v, key);
  r.fail(v, key, "expected a number, a boolean, a string or [x, y, z]");
}

void setAttributes(const Reader& r, const toml::value& table, const std::string& prefix,
                   ParticleState& state) {
  const AttributeTable& attributes = AttributeTable::instance();
  for (const auto& [key, value] : table.as_table()) {
    const std::string full = prefix + key;
    try {
      const AttributeValue v = attributeValue(r, value, full);
      // A file's value out of range is an error, not clamped as a live edit is.
      if (!attributes.validate(full, v).warning.empty())
        r.fail(value, full, attributes.lookup(full).outsideRange(toString(v)));
      attributes.set(state, full, v);
    } catch (const Error& e) {
      const std::string what = e.what();
      if (what.starts_with(r.file())) throw;
      throw Error(concat(r.at(value), ": ", what));
    }
  }
}

// A fixed colour range must be a range, and a log scale's must lie above 0
// (the menu may do either on the fly; a file that does is a mistake).
void checkColorRange(const Reader& r, const toml::value& t, const RenderSettings& s) {
  if (s.colorRange != ColorRange::Fixed) return;
  const toml::value* at = r.find(t, "color_max");
  if (!at) at = r.find(t, "color_range");
  if (!(s.colorMax > s.colorMin))
    r.fail(at ? *at : t, "render.color_max",
           concat("expected color_max > color_min for a fixed colour range (got ", s.colorMin,
                  " to ", s.colorMax, ")"));
  if (s.colorLog && !(s.colorMin > 0.0f)) {
    const toml::value* min = r.find(t, "color_min");
    r.fail(min ? *min : t, "render.color_min",
           concat("expected color_min > 0 for a log scale (color_log = true), got ", s.colorMin));
  }
}

void readRun(const Reader& r, const toml::value& t, RunSpec& run) {
  r.checkKeys(
      t, "run",
      {"seed", "capacity", "capacity_limit", "fixed_dt", "frames", "backend", "shared_simulation",
       "near", "far", "stats_warmup", "offscreen_contexts", "gpus", "max_fps"});
  if (const toml::value* seed = r.find(t, "seed")) {
    if (!seed->is_integer() || seed->as_integer() < 0)
      r.fail(*seed, "run.seed", "expected a non-negative integer");
    run.seed = std::uint64_t(seed->as_integer());
  }
  run.capacity = std::size_t(r.integer(t, "capacity", "run", int(run.capacity), 1, 1 << 27));
  run.capacityLimit =
      std::size_t(r.integer(t, "capacity_limit", "run", int(run.capacityLimit), 1, 1 << 28));
  if (run.capacityLimit < run.capacity)
    r.failKey(t, "run.capacity_limit", "expected capacity_limit >= capacity");
  run.fixedDt = r.real(t, "fixed_dt", "run", run.fixedDt);
  if (run.fixedDt < 0.0f || run.fixedDt > 1.0f)
    r.failKey(t, "run.fixed_dt", "expected 0 (real clock) to 1 s");
  run.frames = r.integer(t, "frames", "run", run.frames, 0, 100000000);
  run.maxFps = r.real(t, "max_fps", "run", float(run.maxFps));
  if (!(run.maxFps >= 0.0 && run.maxFps <= 1000.0))
    r.fail(*r.find(t, "max_fps"), "run.max_fps",
           concat("expected 0 (no limit) to 1000 frames a second, got ", run.maxFps));
  run.backend = r.choice<std::string>(t, "backend", "run", run.backend,
                                      {{"tf-gs", "tf-gs"}, {"compute", "compute"}});
  run.sharedSimulation = r.boolean(t, "shared_simulation", "run", run.sharedSimulation);
  if (run.sharedSimulation && run.backend != "compute")
    r.failKey(t, "run.shared_simulation",
              "needs run.backend = \"compute\" (transform-feedback counts stay in one context)");
  run.nearPlane = r.real(t, "near", "run", run.nearPlane);
  run.farPlane = r.real(t, "far", "run", run.farPlane);
  if (!(run.nearPlane > 0.0f) || !(run.farPlane > run.nearPlane))
    r.failKey(t, "run.near/far", "expected 0 < near < far");
  run.statsWarmup = r.integer(t, "stats_warmup", "run", run.statsWarmup, 0, 100000000);
  run.offscreenContexts =
      r.choice<RunSpec::OffscreenContexts>(t, "offscreen_contexts", "run", run.offscreenContexts,
                                           {{"one", RunSpec::OffscreenContexts::One},
                                            {"per-wall", RunSpec::OffscreenContexts::PerWall}});
  run.gpusRoundRobin = r.choice<bool>(t, "gpus", "run", run.gpusRoundRobin,
                                      {{"first", false}, {"round-robin", true}});
}

void readGpu(const Reader& r, const toml::value& t, GpuTuning& g) {
  r.checkKeys(t, "gpu",
              {"splat", "splat_chunk", "splat_list", "trail_pass", "field_storage", "update_items",
               "scan_spin", "upload_context"});
  g.splat = r.choice<GpuTuning::Splat>(
      t, "splat", "gpu", g.splat,
      {{"tiled", GpuTuning::Splat::Tiled}, {"atomic", GpuTuning::Splat::Atomic}});
  g.splatChunk = std::size_t(r.integer(t, "splat_chunk", "gpu", int(g.splatChunk), 16, 1 << 20));
  g.splatList = std::size_t(r.integer(t, "splat_list", "gpu", int(g.splatList), 0, 1 << 30));
  g.trailPass = r.choice<GpuTuning::TrailPass>(t, "trail_pass", "gpu", g.trailPass,
                                               {{"auto", GpuTuning::TrailPass::Auto},
                                                {"tiled", GpuTuning::TrailPass::Tiled},
                                                {"atomic", GpuTuning::TrailPass::Atomic}});
  g.fieldStorage = r.choice<GpuTuning::FieldStorage>(
      t, "field_storage", "gpu", g.fieldStorage,
      {{"auto", GpuTuning::FieldStorage::Auto}, {"texture", GpuTuning::FieldStorage::Texture}});
  if (const toml::value* items = r.find(t, "update_items")) {
    const int n = r.integer(t, "update_items", "gpu", 4, 1, 8);
    if (n != 1 && n != 2 && n != 4 && n != 8)
      r.fail(*items, "gpu.update_items", "expected 1, 2, 4 or 8");
    g.updateItems = n;
  }
  if (r.find(t, "scan_spin"))
    g.scanSpin = std::uint32_t(r.integer(t, "scan_spin", "gpu", 0, 0, 1 << 24));
  g.uploadContext = r.boolean(t, "upload_context", "gpu", g.uploadContext);
}

glm::mat3 rotationFromDegrees(const glm::vec3& degrees) {
  const glm::vec3 a = glm::radians(degrees);
  const glm::mat3 x(1, 0, 0, 0, std::cos(a.x), std::sin(a.x), 0, -std::sin(a.x), std::cos(a.x));
  const glm::mat3 y(std::cos(a.y), 0, -std::sin(a.y), 0, 1, 0, std::sin(a.y), 0, std::cos(a.y));
  const glm::mat3 z(std::cos(a.z), std::sin(a.z), 0, -std::sin(a.z), std::cos(a.z), 0, 0, 0, 1);
  return z * y * x;
}

// The folder a config file's relative paths start from: the folder of the
// file itself, symbolic links followed (a link to a shared config finds the
// data beside it), as an absolute path. A bare file name's folder is the
// current one: an empty parent path must not reach std::filesystem::absolute.
std::filesystem::path folderOf(const std::string& file) {
  std::error_code ec;
  std::filesystem::path real = std::filesystem::weakly_canonical(file, ec);
  if (ec || real.empty()) real = std::filesystem::absolute(file, ec);
  if (ec || real.empty()) return std::filesystem::path(file).parent_path();
  return real.parent_path();
}

// A file named in a config is relative to that config file's folder (so an
// included scene finds its data wherever it is included from).
std::string relativeTo(const Reader& r, const std::string& path) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
  if (r.commandLine()) return std::filesystem::path(path).lexically_normal().string();
  return (folderOf(r.file()) / path).lexically_normal().string();
}

void readField(const Reader& r, const toml::value& t, FieldSpec& f) {
  r.checkKeys(
      t, "field",
      {"source",     "name",         "dims",          "resolution", "bounds_min",   "bounds_max",
       "params",     "offset",       "scale",         "yaw_deg",    "rotation_deg", "mode",
       "expression", "watch",        "step_interval", "wait_s",     "settle_s",     "memory_budget",
       "read_ahead", "upload_ahead", "precision",     "storage"});
  f.source = r.string(t, "source", "field", f.source);
  if (f.source != "analytic") f.source = relativeTo(r, f.source);
  // A file's array or grid is chosen by name; without one, the file's only (or active) vector one.
  // Three one-component arrays joined into a vector: name = ["u", "v", "w"]
  // (two: a 2D simulation's, z 0).
  const toml::value* name = r.find(t, "name");
  if (name && name->is_array()) {
    const auto& parts = name->as_array();
    f.name.clear();
    for (const toml::value& part : parts) {
      if (!part.is_string() || part.as_string().str.empty() ||
          part.as_string().str.find(',') != std::string::npos)
        r.fail(*name, "field.name",
               "expected three array names, e.g. [\"u\", \"v\", \"w\"], or two (z 0)");
      f.name += (f.name.empty() ? "" : ",") + part.as_string().str;
    }
    if (parts.size() != 3 && parts.size() != 2)
      r.fail(*name, "field.name",
             "expected three array names, e.g. [\"u\", \"v\", \"w\"], or two (z 0)");
  } else {
    f.name = r.string(t, "name", "field", f.source == "analytic" ? f.name : std::string());
  }
  if (const toml::value* res = r.find(t, "resolution")) {
    const glm::vec3 v = r.vec<3>(*res, "field.resolution");
    for (int a = 0; a < 3; ++a)
      if (v[a] < 2 || v[a] > 2048 || v[a] != std::floor(v[a]))
        r.fail(*res, "field.resolution", "expected three whole numbers in 2..2048");
    f.resolution = glm::ivec3(v);
  }
  const glm::vec3 dims = r.vec<3>(t, "dims", "field", glm::vec3(f.dims));
  for (int a = 0; a < 3; ++a)
    if (dims[a] < 1 || dims[a] > 2048 || dims[a] != std::floor(dims[a]))
      r.fail(*r.find(t, "dims"), "field.dims", "expected three whole numbers in 1..2048");
  f.dims = glm::ivec3(dims);
  f.bounds.min = r.vec<3>(t, "bounds_min", "field", f.bounds.min);
  f.bounds.max = r.vec<3>(t, "bounds_max", "field", f.bounds.max);
  if (!glm::all(glm::lessThan(f.bounds.min, f.bounds.max)))
    r.failKey(t, "field.bounds_min/bounds_max", "expected bounds_min < bounds_max on every axis");
  if (const toml::value* params = r.find(t, "params")) {
    if (!params->is_table()) r.fail(*params, "field.params", "expected a table of numbers");
    for (const auto& [k, v] : params->as_table())
      f.params[k] = r.number(v, "field.params." + k);
  }
  f.placement.offset = r.vec<3>(t, "offset", "field", f.placement.offset);
  f.placement.scale = r.real(t, "scale", "field", f.placement.scale);
  if (!(f.placement.scale > 0.0f)) r.failKey(t, "field.scale", "expected a positive scale");
  // rotation_deg = [x, y, z]: turns about the room's x, then y, then z axis
  // (e.g. [90, 0, 0] stands a y-up data set up in the z-up room); yaw_deg is
  // the common case, a turn about z alone.
  if (r.find(t, "rotation_deg") && r.find(t, "yaw_deg"))
    r.failKey(t, "field.rotation_deg", "give rotation_deg or yaw_deg, not both");
  glm::vec3 turns(0.0f, 0.0f, r.real(t, "yaw_deg", "field", 0.0f));
  turns = r.vec<3>(t, "rotation_deg", "field", turns);
  f.placement.rotation = rotationFromDegrees(turns);
  f.rotationDegrees = turns;
  f.watch = r.boolean(t, "watch", "field", f.watch);
  if (f.watch && !(f.source.ends_with(".pvd") || std::filesystem::is_directory(f.source)))
    r.fail(*r.find(t, "watch"), "field.watch",
           "expected a folder or a .pvd source to watch (got '" + f.source + "')");
  f.stepInterval = r.real(t, "step_interval", "field", float(f.stepInterval));
  if (!(f.stepInterval > 0.0 && f.stepInterval <= 1e6))
    r.fail(*r.find(t, "step_interval"), "field.step_interval", "expected 0 < seconds <= 10^6");
  f.settleSeconds = r.real(t, "settle_s", "field", float(f.settleSeconds));
  if (!(f.settleSeconds >= 0.0 && f.settleSeconds <= 3600.0))
    r.fail(*r.find(t, "settle_s"), "field.settle_s", "expected 0..3600 seconds");
  f.waitSeconds = r.real(t, "wait_s", "field", float(f.waitSeconds));
  if (!(f.waitSeconds >= 0.0 && f.waitSeconds <= 86400.0))
    r.fail(*r.find(t, "wait_s"), "field.wait_s", "expected 0..86400 seconds");
  if (const toml::value* budget = r.find(t, "memory_budget")) {
    const char* expected =
        "expected \"auto\" or a size such as \"16 GiB\" or \"800 MiB\" (at least 1 MiB)";
    if (budget->is_integer() && budget->as_integer() >= (1 << 20)) {
      f.memoryBudget = std::uint64_t(budget->as_integer());
    } else if (budget->is_string() && budget->as_string().str == "auto") {
      f.memoryBudget = 0;
    } else {
      const std::optional<std::uint64_t> bytes =
          budget->is_string() ? parseByteSize(budget->as_string().str) : std::nullopt;
      if (!bytes || *bytes < (1u << 20)) r.fail(*budget, "field.memory_budget", expected);
      f.memoryBudget = *bytes;
    }
  }
  f.readAhead = r.integer(t, "read_ahead", "field", f.readAhead, 0, 64);
  f.uploadAhead = r.boolean(t, "upload_ahead", "field", f.uploadAhead);
  const int precision = r.choice<int>(t, "precision", "field",
                                      f.halfPrecision   ? 2
                                      : f.autoPrecision ? 0
                                                        : 1,
                                      {{"auto", 0}, {"float", 1}, {"half", 2}});
  f.halfPrecision = precision == 2;
  f.autoPrecision = precision == 0;
  f.storage = r.choice<FieldSpec::Storage>(t, "storage", "field", f.storage,
                                           {{"auto", FieldSpec::Storage::Auto},
                                            {"dense", FieldSpec::Storage::Dense},
                                            {"sparse", FieldSpec::Storage::Sparse}});
}

void readScene(const Reader& r, const toml::value& t, SceneSpec& s) {
  r.checkKeys(t, "scene", {"terrain", "ground_height", "terrain_min", "terrain_max", "helicopter"});
  s.terrain = r.string(t, "terrain", "scene", s.terrain);
  if (s.terrain != "flat") s.terrain = relativeTo(r, s.terrain);
  // Named here, the missing file points at its key's line; read later, it
  // could not.
  std::error_code ec;  // a name too long for the system, say: refused as missing, not thrown
  if (const toml::value* v = r.find(t, "terrain");
      v && s.terrain != "flat" && !std::filesystem::is_regular_file(s.terrain, ec))
    r.fail(*v, "scene.terrain",
           concat("no height map file ", s.terrain,
                  "; expected \"flat\" or a 16-bit PGM (sandstorm-field terrain makes one)"));
  s.groundHeight = r.real(t, "ground_height", "scene", s.groundHeight);
  s.terrainBounds.min = r.vec<3>(t, "terrain_min", "scene", s.terrainBounds.min);
  s.terrainBounds.max = r.vec<3>(t, "terrain_max", "scene", s.terrainBounds.max);
  if (!glm::all(glm::lessThan(s.terrainBounds.min, s.terrainBounds.max)))
    r.failKey(t, "scene.terrain_min/terrain_max",
              "expected terrain_min < terrain_max on every axis");
  s.helicopter = r.boolean(t, "helicopter", "scene", s.helicopter);
}

void readHead(const Reader& r, const toml::value& t, HeadSpec& h) {
  r.checkKeys(t, "head",
              {"mode", "position", "yaw_deg", "right", "eye_separation", "path", "loop"});
  h.mode = r.choice(t, "mode", "head", h.mode,
                    {{"fixed", HeadMode::Fixed},
                     {"scripted", HeadMode::Scripted},
                     {"desktop", HeadMode::Desktop}});
  h.position = r.vec<3>(t, "position", "head", h.position);
  h.yawDegrees = r.real(t, "yaw_deg", "head", h.yawDegrees);
  // right = [x, y, z]: the eyes' axis itself (a tilted head), instead of yaw_deg.
  if (const toml::value* right = r.find(t, "right")) {
    if (r.find(t, "yaw_deg")) r.fail(*right, "head.right", "give right or yaw_deg, not both");
    const glm::vec3 v = r.vec<3>(*right, "head.right");
    if (!(std::abs(glm::length(v) - 1.0f) < 0.01f))
      r.fail(*right, "head.right", "expected a unit vector from the left eye to the right eye");
    h.right = v;
  }
  h.eyeSeparation = r.real(t, "eye_separation", "head", h.eyeSeparation);
  if (h.eyeSeparation < 0.0f || h.eyeSeparation > 0.5f)
    r.failKey(t, "head.eye_separation", "expected 0..0.5 m");
  h.loop = r.boolean(t, "loop", "head", h.loop);
  if (const toml::value* path = r.find(t, "path")) {
    if (!path->is_array())
      r.fail(*path, "head.path", "expected an array of {time, position} tables");
    float last = -1.0f;
    for (const toml::value& k : path->as_array()) {
      if (!k.is_table()) r.fail(k, "head.path", "expected {time = .., position = [x, y, z]}");
      r.checkKeys(k, "head.path[]", {"time", "position"});
      HeadKeyframe key{r.single(r.require(k, "time", "head.path[]"), "head.path[].time"),
                       r.vec<3>(r.require(k, "position", "head.path[]"), "head.path[].position")};
      if (key.time <= last) r.fail(k, "head.path[].time", "expected times that increase");
      last = key.time;
      h.path.push_back(key);
    }
  }
  if (h.mode == HeadMode::Scripted && h.path.size() < 2)
    r.failKey(t, "head.path", "a scripted head needs at least two keyframes");
}

// [[primitive]]: the field editor's primitives (primitive.N.*), filling the
// slots from 0; the rest stay empty. Each names its kind (none: an empty slot,
// as a saved block writes the gaps, so the slots keep their numbers).
void readPrimitives(const Reader& r, const toml::value& list, AppConfig& c) {
  if (!list.is_array()) r.fail(list, "primitive", "expected [[primitive]] tables");
  if (list.as_array().size() > std::size_t(ParticleState::kMaxPrimitives))
    r.fail(list, "primitive", concat("at most ", ParticleState::kMaxPrimitives, " primitives"));
  c.particles.primitives.assign(std::size_t(ParticleState::kMaxPrimitives), FieldPrimitive{});
  for (std::size_t i = 0; i < list.as_array().size(); ++i) {
    const toml::value& p = list.as_array()[i];
    if (!p.is_table()) r.fail(p, "primitive", "expected a table");
    const std::string name = concat("primitive.", i);
    if (!r.find(p, "kind"))
      r.fail(p, name + ".kind",
             "missing: expected the primitive's kind (vortex, source, wind, tornado, sphere_flow, "
             "curl_noise; none keeps an empty slot)");
    setAttributes(r, p, name + ".", c.particles);
  }
}

// [[obstacle]]: its attributes (obstacle.N.*) and a scripted path, path =
// [{time, position}, ..] and loop, kept beside the state (AppConfig::obstaclePaths).
void readObstacles(const Reader& r, const toml::value& list, AppConfig& c) {
  if (!list.is_array()) r.fail(list, "obstacle", "expected [[obstacle]] tables");
  if (list.as_array().size() > std::size_t(ParticleState::kMaxObstacles))
    r.fail(list, "obstacle", concat("at most ", ParticleState::kMaxObstacles, " obstacles"));
  c.particles.obstacles.clear();
  c.obstaclePaths.clear();
  for (const toml::value& o : list.as_array()) {
    if (!o.is_table()) r.fail(o, "obstacle", "expected a table");
    const std::string name = concat("obstacle.", c.particles.obstacles.size());
    toml::table attributes = o.as_table();
    attributes.erase("path");
    attributes.erase("loop");
    c.particles.obstacles.emplace_back();
    setAttributes(r, toml::value(attributes), name + ".", c.particles);
    const bool loop = r.boolean(o, "loop", name, true);
    std::vector<ObstacleKeyframe> keys;
    if (const toml::value* path = r.find(o, "path")) {
      if (!path->is_array())
        r.fail(*path, name + ".path", "expected an array of {time, position} tables");
      float last = -1e30f;
      for (const toml::value& k : path->as_array()) {
        if (!k.is_table()) r.fail(k, name + ".path", "expected {time = .., position = [x, y, z]}");
        r.checkKeys(k, name + ".path[]", {"time", "position"});
        const toml::value& time = r.require(k, "time", name + ".path[]");
        ObstacleKeyframe key{
            r.single(time, name + ".path[].time"),
            r.vec<3>(r.require(k, "position", name + ".path[]"), name + ".path[].position")};
        if (!(key.time > last)) r.fail(time, name + ".path[].time", "expected times that increase");
        if (!(std::abs(key.time) < 1e7f)) r.fail(time, name + ".path[].time", "expected seconds");
        for (int a = 0; a < 3; ++a)
          if (!(std::abs(key.position[a]) <= 1e6f))
            r.fail(*r.find(k, "position"), name + ".path[].position",
                   "expected metres within +-10^6 (the room's and an obstacle's range)");
        last = key.time;
        keys.push_back(key);
      }
      if (keys.size() < 2) r.fail(*path, name + ".path", "a path needs at least two keyframes");
    }
    c.obstaclePaths.emplace_back(std::move(keys), loop);
  }
}

void readNavigation(const Reader& r, const toml::value& t, NavigationSpec& n) {
  r.checkKeys(t, "navigation", {"offset", "yaw_deg", "scale", "fly_speed", "turn_speed_deg"});
  n.offset = r.vec<3>(t, "offset", "navigation", n.offset);
  n.yawDegrees = r.real(t, "yaw_deg", "navigation", n.yawDegrees);
  n.scale = r.real(t, "scale", "navigation", n.scale);
  if (!(n.scale > 0.0f)) r.failKey(t, "navigation.scale", "expected a positive scale");
  n.flySpeed = r.real(t, "fly_speed", "navigation", n.flySpeed);
  if (!(n.flySpeed >= 0.0f && n.flySpeed <= 1000.0f))
    r.failKey(t, "navigation.fly_speed", "expected 0..1000 m/s");
  n.turnSpeedDeg = r.real(t, "turn_speed_deg", "navigation", n.turnSpeedDeg);
  if (!(n.turnSpeedDeg >= 0.0f && n.turnSpeedDeg <= 720.0f))
    r.failKey(t, "navigation.turn_speed_deg", "expected 0..720 degrees/s");
}

// A direction in a body's own coordinates: three numbers, not all zero.
glm::vec3 axis(const Reader& r, const toml::value& t, const std::string& key, glm::vec3 fallback) {
  const glm::vec3 v = r.vec<3>(t, key, "tracking", fallback);
  if (!(glm::length(v) > 1e-3f) || !std::isfinite(glm::length(v)))
    r.fail(*r.find(t, key), "tracking." + key, "expected a non-zero direction [x, y, z]");
  return glm::normalize(v);
}

void readTracking(const Reader& r, const toml::value& t, TrackingSpec& k) {
  r.checkKeys(
      t, "tracking",
      {"source", "port", "multicast", "sender", "interface", "head_body", "wand_flystick", "offset",
       "rotation_deg", "stale_ms", "eye_offset", "head_right", "head_up", "wand_forward", "wand_up",
       "trigger_button", "grab_button", "grab_radius", "ray_length"});
  k.line = int(t.location().line());
  k.source = r.choice(t, "source", "tracking", k.source,
                      {{"none", TrackingSource::None},
                       {"dtrack", TrackingSource::DTrack},
                       {"replay", TrackingSource::Replay}});
  k.port = r.integer(t, "port", "tracking", k.port, 1, 65535);
  k.multicast = r.string(t, "multicast", "tracking", k.multicast);
  if (!k.multicast.empty()) {
    const std::optional<std::uint32_t> group = parseIpv4(k.multicast);
    if (!group || !isMulticast(*group))
      r.fail(*r.find(t, "multicast"), "tracking.multicast",
             "expected an IPv4 multicast group (224.0.0.0 .. 239.255.255.255), got '" +
                 k.multicast + "'");
  }
  // sender = "10.0.0.5" or ["10.0.0.5", "10.0.0.6"]: the DTrack controllers.
  if (const toml::value* sender = r.find(t, "sender")) {
    std::vector<const toml::value*> items;
    if (sender->is_array())
      for (const toml::value& v : sender->as_array())
        items.push_back(&v);
    else
      items.push_back(sender);
    if (items.empty())
      r.fail(*sender, "tracking.sender", "expected an address or a list of addresses, got []");
    k.senders.clear();
    for (const toml::value* v : items) {
      const std::optional<std::uint32_t> a =
          v->is_string() ? parseIpv4(v->as_string().str) : std::nullopt;
      if (!a || *a == 0 || isMulticast(*a))
        r.fail(*v, "tracking.sender",
               "expected the DTrack controller's IPv4 address (\"192.168.0.20\"), got " +
                   toml::format(*v));
      k.senders.push_back(v->as_string().str);
    }
  }
  k.interfaceAddress = r.string(t, "interface", "tracking", k.interfaceAddress);
  if (!k.interfaceAddress.empty()) {
    const std::optional<std::uint32_t> a = parseIpv4(k.interfaceAddress);
    if (!a || isMulticast(*a))
      r.fail(*r.find(t, "interface"), "tracking.interface",
             "expected a local IPv4 address to listen on (\"192.168.0.10\", \"127.0.0.1\"), got '" +
                 k.interfaceAddress + "'");
  }
  k.headBody = r.integer(t, "head_body", "tracking", k.headBody, 0, 9999);
  k.wandFlystick = r.integer(t, "wand_flystick", "tracking", k.wandFlystick, 0, 9999);
  k.offset = r.vec<3>(t, "offset", "tracking", k.offset);
  k.rotation = rotationFromDegrees(r.vec<3>(t, "rotation_deg", "tracking", glm::vec3(0.0f)));
  k.staleMs = r.real(t, "stale_ms", "tracking", k.staleMs);
  if (!(k.staleMs >= 1.0f && k.staleMs <= 60000.0f))
    r.failKey(t, "tracking.stale_ms", "expected 1..60000 ms");
  k.eyeOffset = r.vec<3>(t, "eye_offset", "tracking", k.eyeOffset);
  if (!(glm::length(k.eyeOffset) <= 1.0f))
    r.failKey(t, "tracking.eye_offset", "expected an offset under 1 m (metres, the glasses' axes)");
  k.headRight = axis(r, t, "head_right", k.headRight);
  k.headUp = axis(r, t, "head_up", k.headUp);
  if (std::abs(glm::dot(k.headRight, k.headUp)) > 1e-3f)
    r.failKey(t, "tracking.head_right/head_up", "expected perpendicular directions");
  k.wandForward = axis(r, t, "wand_forward", k.wandForward);
  k.wandUp = axis(r, t, "wand_up", k.wandUp);
  if (std::abs(glm::dot(k.wandForward, k.wandUp)) > 1e-3f)
    r.failKey(t, "tracking.wand_forward/wand_up", "expected perpendicular directions");
  k.triggerButton = r.integer(t, "trigger_button", "tracking", k.triggerButton, 0, 31);
  k.grabButton = r.integer(t, "grab_button", "tracking", k.grabButton, 0, 31);
  k.grabRadius = r.real(t, "grab_radius", "tracking", k.grabRadius);
  if (!(k.grabRadius > 0.0f && k.grabRadius <= 10.0f))
    r.failKey(t, "tracking.grab_radius", "expected 0..10 m");
  k.rayLength = r.real(t, "ray_length", "tracking", k.rayLength);
  if (!(k.rayLength >= 0.1f && k.rayLength <= 1000.0f))
    r.failKey(t, "tracking.ray_length", "expected 0.1..1000 m");
}

WindowSpec readWindow(const Reader& r, const toml::value& window, const std::string& wp,
                      std::optional<int> monitors) {
  if (!window.is_table()) r.fail(window, wp, "expected a table");
  r.checkKeys(window, wp, {"monitor", "position", "size", "fullscreen", "decorated"});
  WindowSpec s;
  s.monitor = r.integer(window, "monitor", wp, 0, 0, 63);
  if (monitors && s.monitor >= std::max(*monitors, 1))
    r.fail(*r.find(window, "monitor"), wp + ".monitor",
           concat("monitor ", s.monitor, " does not exist; ", *monitors, " connected (0..",
                  *monitors - 1, ")"));
  s.position = r.pixels(window, "position", wp, s.position, -65536, 65536);
  s.size = r.pixels(window, "size", wp, s.size, 16, 16384);
  s.fullscreen = r.boolean(window, "fullscreen", wp, s.fullscreen);
  s.decorated = r.boolean(window, "decorated", wp, s.decorated);
  return s;
}

WallSpec readWall(const Reader& r, const toml::value& t, int index, std::optional<int> monitors) {
  const std::string path = concat("wall[", index, "]");
  r.checkKeys(t, path,
              {"name", "lower_left", "lower_right", "upper_left", "camera", "window", "offscreen",
               "stereo", "menu", "legend", "rank", "host", "gpu"});
  WallSpec w;
  w.line = int(t.location().line());
  w.name = r.string(t, "name", path, concat("wall", index));
  if (const toml::value* camera = r.find(t, "camera")) {
    if (!camera->is_table()) r.fail(*camera, path + ".camera", "expected a table");
    r.checkKeys(*camera, path + ".camera", {"position", "target", "fov_deg"});
    CameraSpec c;
    c.position = r.vec<3>(*camera, "position", path + ".camera", c.position);
    c.target = r.vec<3>(*camera, "target", path + ".camera", c.target);
    c.fovDegrees = r.real(*camera, "fov_deg", path + ".camera", c.fovDegrees);
    if (c.fovDegrees < 1.0f || c.fovDegrees > 170.0f)
      r.fail(*camera, path + ".camera.fov_deg", "expected 1..170");
    w.camera = c;
  } else {
    w.corners.lowerLeft = r.vec<3>(r.require(t, "lower_left", path), path + ".lower_left");
    w.corners.lowerRight = r.vec<3>(r.require(t, "lower_right", path), path + ".lower_right");
    w.corners.upperLeft = r.vec<3>(r.require(t, "upper_left", path), path + ".upper_left");
    validateWall(w.corners, concat(r.at(t), ": ", path, " ('", w.name, "')"));
  }
  const toml::value* window = r.find(t, "window");
  const toml::value* offscreen = r.find(t, "offscreen");
  if (window && offscreen) r.fail(t, path, "give either a window or an offscreen table, not both");
  if (window) w.window = readWindow(r, *window, path + ".window", monitors);
  if (offscreen) {
    if (!offscreen->is_table()) r.fail(*offscreen, path + ".offscreen", "expected a table");
    r.checkKeys(*offscreen, path + ".offscreen", {"size"});
    w.offscreenSize = r.pixels(*offscreen, "size", path + ".offscreen", w.offscreenSize, 16, 16384);
  }
  w.stereo = r.choice(t, "stereo", path, w.stereo,
                      {{"mono", StereoMode::Mono},
                       {"quad-buffer", StereoMode::QuadBuffer},
                       {"side-by-side", StereoMode::SideBySide},
                       {"top-bottom", StereoMode::TopBottom},
                       {"anaglyph", StereoMode::Anaglyph},
                       {"left-eye", StereoMode::LeftEye},
                       {"right-eye", StereoMode::RightEye}});
  if (w.stereo == StereoMode::QuadBuffer && !w.window)
    r.failKey(t, path + ".stereo",
              "quad-buffer stereo needs a window; offscreen walls can use side-by-side");
  w.menu = r.boolean(t, "menu", path, w.menu);
  w.legend = r.boolean(t, "legend", path, w.legend);
  w.rank = r.integer(t, "rank", path, 0, 0, 4095);
  w.host = r.string(t, "host", path, "");
  if (r.find(t, "gpu")) {
    if (w.window)
      r.fail(*r.find(t, "gpu"), path + ".gpu",
             "a window draws on its display's GPU; gpu is for offscreen walls");
    w.gpu = r.integer(t, "gpu", path, 0, 0, 63);
  }
  return w;
}

void readCluster(const Reader& r, const toml::value& t, ClusterSpec& c) {
  r.checkKeys(t, "cluster",
              {"timeout_s", "startup_timeout_s", "field", "steps", "chunk_kib", "field_cache",
               "walls", "ranks", "hosts"});
  c.timeoutSeconds = r.real(t, "timeout_s", "cluster", c.timeoutSeconds);
  if (!(c.timeoutSeconds >= 0.1f && c.timeoutSeconds <= 3600.0f))
    r.fail(*r.find(t, "timeout_s"), "cluster.timeout_s", "expected 0.1..3600 s");
  c.startupTimeoutSeconds = r.real(t, "startup_timeout_s", "cluster", c.startupTimeoutSeconds);
  if (!(c.startupTimeoutSeconds >= 1.0f && c.startupTimeoutSeconds <= 86400.0f))
    r.fail(*r.find(t, "startup_timeout_s"), "cluster.startup_timeout_s", "expected 1..86400 s");
  c.readField =
      r.choice<bool>(t, "field", "cluster", c.readField, {{"broadcast", false}, {"read", true}});
  c.readSteps =
      r.choice<bool>(t, "steps", "cluster", c.readSteps, {{"broadcast", false}, {"read", true}});
  c.chunkKiB = r.integer(t, "chunk_kib", "cluster", c.chunkKiB, 1, 1 << 20);
  c.fieldCache = r.integer(t, "field_cache", "cluster", c.fieldCache, 2, 4096);
  c.roundRobin = r.choice<bool>(t, "walls", "cluster", c.roundRobin,
                                {{"by-rank", false}, {"round-robin", true}});
  if (const toml::value* ranks = r.find(t, "ranks")) {
    if (!ranks->is_table()) r.fail(*ranks, "cluster.ranks", "expected a table {wall = rank, ..}");
    for (const auto& [wall, rank] : ranks->as_table()) {
      const std::string key = "cluster.ranks." + wall;
      if (!rank.is_integer() || rank.as_integer() < 0 || rank.as_integer() > 4095)
        r.fail(rank, key, "expected a rank in 0..4095");
      c.placements.push_back({wall, int(rank.as_integer()), "", concat(r.at(rank), ": ", key)});
    }
  }
  if (const toml::value* hosts = r.find(t, "hosts")) {
    if (!hosts->is_table())
      r.fail(*hosts, "cluster.hosts", "expected a table {wall = \"host name\", ..}");
    for (const auto& [wall, host] : hosts->as_table()) {
      const std::string key = "cluster.hosts." + wall;
      if (!host.is_string() || host.as_string().str.empty())
        r.fail(host, key, "expected a host name");
      c.placements.push_back(
          {wall, std::nullopt, host.as_string().str, concat(r.at(host), ": ", key)});
    }
  }
}

// [cluster] ranks/hosts name walls that may come from an include: applied last.
void placeWalls(AppConfig& c) {
  for (const ClusterSpec::Placement& p : c.cluster.placements) {
    const auto it = std::find_if(c.walls.begin(), c.walls.end(),
                                 [&](const WallSpec& w) { return w.name == p.wall; });
    if (it == c.walls.end()) {
      std::string known;
      for (const WallSpec& w : c.walls)
        known += (known.empty() ? "" : ", ") + w.name;
      throw Error(concat(p.where, ": no wall named '", p.wall, "'; the walls are ", known));
    }
    if (p.rank) it->rank = *p.rank;
    if (!p.host.empty()) it->host = p.host;
  }
}

toml::value parseToml(const std::string& text, const std::string& name) {
  checkTomlText(text, name);
  try {
    std::istringstream in(text);
    return toml::parse(in, name);
  } catch (const toml::syntax_error& e) {
    throw Error(concat(name, ": TOML syntax error:\n", e.what()));
  }
}

std::string readFile(const std::filesystem::path& path, const std::string& from) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(concat(from, "cannot open the configuration file ", path.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The files whose includes led to the one being read, outermost first.
using IncludeChain = std::vector<std::filesystem::path>;

// Reads `root` on top of `c` (the included file's settings, if any).
void read(const toml::value& root, const std::string& file, std::optional<int> monitors,
          AppConfig& c, const IncludeChain& chain);

AppConfig readWithIncludes(const toml::value& root, const std::string& file,
                           std::optional<int> monitors) {
  AppConfig c;
  read(root, file, monitors, c, {});
  return c;
}

void read(const toml::value& root, const std::string& file, std::optional<int> monitors,
          AppConfig& c, const IncludeChain& chain) {
  const Reader r(file);
  r.checkKeys(
      root, "",
      {"include",    "run",       "field",  "scene",      "sim",         "render", "field_playback",
       "helicopter", "emitter",   "head",   "navigation", "tracking",    "menu",   "cluster",
       "wall",       "pvx",       "pvx_up", "gpu",        "streamlines", "slice",  "probe",
       "obstacle",   "molecules", "solver", "primitive"});
  // include = "scene.toml": that file's settings first, this file's on top.
  if (const toml::value* include = r.find(root, "include")) {
    if (!include->is_string()) r.fail(*include, "include", "expected a file name");
    const std::filesystem::path path =
        (folderOf(file) / include->as_string().str).lexically_normal();
    std::error_code ec;
    IncludeChain inner = chain;
    inner.push_back(std::filesystem::weakly_canonical(file, ec));
    if (std::find(inner.begin(), inner.end(), std::filesystem::weakly_canonical(path, ec)) !=
        inner.end())
      r.fail(*include, "include", concat(path.string(), " is already being read: includes loop"));
    if (inner.size() > 5) r.fail(*include, "include", "includes nest more than 5 deep");
    const toml::value innerRoot =
        parseToml(readFile(path, r.at(*include) + ": include: "), path.string());
    read(innerRoot, path.string(), monitors, c, inner);
  }
  const auto section = [&](const char* name) -> const toml::value* {
    const toml::value* v = r.find(root, name);
    if (v && !v->is_table()) r.fail(*v, name, "expected a table [" + std::string(name) + "]");
    return v;
  };
  if (const auto* t = section("run")) readRun(r, *t, c.run);
  if (const auto* t = section("gpu")) readGpu(r, *t, c.gpu);
  if (const auto* t = section("field")) {
    readField(r, *t, c.field);
    // field.mode (texture | equation | expression) is an attribute: the menu and --set change it
    // too.
    if (const toml::value* mode = r.find(*t, "mode")) {
      toml::table one;
      one["mode"] = *mode;
      setAttributes(r, toml::value(one), "field.", c.particles);
    }
    // expression = ["-y", "x", "0.1"]: the field written at run time
    // (field.expression_x, _y, _z); mode expression unless a mode is given.
    if (const toml::value* e = r.find(*t, "expression")) {
      if (!e->is_array() || e->as_array().size() != 3)
        r.fail(*e, "field.expression", "expected three expressions, e.g. [\"-y\", \"x\", \"0.1\"]");
      toml::table parts;
      const char* names[3] = {"expression_x", "expression_y", "expression_z"};
      for (std::size_t i = 0; i < 3; ++i) {
        const toml::value& part = e->as_array()[i];
        if (!part.is_string())
          r.fail(part, "field.expression", "expected each component as a string");
        parts[names[i]] = part;
      }
      setAttributes(r, toml::value(parts), "field.", c.particles);
      if (!r.find(*t, "mode")) c.particles.field.mode = FieldMode::Expression;
    }
  }
  if (const auto* t = section("scene")) readScene(r, *t, c.scene);
  if (const auto* t = section("head")) readHead(r, *t, c.head);
  if (const auto* t = section("navigation")) readNavigation(r, *t, c.navigation);
  if (const auto* t = section("tracking")) readTracking(r, *t, c.tracking);
  if (const auto* t = section("menu")) {
    r.checkKeys(*t, "menu", {"operator_window"});
    if (const toml::value* w = r.find(*t, "operator_window"))
      c.menu.operatorWindow = readWindow(r, *w, "menu.operator_window", monitors);
  }
  if (const auto* t = section("cluster")) readCluster(r, *t, c.cluster);
  if (const auto* t = section("sim")) setAttributes(r, *t, "sim.", c.particles);
  if (const auto* t = section("render")) {
    setAttributes(r, *t, "render.", c.particles);
    checkColorRange(r, *t, c.particles.render);
  }
  if (const auto* t = section("field_playback")) setAttributes(r, *t, "field.", c.particles);
  if (const auto* t = section("helicopter")) setAttributes(r, *t, "helicopter.", c.particles);
  if (const auto* t = section("streamlines")) setAttributes(r, *t, "streamlines.", c.particles);
  if (const auto* t = section("probe")) setAttributes(r, *t, "probe.", c.particles);
  if (const auto* t = section("molecules")) setAttributes(r, *t, "molecules.", c.particles);
  if (const auto* t = section("solver")) setAttributes(r, *t, "solver.", c.particles);
  if (const auto* t = section("slice")) setAttributes(r, *t, "slice.", c.particles);
  if (const toml::value* emitters = r.find(root, "emitter")) {
    if (!emitters->is_array()) r.fail(*emitters, "emitter", "expected [[emitter]] tables");
    if (emitters->as_array().size() > std::size_t(ParticleState::kMaxEmitters))
      r.fail(*emitters, "emitter", concat("at most ", ParticleState::kMaxEmitters, " emitters"));
    c.particles.emitters.clear();
    for (const toml::value& e : emitters->as_array()) {
      if (!e.is_table()) r.fail(e, "emitter", "expected a table");
      c.particles.emitters.emplace_back();
      setAttributes(r, e, concat("emitter.", c.particles.emitters.size() - 1, "."), c.particles);
    }
  }
  if (const toml::value* obstacles = r.find(root, "obstacle")) readObstacles(r, *obstacles, c);
  if (const toml::value* primitives = r.find(root, "primitive")) readPrimitives(r, *primitives, c);
  // Walls from a ParaView CAVE file: pvx = "cave.pvx", pvx_up = "y" (ParaView's usual) or "z".
  if (const toml::value* pvx = r.find(root, "pvx")) {
    if (!pvx->is_string()) r.fail(*pvx, "pvx", "expected the name of a .pvx file");
    if (r.find(root, "wall"))
      r.fail(*pvx, "pvx", "give walls either as [[wall]] or from a .pvx file, not both");
    const std::string up = r.string(root, "pvx_up", "pvx_up", "y");
    if (up != "y" && up != "z")
      r.fail(*r.find(root, "pvx_up"), "pvx_up", "expected \"y\" or \"z\"");
    c.walls = readPvx(relativeTo(r, pvx->as_string().str), up == "y");
    return;
  }
  const toml::value* walls = r.find(root, "wall");
  if (!walls) return;  // an included scene file, or the walls come from an include
  if (!walls->is_array()) r.fail(*walls, "wall", "expected [[wall]] tables");
  c.walls.clear();
  std::set<std::string> names;
  for (const toml::value& w : walls->as_array()) {
    if (!w.is_table()) r.fail(w, "wall", "expected a table");
    c.walls.push_back(readWall(r, w, int(c.walls.size()), monitors));
    if (!names.insert(c.walls.back().name).second)
      r.fail(w, "wall.name", "'" + c.walls.back().name + "' is used twice");
  }
  if (c.walls.empty()) throw Error(concat(file, ": [[wall]] is empty; expected at least one wall"));
  int menus = 0;
  for (const WallSpec& w : c.walls)
    menus += w.menu ? 1 : 0;
  if (menus > 1)
    throw Error(concat(file, ": the menu is shown on ", menus, " walls; expected at most one"));
  int legends = 0;
  for (const WallSpec& w : c.walls)
    legends += w.legend ? 1 : 0;
  if (legends > 1)
    throw Error(
        concat(file, ": the colour legend is shown on ", legends, " walls; expected at most one"));
}

}  // namespace

bool AppConfig::anyWindow() const {
  for (const WallSpec& w : walls)
    if (w.window) return true;
  return false;
}

int AppConfig::glContexts() const {
  int contexts = menu.operatorWindow ? 1 : 0;
  std::set<int> offscreenGpus;
  for (const WallSpec& w : walls) {
    if (w.window)
      ++contexts;
    else if (run.offscreenContexts == RunSpec::OffscreenContexts::PerWall)
      ++contexts;
    else
      offscreenGpus.insert(w.gpu.value_or(0));
  }
  return contexts + int(offscreenGpus.size());
}

AppConfig parseConfig(const std::string& text, const std::filesystem::path& name,
                      std::optional<int> monitors) {
  AppConfig c = readWithIncludes(parseToml(text, name.string()), name.string(), monitors);
  if (c.walls.empty())
    throw Error(
        concat(name.string(), ": no [[wall]] given; expected at least one wall, window or camera"));
  placeWalls(c);
  c.path = name;
  c.folder = folderOf(name.string());
  return c;
}

AppConfig loadConfig(const std::filesystem::path& path, std::optional<int> monitors) {
  return parseConfig(readFile(path, ""), path, monitors);
}

namespace {

// The tables whose keys --set may change (the others are attributes' or arrays).
const std::set<std::string, std::less<>> kSetTables{
    "run", "gpu", "field", "scene", "head", "navigation", "tracking", "cluster", "menu"};

bool readsAsToml(const std::string& value) {
  try {
    std::istringstream in("v = " + value + "\n");
    toml::parse(in, "--set");
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

// A TOML value for `text`: itself where TOML reads it, an array of values
// given with commas (0,0,1.7: as attributes take them), else a string of it.
std::string tomlValue(const std::string& text) {
  if (readsAsToml(text)) return text;
  if (text.find(',') != std::string::npos && readsAsToml("[" + text + "]")) return "[" + text + "]";
  return tomlString(text);
}

}  // namespace

bool isConfigSetting(std::string_view key) {
  const std::size_t dot = key.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 == key.size() ||
      !kSetTables.contains(key.substr(0, dot)))
    return false;
  const AttributeTable& table = AttributeTable::instance();
  const std::string name = table.canonical(key);
  for (const AttributeInfo& info : table.entries())
    if (info.key == name) return false;
  return true;
}

void applyConfigSets(AppConfig& config, const std::vector<std::string>& sets) {
  for (const std::string& set : sets) {
    const std::size_t eq = set.find('=');
    if (eq == std::string::npos || !isConfigSetting(set.substr(0, eq))) continue;
    const std::string label = concat(kSetLabel, set);
    const std::string key = set.substr(0, eq);
    for (const char ch : key)
      if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_' && ch != '.')
        throw Error(concat(label, ": expected a key of letters, digits, '_' and '.'"));
    // A file of one dotted key, read on top of the configuration.
    const toml::value root = parseToml(key + " = " + tomlValue(set.substr(eq + 1)) + "\n", label);
    read(root, label, std::nullopt, config, {});
  }
}

const char* toString(StereoMode mode) {
  switch (mode) {
    case StereoMode::Mono:
      return "mono";
    case StereoMode::QuadBuffer:
      return "quad-buffer";
    case StereoMode::SideBySide:
      return "side-by-side";
    case StereoMode::TopBottom:
      return "top-bottom";
    case StereoMode::Anaglyph:
      return "anaglyph";
    case StereoMode::LeftEye:
      return "left-eye";
    case StereoMode::RightEye:
      return "right-eye";
  }
  return "?";
}

}  // namespace sandstorm
