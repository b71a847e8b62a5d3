#include "verification/scene/ring_speed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "verification/convergence/order_fit.hpp"

namespace stoneskip {

bool RingSpeedOptions::is_valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (contact < 0) return fail("contact must be >= 0");
  if (!(start_after_s >= 0 && end_after_s > start_after_s)) return fail("need 0 <= start_after_s < end_after_s");
  if (!(min_radius_m >= 0 && max_radius_m > min_radius_m)) return fail("need 0 <= min_radius_m < max_radius_m");
  return true;
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ωΔt of a wave of number kd along θ: cos(ωΔt) = 1 + σ² s/2 (undamped leapfrog, model/README.md §2.1).
double omega_dt(const Stencil& st, double sigma, double kd, double theta) {
  const double s = st.symbol(kd * std::cos(theta), kd * std::sin(theta));
  const double c = 1 + 0.5 * sigma * sigma * s;
  if (c < -1 || c > 1) return kNaN;
  return std::acos(c);
}

template <class F>
double direction_mean(F f) {
  constexpr int kAngles = 91;
  double sum = 0;
  for (int k = 0; k < kAngles; ++k) sum += f(0.5 * M_PI * k / (kAngles - 1));
  return sum / kAngles;
}

// Azimuthal RMS of z in rings of one cell around (xc, yc), out to r_max.
void radial_profile(const HeightField& f, const FieldPlacement& at, double xc, double yc, double r_max,
                    std::vector<double>& r_m, std::vector<double>& rms_m, std::vector<double>& mean_m) {
  const double d = f.options().cell_m;
  const int bins = static_cast<int>(r_max / d) + 1;
  std::vector<double> sum(bins, 0.0), plain(bins, 0.0);
  std::vector<int> count(bins, 0);
  const int i0 = std::max(0, static_cast<int>(std::floor((xc - r_max - at.origin_x_m) / d)));
  const int i1 = std::min(f.nx() - 1, static_cast<int>(std::ceil((xc + r_max - at.origin_x_m) / d)));
  const int j0 = std::max(0, static_cast<int>(std::floor((yc - r_max - at.origin_y_m) / d)));
  const int j1 = std::min(f.ny() - 1, static_cast<int>(std::ceil((yc + r_max - at.origin_y_m) / d)));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double x = at.origin_x_m + i * d - xc, y = at.origin_y_m + j * d - yc;
      const int b = static_cast<int>(std::sqrt(x * x + y * y) / d + 0.5);
      if (b >= bins) continue;
      const double z = f.height(i, j);
      sum[b] += z * z;
      plain[b] += z;
      ++count[b];
    }
  r_m.assign(bins, 0);
  rms_m.assign(bins, 0);
  mean_m.assign(bins, 0);
  for (int b = 0; b < bins; ++b) {
    r_m[b] = b * d;
    rms_m[b] = count[b] ? std::sqrt(sum[b] / count[b]) : 0.0;
    mean_m[b] = count[b] ? plain[b] / count[b] : 0.0;
  }
}

// The leading edge: the largest r where the profile reaches half its maximum beyond r_min, found
// by linear interpolation between bins. NaN when there is nothing beyond r_min.
double leading_edge(const std::vector<double>& r, const std::vector<double>& a, double r_min) {
  double peak = 0;
  for (std::size_t b = 0; b < r.size(); ++b)
    if (r[b] >= r_min) peak = std::max(peak, a[b]);
  if (!(peak > 0)) return kNaN;
  for (std::size_t b = r.size() - 1; b > 0; --b)
    if (a[b - 1] >= 0.5 * peak && r[b - 1] >= r_min) {
      const double f = (a[b - 1] - 0.5 * peak) / (a[b - 1] - a[b]);
      return r[b - 1] + f * (r[b] - r[b - 1]);
    }
  return kNaN;
}

// Half a wavelength: from the leading extremum of the azimuthal mean (the outermost one beyond
// r_min reaching a quarter of the largest |mean| there) to the extremum of opposite sign behind it.
double half_wavelength(const std::vector<double>& r, const std::vector<double>& m, double r_min) {
  double peak = 0;
  for (std::size_t b = 0; b < r.size(); ++b)
    if (r[b] >= r_min) peak = std::max(peak, std::abs(m[b]));
  if (!(peak > 0) || r.size() < 3) return kNaN;
  auto extremum = [&](std::size_t b) {
    return (m[b] >= m[b - 1] && m[b] >= m[b + 1]) || (m[b] <= m[b - 1] && m[b] <= m[b + 1]);
  };
  for (std::size_t b = r.size() - 2; b > 0; --b) {
    if (r[b] < r_min) break;
    if (std::abs(m[b]) < 0.25 * peak || !extremum(b)) continue;
    for (std::size_t q = b - 1; q > 0; --q)
      if (extremum(q) && m[q] * m[b] < 0) return r[b] - r[q];
    return kNaN;
  }
  return kNaN;
}

}  // namespace

