#include "core/field/downwash_field.h"

#include <cmath>
#include <numbers>

#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float smoothstep(float edge0, float edge1, float x) {
  const float t = glm::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace

DownwashField::DownwashField(const DownwashParams& params) : params_(params) {
  if (!(params.radius > 0.0f))
    throw Error(concat("DownwashField: radius is ", params.radius, "; expected > 0"));
  if (!(params.thrust > 0.0f))
    throw Error(concat("DownwashField: thrust is ", params.thrust, "; expected > 0"));
  if (!(params.density > 0.0f))
    throw Error(concat("DownwashField: density is ", params.density, "; expected > 0"));
  if (!(params.hub.z > params.ground))
    throw Error(concat("DownwashField: hub height ", params.hub.z, " is not above the ground at ",
                       params.ground));
  if (!(params.groundLayer > 0.0f))
    throw Error(concat("DownwashField: ground layer is ", params.groundLayer, "; expected > 0"));
  const float area = kPi * params.radius * params.radius;
  vh_ = std::sqrt(params.thrust / (2.0f * params.density * area));
  flow_ = area * vh_;
}

glm::vec3 DownwashField::evaluate(const glm::vec3& p) const {
  const float R = params_.radius;
  const glm::vec2 radial(p.x - params_.hub.x, p.y - params_.hub.y);
  const float r = glm::length(radial);
  const glm::vec2 outward = r > 0.0f ? radial / r : glm::vec2(0.0f);
  const float height = p.z - params_.ground;  // above ground
  if (height < 0.0f) return glm::vec3(0.0f);

  // The column, at distance s below the disc.
  const float s = params_.hub.z - p.z;
  const float root = std::sqrt(s * s + R * R);
  const float W = vh_ * (1.0f + s / root);
  const float dW = vh_ * R * R / (root * root * root);
  glm::vec3 v(0.0f);
  if (W > 1e-12f * vh_) {
    const float a2 = R * R * vh_ / W;
    const float profile = std::exp(-r * r / a2);
    const float fade = smoothstep(0.0f, params_.groundLayer, height);
    const float ur = -0.5f * dW * r * profile;
    v += fade * glm::vec3(ur * outward, -W * profile);
  }

  // The wall jet along the ground.
  const float sg = params_.hub.z - params_.ground;
  const float Wg = vh_ * (1.0f + sg / std::sqrt(sg * sg + R * R));
  const float ag2 = R * R * vh_ / Wg;
  if (r > 0.0f) {
    const float delta = 0.1f * R + 0.05f * r;
    const float eta = height / delta;
    const float peak = flow_ / (2.0f * kPi * r * delta * std::numbers::e_v<float>);
    const float ramp = 1.0f - std::exp(-r * r / ag2);
    v += glm::vec3(peak * eta * std::exp(1.0f - eta) * ramp * outward, 0.0f);
  }
  return v;
}

}  // namespace sandstorm
