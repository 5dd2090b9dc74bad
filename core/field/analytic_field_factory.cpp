#include "core/field/analytic_field_factory.h"

#include <cmath>
#include <functional>

#include "core/field/curl_noise_field.h"
#include "core/field/downwash_field.h"
#include "core/field/gravity_point_field.h"
#include "core/field/sphere_flow_field.h"
#include "core/field/sum_field.h"
#include "core/field/vortex_field.h"
#include "core/field/wind_field.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// Parameters of one call: the defaults overridden by what was given.
class Values {
 public:
  explicit Values(FieldParams values) : values_(std::move(values)) {}
  float f(std::string_view key) const { return float(values_.find(key)->second); }
  glm::vec3 v(std::string_view prefix) const {
    const std::string p(prefix);
    return {f(p + "_x"), f(p + "_y"), f(p + "_z")};
  }
  std::uint32_t u(std::string_view key) const {
    return std::uint32_t(std::llround(values_.find(key)->second));
  }

 private:
  FieldParams values_;
};

FieldParams withVector(FieldParams params, const std::string& prefix, glm::vec3 v) {
  params[prefix + "_x"] = v.x;
  params[prefix + "_y"] = v.y;
  params[prefix + "_z"] = v.z;
  return params;
}

struct Entry {
  AnalyticFieldSpec spec;
  std::function<std::unique_ptr<AnalyticField>(const Values&)> make;
};

const std::vector<Entry>& entries() {
  static const std::vector<Entry> table = [] {
    std::vector<Entry> t;
    {
      const VortexParams d;
      FieldParams p{{"range", d.range}, {"height", d.height}, {"core", d.core},
                    {"spin", d.spin},   {"pull", d.pull},     {"up", d.up}};
      p = withVector(withVector(p, "center", d.center), "axis", d.axis);
      t.push_back(
          {{"tornado", "vortex of the texture-vs-equation thesis (spin, pull, up, range)", p},
           [](const Values& v) {
             VortexParams q;
             q.center = v.v("center");
             q.axis = v.v("axis");
             q.range = v.f("range");
             q.height = v.f("height");
             q.core = v.f("core");
             q.spin = v.f("spin");
             q.pull = v.f("pull");
             q.up = v.f("up");
             return std::make_unique<VortexField>(q);
           }});
    }
    {
      const GravityPointParams d;
      FieldParams p = withVector({{"range", d.range}, {"power", d.power}}, "center", d.center);
      t.push_back({{"gravity", "gravity point: pulls towards the centre (power < 0 repels)", p},
                   [](const Values& v) {
                     GravityPointParams q;
                     q.center = v.v("center");
                     q.range = v.f("range");
                     q.power = v.f("power");
                     return std::make_unique<GravityPointField>(q);
                   }});
    }
    {
      const WindParams d;
      FieldParams p{
          {"power", d.power}, {"noise", d.noise}, {"noise_scale", d.noiseScale}, {"seed", d.seed}};
      p = withVector(p, "direction", d.direction);
      t.push_back({{"wind", "uniform wind with smooth noise", p}, [](const Values& v) {
                     WindParams q;
                     q.direction = v.v("direction");
                     q.power = v.f("power");
                     q.noise = v.f("noise");
                     q.noiseScale = v.f("noise_scale");
                     q.seed = v.u("seed");
                     return std::make_unique<WindField>(q);
                   }});
    }
    {
      const CurlNoiseParams d;
      FieldParams p{{"scale", d.scale}, {"amplitude", d.amplitude}, {"seed", d.seed}};
      p = withVector(p, "offset", d.offset);
      t.push_back({{"curl_noise", "divergence-free turbulence (curl of gradient noise)", p},
                   [](const Values& v) {
                     CurlNoiseParams q;
                     q.scale = v.f("scale");
                     q.amplitude = v.f("amplitude");
                     q.offset = v.v("offset");
                     q.seed = v.u("seed");
                     return std::make_unique<CurlNoiseField>(q);
                   }});
    }
    {
      const SphereFlowParams d;
      FieldParams p{
          {"radius", d.radius}, {"speed", d.speed}, {"source", d.source}, {"epsilon", d.epsilon}};
      p = withVector(withVector(p, "center", d.center), "direction", d.direction);
      t.push_back({{"sphere_flow", "potential flow past a sphere, plus a point source", p},
                   [](const Values& v) {
                     SphereFlowParams q;
                     q.center = v.v("center");
                     q.radius = v.f("radius");
                     q.direction = v.v("direction");
                     q.speed = v.f("speed");
                     q.source = v.f("source");
                     q.epsilon = v.f("epsilon");
                     return std::make_unique<SphereFlowField>(q);
                   }});
    }
    {
      const DownwashParams d;
      FieldParams p{{"radius", d.radius},
                    {"thrust", d.thrust},
                    {"density", d.density},
                    {"ground", d.ground},
                    {"ground_layer", d.groundLayer}};
      p = withVector(p, "hub", d.hub);
      t.push_back({{"downwash", "helicopter rotor downwash turning into a wall jet", p},
                   [](const Values& v) {
                     DownwashParams q;
                     q.hub = v.v("hub");
                     q.radius = v.f("radius");
                     q.thrust = v.f("thrust");
                     q.density = v.f("density");
                     q.ground = v.f("ground");
                     q.groundLayer = v.f("ground_layer");
                     return std::make_unique<DownwashField>(q);
                   }});
    }
    // An empty sum is zero: the field editor's blank canvas.
    t.push_back({{"still", "still air, zero everywhere: a canvas for the field editor", {}},
                 [](const Values&) { return std::make_unique<SumField>(); }});
    return t;
  }();
  return table;
}

template <class Range, class Key>
std::string joinKeys(const Range& range, Key key) {
  std::string out;
  for (const auto& item : range) {
    if (!out.empty()) out += ", ";
    out += key(item);
  }
  return out;
}

}  // namespace

const std::vector<AnalyticFieldSpec>& analyticFieldSpecs() {
  static const std::vector<AnalyticFieldSpec> specs = [] {
    std::vector<AnalyticFieldSpec> s;
    for (const Entry& e : entries())
      s.push_back(e.spec);
    return s;
  }();
  return specs;
}

std::unique_ptr<AnalyticField> makeAnalyticField(std::string_view name, const FieldParams& params) {
  for (const Entry& e : entries()) {
    if (e.spec.name != name) continue;
    FieldParams values = e.spec.defaults;
    for (const auto& [key, value] : params) {
      auto it = values.find(key);
      if (it == values.end())
        throw Error(concat("analytic field '", name, "': unknown parameter '", key,
                           "'; known parameters: ",
                           joinKeys(e.spec.defaults, [](const auto& kv) { return kv.first; })));
      if (!std::isfinite(value))
        throw Error(concat("analytic field '", name, "': parameter '", key, "' is ", value,
                           "; expected a finite number"));
      it->second = value;
    }
    return e.make(Values(std::move(values)));
  }
  throw Error(concat("unknown analytic field '", name, "'; known fields: ",
                     joinKeys(entries(), [](const Entry& e) { return e.spec.name; })));
}

}  // namespace sandstorm
