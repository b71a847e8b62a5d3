#include "solvers/scene/draught_window.hpp"

#include <algorithm>
#include <climits>

namespace stoneskip {

DraughtWindow::DraughtWindow(int nx, int ny, bool periodic)
    : nx_(nx), ny_(ny), periodic_(periodic), sum_(static_cast<std::size_t>(nx) * ny, 0.0),
      i_lo_(INT_MAX), i_hi_(INT_MIN), j_lo_(INT_MAX), j_hi_(INT_MIN) {}

void DraughtWindow::add(const DraughtPatch& p, double weight) {
  if (p.empty() || weight == 0) return;
  for (int c = 0; c < p.nj; ++c) {
    int j = p.j0 + c;
    if (periodic_) j = ((j % ny_) + ny_) % ny_;
    else if (j < 0 || j >= ny_) continue;
    for (int a = 0; a < p.ni; ++a) {
      const double b = p.at(a, c);
      if (b == 0) continue;
      int i = p.i0 + a;
      if (periodic_) i = ((i % nx_) + nx_) % nx_;
      else if (i < 0 || i >= nx_) continue;
      sum_[static_cast<std::size_t>(j) * nx_ + i] += weight * b;
      i_lo_ = std::min(i_lo_, i);
      i_hi_ = std::max(i_hi_, i);
      j_lo_ = std::min(j_lo_, j);
      j_hi_ = std::max(j_hi_, j);
    }
  }
}

double DraughtWindow::kept_sum(const DraughtPatch& p) const {
  double sum = 0;
  for (int c = 0; c < p.nj; ++c) {
    const int j = p.j0 + c;
    if (!periodic_ && (j < 0 || j >= ny_)) continue;
    for (int a = 0; a < p.ni; ++a) {
      const int i = p.i0 + a;
      if (!periodic_ && (i < 0 || i >= nx_)) continue;
      sum += p.at(a, c);
    }
  }
  return sum;
}

double DraughtWindow::sum() const {
  double s = 0;
  for (int j = j_lo_; j <= j_hi_; ++j)
    for (int i = i_lo_; i <= i_hi_; ++i) s += sum_[static_cast<std::size_t>(j) * nx_ + i];
  return s;
}

void DraughtWindow::take(DraughtPatch& out) {
  if (empty()) {
    out.clear();
    return;
  }
  out.reset(i_lo_, j_lo_, i_hi_ - i_lo_ + 1, j_hi_ - j_lo_ + 1);
  for (int c = 0; c < out.nj; ++c) {
    double* row = &sum_[static_cast<std::size_t>(j_lo_ + c) * nx_ + i_lo_];
    for (int a = 0; a < out.ni; ++a) {
      out.at(a, c) = row[a];
      row[a] = 0;
    }
  }
  i_lo_ = j_lo_ = INT_MAX;
  i_hi_ = j_hi_ = INT_MIN;
}

}  // namespace stoneskip
