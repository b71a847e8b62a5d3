#include "solvers/realtime/filippov_sliding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "model/stone/rigid_body.hpp"

namespace stoneskip {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

FilippovSliding::FilippovSliding(const Stone& stone, const Environment& env)
    : stone_(stone), env_(env), switches_(stone, env) {}

std::size_t FilippovSliding::index_of(int face) const {
  return 2 * stone_.body_mesh.vertices.size() + static_cast<std::size_t>(face);  // load_switches.hpp's order
}

// The faces' switch values at y: LoadSwitches' loaded_face functions, which depend on the state
// alone (not on a recorded mode), read after recording the mode of y.
void FilippovSliding::switch_values(std::span<const int> faces, const double* y, double* out) {
  RigidState s = from_vector(y);
  s.orientation.normalize();
  switches_.reset(s, g_);
  for (std::size_t n = 0; n < faces.size(); ++n) {
    const std::size_t k = index_of(faces[n]);
    out[n] = k < g_.size() ? g_[k] : kNaN;
  }
}

void FilippovSliding::rates_along(std::span<const int> faces, const double* y, const double* f, double* out) {
  StateVector plus{}, minus{};
  for (int k = 0; k < kStateSize; ++k) {
    plus[k] = y[k] + kDirectionalStep_s * f[k];
    minus[k] = y[k] - kDirectionalStep_s * f[k];
  }
  double gp[kMaxTreatedFaces], gm[kMaxTreatedFaces];
  switch_values(faces, plus.data(), gp);
  switch_values(faces, minus.data(), gm);
  for (std::size_t n = 0; n < faces.size(); ++n) out[n] = (gp[n] - gm[n]) / (2 * kDirectionalStep_s);
}

// The loads with the faces of forced_ held out of (0) or in (1) the loaded region, every other face
// as the loads decide it from the state (LoadMode::kDecide).
void FilippovSliding::rhs_forced(const double* y, double* dydt) {
  mode_.loaded_faces.assign(stone_.body_mesh.triangles.size(), LoadMode::kDecide);
  for (const auto& [face, loaded] : forced_) mode_.loaded_faces[static_cast<std::size_t>(face)] = loaded;
  rigid_body_rhs(stone_, env_, y, dydt, nullptr, nullptr, &mode_);
}

void FilippovSliding::hold(const FaceRules& rules) {
  forced_.clear();
  for (const FaceRule& r : rules)
    if (!r.sliding) forced_.emplace_back(r.face, static_cast<char>(r.side));
}

FilippovSliding::Sides FilippovSliding::sides(int face, const FaceRules& held, const double* y) {
  Sides out;
  hold(held);
  forced_.emplace_back(face, 0);
  rhs_forced(y, out.f0.data());
  forced_.back().second = 1;
  rhs_forced(y, out.f1.data());
  rates_along({&face, 1}, y, out.f0.data(), &out.a0);
  rates_along({&face, 1}, y, out.f1.data(), &out.a1);
  return out;
}

FilippovSliding::SlidingField FilippovSliding::one_switch(int face, const FaceRules& held, const double* y,
                                                          double* dydt) {
  SlidingField out;
  const Sides at = sides(face, held, y);
  const double a0 = at.a0, a1 = at.a1;
  if (!std::isfinite(a0) || !std::isfinite(a1)) {
    // The face has no wetted polygon here: its switch is undefined and the loads decide alone.
    hold(held);
    rhs_forced(y, dydt);
    out.exit = -1;
    return out;
  }
  // α = a₀ / (a₀ − a₁) keeps ∇g · ẏ = 0; outside the sliding region (exit < 0, located as a root)
  // it is clamped to the field on the side the state leaves by.
  out.alpha = a0 - a1 > 0 ? std::clamp(a0 / (a0 - a1), 0.0, 1.0) : (a0 <= 0 ? 0.0 : 1.0);
  out.exit = std::min(a0, -a1);
  for (int k = 0; k < kStateSize; ++k) dydt[k] = (1 - out.alpha) * at.f0[k] + out.alpha * at.f1[k];
  return out;
}

// The four fields with faces i and j held each way, the held faces held, and their rates toward
// both switches; then the bilinear weights.
FilippovSliding::Corners FilippovSliding::corners(int fi, int fj, const FaceRules& held, const double* y) {
  Corners c;
  hold(held);
  forced_.emplace_back(fi, 0);
  forced_.emplace_back(fj, 0);
  const int both[2] = {fi, fj};
  c.defined = true;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      forced_[forced_.size() - 2].second = static_cast<char>(a);
      forced_.back().second = static_cast<char>(b);
      rhs_forced(y, c.f[a][b].data());
      double rates[2];
      rates_along(both, y, c.f[a][b].data(), rates);
      c.A[a][b] = rates[0];
      c.B[a][b] = rates[1];
      c.defined = c.defined && std::isfinite(rates[0]) && std::isfinite(rates[1]);
    }
  if (c.defined) {
    const BilinearWeights w = bilinear_sliding_weights(c.A, c.B);
    c.solved = w.solved;
    c.attracts = w.attracts;
    c.alpha = w.alpha;
    c.beta = w.beta;
  }
  return c;
}

