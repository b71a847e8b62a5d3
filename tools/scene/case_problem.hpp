#pragma once
// A stone case file as the studies' throw: the stone, environment, initial state and the case's
// solver settings (verification/stones/throw_problem.hpp). The studies never read case files
// themselves; the command line loads them and hands them this.
#include "tools/scene/stone_case.hpp"
#include "verification/stones/throw_problem.hpp"

namespace stoneskip {

ThrowProblem problem_from_case(const StoneCase& c);

}  // namespace stoneskip