double discrete_phase_speed(const Stencil& st, double sigma, double kd) {
  return direction_mean([&](double th) { return omega_dt(st, sigma, kd, th) / (sigma * kd); });
}

double discrete_group_speed(const Stencil& st, double sigma, double kd) {
  const double h = 1e-5 * std::max(kd, 1e-3);
  return direction_mean(
      [&](double th) { return (omega_dt(st, sigma, kd + h, th) - omega_dt(st, sigma, kd - h, th)) / (2 * h * sigma); });
}

RingSpeed measure_ring_speed(const SceneOptions& scene, const RingSpeedOptions& o) {
  RingSpeed r;
  std::string why;
  if (!o.is_valid(&why)) {
    r.problem = why;
    return r;
  }
  if (!scene.water || scene.coupling != Coupling::two_way) {
    r.problem = "the scene has no two-way field";
    return r;
  }
  // 1. The contact and the ring's centre.
  const SceneSummary first = run_scene(scene);
  if (static_cast<int>(first.stone.contacts.size()) <= o.contact) {
    r.problem = "the throw has no contact " + std::to_string(o.contact + 1);
    return r;
  }
  const ContactRecord& k = first.stone.contacts[o.contact];
  r.centre_x_m = 0.5 * (k.first_touch_m.x() + k.exit_position_m.x());
  r.centre_y_m = 0.5 * (k.first_touch_m.y() + k.exit_position_m.y());
  r.contact_end_s = k.end_s;
  r.c_m_s = scene.water->field.wave_speed_m_s;
  const double t0 = k.end_s + o.start_after_s, t1 = k.end_s + o.end_after_s;
  const double t_mid = 0.5 * (t0 + t1);
  // 2. The leading edge at every frame of the window.
  std::vector<double> rr, aa, mm;
  double best_mid = 1e300;
  run_scene(scene, [&](const SceneFrame& f) {
    if (f.t_s < t0 || f.t_s > t1) return;
    radial_profile(*f.field, f.placement, r.centre_x_m, r.centre_y_m, o.max_radius_m, rr, aa, mm);
    const double edge = leading_edge(rr, aa, o.min_radius_m);
    if (std::isfinite(edge)) {
      r.t_s.push_back(f.t_s);
      r.radius_m.push_back(edge);
    }
    if (std::abs(f.t_s - t_mid) < best_mid) {
      best_mid = std::abs(f.t_s - t_mid);
      r.profile_t_s = f.t_s;
      r.profile_r_m = rr;
      r.profile_rms_m = aa;
      r.profile_mean_m = mm;
    }
  });
  const LineFit fit = fit_line(r.t_s, r.radius_m);
  if (!fit.valid || r.t_s.size() < 3) {
    r.problem = "fewer than 3 frames with a ring in the window";
    return r;
  }
  r.found = true;
  r.speed_m_s = fit.slope;
  r.speed_low_m_s = fit.slope_low;
  r.speed_high_m_s = fit.slope_high;
  r.r_squared = fit.r_squared;
  r.intercept_m = fit.intercept;
  // 3. The prediction at the ring's dominant wave number.
  const double half = half_wavelength(r.profile_r_m, r.profile_mean_m, o.min_radius_m);
  const HeightFieldOptions& fo = scene.water->field;
  if (std::isfinite(half) && half > 0) {
    r.wavelength_m = 2 * half;
    r.kd = 2 * M_PI / r.wavelength_m * fo.cell_m;
    r.phase_speed_m_s = r.c_m_s * discrete_phase_speed(fo.stencil, fo.courant(), r.kd);
    r.group_speed_m_s = r.c_m_s * discrete_group_speed(fo.stencil, fo.courant(), r.kd);
  } else {
    r.wavelength_m = r.kd = r.phase_speed_m_s = r.group_speed_m_s = kNaN;
  }
  return r;
}

}  // namespace stoneskip
