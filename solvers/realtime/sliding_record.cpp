#include "solvers/realtime/sliding_record.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace stoneskip {

int SlidingRecord::sliding_count() const {
  return static_cast<int>(std::count_if(rules_.begin(), rules_.end(), [](const FaceRule& r) { return r.sliding; }));
}

void SlidingRecord::start(const SlidingChoice& c, double t) {
  if (sliding_count() > 0) slides_.back().to_s = t;
  FaceRules next;
  for (const FaceRule& r : rules_)
    if (!r.sliding && r.face != c.hold_face) next.push_back(r);
  if (c.hold_face >= 0) next.push_back({c.hold_face, false, c.hold_side});  // handed over: it exits to that side
  next.push_back({c.face, true, 0});
  if (c.face2 >= 0) next.push_back({c.face2, true, 0});
  rules_ = next;
  slides_.push_back({c.face, c.face2, t, -1});
}

void SlidingRecord::set(const FaceRules& next, double t) {
  const int before = sliding_count();
  rules_ = next;
  if (before == 0 || sliding_count() == before) return;
  slides_.back().to_s = t;
  for (const FaceRule& r : rules_)
    if (r.sliding) slides_.push_back({r.face, -1, t, -1});
}

std::string SlidingRecord::sliding_what() const {
  std::vector<int> faces;
  for (const FaceRule& r : rules_)
    if (r.sliding) faces.push_back(r.face);
  std::ostringstream m;
  if (faces.size() == 1) m << "face " << faces[0] << "'s loaded-region switch";
  if (faces.size() == 2) m << "the intersection of faces " << faces[0] << " and " << faces[1] << "'s loaded-region switches";
  return m.str();
}

std::string SlidingRecord::summary(double t_end, const std::string& how) const {
  if (slides_.empty()) return "";
  auto to = [&](const Slide& sl) { return sl.to_s < 0 ? t_end : sl.to_s; };
  double total = 0;
  for (const Slide& sl : slides_) total += to(sl) - sl.from_s;
  std::ostringstream m;
  m << "; slid along loaded-region switches (Filippov; the steps " << how << " there) " << slides_.size() << " time(s), "
    << std::setprecision(4) << total * 1e3 << " ms in all:" << std::setprecision(9);
  for (std::size_t k = 0; k < slides_.size() && k < 3; ++k) {
    m << (k ? "," : "") << " face " << slides_[k].face;
    if (slides_[k].face2 >= 0) m << " and " << slides_[k].face2 << " together";
    m << " from t = " << slides_[k].from_s << " s to " << to(slides_[k]) << " s";
  }
  if (slides_.size() > 3) m << ", …";
  return m.str();
}

}  // namespace stoneskip
