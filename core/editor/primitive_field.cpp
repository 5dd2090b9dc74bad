#include "core/editor/primitive_field.h"

#include <cmath>

#include "core/field/curl_noise_field.h"
#include "core/field/sphere_flow_field.h"
#include "core/field/vortex_field.h"

namespace sandstorm {

PrimitiveField::PrimitiveField(const FieldPrimitive& primitive) : p_(primitive) {
  const float length = glm::length(p_.axis);
  axis_ = length > 0.0f && std::isfinite(length) ? p_.axis / length : glm::vec3(0, 0, 1);
  const float r = std::max(p_.radius, 1e-6f);
  switch (p_.kind) {
    case PrimitiveKind::Vortex:
      circulation_ = float(2.0 * M_PI) * r * p_.strength / (1.0f - std::exp(-1.0f));
      break;
    case PrimitiveKind::Tornado: {
      const VortexParams d;
      VortexParams q = d;
      q.center = p_.position;
      q.axis = axis_;
      q.core = r;
      q.range = r * d.range / d.core;
      q.height = r * d.height / d.core;
      q.spin = p_.strength;
      q.pull = p_.strength * d.pull / d.spin;
      q.up = p_.strength * d.up / d.spin;
      library_ = std::make_unique<VortexField>(q);
      break;
    }
    case PrimitiveKind::SphereFlow: {
      SphereFlowParams q;
      q.center = p_.position;
      q.radius = r;
      q.direction = axis_;
      q.speed = p_.strength;
      library_ = std::make_unique<SphereFlowField>(q);
      break;
    }
    case PrimitiveKind::CurlNoise: {
      CurlNoiseParams q;
      q.scale = r;
      q.amplitude = p_.strength;
      q.offset = p_.position;
      library_ = std::make_unique<CurlNoiseField>(q);
      break;
    }
    default:
      break;
  }
}

PrimitiveField::~PrimitiveField() = default;

glm::vec3 PrimitiveField::evaluate(const glm::vec3& x) const {
  if (!p_.active()) return glm::vec3(0.0f);
  const float r = std::max(p_.radius, 1e-6f);
  const glm::vec3 t = x - p_.position;
  switch (p_.kind) {
    case PrimitiveKind::Vortex: {
      const glm::vec3 rho = t - glm::dot(t, axis_) * axis_;
      const float rho2 = glm::dot(rho, rho), r2 = r * r;
      // (1 - exp(-rho^2/R^2)) / rho^2, with its limit 1/R^2 on the axis.
      const float share = rho2 > 1e-6f * r2 ? -std::expm1(-rho2 / r2) / rho2 : 1.0f / r2;
      return circulation_ / float(2.0 * M_PI) * share * glm::cross(axis_, rho);
    }
    case PrimitiveKind::Source: {
      const float d = glm::length(t);
      if (!(d > 0.0f)) return glm::vec3(0.0f);
      const float speed = d >= r ? p_.strength * (r / d) * (r / d) : p_.strength * d / r;
      return speed * (t / d);
    }
    case PrimitiveKind::Wind:
      return p_.strength * axis_;
    default:
      return library_ ? library_->evaluate(x) : glm::vec3(0.0f);
  }
}

}  // namespace sandstorm
