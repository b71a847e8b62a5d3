#include "tools/scene/case_problem.hpp"

namespace stoneskip {

ThrowProblem problem_from_case(const StoneCase& c) {
  ThrowProblem p;
  p.label = c.title;
  p.stone = c.stone;
  p.environment = c.environment;
  p.from_parameters = c.throw_from_parameters;
  p.parameters = c.throw_parameters;
  p.initial = c.initial;
  p.realtime = c.realtime;
  p.reference = c.reference;
  return p;
}

}  // namespace stoneskip
