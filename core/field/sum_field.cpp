#include "core/field/sum_field.h"

#include "core/util/error.h"

namespace sandstorm {

SumField::SumField(std::vector<std::unique_ptr<AnalyticField>> parts) {
  for (auto& part : parts)
    add(std::move(part));
}

SumField& SumField::add(std::unique_ptr<AnalyticField> part) {
  if (!part) throw Error("SumField::add(): part is null");
  parts_.push_back(std::move(part));
  return *this;
}

glm::vec3 SumField::evaluate(const glm::vec3& p) const {
  glm::vec3 v(0.0f);
  for (const auto& part : parts_)
    v += part->evaluate(p);
  return v;
}

}  // namespace sandstorm
