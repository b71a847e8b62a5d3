#include "model/water/leapfrog_kernel.hpp"

#include <cstddef>
#include <cstdint>
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

template <class Real>
[[gnu::always_inline]] inline typename Simd<Real>::V vabs(typename Simd<Real>::V x) {
  using S = Simd<Real>;
  const typename S::I mask = (typename S::I{} + 1) << (8 * sizeof(Real) - 1);  // the sign bit
  return reinterpret_cast<typename S::V>(reinterpret_cast<typename S::I>(x) & ~mask);
}

// The update of spec §2.1 for one row segment; the scalar tail repeats the vector body's
// expression term for term so that both round identically. With `Activity`, the segment's
// largest max(|z⁺|, |z⁺ − z|) goes into vmax/smax and (value − value), 0 unless a value is not
// finite, into vnan/snan.
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

// The activity bookkeeping of one vector of results r over the old values zc.
template <class Real>
[[gnu::always_inline]] inline void track(typename Simd<Real>::V r, typename Simd<Real>::V zc, typename Simd<Real>::V& vmax,
                                         typename Simd<Real>::V& vnan) {
  using V = typename Simd<Real>::V;
  const V a = vabs<Real>(r), b = vabs<Real>(r - zc);
  const V ab = a <= b ? b : a;
  vmax = ab <= vmax ? vmax : ab;
  vnan = vnan + (ab - ab);  // stays 0 unless a value is inf or NaN
}

// The update of spec §2.1 for one row segment. Two vector paths compute the same expression from
// the same operands, so they round alike: where the segment, z⁻ and the row stride are aligned to
// a vector (the field's interior rows, tiles of a multiple of 8 cells), each row's vectors are
// loaded aligned once and the ±1 neighbours are shuffled out of adjacent vectors (an unaligned
// load straddles two cache lines, and a 9-point update needs six of them); elsewhere unaligned
// loads. The scalar tail repeats the expression term for term. With `Activity`, the segment's
// largest max(|z⁺|, |z⁺ − z|) goes into vmax/smax and (value − value), 0 unless a value is not
// finite, into vnan/snan.
template <class Real, bool Diagonal, bool Activity>
[[gnu::always_inline]] inline void row_body(Real* __restrict zp, const Real* __restrict z, std::ptrdiff_t n,
                                            std::ptrdiff_t w, const LeapfrogWeights<Real>& c, typename Simd<Real>::V& vmax,
                                            typename Simd<Real>::V& vnan, Real& smax, Real& snan) {
  using S = Simd<Real>;
  using V = typename S::V;
  constexpr std::ptrdiff_t L = S::lanes;
  const Real wc = c.centre, wo = c.orth, wd = c.diag, wp = c.previous;
  std::ptrdiff_t k = 0;
  const bool aligned = reinterpret_cast<std::uintptr_t>(z) % kVectorBytes == 0 &&
                       reinterpret_cast<std::uintptr_t>(zp) % kVectorBytes == 0 && w % L == 0;
  if (aligned && n >= L) {
    V up0 = load(z - w - L), up1 = load(z - w);
    V mid0 = load(z - L), mid1 = load(z);
    V dn0 = load(z + w - L), dn1 = load(z + w);
    for (; k + L <= n; k += L) {
      __builtin_prefetch(z + k + w + STONESKIP_PF, 0, 3);
      __builtin_prefetch(zp + k + STONESKIP_PF, 1, 3);
      const V mid2 = load(z + k + L), up2 = load(z + k - w + L), dn2 = load(z + k + w + L);
      const V zc = mid1;
      const V orth = (shift_in_left<Real>(mid0, mid1) + shift_in_right<Real>(mid1, mid2)) + (up1 + dn1);
      V r = wc * zc + wo * orth;
      if constexpr (Diagonal) {
        const V diag = (shift_in_left<Real>(up0, up1) + shift_in_right<Real>(up1, up2)) +
                       (shift_in_left<Real>(dn0, dn1) + shift_in_right<Real>(dn1, dn2));
        r = r + wd * diag;
      }
      r = r - wp * load(zp + k);
      std::memcpy(zp + k, &r, sizeof r);
      if constexpr (Activity) track<Real>(r, zc, vmax, vnan);
      up0 = up1;
      up1 = up2;
      mid0 = mid1;
      mid1 = mid2;
      dn0 = dn1;
      dn1 = dn2;
    }
  } else {
    for (; k + L <= n; k += L) {
      __builtin_prefetch(z + k + w + STONESKIP_PF, 0, 3);
      __builtin_prefetch(zp + k + STONESKIP_PF, 1, 3);
      const V zc = load(z + k);
      const V orth = (load(z + k - 1) + load(z + k + 1)) + (load(z + k - w) + load(z + k + w));
      V r = wc * zc + wo * orth;
      if constexpr (Diagonal) {
        const V diag = (load(z + k - w - 1) + load(z + k - w + 1)) + (load(z + k + w - 1) + load(z + k + w + 1));
        r = r + wd * diag;
      }
      r = r - wp * load(zp + k);
      std::memcpy(zp + k, &r, sizeof r);
      if constexpr (Activity) track<Real>(r, zc, vmax, vnan);
    }
  }
  for (; k < n; ++k) {
    const Real zc = z[k];
    const Real orth = (z[k - 1] + z[k + 1]) + (z[k - w] + z[k + w]);
    Real r = wc * zc + wo * orth;
    if constexpr (Diagonal) {
      const Real diag = (z[k - w - 1] + z[k - w + 1]) + (z[k + w - 1] + z[k + w + 1]);
      r = r + wd * diag;
    }
    r = r - wp * zp[k];
    zp[k] = r;
    if constexpr (Activity) {
      const Real a = r < 0 ? -r : r, d = r - zc, b = d < 0 ? -d : d;
      const Real ab = a <= b ? b : a;
      smax = ab <= smax ? smax : ab;
      snan = snan + (ab - ab);
    }
  }
}

