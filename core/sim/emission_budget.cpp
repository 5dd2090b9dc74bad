#include "core/sim/emission_budget.h"

#include <algorithm>

namespace sandstorm {

std::vector<std::uint32_t> EmissionBudget::allocate(const std::vector<std::uint32_t>& desired,
                                                    std::size_t limit, std::size_t count2) const {
  const std::size_t bound = count2 + previousEmitted_;
  std::size_t left = limit > bound ? limit - bound : 0;
  std::vector<std::uint32_t> granted(desired.size(), 0);
  for (std::size_t e = 0; e < desired.size(); ++e) {
    granted[e] = std::uint32_t(std::min<std::size_t>(desired[e], left));
    left -= granted[e];
  }
  return granted;
}

}  // namespace sandstorm
