#include "core/field/grid_match.h"

#include <iomanip>
#include <sstream>

#include "core/util/error.h"

namespace sandstorm {
namespace {

std::string dimsText(glm::ivec3 d) {
  return concat(d.x, "x", d.y, "x", d.z);
}

// Nine digits: bounds that differ in the last bits of a float print apart.
std::string boundsText(const Box& b) {
  std::ostringstream os;
  os << std::setprecision(9) << "[" << b.min.x << "," << b.min.y << "," << b.min.z << "]..["
     << b.max.x << "," << b.max.y << "," << b.max.z << "] m";
  return os.str();
}

}  // namespace

std::string gridDifference(const VectorField& step, const VectorField& first) {
  if (step.dims() != first.dims())
    return concat("a ", dimsText(step.dims()), " grid, not the first step's ",
                  dimsText(first.dims()));
  if (step.bounds().min != first.bounds().min || step.bounds().max != first.bounds().max)
    return concat("bounds ", boundsText(step.bounds()), ", not the first step's ",
                  boundsText(first.bounds()));
  return "";
}

}  // namespace sandstorm
