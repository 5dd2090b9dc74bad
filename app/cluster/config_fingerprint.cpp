#include "app/cluster/config_fingerprint.h"

#include <sstream>

#include "core/sim/attribute_table.h"

namespace sandstorm {
namespace {

class Lines {
 public:
  Lines() { out_ << std::hexfloat; }
  template <class... Args>
  void add(const std::string& key, const Args&... values) {
    out_ << key << " =";
    ((out_ << ' ' << values), ...);
    out_ << '\n';
  }
  void vec(const std::string& key, const glm::vec3& v) { add(key, v.x, v.y, v.z); }
  std::string str() const { return out_.str(); }

 private:
  std::ostringstream out_;
};

}  // namespace

std::string configFingerprint(const AppConfig& c, const AppOptions& o) {
  Lines l;
  l.add("run", c.run.seed, c.run.capacity, c.run.capacityLimit, c.run.fixedDt, c.run.frames,
        c.run.backend, c.run.nearPlane, c.run.farPlane);
  l.add("field.source", c.field.source, c.field.name);
  l.add("field.precision", c.field.halfPrecision, c.field.autoPrecision);
  l.add("field.grid", c.field.dims.x, c.field.dims.y, c.field.dims.z, c.field.resolution.x,
        c.field.resolution.y, c.field.resolution.z);
  l.vec("field.bounds_min", c.field.bounds.min);
  l.vec("field.bounds_max", c.field.bounds.max);
  for (const auto& [key, value] : c.field.params)
    l.add("field.params." + key, value);
  l.vec("field.offset", c.field.placement.offset);
  l.add("field.scale", c.field.placement.scale);
  for (int i = 0; i < 3; ++i)
    l.vec("field.rotation", c.field.placement.rotation[i]);
  l.add("scene", c.scene.terrain, c.scene.groundHeight, c.scene.helicopter);
  l.add("head", int(c.head.mode), c.head.yawDegrees, c.head.eyeSeparation, c.head.loop,
        c.head.path.size());
  l.vec("head.position", c.head.position);
  for (const HeadKeyframe& k : c.head.path)
    l.add("head.path", k.time, k.position.x, k.position.y, k.position.z);
  l.vec("navigation.offset", c.navigation.offset);
  l.add("navigation", c.navigation.yawDegrees, c.navigation.scale);
  l.add("cluster", c.cluster.roundRobin, c.cluster.timeoutSeconds, c.cluster.startupTimeoutSeconds,
        c.cluster.readField, c.cluster.readSteps, c.cluster.chunkKiB, c.cluster.fieldCache);
  // The particle state, every attribute, as the table prints it.
  std::istringstream attributes(AttributeTable::instance().describe(c.particles));
  for (std::string line; std::getline(attributes, line);)
    l.add("attribute", line);
  for (const WallSpec& w : c.walls) {
    const std::string k = "wall." + w.name;
    l.add(k + ".placement", w.rank, w.host.empty() ? "-" : w.host, w.menu, int(w.stereo));
    l.vec(k + ".lower_left", w.corners.lowerLeft);
    l.vec(k + ".lower_right", w.corners.lowerRight);
    l.vec(k + ".upper_left", w.corners.upperLeft);
    if (w.camera)
      l.add(k + ".camera", w.camera->position.x, w.camera->position.y, w.camera->position.z,
            w.camera->target.x, w.camera->target.y, w.camera->target.z, w.camera->fovDegrees);
    if (w.window)
      l.add(k + ".window", w.window->size.x, w.window->size.y, w.window->fullscreen);
    else
      l.add(k + ".offscreen", w.offscreenSize.x, w.offscreenSize.y);
  }
  for (const std::string& set : o.sets)
    l.add("--set", set);
  for (const std::string& wall : o.walls)
    l.add("--walls", wall);
  l.add("--frames", o.frames ? *o.frames : -1);
  l.add("--headless", o.headless);
  return l.str();
}

std::string firstDifference(const std::string& ours, const std::string& theirs) {
  std::istringstream a(ours), b(theirs);
  std::string x, y;
  for (;;) {
    const bool moreA = bool(std::getline(a, x)), moreB = bool(std::getline(b, y));
    if (!moreA && !moreB) return "";
    if (!moreA) x = "(nothing)";
    if (!moreB) y = "(nothing)";
    if (x != y) return x + " | " + y;
  }
}

}  // namespace sandstorm
