// makeAnalyticField(): builds an analytic field by name from numeric
// parameters, for configs and `sandstorm-field generate`.
//
//   auto f = makeAnalyticField("gravity", {{"power", -3.0}, {"range", 6.0}});
//
// Names: tornado, gravity, wind, curl_noise, sphere_flow, downwash, still. Parameters
// not given take the defaults of the field's Params struct (listed by
// analyticFieldSpecs(), which `sandstorm-field generate --help` prints).
// Vectors are spelled per component: center_x, center_y, center_z.
// An unknown name, an unknown parameter or a non-finite value throws Error
// listing what is known.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/field/analytic_field.h"

namespace sandstorm {

using FieldParams = std::map<std::string, double, std::less<>>;

struct AnalyticFieldSpec {
  std::string name;
  std::string summary;
  FieldParams defaults;  // every parameter the field takes, with its default
};

const std::vector<AnalyticFieldSpec>& analyticFieldSpecs();

std::unique_ptr<AnalyticField> makeAnalyticField(std::string_view name, const FieldParams& params);

}  // namespace sandstorm
