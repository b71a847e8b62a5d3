#include "verification/scene/coupled_stability.hpp"

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "model/coupling/draught.hpp"
#include "model/stone/mesh.hpp"
#include "tools/io/portable_random.hpp"

namespace stoneskip {

bool CoupledStabilityOptions::is_valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (!is_stencil_name(stencil)) return fail("unknown stencil '" + stencil + "'");
  if (!(margin > 0 && margin < 0.5)) return fail("margin must be in (0, 0.5)");
  if (n < 16 || n > 1024) return fail("n must be in [16, 1024]");
  if (steps < 20 || steps_above < 20) return fail("steps must be >= 20");
  if (!(damping_per_s >= 0)) return fail("damping must be >= 0");
  return true;
}

namespace {

double rms_departure(const HeightField& f, const std::vector<double>& ref) {
  double s = 0;
  for (int j = 0; j < f.ny(); ++j)
    for (int i = 0; i < f.nx(); ++i) {
      const double e = f.height(i, j) - ref[static_cast<std::size_t>(j) * f.nx() + i];
      s += e * e;
    }
  return std::sqrt(s / (static_cast<double>(f.nx()) * f.ny()));
}

struct Growth {
  double rate = 0, departure = 0;
};

// The held stone: a prism of radius n/4 cells, 4 cm thick, bottom at −2 cm (b stays linear in z
// while the departure is below 1 cm).
Growth growth(const CoupledStabilityOptions& o, double sigma, bool with_stone, long steps) {
  HeightFieldOptions f;
  f.nx = f.ny = o.n;
  f.cell_m = 1.0 / o.n;
  f.wave_speed_m_s = 1;
  f.damping_per_s = o.damping_per_s;
  f.dt_s = sigma * f.cell_m;
  f.stencil = named_stencil(o.stencil);
  f.boundary = Boundary::periodic;
  HeightField field(f);
  const double h = 0.04, s = -0.02;
  StoneDraught stone(make_prism(0.25, h, 11));
  const Vec3 at(0.5 + 0.3 * f.cell_m, 0.5 + 0.2 * f.cell_m, s + 0.5 * h);
  DraughtPatch p;
  std::vector<double> eq(static_cast<std::size_t>(o.n) * o.n, 0.0);
  if (with_stone) {
    stone.compute(at, Mat3::Identity(), field, FieldPlacement{}, p);
    int k = 0;
    for (double b : p.b_m) k += b > 0;
    const double N = static_cast<double>(o.n) * o.n, C = -k * s / (2 * N - k);
    for (auto& z : eq) z = C;
    for (int c = 0; c < p.nj; ++c)
      for (int a = 0; a < p.ni; ++a)
        if (p.at(a, c) > 0) {
          const int i = ((p.i0 + a) % o.n + o.n) % o.n, j = ((p.j0 + c) % o.n + o.n) % o.n;
          eq[static_cast<std::size_t>(j) * o.n + i] = 0.5 * (C + s);
        }
  }
  std::vector<double> z = eq;
  PortableDraws<std::mt19937> rng(5);  // the same perturbation on every standard library
  for (auto& v : z) v += rng.uniform(-1e-12, 1e-12);
  field.set_levels(z, z);
  double at10 = 0;
  for (long step = 0; step < steps; ++step) {
    if (with_stone) stone.compute(at, Mat3::Identity(), field, FieldPlacement{}, p);
    else p.clear();
    field.step(p);
    if (step + 1 == 10) at10 = rms_departure(field, eq);
  }
  Growth g;
  g.departure = rms_departure(field, eq);
  g.rate = at10 > 0 ? std::pow(g.departure / at10, 1.0 / static_cast<double>(steps - 10)) : 0;
  return g;
}

}  // namespace

CoupledStability measure_coupled_stability(const CoupledStabilityOptions& o) {
  std::string why;
  if (!o.is_valid(&why)) throw std::invalid_argument("coupled stability: " + why);
  CoupledStability r;
  r.stencil = o.stencil;
  const Stencil st = named_stencil(o.stencil);
  r.free_limit = leapfrog_courant_limit(st);
  r.coupled_limit = coupled_courant_limit(st);
  r.sigma_below = (1 - o.margin) * r.coupled_limit;
  r.sigma_above = (1 + o.margin) * r.coupled_limit;
  r.growth_below = growth(o, r.sigma_below, true, o.steps).rate;
  const Growth above = growth(o, r.sigma_above, true, o.steps_above);
  r.growth_above = above.rate;
  r.departure_above_m = above.departure;
  r.growth_free_above = growth(o, r.sigma_above, false, o.steps).rate;
  return r;
}

}  // namespace stoneskip
