#pragma once
// Time histories of one throw, for the paper's Fig. 9 (momentum against time) and for explaining
// why the two conventions disagree: momentum, energy, the rate at which the fluids do work on the
// stone (model/README.md §1.6: never positive in the physical convention), height, attitude (attack and roll
// angle), spin.
#include <limits>
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
  // The time the stone would take to pass through its own vertical extent (its mesh's, at the pose of
  // the trajectory sample nearest the first contact's start) at the first contact's vertical entry
  // speed: how long a plunge into the water would last if the water did not hold the stone up
  // (the surfing rule, verdict_rules.hpp). NaN without a contact or without a downward entry.
  double plunge_s = std::numeric_limits<double>::quiet_NaN();
};

ThrowHistory make_history(const ThrowProblem& p, ThrowResult result, const std::string& label);

}  // namespace stoneskip
