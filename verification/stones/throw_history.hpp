#pragma once
// Time histories of one throw, for the paper's Fig. 9 (momentum against time) and for explaining
// why the two conventions disagree: momentum, energy, the rate at which the fluids do work on the
// stone (model/README.md §1.6: never positive in the physical convention), height, attitude (attack and roll
// angle), spin.
#include <string>
#include <vector>

#include "tools/io/hdf5_file.hpp"
#include "verification/stones/throw_problem.hpp"

namespace stoneskip {

struct ThrowHistory {
  std::string label;        // "8 m/s, 10 rev/s, physical, reference"
  std::string solver;
  Convention convention = Convention::physical;
  ThrowResult result;       // trajectory cleared (the table below holds it)
  // Columns: t_s, momentum_kg_m_s, energy_J, fluid_power_W, x_m, y_m, z_m, attack_deg, roll_deg,
  //          spin_rev_s (about body z), wetted_area_m2.
  Table table;
};

ThrowHistory make_history(const ThrowProblem& p, ThrowResult result, const std::string& label);

}  // namespace stoneskip
