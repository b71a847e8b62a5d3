#include "verification/captures/capture_chain.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "model/stone/throw.hpp"
#include "tools/io/portable_random.hpp"
#include "verification/captures/virtual_thrower.hpp"

namespace stoneskip {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;

// Rotation by the rotation vector theta (rad).
Quat exp_rotation(const Vec3& theta) {
  const double angle = theta.norm();
  if (angle < 1e-12) return Quat(1.0, 0.5 * theta.x(), 0.5 * theta.y(), 0.5 * theta.z()).normalized();
  return Quat(Eigen::AngleAxisd(angle, theta / angle));
}
}  // namespace

ChainInput make_chain_input(const Trace& trace, const TimedSamples& timing, const CaptureOptions& o) {
  ChainInput in;
  const std::size_t n = timing.index.size();
  const double t0 = n ? timing.t_s.front() : 0.0;
  in.period_s = timing.stats.period_s;
  // Host stamps used as given carry their own noise: σ = jitter/√2 for independent stamps, drawn
  // uniform (half-width √3 σ).
  if (!timing.stats.nominal && timing.stats.clock == ClockModel::stamps_as_given)
    in.stamp_noise_s = std::sqrt(1.5) * timing.stats.jitter_s;
  in.fast_factor = trace.calibration.gyro_fast_factor;
  in.mounting = o.mounting;
  for (int i = 0; i < 3; ++i) {
    // Y and Z lose their lowest bit in the reports (model/README.md §4): a step of two counts. A logger that
    // kept fewer bits (WiiYourself! uses the 8 high bits) shows a coarser step: the smallest change
    // between consecutive samples, when larger, is taken as the step.
    in.accel_lsb_g[i] = trace.calibration.accel_lsb_g(i) * (i == 0 ? 1.0 : 2.0);
    double smallest = 0;
    for (std::size_t j = 1; j < n; ++j) {
      const double d = std::abs(trace.samples[timing.index[j]].accel_g[i] - trace.samples[timing.index[j - 1]].accel_g[i]);
      if (d > 0 && (smallest == 0 || d < smallest)) smallest = d;
    }
    in.accel_lsb_g[i] = std::max(in.accel_lsb_g[i], smallest);
    in.gyro_lsb_deg_s[i] = trace.calibration.gyro_lsb_deg_s(false);
  }
  for (std::size_t j = 0; j < n; ++j) {
    const TraceSample& x = trace.samples[timing.index[j]];
    in.t_s.push_back(timing.t_s[j] - t0);
    in.accel_g.push_back(x.accel_g);
    in.rate_deg_s.push_back(x.rate_deg_s);
    in.fast.push_back(x.gyro_fast);
    in.buttons.push_back(x.buttons);
    std::uint32_t f = x.flags & ~(kRepeated | kGapBefore);
    for (int i = 0; i < 3; ++i)
      if (std::abs(x.accel_g[i]) >= o.saturation_g) f |= kSaturatedX << i;
    if (j > 0 && timing.report_index[j] - timing.report_index[j - 1] > 1) f |= kGapBefore;
    in.flags.push_back(f);
  }
  return in;
}

std::vector<SaturatedSpan> saturated_spans(const ChainInput& in) {
  std::vector<SaturatedSpan> spans;
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t bit = kSaturatedX << i;
    for (std::size_t k = 0; k < in.t_s.size();) {
      if (!(in.flags[k] & bit)) {
        ++k;
        continue;
      }
      SaturatedSpan s;
      s.axis = i;
      s.t0_s = in.t_s[k];
      while (k < in.t_s.size() && (in.flags[k] & bit)) {
        s.t1_s = in.t_s[k];
        ++s.samples;
        ++k;
      }
      spans.push_back(s);
    }
  }
  return spans;
}