PairHandover handover_pair(const double (&A)[2][2], const double (&B)[2][2], int prefer) {
  // Rates in the corner order of Corners: [a][b], a face i's side, b face j's.
  auto j_slides = [&](int a, PairHandover& out) {
    const double b0 = B[a][0], b1 = B[a][1];
    if (!(b0 > 0 && b1 < 0)) return false;
    const double beta = b0 / (b0 - b1);
    const double ri = (1 - beta) * A[a][0] + beta * A[a][1];
    if (!(a == 0 ? ri < 0 : ri > 0)) return false;
    out = {1, a};
    return true;
  };
  auto i_slides = [&](int b, PairHandover& out) {
    const double a0 = A[0][b], a1 = A[1][b];
    if (!(a0 > 0 && a1 < 0)) return false;
    const double alpha = a0 / (a0 - a1);
    const double rj = (1 - alpha) * B[0][b] + alpha * B[1][b];
    if (!(b == 0 ? rj < 0 : rj > 0)) return false;
    out = {0, b};
    return true;
  };
  PairHandover out;
  for (int first = 0; first < 2; ++first) {
    const int who = first == 0 ? prefer : 1 - prefer;
    for (int side = 0; side < 2; ++side)
      if (who == 1 ? j_slides(side, out) : i_slides(side, out)) return out;
  }
  return PairHandover{};
}

// wᵢ(α, β) = ∇gᵢ · ẏ = p₀ + p₁α + p₂β + p₃αβ and wⱼ = q₀ + q₁α + q₂β + q₃αβ (the bilinear field's
// rates). wᵢ = 0 gives α = −(p₀ + p₂β)/(p₁ + p₃β); put in wⱼ = 0 it leaves c₂β² + c₁β + c₀ = 0.
// Of its real roots the one nearest the unit square (by its largest excursion outside it) is taken:
// Dieci & Lopez show that under attractivity exactly one lies inside.
BilinearWeights bilinear_sliding_weights(const double (&A)[2][2], const double (&B)[2][2]) {
  BilinearWeights w;
  const double p0 = A[0][0], p1 = A[1][0] - A[0][0], p2 = A[0][1] - A[0][0], p3 = A[1][1] - A[1][0] - A[0][1] + A[0][0];
  const double q0 = B[0][0], q1 = B[1][0] - B[0][0], q2 = B[0][1] - B[0][0], q3 = B[1][1] - B[1][0] - B[0][1] + B[0][0];
  const double c2 = q2 * p3 - q3 * p2, c1 = q0 * p3 + q2 * p1 - q1 * p2 - q3 * p0, c0 = q0 * p1 - q1 * p0;
  double roots[2];
  int n = 0;
  const double scale = std::abs(c0) + std::abs(c1) + std::abs(c2);
  if (!(scale > 0) || !std::isfinite(scale)) return w;
  if (std::abs(c2) <= 1e-12 * scale) {
    if (c1 != 0) roots[n++] = -c0 / c1;
  } else {
    const double disc = c1 * c1 - 4 * c2 * c0;
    if (disc < 0) return w;
    const double qq = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));  // the stable pair of roots
    roots[n++] = qq / c2;
    if (qq != 0) roots[n++] = c0 / qq;
  }
  double best_excursion = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k) {
    const double beta = roots[k];
    // α from whichever equation is better conditioned at this β.
    const double di = p1 + p3 * beta, dj = q1 + q3 * beta;
    if (di == 0 && dj == 0) continue;
    const double alpha = std::abs(di) >= std::abs(dj) ? -(p0 + p2 * beta) / di : -(q0 + q2 * beta) / dj;
    if (!std::isfinite(alpha) || !std::isfinite(beta)) continue;
    const double excursion = std::max({-alpha, alpha - 1, -beta, beta - 1});
    if (excursion < best_excursion) {
      best_excursion = excursion;
      w.alpha = alpha;
      w.beta = beta;
      w.solved = true;
    }
  }
  if (!w.solved || !(w.alpha > 0 && w.alpha < 1 && w.beta > 0 && w.beta < 1)) return w;
  // Dieci & Lopez's attractivity at the solution: along each switch's own weight, the rate toward it
  // is positive with the face out (weight 0) and negative with it in (weight 1).
  auto rate = [](const double (&R)[2][2], double a, double b) {
    return (1 - a) * (1 - b) * R[0][0] + a * (1 - b) * R[1][0] + (1 - a) * b * R[0][1] + a * b * R[1][1];
  };
  w.attracts = rate(A, 0, w.beta) > 0 && rate(A, 1, w.beta) < 0 && rate(B, w.alpha, 0) > 0 && rate(B, w.alpha, 1) < 0;
  return w;
}

