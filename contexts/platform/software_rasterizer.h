// Keeps Mesa's software OpenGL (llvmpipe: CI, and machines without a GPU)
// from racing when several contexts draw in threads.
//
// llvmpipe's rasterizer threads signal a flush's fence (lock, count, broadcast,
// unlock) while the drawing thread's wait first reads the count unlocked
// (Mesa 22.3's lp_fence_signalled) and may free the fence at once: a
// rasterizer thread descheduled before its unlock then writes freed memory.
// ThreadSanitizer shows the race in a run of four walls in threads, and such a
// run crashed on a loaded CI machine. With LP_NUM_THREADS=0 each context
// rasterizes in the thread that flushes it: no fence crosses threads, and the
// walls' threads are the parallelism.
#pragma once

namespace sandstorm {

// Call before the first OpenGL context (the driver reads the setting when it
// loads) and before other threads run. With more than one context drawing in
// threads, sets LP_NUM_THREADS=0 unless the user set it; other drivers ignore
// it. One context keeps llvmpipe's threads (it draws about twice as fast).
void keepSoftwareRasterizingInDrawingThreads(int contexts);

}  // namespace sandstorm