bool find_still(const ChainInput& in, const CaptureOptions& o, std::size_t last, std::size_t& begin, std::size_t& end) {
  constexpr double kMaxStill_s = 2.0;   // the gravity direction and the bias need no more
  constexpr std::size_t kMinSamples = 3;
  const std::size_t n = in.t_s.size();
  if (n < kMinSamples || last >= n) return false;
  auto quiet = [&](std::size_t b, std::size_t e) {
    Vec3 fa = Vec3::Zero(), wa = Vec3::Zero();
    for (std::size_t k = b; k <= e; ++k) {
      if (in.flags[k] & (kAccelSaturated | kGyroSaturated)) return false;
      fa += in.accel_g[k];
      wa += in.rate_slow_deg_s(k);
    }
    fa /= double(e - b + 1);
    wa /= double(e - b + 1);
    // A quick reject before the per-sample test: far from 1 g, or turning.
    if (std::abs(fa.norm() - 1.0) > 0.3 || wa.cwiseAbs().maxCoeff() > 60.0) return false;
    for (std::size_t k = b; k <= e; ++k) {
      if ((in.accel_g[k] - fa).cwiseAbs().maxCoeff() > o.still_accel_tol_g) return false;
      if ((in.rate_slow_deg_s(k) - wa).cwiseAbs().maxCoeff() > o.still_rate_tol_deg_s) return false;
    }
    return true;
  };
  // For each candidate end (latest first), the shortest window reaching min_still_s in time.
  std::size_t b = last + 1;
  for (std::size_t e = last + 1; e-- > 0;) {
    if (b > e) b = e;
    while (b > 0 && in.t_s[e] - in.t_s[b] < o.min_still_s) --b;
    if (in.t_s[e] - in.t_s[b] < o.min_still_s) return false;  // not enough time before e
    if (e - b + 1 < kMinSamples || !quiet(b, e)) continue;
    std::size_t s = b;
    while (s > 0 && in.t_s[e] - in.t_s[s - 1] <= kMaxStill_s && quiet(s - 1, e)) --s;
    begin = s;
    end = e;
    return true;
  }
  return false;
}

int count_range_switches(const ChainInput& in) {
  int n = 0;
  for (std::size_t k = 1; k < in.fast.size(); ++k)
    for (int i = 0; i < 3; ++i) n += in.fast[k][i] != in.fast[k - 1][i];
  return n;
}