SlidingChoice FilippovSliding::attracting(const RigidState& s, const FaceRules& rules) {
  SlidingChoice c;
  if (!available()) {
    c.why = "only the savitsky distributions' loaded-region switches are slid along (physical convention)";
    return c;
  }
  FaceRules held;
  for (const FaceRule& r : rules)
    if (!r.sliding) held.push_back(r);
  auto is_held = [&](int face) {
    return std::any_of(held.begin(), held.end(), [face](const FaceRule& r) { return r.face == face; });
  };
  RigidState sn = s;
  sn.orientation.normalize();
  const StateVector y = to_vector(sn);
  switches_.reset(sn, g_);
  const int nf = static_cast<int>(stone_.body_mesh.triangles.size());
  int best = -1;
  std::vector<int> at_zero;
  for (int i = 0; i < nf; ++i) {
    const double gi = g_[index_of(i)];
    if (!std::isfinite(gi) || is_held(i)) continue;
    if (std::abs(gi) <= kAtSwitch_m_s) at_zero.push_back(i);
    if (best < 0 || std::abs(gi) < std::abs(g_[index_of(best)])) best = i;
  }
  // A face already sliding is on its switch by construction, though its g may have drifted past
  // kAtSwitch_m_s (the sliding field holds ∇g · ẏ = 0 to its central differences' round-off): a
  // second switch reached while sliding on one is tried with it, on their intersection (a 20 cm
  // lens sliding on face 62 reached face 64's switch with 62's g no longer within 1e-6 m/s, and
  // the real-time stepper's steps then collapsed where the reference, by another path, slid on).
  if (!at_zero.empty())
    for (const FaceRule& r : rules)
      if (r.sliding && std::find(at_zero.begin(), at_zero.end(), r.face) == at_zero.end()) {
        at_zero.push_back(r.face);
        std::sort(at_zero.begin(), at_zero.end());
      }
  std::ostringstream m;
  if (best < 0) {
    c.why = "no face is wetted there";
    return c;
  }
  c.g = g_[index_of(best)];
  if (at_zero.empty()) {
    m << "no loaded-region switch is at zero there (the nearest, face " << best << "'s, is at g = " << c.g
      << " m/s, beyond " << kAtSwitch_m_s << ")";
    c.why = m.str();
    return c;
  }
  if (at_zero.size() > kMaxSlidingFaces || at_zero.size() + held.size() > kMaxTreatedFaces) {
    auto faces = [&m](const std::vector<int>& f) {
      m << (f.size() == 1 ? "face " : "faces ");
      for (std::size_t k = 0; k < f.size(); ++k) m << (k ? (k + 1 == f.size() ? " and " : ", ") : "") << f[k];
    };
    m << "the loaded-region switch" << (at_zero.size() == 1 ? " of " : "es of ");
    faces(at_zero);
    m << (at_zero.size() == 1 ? " is" : at_zero.size() == 2 ? " are both" : " are all") << " at zero there";
    if (!held.empty()) {
      std::vector<int> h;
      for (const FaceRule& r : held) h.push_back(r.face);
      m << " while ";
      faces(h);
      m << (h.size() == 1 ? " is" : " are") << " held on one side after sliding";
    }
    if (at_zero.size() > kMaxSlidingFaces)
      m << ": sliding on more than " << kMaxSlidingFaces << " switches at once is not built";
    else
      m << ": treating more than " << kMaxTreatedFaces << " switches apart at once (slid along or held) is not built";
    c.why = m.str();
    return c;
  }
  if (at_zero.size() == 2) {
    const int fi = at_zero[0], fj = at_zero[1];
    const Corners k = corners(fi, fj, held, y.data());
    c.alpha = k.alpha;
    c.beta = k.beta;
    if (k.attracts) {
      c.face = fi;
      c.face2 = fj;
      return c;
    }
    // Not on the intersection: one face may slide alone with the other held (a face already sliding
    // exits as the new one's switch takes over), when the corner rates say so consistently.
    if (k.defined) {
      const bool i_slides_now = std::any_of(rules.begin(), rules.end(), [fi](const FaceRule& r) { return r.sliding && r.face == fi; });
      const PairHandover h = handover_pair(k.A, k.B, i_slides_now ? 1 : 0);
      if (h.slides >= 0) {
        c.face = h.slides == 0 ? fi : fj;
        c.hold_face = h.slides == 0 ? fj : fi;
        c.hold_side = h.held_side;
        return c;
      }
    }
    m << "the loaded-region switches of faces " << fi << " and " << fj << " are both at zero there, and their intersection "
      << (k.solved ? "does not attract" : "has no bilinear sliding field")
      << " (Dieci & Lopez; weights α = " << k.alpha << ", β = " << k.beta << "; rates toward face " << fi
      << "'s switch " << k.A[0][0] << ", " << k.A[1][0] << ", " << k.A[0][1] << ", " << k.A[1][1] << " m/s², toward face "
      << fj << "'s " << k.B[0][0] << ", " << k.B[1][0] << ", " << k.B[0][1] << ", " << k.B[1][1]
      << " m/s², with the faces out-out, in-out, out-in, in-in)";
    c.why = m.str();
    return c;
  }
  const Sides at = sides(at_zero[0], held, y.data());
  c.g = g_[index_of(at_zero[0])];
  c.a0 = at.a0;
  c.a1 = at.a1;
  if (c.a0 > 0 && c.a1 < 0) {
    c.face = at_zero[0];
    return c;
  }
  m << "the switch at zero there, face " << at_zero[0] << "'s loaded-region switch (g = " << c.g
    << " m/s), does not attract from both sides (its rate is " << c.a0 << " m/s² with the face out of the loaded region, "
    << c.a1 << " m/s² with it in)";
  c.why = m.str();
  return c;
}

