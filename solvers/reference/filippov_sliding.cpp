#include "solvers/reference/filippov_sliding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "model/stone/rigid_body.hpp"

namespace stoneskip {

FilippovSliding::FilippovSliding(const Stone& stone, const Environment& env)
    : stone_(stone), env_(env), switches_(stone, env) {}

std::size_t FilippovSliding::index_of(int face) const {
  return 2 * stone_.body_mesh.vertices.size() + static_cast<std::size_t>(face);  // load_switches.hpp's order
}

// The face's switch value at y: LoadSwitches' loaded_face function, which depends on the state
// alone (not on a recorded mode), read after recording the mode of y.
double FilippovSliding::switch_value(int face, const double* y) {
  RigidState s = from_vector(y);
  s.orientation.normalize();
  switches_.reset(s, g_);
  const std::size_t k = index_of(face);
  return k < g_.size() ? g_[k] : std::numeric_limits<double>::quiet_NaN();
}

double FilippovSliding::rate_along(int face, const double* y, const double* f) {
  StateVector plus{}, minus{};
  for (int k = 0; k < kStateSize; ++k) {
    plus[k] = y[k] + kDirectionalStep_s * f[k];
    minus[k] = y[k] - kDirectionalStep_s * f[k];
  }
  return (switch_value(face, plus.data()) - switch_value(face, minus.data())) / (2 * kDirectionalStep_s);
}

FilippovSliding::Sides FilippovSliding::sides(int face, const double* y) {
  Sides out;
  rhs_with_face(face, 0, y, out.f0.data());
  rhs_with_face(face, 1, y, out.f1.data());
  out.a0 = rate_along(face, y, out.f0.data());
  out.a1 = rate_along(face, y, out.f1.data());
  return out;
}

// The loads with the face held out of (loaded = 0) or in (1) the loaded region, every other face
// as the loads decide it from the state (LoadMode::kDecide).
void FilippovSliding::rhs_with_face(int face, char loaded, const double* y, double* dydt) {
  mode_.loaded_faces.assign(stone_.body_mesh.triangles.size(), LoadMode::kDecide);
  mode_.loaded_faces[static_cast<std::size_t>(face)] = loaded;
  rigid_body_rhs(stone_, env_, y, dydt, nullptr, nullptr, &mode_);
}

SlidingChoice FilippovSliding::attracting_face(const RigidState& s) {
  SlidingChoice c;
  if (!available()) {
    c.why = "only the savitsky distributions' loaded-region switches are slid along (physical convention)";
    return c;
  }
  RigidState sn = s;
  sn.orientation.normalize();
  const StateVector y = to_vector(sn);
  switches_.reset(sn, g_);
  const int nf = static_cast<int>(stone_.body_mesh.triangles.size());
  int best = -1;
  std::vector<int> at_zero;
  for (int i = 0; i < nf; ++i) {
    const double gi = g_[index_of(i)];
    if (!std::isfinite(gi)) continue;
    if (std::abs(gi) <= kAtSwitch_m_s) at_zero.push_back(i);
    if (best < 0 || std::abs(gi) < std::abs(g_[index_of(best)])) best = i;
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
  if (at_zero.size() > 1) {
    m << "the loaded-region switches of faces";
    for (std::size_t k = 0; k < at_zero.size(); ++k) m << (k ? (k + 1 == at_zero.size() ? " and " : ", ") : " ") << at_zero[k];
    m << (at_zero.size() == 2 ? " are both" : " are all") << " at zero there (a mirror-symmetric throw's twin faces, say): sliding on two switches at once "
         "has no unique field and is not treated";
    c.why = m.str();
    return c;
  }
  const Sides at = sides(best, y.data());
  c.a0 = at.a0;
  c.a1 = at.a1;
  if (c.a0 > 0 && c.a1 < 0) {
    c.face = best;
    return c;
  }
  m << "the switch at zero there, face " << best << "'s loaded-region switch (g = " << c.g
    << " m/s), does not attract from both sides (its rate is " << c.a0 << " m/s² with the face out of the loaded region, "
    << c.a1 << " m/s² with it in)";
  c.why = m.str();
  return c;
}

SlidingField FilippovSliding::field(int face, const double* y, double* dydt) {
  SlidingField out;
  const Sides at = sides(face, y);
  const double a0 = at.a0, a1 = at.a1;
  if (!std::isfinite(a0) || !std::isfinite(a1)) {
    // The face has no wetted polygon here: its switch is undefined and the loads decide alone.
    rigid_body_rhs(stone_, env_, y, dydt);
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

double FilippovSliding::exit_value(int face, const double* y) {
  StateVector f{};
  return field(face, y, f.data()).exit;
}

int FilippovSliding::leaving_side(int face, const double* y) {
  // The field that turned tangent is the one whose rate toward the switch reached zero first.
  const Sides at = sides(face, y);
  return at.a0 <= -at.a1 ? 0 : 1;
}

void FilippovSliding::held_rhs(int face, int side, const double* y, double* dydt) {
  rhs_with_face(face, static_cast<char>(side), y, dydt);
}

double FilippovSliding::held_value(int face, int side, const double* y) {
  const double g = switch_value(face, y);
  if (!std::isfinite(g)) return -1;
  return side == 0 ? -g : g;
}

}  // namespace stoneskip