ReleaseKinematics run_chain(const ChainInput& in, const CaptureOptions& o, const Perturbation& p,
                            ProcessedSeries* series, ChainDiagnostics* diagnostics) {
  ReleaseKinematics r;
  const std::size_t n = in.t_s.size();
  if (n < 2 || in.still_end >= n || in.still_begin > in.still_end) return r;
  // The same ensemble for a seed whatever standard library built the program (portable_random.hpp).
  PortableDraws<std::mt19937_64> rng(p.seed);
  auto sym = [&] { return 2.0 * rng.unit() - 1.0; };

  // 1. The samples, perturbed for an ensemble member.
  const std::size_t stop = series ? n - 1 : std::min(n - 1, in.release_sample + 1);
  std::vector<Vec3> f(in.accel_g.begin(), in.accel_g.begin() + stop + 1);
  std::vector<Vec3> w(stop + 1);
  for (std::size_t k = 0; k <= stop; ++k) w[k] = in.rate_deg_s[k];
  double gyro_scale = 1.0, lever_scale = 1.0, height_offset = 0.0, release_t = in.release_t_s;
  if (p.kind == Perturb::random) {
    // A calibration offset on every sample, and the still part's own error: a constant signal read
    // without enough noise to dither it keeps its rounding, up to half a step, in its mean.
    Vec3 bias, still_bias;
    for (int i = 0; i < 3; ++i) {
      bias[i] = o.accel_bias_g * sym();
      still_bias[i] = 0.5 * in.accel_lsb_g[i] * sym();
    }
    for (std::size_t k = 0; k <= stop; ++k)
      for (int i = 0; i < 3; ++i) {
        const bool still = k >= in.still_begin && k <= in.still_end;
        // One draw a statement: the order of two draws in one expression is unspecified (compilers
        // differ), and the seed must give the same ensemble whatever built the program.
        const double accel_noise = rng.gauss(), accel_round = sym();
        f[k][i] += bias[i] + (still ? still_bias[i] : 0.0) + o.accel_noise_g * accel_noise + 0.5 * in.accel_lsb_g[i] * accel_round;
        const double lsb = in.gyro_lsb_deg_s[i] * (in.fast[k][i] ? in.fast_factor : 1.0);
        const double gyro_noise = rng.gauss(), gyro_round = sym();
        w[k][i] += o.gyro_noise_deg_s * gyro_noise * (in.fast[k][i] ? in.fast_factor : 1.0) + 0.5 * lsb * gyro_round;
      }
    gyro_scale = 1.0 + o.gyro_scale_rel_uncertainty * sym();
    lever_scale = 1.0 + in.mounting.lever_arm_rel_uncertainty * sym();
    height_offset = o.thrower.height_uncertainty_m * sym();
    release_t = in.release_t_low_s + rng.unit() * (in.release_t_high_s - in.release_t_low_s);
  }
  // The times: as chosen by the timing analysis; a member redraws each host stamp within the
  // stamps' own noise when they are used as given (kept in order).
  std::vector<double> t(in.t_s.begin(), in.t_s.begin() + stop + 1);
  if (p.kind == Perturb::random && in.stamp_noise_s > 0)
    for (std::size_t k = 0; k <= stop; ++k) {
      t[k] += in.stamp_noise_s * sym();
      if (k > 0) t[k] = std::max(t[k], t[k - 1]);
    }
  // 2. Clipped spans: what the accelerometer could not show. A random bump is a half sine in time
  // from the last unclipped sample before the span to the first after it; each span on each axis
  // draws its own height (a share of the way from the recorded level up to max_value). The
  // accelerometer's spans draw last from the member's stream and the MotionPlus's from a stream of
  // their own, so a member re-run with its accelerometer spans as recorded (its speed floor,
  // estimate_throw) draws every other perturbation as the member does.
  const double edge = in.period_s > 0 ? in.period_s : 0.01;
  auto fill_spans = [&](ClipFill fill, const auto& in_span, const std::vector<Vec3>& recorded, double max_value,
                        std::vector<Vec3>& out, PortableDraws<std::mt19937_64>& stream) {
    for (int i = 0; i < 3; ++i)
      for (std::size_t k = 0; k <= stop;) {
        if (!in_span(k, i)) {
          ++k;
          continue;
        }
        std::size_t e = k;
        while (e <= stop && in_span(e, i)) ++e;
        const double ta = k > 0 ? t[k - 1] : t[k] - edge;
        const double tb = e <= stop ? t[e] : t[e - 1] + edge;
        const double s = fill == ClipFill::at_max ? 1.0 : stream.unit();
        for (std::size_t j = k; j < e; ++j) {
          const double bump = fill == ClipFill::at_max ? 1.0 : std::sin(std::numbers::pi * (t[j] - ta) / (tb - ta));
          const double level = std::abs(recorded[j][i]);
          const double extra = std::max(0.0, max_value - level) * s * bump;
          out[j][i] = std::copysign(level + extra, recorded[j][i]);
        }
        k = e;
      }
  };
  if (p.fill != ClipFill::as_recorded)
    fill_spans(p.fill, [&](std::size_t k, int i) { return (in.flags[k] & (kSaturatedX << i)) != 0; }, in.accel_g,
               o.max_accel_g, f, rng);
  // The MotionPlus's saturated samples (kGyroSaturated: some axis at the end of its 14-bit range):
  // on each axis at 90 % of its range or more (the zero offset moves the ends by a few percent),
  // or, if none is, on the axis nearest its range, the rate is a lower bound, filled as above up to
  // max_rate_deg_s.
  if (p.gyro_fill != ClipFill::as_recorded) {
    auto range = [&](std::size_t k, int i) { return 8192.0 * in.gyro_lsb_deg_s[i] * (in.fast[k][i] ? in.fast_factor : 1.0); };
    std::vector<std::array<bool, 3>> at_end(stop + 1, {false, false, false});
    for (std::size_t k = 0; k <= stop; ++k) {
      if (!(in.flags[k] & kGyroSaturated)) continue;
      int nearest = 0;
      bool any = false;
      for (int i = 0; i < 3; ++i) {
        const double share = std::abs(in.rate_deg_s[k][i]) / range(k, i);
        if (share > std::abs(in.rate_deg_s[k][nearest]) / range(k, nearest)) nearest = i;
        if (share >= 0.9) at_end[k][i] = any = true;
      }
      if (!any) at_end[k][nearest] = true;
    }
    // The member's seed mixed with 2^64/φ (SplitMix64's increment): a stream apart from the member's.
    constexpr std::uint64_t kMotionPlusStream = 0x9e3779b97f4a7c15ULL;
    PortableDraws<std::mt19937_64> gyro_stream(p.seed ^ kMotionPlusStream);
    fill_spans(p.gyro_fill, [&](std::size_t k, int i) { return at_end[k][i]; }, in.rate_deg_s, o.max_rate_deg_s, w,
               gyro_stream);
  }
  // 3. The still part: gravity direction, |a|, gyro bias (slow-mode deg/s).
  Vec3 f_still = Vec3::Zero(), bias_slow = Vec3::Zero();
  for (std::size_t k = in.still_begin; k <= in.still_end; ++k) {
    f_still += f[k];
    Vec3 ws = w[k];
    for (int i = 0; i < 3; ++i)
      if (in.fast[k][i]) ws[i] /= in.fast_factor;
    bias_slow += ws;
  }
  const double count = double(in.still_end - in.still_begin + 1);
  f_still /= count;
  bias_slow /= count;
  const double g_still = f_still.norm();
  if (diagnostics) {
    diagnostics->still_accel_g = g_still;
    diagnostics->gyro_bias_deg_s = bias_slow;
  }
  auto omega = [&](std::size_t k) {  // corrected rate, rad/s, remote frame
    Vec3 x = w[k];
    for (int i = 0; i < 3; ++i) x[i] -= bias_slow[i] * (in.fast[k][i] ? in.fast_factor : 1.0);
    return Vec3(gyro_scale * kDeg * x);
  };
  // 4. Orientation, acceleration, velocity, position from the start of the still part: at rest on
  // average there (its mean acceleration is gravity by construction, so integrating across it adds
  // nothing), while its last samples may already hold the slow onset of the swing within the
  // stillness tolerances — starting at its end would take that motion as rest.
  const double g0 = o.gravity_m_s2;
  const Quat q0 = Quat::FromTwoVectors(f_still.normalized(), Vec3::UnitZ());
  const std::size_t s0 = in.still_begin;
  std::vector<Quat> q(stop + 1, q0);
  std::vector<Vec3> v(stop + 1, Vec3::Zero()), x(stop + 1, Vec3::Zero());
  auto world_accel = [&](std::size_t k) { return Vec3(g0 * (q[k] * f[k] - g_still * Vec3::UnitZ())); };
  Vec3 a_prev = world_accel(s0);
  if (series) {
    series->world_accel_m_s2.assign(n, Vec3::Zero());
    series->remote_velocity_m_s.assign(n, Vec3::Zero());
    series->stone_speed_m_s.assign(n, 0.0);
    series->stone_position_m.assign(n, Vec3::Zero());
    series->rate_deg_s.assign(n, Vec3::Zero());
    for (std::size_t k = 0; k < n; ++k) series->rate_deg_s[k] = omega(k) / kDeg;
    series->world_accel_m_s2[s0] = a_prev;
  }
  for (std::size_t k = s0; k < stop; ++k) {
    const double dt = t[k + 1] - t[k];
    const Vec3 w0 = omega(k), w1 = omega(k + 1);
    const Vec3 theta = 0.5 * (w0 + w1) * dt + (dt * dt / 12.0) * w0.cross(w1);  // Bortz, 2nd order
    q[k + 1] = (q[k] * exp_rotation(theta)).normalized();
    const Vec3 a_next = world_accel(k + 1);
    v[k + 1] = v[k] + 0.5 * (a_prev + a_next) * dt;
    x[k + 1] = x[k] + 0.5 * (v[k] + v[k + 1]) * dt;
    a_prev = a_next;
    if (series) {
      series->world_accel_m_s2[k + 1] = a_next;
      series->remote_velocity_m_s[k + 1] = v[k + 1];
      const Vec3 wr = q[k + 1] * w1;
      series->stone_speed_m_s[k + 1] = (v[k + 1] + wr.cross(q[k + 1] * in.mounting.stone_offset_m)).norm();
      series->stone_position_m[k + 1] = x[k + 1] + q[k + 1] * in.mounting.stone_offset_m - q0 * in.mounting.stone_offset_m;
    }
  }
  // 5. The state at the release time: integrated from the sample before it with the rate and the
  // acceleration interpolated linearly, as the steps above (a straight line between the velocities
  // of two samples would cut off the peak of speed that a release sits on, by a few percent when a
  // report around it was lost). A release after the last sample (the button still held at the
  // file's end) is extrapolated at constant rate and acceleration over at most one interval.
  Quat qr;
  Vec3 vr, xr, wr;  // wr: remote frame
  if (release_t > t[stop]) {
    const double d = release_t - t[stop];
    const Vec3 a_end = world_accel(stop);
    wr = omega(stop);
    qr = (q[stop] * exp_rotation(wr * d)).normalized();
    vr = v[stop] + a_end * d;
    xr = x[stop] + v[stop] * d + 0.5 * a_end * d * d;
  } else {
    std::size_t j = std::max(s0, std::min(in.release_sample, stop > 0 ? stop - 1 : 0));
    while (j + 1 < stop && t[j + 1] < release_t) ++j;
    while (j > s0 && t[j] > release_t) --j;
    const std::size_t j1 = std::min(j + 1, stop);
    const double h = t[j1] - t[j];
    const double d = std::clamp(release_t - t[j], 0.0, std::max(h, 0.0));
    const double u = h > 0 ? d / h : 0.0;
    const Vec3 w0 = omega(j);
    wr = (1 - u) * w0 + u * omega(j1);
    qr = (q[j] * exp_rotation(0.5 * (w0 + wr) * d + (d * d / 12.0) * w0.cross(wr))).normalized();
    const Vec3 a0 = world_accel(j), da = h > 0 ? Vec3((world_accel(j1) - a0) / h) : Vec3::Zero();
    vr = v[j] + a0 * d + 0.5 * da * d * d;
    xr = x[j] + v[j] * d + 0.5 * a0 * d * d + da * d * d * d / 6.0;
  }
  const Mat3 R = qr.toRotationMatrix();
  const Vec3 w_world = R * wr;
  const Vec3 v_accel = vr + w_world.cross(R * in.mounting.stone_offset_m);
  const Vec3 v_lever = R * wr.cross(lever_scale * in.mounting.lever_arm_m);
  // Clipped: the lever arm's velocity, but not slower than the accelerometer shows even with its
  // clipped spans as recorded (the lever arm misses the pivot's own motion, so it can fall below
  // that bound; the direction stays the lever arm's).
  // A lever arm with no speed (a rate along it, or none) has no direction: the accelerometer's.
  const double lever_speed = v_lever.norm(), accel_speed = v_accel.norm();
  const bool floored = in.use_lever && lever_speed < in.speed_floor_m_s && (lever_speed > 0 || accel_speed > 0);
  const Vec3 v_used = !in.use_lever ? v_accel
                      : !floored    ? v_lever
                      : lever_speed > 0 ? Vec3(v_lever * (in.speed_floor_m_s / lever_speed))
                                        : Vec3(v_accel * (in.speed_floor_m_s / accel_speed));
  r.speed_floored = floored;
  r.speed_floor_m_s = in.use_lever ? in.speed_floor_m_s : 0.0;
  // 6. Turn the heading so the horizontal velocity points along +x.
  const double psi = std::hypot(v_used.x(), v_used.y()) > 1e-9 ? std::atan2(v_used.y(), v_used.x()) : 0.0;
  const Mat3 turn = Eigen::AngleAxisd(-psi, Vec3::UnitZ()).toRotationMatrix();
  if (series)
    for (auto& x_m : series->stone_position_m) x_m = turn * x_m;
  const Mat3 M = in.mounting.stone_axes();
  r.t_s = release_t;
  r.accel_velocity_m_s = turn * v_accel;
  r.lever_velocity_m_s = turn * v_lever;
  r.stone_orientation = Quat(turn * R * M).normalized();
  r.measured.velocity_m_s = turn * v_used;
  r.measured.omega_body_rad_s = M.transpose() * wr;
  const Vec3 stone_rise = xr + R * in.mounting.stone_offset_m - q0 * in.mounting.stone_offset_m;
  r.measured.rise_m = stone_rise.z();
  // 7. The virtual thrower.
  const VirtualThrow virt = map_to_virtual(r.measured, o.thrower, height_offset);
  r.velocity_m_s = virt.velocity_m_s;
  r.omega_body_rad_s = virt.omega_body_rad_s;
  r.height_m = virt.height_m;
  r.speed_m_s = r.velocity_m_s.norm();
  r.accel_speed_m_s = r.accel_velocity_m_s.norm();
  r.lever_speed_m_s = r.lever_velocity_m_s.norm();
  r.measured_speed_m_s = r.measured.velocity_m_s.norm();
  r.measured_spin_rev_s = r.measured.omega_body_rad_s.z() / (2.0 * std::numbers::pi);
  RigidState st;
  st.orientation = r.stone_orientation;
  st.velocity_m_s = r.measured.velocity_m_s;
  const AttitudeAngles ang = attitude_angles(st);
  r.attack_angle_deg = ang.attack_angle_deg;
  r.path_angle_deg = ang.path_angle_deg;
  r.roll_angle_deg = ang.roll_angle_deg;
  r.spin_rev_s = r.omega_body_rad_s.z() / (2.0 * std::numbers::pi);
  return r;
}

}  // namespace stoneskip
