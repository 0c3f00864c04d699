#pragma once
// Background threads (chunk generation and loading, meshing) yield to the frame: on a machine with few
// cores the renderer (and llvmpipe's rasterizer threads, where there is no GPU) would otherwise lose
// whole time slices to them, and those frames would stutter. A lower priority, not an idle one, so the
// world still loads while the frame keeps every core busy.

namespace terrasol {

// Lowers the calling thread's scheduling priority (Linux: nice 10; elsewhere nothing).
void lowerThisThreadsPriority();

}  // namespace terrasol
