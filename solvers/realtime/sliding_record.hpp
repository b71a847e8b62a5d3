#pragma once
// The rules of one solve's sliding (filippov_sliding.hpp) and the intervals it slid, kept alike by
// the CVODE reference (cvode_stone.cpp) and the adaptive real-time stepper (sliding_steps.hpp): the
// faces treated apart now, what slides, and the outcome's account of every slide.
#include <string>
#include <vector>

#include "solvers/realtime/filippov_sliding.hpp"

namespace stoneskip {

class SlidingRecord {
 public:
  const FaceRules& rules() const { return rules_; }
  int sliding_count() const;  // faces sliding now (0, 1 or 2)
  std::size_t slides() const { return slides_.size(); }
  double sliding_since() const { return slides_.empty() ? 0 : slides_.back().from_s; }

  // The sliding faces of c replace any sliding now (its interval ends at t); held faces stay held.
  void start(const SlidingChoice& c, double t);
  // The rules after roots at t (FilippovSliding::after_roots): where the sliding faces changed, the
  // slide ends at t and what still slides begins a new one.
  void set(const FaceRules& next, double t);

  // "face 4's loaded-region switch", or the two faces' intersection; empty where nothing slides.
  std::string sliding_what() const;
  // "; slid along loaded-region switches (Filippov; the steps <how> there) n time(s), … ms in all:
  // face …" (the first three slides; one still open ends at t_end), or empty.
  std::string summary(double t_end, const std::string& how) const;

 private:
  struct Slide {
    int face = -1, face2 = -1;  // face2: the second face, sliding on the two switches' intersection
    double from_s = 0, to_s = -1;  // to_s < 0: still sliding
  };
  FaceRules rules_;
  std::vector<Slide> slides_;
};

}  // namespace stoneskip
