#include "solvers/realtime/sliding_steps.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace stoneskip {

SlidingSteps::SlidingSteps(const Stone& stone, const Environment& env, bool still_water)
    : still_water_(still_water), stone_(stone), env_(env) {
  field_ = [this](const double* y, double* dydt) { extra_loads_ += sliding_->rhs(rules_, y, dydt) - 1; };
}

int SlidingSteps::sliding_count() const {
  return static_cast<int>(std::count_if(rules_.begin(), rules_.end(), [](const FaceRule& r) { return r.sliding; }));
}

StateVector SlidingSteps::rhs(const StateVector& y) {
  StateVector d{};
  field_(y.data(), d.data());
  return d;
}

std::vector<double> SlidingSteps::roots_at(const StateVector& y) {
  std::vector<double> g(rules_.size());
  if (!rules_.empty()) extra_loads_ += sliding_->roots(rules_, y.data(), g.data());
  return g;
}

void SlidingSteps::start_step(const StateVector& y) { roots0_ = roots_at(y); }

void SlidingSteps::start(const SlidingChoice& c, double t) {
  if (sliding_count() > 0) slides_.back().to_s = t;
  FaceRules next;
  for (const FaceRule& r : rules_)
    if (!r.sliding) next.push_back(r);
  next.push_back({c.face, true, 0});
  if (c.face2 >= 0) next.push_back({c.face2, true, 0});
  rules_ = next;
  slides_.push_back({c.face, c.face2, t, -1});
}

bool SlidingSteps::probe(long steps, double t, const RigidState& s) {
  if (!still_water_ || steps - probe_steps_ < kProbeSteps) return false;
  const bool stalled = t - probe_t_ < kProbeSpan_s;
  probe_steps_ = steps;
  probe_t_ = t;
  if (!stalled || sliding_count() == 2 || slides_.size() >= kMaxSlides) return false;
  if (!sliding_) sliding_.emplace(stone_, env_);
  if (!sliding_->available()) return false;
  const SlidingChoice c = sliding_->attracting(s, rules_);
  if (c.face < 0 || (sliding_count() == 1 && c.face2 < 0)) return false;
  start(c, t);
  return true;
}

double SlidingSteps::first_root(const HermiteStep& step) {
  if (rules_.empty()) return -1;
  const std::vector<double> g1 = roots_at(step.y1);
  double first = -1;
  for (std::size_t k = 0; k < rules_.size(); ++k) {
    // Watched falling through zero, as the reference watches them (a root at the start is behind).
    if (!(roots0_[k] > 0 && g1[k] <= 0)) continue;
    const double f = sign_change_fraction(
        [&](double theta) {
          std::vector<double> g(rules_.size());
          extra_loads_ += sliding_->roots(rules_, step.at(theta).data(), g.data());
          return g[k];
        },
        roots0_[k], g1[k]);
    if (first < 0 || f < first) first = f;
  }
  return first;
}

bool SlidingSteps::after_step(double t, const StateVector& y) {
  if (rules_.empty()) return false;
  const std::vector<double> g = roots_at(y);
  std::vector<int> found(rules_.size(), 0);
  bool any = false, hold_ended = false;
  for (std::size_t k = 0; k < rules_.size(); ++k) {
    found[k] = roots0_[k] > 0 && g[k] <= 0;
    any = any || found[k];
    hold_ended = hold_ended || (found[k] && !rules_[k].sliding);
  }
  if (!any) return false;
  const int before = sliding_count();
  rules_ = sliding_->after_roots(rules_, found.data(), y.data());
  const int after = sliding_count();
  if (before > 0 && after != before) {
    slides_.back().to_s = t;
    for (const FaceRule& r : rules_)
      if (r.sliding) slides_.push_back({r.face, -1, t, -1});
  }
  if (hold_ended && after == 0 && slides_.size() < kMaxSlides) {
    RigidState s = from_vector(y.data());
    s.orientation.normalize();
    const SlidingChoice c = sliding_->attracting(s, rules_);
    if (c.face >= 0) start(c, t);
  }
  return true;
}

std::string SlidingSteps::sliding_what() const {
  std::vector<int> faces;
  for (const FaceRule& r : rules_)
    if (r.sliding) faces.push_back(r.face);
  std::ostringstream m;
  if (faces.size() == 1) m << "face " << faces[0] << "'s loaded-region switch";
  if (faces.size() == 2) m << "the intersection of faces " << faces[0] << " and " << faces[1] << "'s loaded-region switches";
  return m.str();
}

std::string SlidingSteps::summary(double t_end) const {
  if (slides_.empty()) return "";
  double total = 0;
  for (const Slide& sl : slides_) total += (sl.to_s < 0 ? t_end : sl.to_s) - sl.from_s;
  std::ostringstream m;
  m << "; slid along loaded-region switches (Filippov; the steps stalled there) " << slides_.size() << " time(s), "
    << std::setprecision(4) << total * 1e3 << " ms in all:" << std::setprecision(9);
  for (std::size_t k = 0; k < slides_.size() && k < 3; ++k) {
    m << (k ? "," : "") << " face " << slides_[k].face;
    if (slides_[k].face2 >= 0) m << " and " << slides_[k].face2 << " together";
    m << " from t = " << slides_[k].from_s << " s to " << (slides_[k].to_s < 0 ? t_end : slides_[k].to_s) << " s";
  }
  if (slides_.size() > 3) m << ", …";
  return m.str();
}

}  // namespace stoneskip