template <class Real, bool Diagonal, bool Activity>
[[gnu::always_inline]] inline Real block_body(Real* zp, const Real* z, std::ptrdiff_t n, std::ptrdiff_t rows,
                                              std::ptrdiff_t w, const LeapfrogWeights<Real>& c) {
  using V = typename Simd<Real>::V;
  V vmax = V{} * 0, vnan = V{} * 0;
  Real smax = 0, snan = 0;
  for (std::ptrdiff_t r = 0; r < rows; ++r)
    row_body<Real, Diagonal, Activity>(zp + r * w, z + r * w, n, w, c, vmax, vnan, smax, snan);
  if constexpr (Activity) {
    for (int l = 0; l < Simd<Real>::lanes; ++l) {
      smax = vmax[l] <= smax ? smax : vmax[l];
      snan = snan + vnan[l];
    }
    return snan == 0 ? smax : snan - snan;  // NaN when anything was not finite
  }
  return 0;
}

template <class Real, bool Activity>
[[gnu::always_inline]] inline Real block_dispatch(Real* zp, const Real* z, std::ptrdiff_t n, std::ptrdiff_t rows,
                                                  std::ptrdiff_t w, const LeapfrogWeights<Real>& c, bool diagonal) {
  return diagonal ? block_body<Real, true, Activity>(zp, z, n, rows, w, c)
                  : block_body<Real, false, Activity>(zp, z, n, rows, w, c);
}

}  // namespace

#define STONESKIP_KERNEL_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))

STONESKIP_KERNEL_CLONES
void leapfrog_block(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                    const LeapfrogWeights<double>& c, bool diagonal) {
  block_dispatch<double, false>(zp, z, n, rows, w, c, diagonal);
}

STONESKIP_KERNEL_CLONES
void leapfrog_block(float* zp, const float* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                    const LeapfrogWeights<float>& c, bool diagonal) {
  block_dispatch<float, false>(zp, z, n, rows, w, c, diagonal);
}

STONESKIP_KERNEL_CLONES
double leapfrog_block_activity(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                               const LeapfrogWeights<double>& c, bool diagonal) {
  return block_dispatch<double, true>(zp, z, n, rows, w, c, diagonal);
}

STONESKIP_KERNEL_CLONES
float leapfrog_block_activity(float* zp, const float* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                              const LeapfrogWeights<float>& c, bool diagonal) {
  return block_dispatch<float, true>(zp, z, n, rows, w, c, diagonal);
}

const char* leapfrog_kernel_isa() {
  __builtin_cpu_init();
  if (__builtin_cpu_supports("x86-64-v4")) return "x86-64-v4";
  if (__builtin_cpu_supports("x86-64-v3")) return "x86-64-v3";
  return "baseline";
}

}  // namespace stoneskip
