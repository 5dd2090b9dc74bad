// SumField: fields composed by adding them, v(p) = sum_i f_i(p) (a tornado in
// a wind, a rotor over curl noise). Holds its parts; evaluating an empty sum
// gives zero.
#pragma once

#include <memory>
#include <vector>

#include "core/field/analytic_field.h"

namespace sandstorm {

class SumField final : public AnalyticField {
 public:
  SumField() = default;
  explicit SumField(std::vector<std::unique_ptr<AnalyticField>> parts);

  // Adds a part (not null). Returns *this for chaining.
  SumField& add(std::unique_ptr<AnalyticField> part);
  std::size_t size() const { return parts_.size(); }
  const AnalyticField& part(std::size_t i) const { return *parts_.at(i); }

  glm::vec3 evaluate(const glm::vec3& p) const override;

 private:
  std::vector<std::unique_ptr<AnalyticField>> parts_;
};

}  // namespace sandstorm
