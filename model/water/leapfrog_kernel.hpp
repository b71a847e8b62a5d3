#pragma once
// The inner loop of the height field (model/README.md §2.1): one row segment of the damped leapfrog
//   z⁺ = (4z − (2 − μΔt) z⁻ + 2σ² d²L[z]) / (2 + μΔt),
// with s = 2σ²/(2 + μΔt) and the 3×3 stencil of model/water/stencil.hpp, evaluated
//   float64: z⁺ = wc z + wo Σ_orth + wd Σ_diag − wp z⁻ (wc = 4/(2 + μΔt) + s·centre),
//   float64 with corners (wd ≠ 0), the column form: with u_k = z[k − w] + z[k + w] (the cells
//     above and below) and the column value q_k = wd u_k + wo z_k,
//     z⁺ = ((q_{k−1} + q_{k+1}) + wo u_k) + wc z_k − wp z⁻,
//   float32: z⁺ = z + [wp (z − z⁻) + wo (Σ_orth − 4z) + wd (Σ_diag − 4z) + wx z],
// wo = s·orth, wd = s·diag, wp = (2 − μΔt)/(2 + μΔt), wx = s·(centre + 4 orth + 4 diag). All
// agree in exact arithmetic (q_{k−1} + q_{k+1} = wd Σ_diag + wo (z_{k−1} + z_{k+1})). The column
// form shares a column's value between the cells on either side: a cell costs six additions and
// five multiplications instead of seven and four, and a vector path shifts one stream (q) where
// the direct form shifts two (the row and u). Measured at 500² float64, one thread, in one binary
// against the direct form (2-core AMD EPYC Zen 5, 6 December): AVX2 +7–10 % (four runs of five),
// AVX-512 +12–23 %, SSE2 −4 %, scalar −7 % (the reference path, which recomputes each q it needs). The increment form keeps a uniform level exactly whatever the
// rounding of the weights (for a consistent stencil wx = 0 and every bracket vanishes); the direct
// form does not: with weights rounded to float, wc + 4wo + 4wd − wp misses 1 by ~1e-7 and the mean
// mode, whose other root is wp ≈ 1 − μΔt, drifts by ~1e-7/(μΔt) per step — 7 % of the amplitude
// in 5000 steps at μΔt = 5e-4 (measured: verification/waves/precision_error.hpp). In float64 that
// drift is ~1e-13 per step, and the direct form has fewer operations (≈ 30 % faster in cache).
// z⁺ overwrites z⁻ in place (each cell reads only its own z⁻).
//
// Written with explicit SIMD (GCC vector extensions) at the width of each instruction set — SSE2
// and NEON 16 bytes, AVX2 32, AVX-512 64 — plus a scalar path, each compiled for its target in
// one file and chosen at run time (best the CPU has, or STONESKIP_ISA): no -march flag, so the
// binary runs on any x86-64. The file is compiled with -ffp-contract=off and every path, vector
// lane and scalar tail evaluates the same expression in the same order, so every cell gets the
// same bits whichever path, lane or row segment computes it (the active-tile mode relies on
// that: model/README.md §2.6, ε = 0).
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace stoneskip {

template <class Real>
struct LeapfrogWeights {
  Real centre = 0, orth = 0, diag = 0, previous = 0, defect = 0;  // wc, wo, wd, wp, wx above
};
// The weights for a stencil, σ = cΔt/d and μΔt.
template <class Real>
LeapfrogWeights<Real> leapfrog_weights(double centre, double orth, double diag, double sigma, double mu_dt) {
  const double inv = 1.0 / (2 + mu_dt), s = 2 * sigma * sigma * inv;
  // Weights that sum to zero up to their own rounding (γ = 1/3's thirds) are a consistent stencil.
  double sum = centre + 4 * orth + 4 * diag;
  if (std::abs(sum) <= 1e-14 * (std::abs(centre) + 4 * std::abs(orth) + 4 * std::abs(diag))) sum = 0;
  return {static_cast<Real>(s * centre + 4 * inv), static_cast<Real>(s * orth), static_cast<Real>(s * diag),
          static_cast<Real>((2 - mu_dt) * inv), static_cast<Real>(s * sum)};
}

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
// chunk q's cells (model/README.md §2.6). The values are compared as bit patterns, in which NaN > ∞ > any
// finite value, so a blown-up chunk reports NaN and is never taken for a quiet one.
void leapfrog_row_chunks(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t w, const LeapfrogWeights<double>& c,
                         bool diagonal, std::ptrdiff_t chunk, double* activity);
void leapfrog_row_chunks(float* zp, const float* z, std::ptrdiff_t n, std::ptrdiff_t w, const LeapfrogWeights<float>& c,
                         bool diagonal, std::ptrdiff_t chunk, float* activity);

// What a caller of leapfrog_wavefront can do between rows (a boundary condition). Rows are numbered
// from the block's first row (0) to rows − 1; halo rows lie outside that range.
template <class Real>
struct WavefrontHooks {
  // With halo_rows = H > 0 a pass advances at most H levels, and a pass of P levels also computes
  // P − s rows above and below the block at level s (the images of a periodic boundary, say): then
  // before_pass must have filled P rows above and below of `level` and P − 1 of `previous` (rows
  // −P…−1 and rows…rows + P − 1), the memory for them must exist, and the results of those rows
  // are scratch. Without a halo the ghost rows −1 and `rows` are read as they are.
  int halo_rows = 0;
  void* context = nullptr;
  // Called at the start of each pass with the two levels (newest first) and the pass's levels.
  void (*before_pass)(void* context, Real* level, Real* previous, int levels) = nullptr;
  // Called once row `row` of a level has been computed into `level` (which points at row 0's first
  // cell): the place to fill that row's ghost cells, or a ghost row that mirrors it.
  void (*after_row)(void* context, Real* level, std::ptrdiff_t row) = nullptr;
};

// Advances a whole field `steps` leapfrog steps, as `steps` times { leapfrog_block(zp, z, n, rows,
// w); hooks' ghost filling; swap(z, zp) } would, to the bit, but two rows at a time along a
// wavefront (temporal blocking): rows j, j + 1 of level s + 1 are computed as soon as rows
// j − 1…j + 2 of level s are, so the rows in flight stay in cache while several levels pass over
// them. Without hooks the ghost cells around the block (rows −1 and `rows`, columns −1 and n) are
// held as they are (a fixed rim, or a block inside a larger field whose ring is not advanced).
// After an odd number of steps the newest level is in zp.
void leapfrog_wavefront(double* z, double* zp, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                        const LeapfrogWeights<double>& c, bool diagonal, int steps,
                        const WavefrontHooks<double>& hooks = {});
void leapfrog_wavefront(float* z, float* zp, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                        const LeapfrogWeights<float>& c, bool diagonal, int steps, const WavefrontHooks<float>& hooks = {});
// The most levels a pass advances for rows of `row_bytes` bytes (1…16: the rows in flight fit a share of L3).
int wavefront_depth(std::ptrdiff_t row_bytes);

// The instruction-set paths of the kernel. Each computes the same bits.
enum class SimdPath { scalar, sse2, avx2, avx512, neon };
const char* to_string(SimdPath p);              // "scalar", "sse2", "avx2", "avx512", "neon"
bool parse_simd_path(const std::string& s, SimdPath& out);
int simd_path_vector_bytes(SimdPath p);         // 0 (scalar), 16, 32 or 64
std::vector<SimdPath> supported_simd_paths();   // those this build and CPU can run, scalar first, best last
// The path STONESKIP_ISA asks for, or the best supported one when it is unset or empty; false
// (with *why, one line) when it names no path or one this CPU lacks.
bool simd_path_from_environment(SimdPath& out, std::string* why = nullptr);
// The path the kernel uses: at first use, simd_path_from_environment's (the best supported one
// when that fails; the command line refuses such a value before). Tests and benchmarks set it;
// setting a path that is not supported returns false and changes nothing. Not to be changed
// while a step runs.
SimdPath leapfrog_kernel_path();
bool set_leapfrog_kernel_path(SimdPath p);
// to_string(leapfrog_kernel_path()).
const char* leapfrog_kernel_isa();

}  // namespace stoneskip
