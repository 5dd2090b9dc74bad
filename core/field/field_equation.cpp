#include "core/field/field_equation.h"

#include "core/field/curl_noise_field.h"
#include "core/field/downwash_field.h"
#include "core/field/gravity_point_field.h"
#include "core/field/sphere_flow_field.h"
#include "core/field/sum_field.h"
#include "core/field/vortex_field.h"
#include "core/field/wind_field.h"

namespace sandstorm {
namespace {

bool addTerms(const AnalyticField& field, FieldEquation& out) {
  if (const auto* sum = dynamic_cast<const SumField*>(&field)) {
    for (std::size_t i = 0; i < sum->size(); ++i)
      if (!addTerms(sum->part(i), out)) return false;
    return true;
  }
  if (int(out.terms.size()) >= FieldEquation::kMaxTerms) return false;
  EquationTerm t;
  if (const auto* f = dynamic_cast<const VortexField*>(&field)) {
    const VortexParams& p = f->params();
    t.kind = EquationKind::Tornado;
    t.a = glm::vec4(p.center, p.range);
    t.b = glm::vec4(glm::normalize(p.axis), p.height);
    t.c = glm::vec4(p.core, p.spin, p.pull, p.up);
  } else if (const auto* f = dynamic_cast<const GravityPointField*>(&field)) {
    const GravityPointParams& p = f->params();
    t.kind = EquationKind::Gravity;
    t.a = glm::vec4(p.center, p.range);
    t.b = glm::vec4(p.power, 0.0f, 0.0f, 0.0f);
  } else if (const auto* f = dynamic_cast<const WindField*>(&field)) {
    const WindParams& p = f->params();
    t.kind = EquationKind::Wind;
    t.seed = p.seed * 3u;
    t.a = glm::vec4(glm::normalize(p.direction), p.power);
    t.b = glm::vec4(p.noise, p.noiseScale, 0.0f, 0.0f);
  } else if (const auto* f = dynamic_cast<const CurlNoiseField*>(&field)) {
    const CurlNoiseParams& p = f->params();
    t.kind = EquationKind::CurlNoise;
    t.seed = p.seed * 3u;
    t.a = glm::vec4(p.offset, p.scale);
    t.b = glm::vec4(p.amplitude, 0.0f, 0.0f, 0.0f);
  } else if (const auto* f = dynamic_cast<const SphereFlowField*>(&field)) {
    const SphereFlowParams& p = f->params();
    t.kind = EquationKind::SphereFlow;
    t.a = glm::vec4(p.center, p.radius);
    t.b = glm::vec4(p.speed * glm::normalize(p.direction), p.source);
    t.c = glm::vec4(p.epsilon, 0.0f, 0.0f, 0.0f);
  } else if (const auto* f = dynamic_cast<const DownwashField*>(&field)) {
    const DownwashParams& p = f->params();
    t.kind = EquationKind::Downwash;
    t.a = glm::vec4(p.hub, p.radius);
    t.b = glm::vec4(f->hoverInducedSpeed(), f->volumeFlow(), p.ground, p.groundLayer);
  } else {
    return false;
  }
  out.terms.push_back(t);
  return true;
}

}  // namespace

std::optional<FieldEquation> fieldEquation(const AnalyticField& field) {
  FieldEquation e;
  if (!addTerms(field, e)) return std::nullopt;
  return e;
}

}  // namespace sandstorm
