#include "contexts/particles/expression_programs.h"

#include "core/expr/field_expression.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

namespace {
constexpr std::size_t kKept = 8;  // programs kept besides the ones in use
}

const gl::Program* ExpressionPrograms::get(const ParticleState& state,
                                           const std::vector<std::string>& defines,
                                           const Make& make) {
  std::string variant;
  for (const std::string& d : defines)
    variant += d + ";";
  const std::array<std::string, 3>& text = state.field.expression;
  const std::string key = variant + text[0] + ";" + text[1] + ";" + text[2];
  if (const auto it = programs_.find(key); it != programs_.end()) return it->second.get();
  const auto fallback = [&]() -> const gl::Program* {
    const auto it = lastGood_.find(variant);
    return it == lastGood_.end() ? nullptr : it->second;
  };
  if (failed_.count(key)) return fallback();
  try {
    const auto expression = FieldExpression::compile(text);
    std::vector<std::string> all = defines;
    all.push_back("FIELD_EXPRESSION");
    const char* names[3] = {"EXPRESSION_X ", "EXPRESSION_Y ", "EXPRESSION_Z "};
    for (std::size_t c = 0; c < 3; ++c)
      all.push_back(names[c] + expression->glsl()[c]);
    if (programs_.size() >= kKept) {
      // Keep the last good programs; drop the rest.
      for (auto it = programs_.begin(); it != programs_.end();) {
        bool used = false;
        for (const auto& [v, p] : lastGood_)
          used = used || p == it->second.get();
        it = used ? std::next(it) : programs_.erase(it);
      }
    }
    auto program = std::make_unique<gl::Program>(make(all));
    const gl::Program* made = program.get();
    programs_[key] = std::move(program);
    lastGood_[variant] = made;
    return made;
  } catch (const Error& e) {
    failed_.insert(key);
    log::error("field expression (", text[0], ", ", text[1], ", ", text[2],
               "): the GPU program failed; the last good one stays: ", e.what());
    return fallback();
  }
}

}  // namespace sandstorm