int FilippovSliding::rhs(const FaceRules& rules, const double* y, double* dydt) {
  int sliding[kMaxSlidingFaces];  // the first sliding faces (the rules hold at most kMaxSlidingFaces)
  std::size_t n_sliding = 0;
  for (const FaceRule& r : rules)
    if (r.sliding && n_sliding < kMaxSlidingFaces) sliding[n_sliding++] = r.face;
  if (n_sliding == 0) {
    hold(rules);
    rhs_forced(y, dydt);
    return 1;
  }
  if (n_sliding == 1) {
    one_switch(sliding[0], rules, y, dydt);
    return 2;
  }
  const Corners c = corners(sliding[0], sliding[1], rules, y);
  if (!c.defined) {
    hold(rules);
    rhs_forced(y, dydt);  // a face's polygon went: the loads decide (the exit is located)
    return 5;
  }
  // Outside the square (past the exit, located as a root) the weights are clamped; without a
  // solution the fields are averaged, also only past the exit.
  const double a = c.solved ? std::clamp(c.alpha, 0.0, 1.0) : 0.5, b = c.solved ? std::clamp(c.beta, 0.0, 1.0) : 0.5;
  for (int k = 0; k < kStateSize; ++k)
    dydt[k] = (1 - a) * (1 - b) * c.f[0][0][k] + a * (1 - b) * c.f[1][0][k] + (1 - a) * b * c.f[0][1][k] + a * b * c.f[1][1][k];
  return 4;
}

