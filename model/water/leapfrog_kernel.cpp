#include "model/water/leapfrog_kernel.hpp"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <algorithm>
#include <cstring>
#include <type_traits>
#include <utility>

// Vectors wider than the baseline are passed between always-inline helpers only; GCC's note about
// the ABI of such values does not apply to anything that crosses a call.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace stoneskip {
namespace {

// Software prefetch distance in values: 1 KB (double) ahead of the row being read and written.
// Measured: +10–20 % in cache at 500², a few % from memory at 2048² (the hardware prefetchers do
// most of it).
#define STONESKIP_PF 128

// Vectors of `Bytes` bytes (16, 32 or 64); Bytes = 0 is the scalar path (no vector type is used).
template <class Real, int Bytes>
struct Simd {
  static constexpr int bytes = Bytes > 0 ? Bytes : 16;
  typedef Real V __attribute__((vector_size(bytes)));
  using Int = std::conditional_t<std::is_same_v<Real, double>, std::int64_t, std::int32_t>;
  typedef Int I __attribute__((vector_size(bytes)));
  static constexpr int lanes = bytes / sizeof(Real);
};

template <class V, class Real>
[[gnu::always_inline]] inline V load(const Real* p) {
  V v;
  std::memcpy(&v, p, sizeof v);  // an unaligned vector load
  return v;
}

// The shuffle mask {first, first + 1, …} of a vector of L lanes, and {k ^ h}.
template <class I, long First, std::size_t... k>
[[gnu::always_inline]] inline I iota_mask(std::index_sequence<k...>) {
  return I{static_cast<decltype(I{}[0])>(First + static_cast<long>(k))...};
}
template <class I, long H, std::size_t... k>
[[gnu::always_inline]] inline I xor_mask(std::index_sequence<k...>) {
  return I{static_cast<decltype(I{}[0])>(static_cast<long>(k) ^ H)...};
}

// z[k − 1] and z[k + 1] of an aligned vector z[k] from its aligned neighbours z[k − L], z[k + L].
template <class S>
[[gnu::always_inline]] inline typename S::V shift_in_left(typename S::V prev, typename S::V cur) {
  return __builtin_shuffle(prev, cur, iota_mask<typename S::I, S::lanes - 1>(std::make_index_sequence<S::lanes>()));
}
template <class S>
[[gnu::always_inline]] inline typename S::V shift_in_right(typename S::V cur, typename S::V next) {
  return __builtin_shuffle(cur, next, iota_mask<typename S::I, 1>(std::make_index_sequence<S::lanes>()));
}

// v[k − 1] + v[k + 1] over a stream of aligned vectors …, prev, cur, next, … (shifted-left plus
// shifted-right, the order of the scalar expression). With 32-byte vectors (AVX2) a shift across
// two vectors is two shuffles, a lane-crossing one that builds the straddling vector
// [prev's upper half, cur's lower half] and an in-lane one; the straddling vector of (cur, next)
// is also the one of the next vector's left shift, so a stream carries it (`Sides::m`) and
// pays three shuffles per vector, not four. Other widths shift in one shuffle and carry nothing.
template <class S>
struct Sides {
  using V = typename S::V;
  using I = typename S::I;
  static constexpr bool kCarry = S::bytes == 32;
  static constexpr int L = S::lanes, H = L / 2;
  V m{};  // the straddling vector of (prev, cur) when kCarry

  [[gnu::always_inline]] static V straddle(V a, V b) {
    return __builtin_shuffle(a, b, iota_mask<I, H>(std::make_index_sequence<L>()));
  }
  // Before the first vector: the stream's first two vectors.
  [[gnu::always_inline]] void start(V prev, V cur) {
    if constexpr (kCarry) m = straddle(prev, cur);
  }
  // The sum for `cur`, then the stream moves on by one vector.
  [[gnu::always_inline]] V sum(V prev, V cur, V next) {
    if constexpr (kCarry) {
      const V mn = straddle(cur, next);
      // Lane i of the left shift is prev[L − 1] (m[H − 1]) at i = 0, cur[H − 1] (m[L − 1]) at
      // i = H, else cur[i − 1]; of the right shift cur[H] (mn[0]) at i = H − 1, next[0] (mn[H]) at
      // i = L − 1, else cur[i + 1]: each lane taken from within its own 128-bit half.
      const V left = __builtin_shuffle(m, cur, mask([](int i) { return i == 0 ? H - 1 : i == H ? L - 1 : L + i - 1; }));
      const V right = __builtin_shuffle(cur, mn, mask([](int i) { return i == H - 1 ? L : i == L - 1 ? L + H : i + 1; }));
      m = mn;
      return left + right;
    } else {
      return shift_in_left<S>(prev, cur) + shift_in_right<S>(cur, next);
    }
  }

