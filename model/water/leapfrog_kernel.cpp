#include "model/water/leapfrog_kernel.hpp"

#include <cstdint>
#include <cstring>
#include <type_traits>

// 64-byte vectors are passed between always-inline helpers only; GCC's note about the ABI of
// such values in non-AVX-512 code does not apply to anything that crosses a call.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace stoneskip {
namespace {

constexpr int kVectorBytes = 64;

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
template <class Real, bool Diagonal, bool Activity>
[[gnu::always_inline]] inline void row_body(Real* __restrict zp, const Real* __restrict z, std::ptrdiff_t n,
                                            std::ptrdiff_t w, const LeapfrogWeights<Real>& c, typename Simd<Real>::V& vmax,
                                            typename Simd<Real>::V& vnan, Real& smax, Real& snan) {
  using S = Simd<Real>;
  using V = typename S::V;
  const Real wc = c.centre, wo = c.orth, wd = c.diag, wp = c.previous;
  std::ptrdiff_t k = 0;
  for (; k + S::lanes <= n; k += S::lanes) {
    const V zc = load(z + k);
    const V orth = (load(z + k - 1) + load(z + k + 1)) + (load(z + k - w) + load(z + k + w));
    V r = wc * zc + wo * orth;
    if constexpr (Diagonal) {
      const V diag = (load(z + k - w - 1) + load(z + k - w + 1)) + (load(z + k + w - 1) + load(z + k + w + 1));
      r = r + wd * diag;
    }
    r = r - wp * load(zp + k);
    std::memcpy(zp + k, &r, sizeof r);
    if constexpr (Activity) {
      const V a = vabs<Real>(r), b = vabs<Real>(r - zc);
      const V ab = a <= b ? b : a;
      vmax = ab <= vmax ? vmax : ab;
      vnan = vnan + (ab - ab);
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
