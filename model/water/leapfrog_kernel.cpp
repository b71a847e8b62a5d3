#include "model/water/leapfrog_kernel.hpp"

#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <cstring>
#include <type_traits>

// 64-byte vectors are passed between always-inline helpers only; GCC's note about the ABI of
// such values in non-AVX-512 code does not apply to anything that crosses a call.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace stoneskip {
namespace {

constexpr int kVectorBytes = 64;
// Software prefetch distance in values: 1 KB (double) ahead of the row being read and written.
// Measured: +10–20 % in cache at 500², a few % from memory at 2048² (the hardware prefetchers do
// most of it).
#define STONESKIP_PF 128

template <class Real>
struct Simd {
  typedef Real V __attribute__((vector_size(kVectorBytes)));
  using Int = std::conditional_t<std::is_same_v<Real, double>, std::int64_t, std::int32_t>;
  typedef Int I __attribute__((vector_size(kVectorBytes)));
  static constexpr int lanes = kVectorBytes / sizeof(Real);
};

template <class Real>
[[gnu::always_inline]] inline typename Simd<Real>::V load(const Real* p) {
  typename Simd<Real>::V v;
  std::memcpy(&v, p, sizeof v);  // an unaligned vector load
  return v;
}

// z[k − 1] and z[k + 1] of an aligned vector z[k] from its aligned neighbours z[k − L], z[k + L].
template <class Real>
[[gnu::always_inline]] inline typename Simd<Real>::V shift_in_left(typename Simd<Real>::V prev, typename Simd<Real>::V cur) {
  using I = typename Simd<Real>::I;
  if constexpr (Simd<Real>::lanes == 8)
    return __builtin_shuffle(prev, cur, I{7, 8, 9, 10, 11, 12, 13, 14});
  else
    return __builtin_shuffle(prev, cur, I{15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30});
}
template <class Real>
[[gnu::always_inline]] inline typename Simd<Real>::V shift_in_right(typename Simd<Real>::V cur, typename Simd<Real>::V next) {
  using I = typename Simd<Real>::I;
  if constexpr (Simd<Real>::lanes == 8)
    return __builtin_shuffle(cur, next, I{1, 2, 3, 4, 5, 6, 7, 8});
  else
    return __builtin_shuffle(cur, next, I{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16});
}

// One update, on a vector or a scalar alike (so that both round the same): zc = z, orth and diag
// the neighbour sums, zm = z⁻; the direct or the increment form of leapfrog_kernel.hpp.
template <class Real, class T, bool Diagonal, bool Defect, bool IncrementForm>
[[gnu::always_inline]] inline T update(T zc, T orth, T diag, T zm, Real wc, Real wo, Real wd, Real wp, Real wx) {
  if constexpr (IncrementForm) {
    const T four = zc * 4;
    T dz = wp * (zc - zm) + wo * (orth - four);
    if constexpr (Diagonal) dz = dz + wd * (diag - four);
    if constexpr (Defect) dz = dz + wx * zc;  // wx = 0 exactly for a consistent stencil
    return zc + dz;
  } else {
    T r = wc * zc + wo * orth;
    if constexpr (Diagonal) r = r + wd * diag;
    return r - wp * zm;
  }
}

// The activity of one vector of results r over the old values zc: the bit patterns of |r| and
// |r − zc| (sign cleared), whose integer order is the numbers' order with NaN above ∞ above all.
template <class Real>
[[gnu::always_inline]] inline void track(typename Simd<Real>::V r, typename Simd<Real>::V zc, typename Simd<Real>::I& vmax) {
  using S = Simd<Real>;
  using I = typename S::I;
  const I sign = (I{} + 1) << (8 * sizeof(Real) - 1);
  const I a = reinterpret_cast<I>(r) & ~sign, b = reinterpret_cast<I>(r - zc) & ~sign;
  const I ab = a > b ? a : b;
  vmax = ab > vmax ? ab : vmax;
}

// The largest lane, by halving shuffles.
template <class Real>
[[gnu::always_inline]] inline typename Simd<Real>::Int lane_max(typename Simd<Real>::I v) {
  using I = typename Simd<Real>::I;
  auto fold = [](I x, I y) { return x > y ? x : y; };
  if constexpr (Simd<Real>::lanes == 16) {
    v = fold(v, __builtin_shuffle(v, I{8, 9, 10, 11, 12, 13, 14, 15, 0, 1, 2, 3, 4, 5, 6, 7}));
    v = fold(v, __builtin_shuffle(v, I{4, 5, 6, 7, 0, 1, 2, 3, 12, 13, 14, 15, 8, 9, 10, 11}));
    v = fold(v, __builtin_shuffle(v, I{2, 3, 0, 1, 6, 7, 4, 5, 10, 11, 8, 9, 14, 15, 12, 13}));
    v = fold(v, __builtin_shuffle(v, I{1, 0, 3, 2, 5, 4, 7, 6, 9, 8, 11, 10, 13, 12, 15, 14}));
  } else {
    v = fold(v, __builtin_shuffle(v, I{4, 5, 6, 7, 0, 1, 2, 3}));
    v = fold(v, __builtin_shuffle(v, I{2, 3, 0, 1, 6, 7, 4, 5}));
    v = fold(v, __builtin_shuffle(v, I{1, 0, 3, 2, 5, 4, 7, 6}));
  }
  return v[0];
}

// activity[q] = max(activity[q], the value whose bit pattern is m).
template <class Real>
[[gnu::always_inline]] inline void raise(Real* activity, typename Simd<Real>::Int m) {
  using Int = typename Simd<Real>::Int;
  Int old;
  std::memcpy(&old, activity, sizeof old);
  old &= ~(Int(1) << (8 * sizeof(Real) - 1));  // a start of −0 reads as 0
  if (m > old) std::memcpy(activity, &m, sizeof m);
}

// The update of model/README.md §2.1 for one row segment. Two vector paths compute the same expression from
// the same operands, so they round alike: where the segment, z⁻ and the row stride are aligned to
// a vector (the field's interior rows, tiles of a multiple of 8 cells), each row's vectors are
// loaded aligned once and the ±1 neighbours are shuffled out of adjacent vectors (an unaligned
// load straddles two cache lines, and a 9-point update needs six of them); elsewhere unaligned
// loads. The scalar tail repeats the expression term for term. With `Activity`, the segment is
// made of chunks of `chunk` cells, a multiple of the vector length (or the whole segment), and
// the bit pattern of each chunk's largest max(|z⁺|, |z⁺ − z|) raises activity[chunk index].
template <class Real, bool Diagonal, bool Defect, bool Activity>
[[gnu::always_inline]] inline void row_body(Real* __restrict zp, const Real* __restrict z, std::ptrdiff_t n,
                                            std::ptrdiff_t w, const LeapfrogWeights<Real>& c, std::ptrdiff_t chunk,
                                            Real* activity) {
  using S = Simd<Real>;
  using V = typename S::V;
  using I = typename S::I;
  using Int = typename S::Int;
  constexpr std::ptrdiff_t L = S::lanes;
  const Real wc = c.centre, wo = c.orth, wd = c.diag, wp = c.previous, wx = c.defect;
  constexpr bool increment_form = std::is_same_v<Real, float>;  // see leapfrog_kernel.hpp
  std::ptrdiff_t k = 0;
  I vmax{};
  // After each vector: hand a finished chunk's maximum over (a countdown, not a division).
  std::ptrdiff_t left_in_chunk = chunk;
  Real* chunk_activity = activity;
  auto chunk_end = [&] {
    if constexpr (Activity) {
      left_in_chunk -= L;
      if (left_in_chunk == 0) {
        raise<Real>(chunk_activity++, lane_max<Real>(vmax));
        vmax = I{};
        left_in_chunk = chunk;
      }
    }
  };
  const bool aligned = reinterpret_cast<std::uintptr_t>(z) % kVectorBytes == 0 &&
                       reinterpret_cast<std::uintptr_t>(zp) % kVectorBytes == 0 && w % L == 0;
  if (aligned && n >= L) {
    // Rows above and below enter only as up + dn (z[k ± w] in Σ_orth, z[k ± w ± 1] in Σ_diag), and
    // a shift of a sum is the sum of the shifts: Σ_diag = shifted-left(ud) + shifted-right(ud), two
    // shuffles where four would do the rows one by one.
    V mid0 = load(z - L), mid1 = load(z);
    V ud0 = load(z - w - L) + load(z + w - L), ud1 = load(z - w) + load(z + w);
    for (; k + L <= n; k += L) {
      __builtin_prefetch(z + k + w + STONESKIP_PF, 0, 3);
      __builtin_prefetch(zp + k + STONESKIP_PF, 1, 3);
      const V mid2 = load(z + k + L), ud2 = load(z + k - w + L) + load(z + k + w + L);
      const V zc = mid1;
      const V orth = (shift_in_left<Real>(mid0, mid1) + shift_in_right<Real>(mid1, mid2)) + ud1;
      V diag{};
      if constexpr (Diagonal) diag = shift_in_left<Real>(ud0, ud1) + shift_in_right<Real>(ud1, ud2);
      const V r = update<Real, V, Diagonal, Defect, increment_form>(zc, orth, diag, load(zp + k), wc, wo, wd, wp, wx);
      std::memcpy(zp + k, &r, sizeof r);
      if constexpr (Activity) {
        track<Real>(r, zc, vmax);
        chunk_end();
      }
      mid0 = mid1;
      mid1 = mid2;
      ud0 = ud1;
      ud1 = ud2;
    }
  } else {
    for (; k + L <= n; k += L) {
      __builtin_prefetch(z + k + w + STONESKIP_PF, 0, 3);
      __builtin_prefetch(zp + k + STONESKIP_PF, 1, 3);
      const V zc = load(z + k);
      const V orth = (load(z + k - 1) + load(z + k + 1)) + (load(z + k - w) + load(z + k + w));
      V diag{};
      if constexpr (Diagonal)
        diag = (load(z + k - w - 1) + load(z + k + w - 1)) + (load(z + k - w + 1) + load(z + k + w + 1));
      const V r = update<Real, V, Diagonal, Defect, increment_form>(zc, orth, diag, load(zp + k), wc, wo, wd, wp, wx);
      std::memcpy(zp + k, &r, sizeof r);
      if constexpr (Activity) {
        track<Real>(r, zc, vmax);
        chunk_end();
      }
    }
  }
  Int smax = 0;
  for (; k < n; ++k) {
    const Real zc = z[k];
    const Real orth = (z[k - 1] + z[k + 1]) + (z[k - w] + z[k + w]);
    Real diag = 0;
    if constexpr (Diagonal) diag = (z[k - w - 1] + z[k + w - 1]) + (z[k - w + 1] + z[k + w + 1]);
    const Real r = update<Real, Real, Diagonal, Defect, increment_form>(zc, orth, diag, zp[k], wc, wo, wd, wp, wx);
    zp[k] = r;
    if constexpr (Activity) {
      const Int sign = Int(1) << (8 * sizeof(Real) - 1);
      const Real d = r - zc;
      Int a, b;
      std::memcpy(&a, &r, sizeof a);
      std::memcpy(&b, &d, sizeof b);
      a &= ~sign;
      b &= ~sign;
      const Int ab = a > b ? a : b;
      smax = ab > smax ? ab : smax;
    }
  }
  if constexpr (Activity) {
    if (n % chunk != 0 || n % L != 0) {  // the last chunk is unfinished: its vectors and its tail
      const Int m = lane_max<Real>(vmax);
      raise<Real>(activity + (n - 1) / chunk, m > smax ? m : smax);
    }
  }
}

template <class Real, bool Diagonal, bool Defect>
[[gnu::always_inline]] inline void block_body(Real* zp, const Real* z, std::ptrdiff_t n, std::ptrdiff_t rows,
                                              std::ptrdiff_t w, const LeapfrogWeights<Real>& c) {
  for (std::ptrdiff_t r = 0; r < rows; ++r)
    row_body<Real, Diagonal, Defect, false>(zp + r * w, z + r * w, n, w, c, n, nullptr);
}

template <class Real, bool Diagonal, bool Defect>
[[gnu::always_inline]] inline void chunks_body(Real* zp, const Real* z, std::ptrdiff_t n, std::ptrdiff_t w,
                                               const LeapfrogWeights<Real>& c, std::ptrdiff_t chunk, Real* activity) {
  if (chunk % Simd<Real>::lanes == 0 || chunk >= n) {  // chunk boundaries fall between vectors
    row_body<Real, Diagonal, Defect, true>(zp, z, n, w, c, chunk, activity);
    return;
  }
  for (std::ptrdiff_t k0 = 0, q = 0; k0 < n; k0 += chunk, ++q) {
    const std::ptrdiff_t m = std::min(chunk, n - k0);
    row_body<Real, Diagonal, Defect, true>(zp + k0, z + k0, m, w, c, m, activity + q);
  }
}

// Calls f.operator()<Diagonal, Defect>() with the stencil's shape as compile-time flags.
template <class F>
[[gnu::always_inline]] inline void with_shape(bool diagonal, bool defect, F&& f) {
  if (diagonal)
    defect ? f.template operator()<true, true>() : f.template operator()<true, false>();
  else
    defect ? f.template operator()<false, true>() : f.template operator()<false, false>();
}

}  // namespace

