#pragma once
// Test support for the walled references' tests (walled_wave_test.cpp, forced_walled_wave_test.cpp):
// a walled field's extension to the periodic grid it is part of, the oracle's input. Even about the
// half-cell walls (period 2n) for a reflecting pond; odd about the rims one cell out (period
// 2(n + 1), zeros on the rims) for a fixed one.
#include <vector>

#include "model/water/height_field.hpp"

namespace stoneskip::test {

inline std::vector<double> extended(Boundary b, const std::vector<double>& f, int nx, int ny, int& px, int& py) {
  px = b == Boundary::reflecting ? 2 * nx : 2 * (nx + 1);
  py = b == Boundary::reflecting ? 2 * ny : 2 * (ny + 1);
  std::vector<double> e(static_cast<std::size_t>(px) * py, 0.0);
  // Index along the extension → (pond index, sign); indices n and p − 1 of a fixed axis are the rims.
  auto fold = [&](int k, int n, int p, int& i) -> double {
    if (b == Boundary::reflecting) {
      i = k < n ? k : p - 1 - k;
      return 1;
    }
    if (k < n) {
      i = k;
      return 1;
    }
    if (k == n || k == p - 1) return 0;
    i = p - 2 - k;  // odd about index n: k = n + 1 + r ↔ n − 1 − r
    return -1;
  };
  for (int j = 0; j < py; ++j)
    for (int i = 0; i < px; ++i) {
      int fi = 0, fj = 0;
      const double s = fold(i, nx, px, fi) * fold(j, ny, py, fj);
      if (s != 0) e[static_cast<std::size_t>(j) * px + i] = s * f[static_cast<std::size_t>(fj) * nx + fi];
    }
  return e;
}

}  // namespace stoneskip::test
