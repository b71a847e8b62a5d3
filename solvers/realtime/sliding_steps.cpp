#include "solvers/realtime/sliding_steps.hpp"

namespace stoneskip {

SlidingSteps::SlidingSteps(const Stone& stone, const Environment& env, bool enabled)
    : enabled_(enabled), stone_(stone), env_(env) {
  field_ = [this](const double* y, double* dydt) { extra_loads_ += sliding_->rhs(record_.rules(), y, dydt) - 1; };
}

StateVector SlidingSteps::rhs(const StateVector& y) {
  StateVector d{};
  field_(y.data(), d.data());
  return d;
}

void SlidingSteps::roots_at(const StateVector& y, std::vector<double>& g) {
  g.resize(record_.rules().size());
  if (!g.empty()) extra_loads_ += sliding_->roots(record_.rules(), y.data(), g.data());
}

void SlidingSteps::start_step(const StateVector& y) { roots_at(y, roots0_); }

bool SlidingSteps::probe(long steps, double t, const RigidState& s) {
  if (!enabled_ || steps - probe_steps_ < kProbeSteps) return false;
  const bool stalled = t - probe_t_ < kProbeSpan_s;
  probe_steps_ = steps;
  probe_t_ = t;
  const int sliding = record_.sliding_count();
  if (!stalled || sliding == 2 || record_.slides() >= kMaxSlides) return false;
  if (!sliding_) sliding_.emplace(stone_, env_);
  if (!sliding_->available()) return false;
  const SlidingChoice c = sliding_->attracting(s, record_.rules());
  if (c.face < 0 || (sliding == 1 && !c.changes_sliding())) return false;
  record_.start(c, t);
  return true;
}

double SlidingSteps::first_root(const HermiteStep& step) {
  const FaceRules& rules = record_.rules();
  if (rules.empty()) return -1;
  roots_at(step.y1, roots1_);
  const std::vector<double>& g1 = roots1_;
  double first = -1;
  for (std::size_t k = 0; k < rules.size(); ++k) {
    // Watched falling through zero, as the reference watches them (a root at the start is behind).
    if (!(roots0_[k] > 0 && g1[k] <= 0)) continue;
    const double f = sign_change_fraction(
        [&](double theta) {
          roots_at(step.at(theta), roots_inside_);
          return roots_inside_[k];
        },
        roots0_[k], g1[k]);
    if (first < 0 || f < first) first = f;
  }
  return first;
}

bool SlidingSteps::after_step(double t, const StateVector& y) {
  const FaceRules& rules = record_.rules();
  if (rules.empty()) return false;
  roots_at(y, roots1_);
  found_.assign(rules.size(), 0);
  bool any = false, hold_ended = false;
  for (std::size_t k = 0; k < rules.size(); ++k) {
    found_[k] = roots0_[k] > 0 && roots1_[k] <= 0;
    any = any || found_[k];
    hold_ended = hold_ended || (found_[k] && !rules[k].sliding);
  }
  if (!any) return false;
  // The new rules are made whole from the old before they replace them (`rules` is not read after).
  record_.set(sliding_->after_roots(rules, found_.data(), y.data()), t);
  if (hold_ended && record_.sliding_count() == 0 && record_.slides() < kMaxSlides) {
    RigidState s = from_vector(y.data());
    s.orientation.normalize();
    const SlidingChoice c = sliding_->attracting(s, record_.rules());
    if (c.face >= 0) record_.start(c, t);
  }
  return true;
}

}  // namespace stoneskip