#define STONESKIP_KERNEL_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))

STONESKIP_KERNEL_CLONES
void leapfrog_block(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                    const LeapfrogWeights<double>& c, bool diagonal) {
  with_shape(diagonal, c.defect != 0, [&]<bool D, bool X>() __attribute__((always_inline)) { block_body<double, D, X>(zp, z, n, rows, w, c); });
}

STONESKIP_KERNEL_CLONES
void leapfrog_block(float* zp, const float* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                    const LeapfrogWeights<float>& c, bool diagonal) {
  with_shape(diagonal, c.defect != 0, [&]<bool D, bool X>() __attribute__((always_inline)) { block_body<float, D, X>(zp, z, n, rows, w, c); });
}

STONESKIP_KERNEL_CLONES
void leapfrog_row_chunks(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t w, const LeapfrogWeights<double>& c,
                         bool diagonal, std::ptrdiff_t chunk, double* activity) {
  with_shape(diagonal, c.defect != 0, [&]<bool D, bool X>() __attribute__((always_inline)) { chunks_body<double, D, X>(zp, z, n, w, c, chunk, activity); });
}

STONESKIP_KERNEL_CLONES
void leapfrog_row_chunks(float* zp, const float* z, std::ptrdiff_t n, std::ptrdiff_t w, const LeapfrogWeights<float>& c,
                         bool diagonal, std::ptrdiff_t chunk, float* activity) {
  with_shape(diagonal, c.defect != 0, [&]<bool D, bool X>() __attribute__((always_inline)) { chunks_body<float, D, X>(zp, z, n, w, c, chunk, activity); });
}

const char* leapfrog_kernel_isa() {
  __builtin_cpu_init();
  if (__builtin_cpu_supports("x86-64-v4")) return "x86-64-v4";
  if (__builtin_cpu_supports("x86-64-v3")) return "x86-64-v3";
  return "baseline";
}

}  // namespace stoneskip