int FilippovSliding::roots(const FaceRules& rules, const double* y, double* g) {
  std::size_t sliding[kMaxSlidingFaces];  // indices of the first sliding rules
  std::size_t n_sliding = 0;
  for (std::size_t k = 0; k < rules.size(); ++k) {
    if (rules[k].sliding) {
      if (n_sliding < kMaxSlidingFaces) sliding[n_sliding] = k;
      ++n_sliding;
      continue;
    }
    double v = kNaN;
    switch_values({&rules[k].face, 1}, y, &v);
    g[k] = !std::isfinite(v) ? -1 : (rules[k].side == 0 ? -v : v);
  }
  if (n_sliding == 1) {
    StateVector f{};
    g[sliding[0]] = one_switch(rules[sliding[0]].face, rules, y, f.data()).exit;
    return 2;
  }
  if (n_sliding == 2) {
    const Corners c = corners(rules[sliding[0]].face, rules[sliding[1]].face, rules, y);
    const bool ok = c.defined && c.solved;
    g[sliding[0]] = ok ? std::min(c.alpha, 1 - c.alpha) : -1;
    g[sliding[1]] = ok ? std::min(c.beta, 1 - c.beta) : -1;
    return 4;
  }
  return 0;
}

FaceRules FilippovSliding::after_roots(const FaceRules& rules, const int* found, const double* y) {
  std::vector<std::size_t> sliding;
  for (std::size_t k = 0; k < rules.size(); ++k)
    if (rules[k].sliding) sliding.push_back(k);
  FaceRules next;
  if (sliding.size() == 2) {
    const std::size_t i = sliding[0], j = sliding[1];
    if (!found[i] && !found[j]) return rules;
    const Corners c = corners(rules[i].face, rules[j].face, rules, y);
    for (std::size_t k = 0; k < rules.size(); ++k)
      if (!rules[k].sliding && !found[k]) next.push_back(rules[k]);
    // The face whose weight reached 0 or 1 leaves to that side (out at 0, in at 1), and so does the
    // other where its weight is there too within kWeightAtBoundary (the twins of a mirror-symmetric
    // throw, whose two roots the root finder separates by round-off); where the weights ceased to
    // exist, both leave, each to the side its weight last pointed at.
    const bool gone = !c.defined || !c.solved;
    const double w[2] = {c.alpha, c.beta};
    const std::size_t idx[2] = {i, j};
    std::vector<std::size_t> staying;
    for (int n = 0; n < 2; ++n) {
      const FaceRule& r = rules[idx[n]];
      if (found[idx[n]] || gone || std::min(w[n], 1 - w[n]) <= kWeightAtBoundary)
        next.push_back({r.face, false, w[n] > 0.5 ? 1 : 0});
      else
        staying.push_back(idx[n]);
    }
    for (std::size_t k : staying) {
      // It slides on alone, with the other held, where its switch attracts; else it is held too.
      const Sides at = sides(rules[k].face, next, y);
      if (at.a0 > 0 && at.a1 < 0)
        next.push_back({rules[k].face, true, 0});
      else
        next.push_back({rules[k].face, false, at.a0 <= -at.a1 ? 0 : 1});
    }
    return next;
  }
  for (std::size_t k = 0; k < rules.size(); ++k) {
    const FaceRule& r = rules[k];
    if (!found[k]) {
      next.push_back(r);
      continue;
    }
    if (!r.sliding) continue;  // the hold ends: the loads decide again
    // The field that turned tangent is the one whose rate toward the switch reached zero first.
    FaceRules others;
    for (std::size_t n = 0; n < rules.size(); ++n)
      if (n != k) others.push_back(rules[n]);
    const Sides at = sides(r.face, others, y);
    next.push_back({r.face, false, at.a0 <= -at.a1 ? 0 : 1});
  }
  return next;
}

}  // namespace stoneskip
