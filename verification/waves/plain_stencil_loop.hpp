#pragma once
// A plain loop of the leapfrog update (model/README.md §2.1, the float64 direct form of
// model/water/leapfrog_kernel.hpp): one cell at a time, no intrinsics, compiled without
// auto-vectorisation (verification/CMakeLists.txt). The benchmark's stand-in for "the same stencil
// written plainly" (what a straightforward numba or C loop does), against which the SIMD kernel's
// gain is stated. Not used by any simulation.
#include <cstddef>

#include "model/water/leapfrog_kernel.hpp"

namespace stoneskip {

// zp[r·w + k] = update of cell k of row r, k ∈ [0, n), r ∈ [0, rows) (as leapfrog_block).
void plain_leapfrog_block(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                          const LeapfrogWeights<double>& c);

}  // namespace stoneskip
