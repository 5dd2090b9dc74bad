#include "contexts/particles/equation_block.h"

#include <algorithm>

namespace sandstorm {

EquationBlock makeEquationBlock(const FieldEquation& e) {
  EquationBlock b{};
  const int count = std::min(int(e.terms.size()), FieldEquation::kMaxTerms);
  b.termCount = glm::ivec4(count, 0, 0, 0);
  for (int i = 0; i < count; ++i) {
    const EquationTerm& t = e.terms[std::size_t(i)];
    b.terms[i].kindSeed = glm::ivec4(int(t.kind), int(t.seed), 0, 0);
    b.terms[i].a = t.a;
    b.terms[i].b = t.b;
    b.terms[i].c = t.c;
  }
  return b;
}

}  // namespace sandstorm
