#include "contexts/platform/software_rasterizer.h"

#include <cstdlib>

#include "core/util/log.h"

namespace sandstorm {

void keepSoftwareRasterizingInDrawingThreads(int contexts) {
  if (contexts < 2 || std::getenv("LP_NUM_THREADS")) return;
  setenv("LP_NUM_THREADS", "0", /*overwrite=*/0);
  log::debug("LP_NUM_THREADS=0: a software (llvmpipe) context rasterizes in its own thread");
}

}  // namespace sandstorm