 private:
  template <class F>
  [[gnu::always_inline]] static I mask(F lane) {
    return [&]<std::size_t... k>(std::index_sequence<k...>) __attribute__((always_inline)) {
      return I{static_cast<decltype(I{}[0])>(lane(static_cast<int>(k)))...};
    }(std::make_index_sequence<L>());
  }
};

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

// The column form of the float64 update with corners (leapfrog_kernel.hpp): the column value
// q = wd·ud + wo·z of a cell, ud = z[k − w] + z[k + w] its column's sum above and below, and the
// update from q[k − 1] + q[k + 1] (`sides`), on a vector or a scalar alike.
template <class Real, class T>
[[gnu::always_inline]] inline T column(T ud, T zc, Real wo, Real wd) {
  return wd * ud + wo * zc;
}
template <class Real, class T>
[[gnu::always_inline]] inline T column_update(T sides, T ud, T zc, T zm, Real wc, Real wo, Real wp) {
  return ((sides + wo * ud) + wc * zc) - wp * zm;
}
// Whether a path evaluates the column form: float64 with corners (the float32 increment form and
// the five-point stencils keep the form of update()).
template <class Real, bool Diagonal>
inline constexpr bool kColumnForm = std::is_same_v<Real, double> && Diagonal;

// The activity of one vector of results r over the old values zc: the bit patterns of |r| and
// |r − zc| (sign cleared), whose integer order is the numbers' order with NaN above ∞ above all.
template <class S>
[[gnu::always_inline]] inline void track(typename S::V r, typename S::V zc, typename S::I& vmax) {
  using I = typename S::I;
  const I sign = (I{} + 1) << (8 * sizeof(typename S::Int) - 1);
  const I a = reinterpret_cast<I>(r) & ~sign, b = reinterpret_cast<I>(r - zc) & ~sign;
  const I ab = a > b ? a : b;
  vmax = ab > vmax ? ab : vmax;
}

// The largest lane, by halving shuffles.
template <class S>
[[gnu::always_inline]] inline typename S::Int lane_max(typename S::I v) {
  using I = typename S::I;
  auto fold = [&]<long H>() __attribute__((always_inline)) {
    if constexpr (H >= 1 && H < S::lanes) {
      const I u = __builtin_shuffle(v, xor_mask<I, H>(std::make_index_sequence<S::lanes>()));
      v = v > u ? v : u;
    }
  };
  fold.template operator()<8>();
  fold.template operator()<4>();
  fold.template operator()<2>();
  fold.template operator()<1>();
  return v[0];
}

// activity[q] = max(activity[q], the value whose bit pattern is m).
template <class Real, class Int>
[[gnu::always_inline]] inline void raise(Real* activity, Int m) {
  Int old;
  std::memcpy(&old, activity, sizeof old);
  old &= ~(Int(1) << (8 * sizeof(Real) - 1));  // a start of −0 reads as 0
  if (m > old) std::memcpy(activity, &m, sizeof m);
}

// The update of model/README.md §2.1 for one row segment, with vectors of `Bytes` bytes (none
// when 0). Two vector paths compute the same expression from the same operands, so they round
// alike: where the segment, z⁻ and the row stride are aligned to a vector (the field's interior
// rows, tiles of a multiple of 8 cells), each row's vectors are loaded aligned once and the ±1
// neighbours are shuffled out of adjacent vectors (an unaligned load straddles two cache lines,
// and a 9-point update needs six of them); elsewhere unaligned loads. The scalar tail repeats the
// expression term for term. With `Activity`, the segment is made of chunks of `chunk` cells, a
// multiple of the vector length (or the whole segment), and the bit pattern of each chunk's
// largest max(|z⁺|, |z⁺ − z|) raises activity[chunk index].
template <int Bytes, class Real, bool Diagonal, bool Defect, bool Activity>
[[gnu::always_inline]] inline void row_body(Real* __restrict zp, const Real* __restrict z, std::ptrdiff_t n,
                                            std::ptrdiff_t w, const LeapfrogWeights<Real>& c, std::ptrdiff_t chunk,
                                            Real* activity) {
  using S = Simd<Real, Bytes>;
  using V = typename S::V;
  using I = typename S::I;
  using Int = typename S::Int;
  constexpr std::ptrdiff_t L = S::lanes;
  const Real wc = c.centre, wo = c.orth, wd = c.diag, wp = c.previous, wx = c.defect;
  constexpr bool increment_form = std::is_same_v<Real, float>;  // see leapfrog_kernel.hpp
  std::ptrdiff_t k = 0;
  I vmax{};
  if constexpr (Bytes > 0) {
    // After each vector: hand a finished chunk's maximum over (a countdown, not a division).
    std::ptrdiff_t left_in_chunk = chunk;
    Real* chunk_activity = activity;
    auto chunk_end = [&] {
      if constexpr (Activity) {
        left_in_chunk -= L;
        if (left_in_chunk == 0) {
          raise<Real, Int>(chunk_activity++, lane_max<S>(vmax));
          vmax = I{};
          left_in_chunk = chunk;
        }
      }
    };
    const bool aligned = reinterpret_cast<std::uintptr_t>(z) % Bytes == 0 &&
                         reinterpret_cast<std::uintptr_t>(zp) % Bytes == 0 && w % L == 0;
    if (aligned && n >= L) {
      // Rows above and below enter only as up + dn (z[k ± w] in Σ_orth, z[k ± w ± 1] in Σ_diag), and
      // a shift of a sum is the sum of the shifts: Σ_diag = shifted-left(ud) + shifted-right(ud), two
      // shuffles where four would do the rows one by one.
      V mid0 = load<V>(z - L), mid1 = load<V>(z);
      V ud0 = load<V>(z - w - L) + load<V>(z + w - L), ud1 = load<V>(z - w) + load<V>(z + w);
      // The column form shifts one stream (q), the other form two (the row and ud).
      V q0{}, q1{};
      Sides<S> mid_sides, ud_sides;
      if constexpr (kColumnForm<Real, Diagonal>) {
        q0 = column<Real>(ud0, mid0, wo, wd);
        q1 = column<Real>(ud1, mid1, wo, wd);
        mid_sides.start(q0, q1);
      } else {
        mid_sides.start(mid0, mid1);
        ud_sides.start(ud0, ud1);
      }
      for (; k + L <= n; k += L) {
        __builtin_prefetch(z + k + w + STONESKIP_PF, 0, 3);
        __builtin_prefetch(zp + k + STONESKIP_PF, 1, 3);
        const V mid2 = load<V>(z + k + L), ud2 = load<V>(z + k - w + L) + load<V>(z + k + w + L);
        const V zc = mid1;
        V r;
        if constexpr (kColumnForm<Real, Diagonal>) {
          const V q2 = column<Real>(ud2, mid2, wo, wd);
          r = column_update<Real>(mid_sides.sum(q0, q1, q2), ud1, zc, load<V>(zp + k), wc, wo, wp);
          q0 = q1;
          q1 = q2;
        } else {
          const V orth = mid_sides.sum(mid0, mid1, mid2) + ud1;
          V diag{};
          if constexpr (Diagonal) diag = ud_sides.sum(ud0, ud1, ud2);
          r = update<Real, V, Diagonal, Defect, increment_form>(zc, orth, diag, load<V>(zp + k), wc, wo, wd, wp, wx);
        }
        std::memcpy(zp + k, &r, sizeof r);
        if constexpr (Activity) {
          track<S>(r, zc, vmax);
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
        const V zc = load<V>(z + k);
        V r;
        if constexpr (kColumnForm<Real, Diagonal>) {
          const V ql = column<Real>(load<V>(z + k - w - 1) + load<V>(z + k + w - 1), load<V>(z + k - 1), wo, wd);
          const V qr = column<Real>(load<V>(z + k - w + 1) + load<V>(z + k + w + 1), load<V>(z + k + 1), wo, wd);
          r = column_update<Real>(ql + qr, load<V>(z + k - w) + load<V>(z + k + w), zc, load<V>(zp + k), wc, wo, wp);
        } else {
          const V orth = (load<V>(z + k - 1) + load<V>(z + k + 1)) + (load<V>(z + k - w) + load<V>(z + k + w));
          V diag{};
          if constexpr (Diagonal)
            diag = (load<V>(z + k - w - 1) + load<V>(z + k + w - 1)) + (load<V>(z + k - w + 1) + load<V>(z + k + w + 1));
          r = update<Real, V, Diagonal, Defect, increment_form>(zc, orth, diag, load<V>(zp + k), wc, wo, wd, wp, wx);
        }
        std::memcpy(zp + k, &r, sizeof r);
        if constexpr (Activity) {
          track<S>(r, zc, vmax);
          chunk_end();
        }
      }
    }
  }
  Int smax = 0;
  for (; k < n; ++k) {
    const Real zc = z[k];
    Real r;
    if constexpr (kColumnForm<Real, Diagonal>) {
      const Real ql = column<Real>(z[k - w - 1] + z[k + w - 1], z[k - 1], wo, wd);
      const Real qr = column<Real>(z[k - w + 1] + z[k + w + 1], z[k + 1], wo, wd);
      r = column_update<Real>(ql + qr, z[k - w] + z[k + w], zc, zp[k], wc, wo, wp);
    } else {
      const Real orth = (z[k - 1] + z[k + 1]) + (z[k - w] + z[k + w]);
      Real diag = 0;
      if constexpr (Diagonal) diag = (z[k - w - 1] + z[k + w - 1]) + (z[k - w + 1] + z[k + w + 1]);
      r = update<Real, Real, Diagonal, Defect, increment_form>(zc, orth, diag, zp[k], wc, wo, wd, wp, wx);
    }
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
    if constexpr (Bytes > 0) {
      if (n % chunk != 0 || n % L != 0) {  // the last chunk is unfinished: its vectors and its tail
        const Int m = lane_max<S>(vmax);
        raise<Real, Int>(activity + (n - 1) / chunk, m > smax ? m : smax);
      }
    } else {
      raise<Real, Int>(activity, smax);  // the scalar path is called chunk by chunk
    }
  }
}

// Rows j and j + 1 together (vectors of `Bytes` bytes > 0): each of the two rows is loaded once
// and serves as the middle row of one update and the row above or below of the other, and the ±1
// neighbours of the middle rows are unaligned loads (no shuffles). The sums above and below,
// ud = z[k − w] + z[k + w], enter Σ_orth as they are and Σ_diag shifted by ±1: with `ShuffleUd` (z,
// zp and w aligned to a vector) they are shifted out of adjacent ud vectors (two shuffles, one
// addition fewer), otherwise the corners are loaded and added like the scalar tail. In the column
// form (float64 with corners) the column values q = wd·ud + wo·z of each row are what is shifted
// (with `ShuffleUd`: no ±1 loads at all) or loaded at k ± 1. Either way every cell's operands and
// the order of its operations are the scalar expression's.
template <int Bytes, class Real, bool Diagonal, bool Defect, bool ShuffleUd>
[[gnu::always_inline]] inline void row_pair_body(Real* __restrict zp, const Real* __restrict z, std::ptrdiff_t n,
                                                 std::ptrdiff_t w, const LeapfrogWeights<Real>& c) {
  using S = Simd<Real, Bytes>;
  using V = typename S::V;
  constexpr std::ptrdiff_t L = S::lanes;
  const Real wc = c.centre, wo = c.orth, wd = c.diag, wp = c.previous, wx = c.defect;
  constexpr bool increment_form = std::is_same_v<Real, float>;
  const Real* a = z;      // row j
  const Real* b = z + w;  // row j + 1
  Real* pa = zp;
  Real* pb = zp + w;
  std::ptrdiff_t k = 0;
  if constexpr (ShuffleUd) {
    V ac = load<V>(a), bc = load<V>(b);
    V uda0 = load<V>(a - w - L) + load<V>(b - L), uda1 = load<V>(a - w) + bc;
    V udb0 = load<V>(a - L) + load<V>(b + w - L), udb1 = ac + load<V>(b + w);
    // The column form shifts the column values q of each row (and loads no ±1 neighbours).
    V qa0{}, qa1{}, qb0{}, qb1{};
    Sides<S> sides_a, sides_b;
    if constexpr (kColumnForm<Real, Diagonal>) {
      qa0 = column<Real>(uda0, load<V>(a - L), wo, wd);
      qa1 = column<Real>(uda1, ac, wo, wd);
      qb0 = column<Real>(udb0, load<V>(b - L), wo, wd);
      qb1 = column<Real>(udb1, bc, wo, wd);
      sides_a.start(qa0, qa1);
      sides_b.start(qb0, qb1);
    } else {
      sides_a.start(uda0, uda1);
      sides_b.start(udb0, udb1);
    }
    auto step = [&](std::ptrdiff_t j) __attribute__((always_inline)) {
      const V an = load<V>(a + j + L), bn = load<V>(b + j + L);
      const V uda2 = load<V>(a - w + j + L) + bn, udb2 = an + load<V>(b + w + j + L);
      V ra, rb;
      if constexpr (kColumnForm<Real, Diagonal>) {
        const V qa2 = column<Real>(uda2, an, wo, wd), qb2 = column<Real>(udb2, bn, wo, wd);
        ra = column_update<Real>(sides_a.sum(qa0, qa1, qa2), uda1, ac, load<V>(pa + j), wc, wo, wp);
        rb = column_update<Real>(sides_b.sum(qb0, qb1, qb2), udb1, bc, load<V>(pb + j), wc, wo, wp);
        qa0 = qa1;
        qa1 = qa2;
        qb0 = qb1;
        qb1 = qb2;
      } else {
        const V orth_a = (load<V>(a + j - 1) + load<V>(a + j + 1)) + uda1;
        const V orth_b = (load<V>(b + j - 1) + load<V>(b + j + 1)) + udb1;
        V diag_a{}, diag_b{};
        if constexpr (Diagonal) {
          diag_a = sides_a.sum(uda0, uda1, uda2);
          diag_b = sides_b.sum(udb0, udb1, udb2);
        }
        ra = update<Real, V, Diagonal, Defect, increment_form>(ac, orth_a, diag_a, load<V>(pa + j), wc, wo, wd, wp, wx);
        rb = update<Real, V, Diagonal, Defect, increment_form>(bc, orth_b, diag_b, load<V>(pb + j), wc, wo, wd, wp, wx);
      }
      std::memcpy(pa + j, &ra, sizeof ra);
      std::memcpy(pb + j, &rb, sizeof rb);
      ac = an;
      bc = bn;
      uda0 = uda1;
      uda1 = uda2;
      udb0 = udb1;
      udb1 = udb2;
    };
    // Two vectors a trip and one prefetch per stream a trip, not one per vector (with AVX2 and
    // double a trip is one 64-byte line of each stream; measured at 500² float64, AVX2: +2–3 %).
    constexpr std::ptrdiff_t T = 2;
    for (; k + T * L <= n; k += T * L) {
      __builtin_prefetch(b + k + 2 * w + STONESKIP_PF, 0, 3);
      __builtin_prefetch(pa + k + STONESKIP_PF, 1, 3);
      __builtin_prefetch(pb + k + STONESKIP_PF, 1, 3);
      for (std::ptrdiff_t t = 0; t < T; ++t) step(k + t * L);
    }
    for (; k + L <= n; k += L) step(k);
  } else {
    for (; k + L <= n; k += L) {
      __builtin_prefetch(b + k + 2 * w + STONESKIP_PF, 0, 3);
      __builtin_prefetch(pa + k + STONESKIP_PF, 1, 3);
      __builtin_prefetch(pb + k + STONESKIP_PF, 1, 3);
      const V al = load<V>(a + k - 1), ac = load<V>(a + k), ar = load<V>(a + k + 1);
      const V bl = load<V>(b + k - 1), bc = load<V>(b + k), br = load<V>(b + k + 1);
      if constexpr (kColumnForm<Real, Diagonal>) {
        const V qal = column<Real>(load<V>(a - w + k - 1) + bl, al, wo, wd);
        const V qar = column<Real>(load<V>(a - w + k + 1) + br, ar, wo, wd);
        const V qbl = column<Real>(al + load<V>(b + w + k - 1), bl, wo, wd);
        const V qbr = column<Real>(ar + load<V>(b + w + k + 1), br, wo, wd);
        const V ra = column_update<Real>(qal + qar, load<V>(a - w + k) + bc, ac, load<V>(pa + k), wc, wo, wp);
        const V rb = column_update<Real>(qbl + qbr, ac + load<V>(b + w + k), bc, load<V>(pb + k), wc, wo, wp);
        std::memcpy(pa + k, &ra, sizeof ra);
        std::memcpy(pb + k, &rb, sizeof rb);
        continue;
      }
      const V orth_a = (al + ar) + (load<V>(a - w + k) + bc);
      const V orth_b = (bl + br) + (ac + load<V>(b + w + k));
      V diag_a{}, diag_b{};
      if constexpr (Diagonal) {
        diag_a = (load<V>(a - w + k - 1) + bl) + (load<V>(a - w + k + 1) + br);
        diag_b = (al + load<V>(b + w + k - 1)) + (ar + load<V>(b + w + k + 1));
      }
      const V ra = update<Real, V, Diagonal, Defect, increment_form>(ac, orth_a, diag_a, load<V>(pa + k), wc, wo, wd, wp, wx);
      const V rb = update<Real, V, Diagonal, Defect, increment_form>(bc, orth_b, diag_b, load<V>(pb + k), wc, wo, wd, wp, wx);
      std::memcpy(pa + k, &ra, sizeof ra);
      std::memcpy(pb + k, &rb, sizeof rb);
    }
  }
  if (k < n) {  // the scalar tails of both rows
    row_body<0, Real, Diagonal, Defect, false>(pa + k, a + k, n - k, w, c, n - k, nullptr);
    row_body<0, Real, Diagonal, Defect, false>(pb + k, b + k, n - k, w, c, n - k, nullptr);
  }
}

template <int Bytes, class Real, bool Diagonal, bool Defect>
[[gnu::always_inline]] inline void block_body(Real* zp, const Real* z, std::ptrdiff_t n, std::ptrdiff_t rows,
                                              std::ptrdiff_t w, const LeapfrogWeights<Real>& c) {
  std::ptrdiff_t r = 0;
  // Pairs pay in cache, L2 or L3 (the wavefront's blocks of two rows; 500² float64, 2 MB a
  // level, AVX2: 1.9e9 against 1.7e9 cells/s); from memory they were slower than single rows
  // (2048² float64, AVX2, loaded machine: 1.1e9 against 1.5e9 cells/s).
  constexpr std::ptrdiff_t kPairsUpToBytes = 8 << 20;
  if constexpr (Bytes > 0) {
    constexpr std::ptrdiff_t L = Simd<Real, Bytes>::lanes;
    const bool aligned = reinterpret_cast<std::uintptr_t>(z) % Bytes == 0 &&
                         reinterpret_cast<std::uintptr_t>(zp) % Bytes == 0 && w % L == 0;
    if (rows * w * static_cast<std::ptrdiff_t>(sizeof(Real)) <= kPairsUpToBytes)
      for (; r + 2 <= rows; r += 2) {
        if (aligned)
          row_pair_body<Bytes, Real, Diagonal, Defect, true>(zp + r * w, z + r * w, n, w, c);
        else
          row_pair_body<Bytes, Real, Diagonal, Defect, false>(zp + r * w, z + r * w, n, w, c);
      }
  }
  for (; r < rows; ++r)
    row_body<Bytes, Real, Diagonal, Defect, false>(zp + r * w, z + r * w, n, w, c, n, nullptr);
}

template <int Bytes, class Real, bool Diagonal, bool Defect>
[[gnu::always_inline]] inline void chunks_body(Real* zp, const Real* z, std::ptrdiff_t n, std::ptrdiff_t w,
                                               const LeapfrogWeights<Real>& c, std::ptrdiff_t chunk, Real* activity) {
  if (Bytes > 0 && (chunk % Simd<Real, Bytes>::lanes == 0 || chunk >= n)) {  // chunk boundaries fall between vectors
    row_body<Bytes, Real, Diagonal, Defect, true>(zp, z, n, w, c, chunk, activity);
    return;
  }
  for (std::ptrdiff_t k0 = 0, q = 0; k0 < n; k0 += chunk, ++q) {
    const std::ptrdiff_t m = std::min(chunk, n - k0);
    row_body<Bytes, Real, Diagonal, Defect, true>(zp + k0, z + k0, m, w, c, m, activity + q);
  }
}

// Calls FN<BYTES, REAL, Diagonal, Defect>(ARGS...) with the stencil's shape as compile-time flags
// (a macro, not a helper taking a lambda: a lambda defined under a target pragma could not be
// inlined into a helper compiled without it).
#define STONESKIP_WITH_SHAPE(FN, BYTES, REAL, ...)                 \
  do {                                                           \
    if (diagonal) {                                              \
      if (c.defect != 0) FN<BYTES, REAL, true, true>(__VA_ARGS__);   \
      else FN<BYTES, REAL, true, false>(__VA_ARGS__);                \
    } else {                                                     \
      if (c.defect != 0) FN<BYTES, REAL, false, true>(__VA_ARGS__);  \
      else FN<BYTES, REAL, false, false>(__VA_ARGS__);               \
    }                                                            \
  } while (false)

// One path's entry points.
struct KernelPath {
  SimdPath path;
  void (*block_d)(double*, const double*, std::ptrdiff_t, std::ptrdiff_t, std::ptrdiff_t, const LeapfrogWeights<double>&, bool);
  void (*block_f)(float*, const float*, std::ptrdiff_t, std::ptrdiff_t, std::ptrdiff_t, const LeapfrogWeights<float>&, bool);
  void (*chunks_d)(double*, const double*, std::ptrdiff_t, std::ptrdiff_t, const LeapfrogWeights<double>&, bool,
                   std::ptrdiff_t, double*);
  void (*chunks_f)(float*, const float*, std::ptrdiff_t, std::ptrdiff_t, const LeapfrogWeights<float>&, bool,
                   std::ptrdiff_t, float*);
};

}  // namespace

// The four entry points of one path, compiled for its instruction set (the pragma before the
// expansion); NAME is the path's namespace, BYTES its vector width.
#define STONESKIP_KERNEL_PATH(NAME, BYTES)                                                                           \
  namespace NAME {                                                                                                   \
  void block_d(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,                \
               const LeapfrogWeights<double>& c, bool diagonal) {                                                    \
        STONESKIP_WITH_SHAPE(block_body, BYTES, double, zp, z, n, rows, w, c);                                           \
  }                                                                                                                  \
  void block_f(float* zp, const float* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,                  \
               const LeapfrogWeights<float>& c, bool diagonal) {                                                     \
        STONESKIP_WITH_SHAPE(block_body, BYTES, float, zp, z, n, rows, w, c);                                            \
  }                                                                                                                  \
  void chunks_d(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t w, const LeapfrogWeights<double>& c, \
                bool diagonal, std::ptrdiff_t chunk, double* activity) {                                             \
        STONESKIP_WITH_SHAPE(chunks_body, BYTES, double, zp, z, n, w, c, chunk, activity);                               \
  }                                                                                                                  \
  void chunks_f(float* zp, const float* z, std::ptrdiff_t n, std::ptrdiff_t w, const LeapfrogWeights<float>& c,    \
                bool diagonal, std::ptrdiff_t chunk, float* activity) {                                              \
        STONESKIP_WITH_SHAPE(chunks_body, BYTES, float, zp, z, n, w, c, chunk, activity);                                \
  }                                                                                                                  \
  }

namespace kernel_paths {
// The scalar path: the scalar tail alone, kept scalar (no auto-vectorisation), the reference of
// the others.
#pragma GCC push_options
#pragma GCC optimize("no-tree-vectorize")
STONESKIP_KERNEL_PATH(scalar, 0)
#pragma GCC pop_options
// The vector paths use GCC's vector extensions (__builtin_shuffle, ?: on vectors), which clang
// does not have: a clang build (the libFuzzer targets, tools/README.md) has the scalar path alone,
// whose results every other path's equal bit for bit (leapfrog_kernel.hpp), at a scalar speed.
#if defined(__clang__)
#define STONESKIP_VECTOR_PATHS 0
#else
#define STONESKIP_VECTOR_PATHS 1
#endif
#if STONESKIP_VECTOR_PATHS && defined(__x86_64__)
// SSE2 is the x86-64 baseline.
STONESKIP_KERNEL_PATH(sse2, 16)
#pragma GCC push_options
#pragma GCC target("arch=x86-64-v3")
STONESKIP_KERNEL_PATH(avx2, 32)
#pragma GCC pop_options
#pragma GCC push_options
#pragma GCC target("arch=x86-64-v4")
STONESKIP_KERNEL_PATH(avx512, 64)
#pragma GCC pop_options
#elif STONESKIP_VECTOR_PATHS && defined(__aarch64__)
// NEON (Advanced SIMD) is the aarch64 baseline.
STONESKIP_KERNEL_PATH(neon, 16)
#endif
}  // namespace kernel_paths

namespace {

#define STONESKIP_PATH_ENTRY(P, NAME) \
  KernelPath{P, kernel_paths::NAME::block_d, kernel_paths::NAME::block_f, kernel_paths::NAME::chunks_d, kernel_paths::NAME::chunks_f}

const KernelPath kPaths[] = {
    STONESKIP_PATH_ENTRY(SimdPath::scalar, scalar),
#if STONESKIP_VECTOR_PATHS && defined(__x86_64__)
    STONESKIP_PATH_ENTRY(SimdPath::sse2, sse2),
    STONESKIP_PATH_ENTRY(SimdPath::avx2, avx2),
    STONESKIP_PATH_ENTRY(SimdPath::avx512, avx512),
#elif STONESKIP_VECTOR_PATHS && defined(__aarch64__)
    STONESKIP_PATH_ENTRY(SimdPath::neon, neon),
#endif
};

bool cpu_supports(SimdPath p) {
  switch (p) {
    case SimdPath::scalar:
      return true;
#if STONESKIP_VECTOR_PATHS && defined(__x86_64__)
    case SimdPath::sse2:
      return true;
    case SimdPath::avx2:
      __builtin_cpu_init();
      return __builtin_cpu_supports("x86-64-v3");
    case SimdPath::avx512:
      __builtin_cpu_init();
      return __builtin_cpu_supports("x86-64-v4");
#elif STONESKIP_VECTOR_PATHS && defined(__aarch64__)
    case SimdPath::neon:
      return true;
#endif
    default:
      return false;
  }
}

const KernelPath* find_path(SimdPath p) {
  for (const KernelPath& k : kPaths)
    if (k.path == p) return cpu_supports(p) ? &k : nullptr;
  return nullptr;
}

const KernelPath* initial_path() {
  SimdPath p;
  if (!simd_path_from_environment(p)) p = supported_simd_paths().back();
  return find_path(p);
}

std::atomic<const KernelPath*>& active_slot() {
  static std::atomic<const KernelPath*> slot{initial_path()};
  return slot;
}

const KernelPath& active() { return *active_slot().load(std::memory_order_relaxed); }

// The wavefront of leapfrog_wavefront (see the header), two rows at a time so that the kernel
// can share their loads. Rows are grouped in pairs {2m, 2m + 1} (m may be negative: halo rows).
// In a pass of P levels, level s ∈ [1, P] computes the rows [lo_s, hi_s): the block, or with a
// halo the block widened by P − s rows on each side. At front i, stage s computes pair i − s + 1 of
// level s from level s − 1 (in the buffer that did not receive level s − 1) into the buffer that
// held level s − 2. It reads pairs i − s … i − s + 2 of level s − 1: the first two were done at
// earlier fronts, the third at this front's stage s − 1 (or lies outside level s − 1's rows, which
// contain level s's rows ± 1). The rows of level s − 2 it overwrites were last read by those same
// three pairs of level s − 1, all done. So the order computes what P whole sweeps do, cell for cell.
template <class Real, class Block>
void wavefront(Real* z, Real* zp, std::ptrdiff_t rows, std::ptrdiff_t w, int steps, const WavefrontHooks<Real>& hooks,
               Block&& block) {
  if (steps <= 0 || rows <= 0) return;
  const int depth = std::max(1, std::min(wavefront_depth(w * static_cast<std::ptrdiff_t>(sizeof(Real))),
                                         hooks.halo_rows > 0 ? hooks.halo_rows : 1 << 20));
  auto floor_half = [](std::ptrdiff_t r) { return r >= 0 ? r / 2 : -((1 - r) / 2); };
  Real* a = z;
  Real* b = zp;
  for (int done = 0; done < steps;) {
    // The steps left in passes of at most `depth` levels, as even as they go (16 steps at depth 13:
    // 8 + 8, not 13 + 3, whose short pass reuses little of what it brings in).
    const int left = steps - done, passes = (left + depth - 1) / depth;
    const int pass = (left + passes - 1) / passes;
    const std::ptrdiff_t widen = hooks.halo_rows > 0 ? pass - 1 : 0;  // level 1's extra rows on each side
    if (hooks.before_pass) hooks.before_pass(hooks.context, a, b, pass);
    const std::ptrdiff_t m_first = floor_half(-widen), m_last = floor_half(rows - 1 + widen);
    for (std::ptrdiff_t i = m_first; i <= m_last + pass - 1; ++i)
      for (int s = 1; s <= pass; ++s) {
        const std::ptrdiff_t m = i - s + 1;
        if (m < m_first) break;  // and so for every later stage
        const std::ptrdiff_t extra = hooks.halo_rows > 0 ? widen - (s - 1) : 0;  // level s's halo rows
        const std::ptrdiff_t lo = -extra, hi = rows + extra;
        const std::ptrdiff_t r0 = std::max(2 * m, lo), r1 = std::min(2 * m + 2, hi);
        if (r0 >= r1) continue;
        Real* dst = s % 2 == 1 ? b : a;
        const Real* src = s % 2 == 1 ? a : b;
        block(dst + r0 * w, src + r0 * w, r1 - r0);
        if (hooks.after_row)
          for (std::ptrdiff_t r = r0; r < r1; ++r) hooks.after_row(hooks.context, dst, r);
      }
    if (pass % 2) std::swap(a, b);
    done += pass;
  }
}

}  // namespace

void leapfrog_block(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                    const LeapfrogWeights<double>& c, bool diagonal) {
  active().block_d(zp, z, n, rows, w, c, diagonal);
}
void leapfrog_block(float* zp, const float* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                    const LeapfrogWeights<float>& c, bool diagonal) {
  active().block_f(zp, z, n, rows, w, c, diagonal);
}
void leapfrog_row_chunks(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t w, const LeapfrogWeights<double>& c,
                         bool diagonal, std::ptrdiff_t chunk, double* activity) {
  active().chunks_d(zp, z, n, w, c, diagonal, chunk, activity);
}
void leapfrog_row_chunks(float* zp, const float* z, std::ptrdiff_t n, std::ptrdiff_t w, const LeapfrogWeights<float>& c,
                         bool diagonal, std::ptrdiff_t chunk, float* activity) {
  active().chunks_f(zp, z, n, w, c, diagonal, chunk, activity);
}

int wavefront_depth(std::ptrdiff_t row_bytes) {
  // About 2(P + 2) rows of each of the two buffers are in flight in a pass of P levels. They need
  // not fit L2: streamed from L3 the pair kernel runs at its in-cache rate, and each level a pass
  // adds saves a sweep over memory. So the budget is a share of L3 (32 MB on the machines
  // measured), not L2. Measured at 2048² float64 (16 KB rows) on AVX2, 2-core AMD EPYC, loaded,
  // 16 steps a call, cells/s: passes of 4 levels 1.1e9, of 8 1.45e9, one of 16 1.6e9; one step 0.7e9.
  constexpr std::ptrdiff_t kBudgetBytes = 4 << 20;
  return static_cast<int>(std::clamp<std::ptrdiff_t>(kBudgetBytes / (4 * std::max<std::ptrdiff_t>(row_bytes, 1)) - 2, 1, 16));
}

void leapfrog_wavefront(double* z, double* zp, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                        const LeapfrogWeights<double>& c, bool diagonal, int steps, const WavefrontHooks<double>& hooks) {
  const auto f = active().block_d;
  wavefront(z, zp, rows, w, steps, hooks,
            [&](double* dst, const double* src, std::ptrdiff_t count) { f(dst, src, n, count, w, c, diagonal); });
}
void leapfrog_wavefront(float* z, float* zp, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                        const LeapfrogWeights<float>& c, bool diagonal, int steps, const WavefrontHooks<float>& hooks) {
  const auto f = active().block_f;
  wavefront(z, zp, rows, w, steps, hooks,
            [&](float* dst, const float* src, std::ptrdiff_t count) { f(dst, src, n, count, w, c, diagonal); });
}

const char* to_string(SimdPath p) {
  switch (p) {
    case SimdPath::scalar: return "scalar";
    case SimdPath::sse2: return "sse2";
    case SimdPath::avx2: return "avx2";
    case SimdPath::avx512: return "avx512";
    case SimdPath::neon: return "neon";
  }
  return "?";
}

bool parse_simd_path(const std::string& s, SimdPath& out) {
  for (SimdPath p : {SimdPath::scalar, SimdPath::sse2, SimdPath::avx2, SimdPath::avx512, SimdPath::neon})
    if (s == to_string(p)) {
      out = p;
      return true;
    }
  return false;
}

int simd_path_vector_bytes(SimdPath p) {
  switch (p) {
    case SimdPath::scalar: return 0;
    case SimdPath::sse2: case SimdPath::neon: return 16;
    case SimdPath::avx2: return 32;
    case SimdPath::avx512: return 64;
  }
  return 0;
}

std::vector<SimdPath> supported_simd_paths() {
  std::vector<SimdPath> v;
  for (const KernelPath& k : kPaths)
    if (cpu_supports(k.path)) v.push_back(k.path);
  return v;
}

bool simd_path_from_environment(SimdPath& out, std::string* why) {
  const char* e = std::getenv("STONESKIP_ISA");
  if (!e || !*e) {
    out = supported_simd_paths().back();
    return true;
  }
  std::string names;
  for (SimdPath p : supported_simd_paths()) names += std::string(names.empty() ? "" : ", ") + to_string(p);
  SimdPath p;
  if (!parse_simd_path(e, p)) {
    if (why) *why = std::string("STONESKIP_ISA: unknown path '") + e + "' (this machine runs: " + names + ")";
    return false;
  }
  if (!find_path(p)) {
    if (why) *why = std::string("STONESKIP_ISA: this CPU or build cannot run '") + e + "' (it runs: " + names + ")";
    return false;
  }
  out = p;
  return true;
}

SimdPath leapfrog_kernel_path() { return active().path; }

bool set_leapfrog_kernel_path(SimdPath p) {
  const KernelPath* k = find_path(p);
  if (!k) return false;
  active_slot().store(k, std::memory_order_relaxed);
  return true;
}

const char* leapfrog_kernel_isa() { return to_string(leapfrog_kernel_path()); }

}  // namespace stoneskip
