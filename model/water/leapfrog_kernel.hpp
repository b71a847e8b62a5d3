#pragma once
// The inner loop of the height field (spec §2.1): one row segment of the damped leapfrog
//   z⁺ = wc·z + wo·Σ_orth + wd·Σ_diag − wp·z⁻,
// with wc = 4/(2 + μΔt) + s·centre, wo = s·orth, wd = s·diag, wp = (2 − μΔt)/(2 + μΔt),
// s = 2σ²/(2 + μΔt) (the 3×3 stencil of model/water/stencil.hpp folded into the update).
// z⁺ overwrites z⁻ in place (each cell reads only its own z⁻).
//
// Written with explicit SIMD (GCC vector extensions, 64-byte vectors) and compiled three times
// (x86-64-v4 = AVX-512, x86-64-v3 = AVX2 + FMA, baseline SSE2) with a run-time choice of the
// best the CPU has (GCC target_clones): no -march flag, so the binary runs on any x86-64. The
// file is compiled with -ffp-contract=off and the vector body and the scalar tail evaluate the
// same expression in the same order, so every cell gets the same bits whichever variant, vector
// lane or row segment computes it (the active-tile mode relies on that: spec §2.6, ε = 0).
#include <cstddef>

namespace stoneskip {

template <class Real>
struct LeapfrogWeights {
  Real centre = 0, orth = 0, diag = 0, previous = 0;  // wc, wo, wd, wp above
};

// Updates a block of `rows` row segments of n cells: zp[r·w + k], k ∈ [0, n), r ∈ [0, rows)
// (zp and z point at the block's first cell; w is the row stride, so z[k ± w] are the rows above
// and below). `diagonal` false skips the corner terms (wd = 0). When z, zp and w are aligned to
// 64 bytes the kernel reads whole aligned vectors, including up to one vector before and after
// each row segment of rows −1…rows: that memory must exist (the height field pads for it).
void leapfrog_block(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                    const LeapfrogWeights<double>& c, bool diagonal);
void leapfrog_block(float* zp, const float* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                    const LeapfrogWeights<float>& c, bool diagonal);

// The update of one row segment of n cells that consists of consecutive chunks of `chunk` cells
// (tiles; the last may be shorter), raising activity[q] to the largest max(|z⁺|, |z⁺ − z|) over
// chunk q's cells (spec §2.6). The values are compared as bit patterns, in which NaN > ∞ > any
// finite value, so a blown-up chunk reports NaN and is never taken for a quiet one.
void leapfrog_row_chunks(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t w, const LeapfrogWeights<double>& c,
                         bool diagonal, std::ptrdiff_t chunk, double* activity);
void leapfrog_row_chunks(float* zp, const float* z, std::ptrdiff_t n, std::ptrdiff_t w, const LeapfrogWeights<float>& c,
                         bool diagonal, std::ptrdiff_t chunk, float* activity);

// Which variant the run-time dispatch chose on this CPU: "x86-64-v4", "x86-64-v3" or "baseline".
const char* leapfrog_kernel_isa();

}  // namespace stoneskip
