#include "verification/waves/plain_stencil_loop.hpp"

namespace stoneskip {

void plain_leapfrog_block(double* zp, const double* z, std::ptrdiff_t n, std::ptrdiff_t rows, std::ptrdiff_t w,
                          const LeapfrogWeights<double>& c) {
  for (std::ptrdiff_t r = 0; r < rows; ++r)
    for (std::ptrdiff_t k = r * w; k < r * w + n; ++k) {
      const double orth = (z[k - 1] + z[k + 1]) + (z[k - w] + z[k + w]);
      const double diag = (z[k - w - 1] + z[k + w - 1]) + (z[k - w + 1] + z[k + w + 1]);
      zp[k] = c.centre * z[k] + c.orth * orth + c.diag * diag - c.previous * zp[k];
    }
}

}  // namespace stoneskip
