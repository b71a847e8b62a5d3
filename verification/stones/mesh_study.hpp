#pragma once
// Bounce counts against the stone's mesh (model/README.md §1.1): is a count a property of the
// stone, or of the 44 triangles it is drawn with? The same throws are thrown with prisms of N rim
// segments, each rim face cut along one diagonal (the paper's mesh: it has a hand) or at its centre
// (a mesh that is its own mirror image), and each mesh's counts are compared with those of its
// cut's reference mesh, the same cut at the largest N (the cut changes the faces, not the solid; N
// changes both: with the case's density the N-gon's mass follows N, with its mass the inertia).
// Where both cuts reach one largest N, their two references are compared with each other too.
//
// A count is chaotic (it may change under a 1e-9 relative change of the speed), so each throw runs
// as an ensemble (speed × 1 ± ε, ε log-spaced over [smallest, largest], the same factors for every
// mesh) and two ensembles, whose members pair up by their speed factor, are compared by the paired
// t interval of the difference of their counts (verification/study/ensemble_difference.hpp;
// rule ensemble_count_difference). Where the
// throws hold a spin s and its mirror −s at one attack angle, each mesh's pair is compared the same
// way: a difference is the mesh's hand.
//
// The levels. Against its cut's reference each verdict is at 95 % on its own: there a chance
// "different" can only make a mesh look unsettled (the cautious side of the settled N), while a
// stricter level would make settling easier by chance. The cuts' comparisons and the mirror pairs
// claim a difference where they find one (the cut changes the count; the mesh shows its hand), so
// each is one family held to family_confidence together (Bonferroni: each of its m verdicts at
// 1 − (1 − family_confidence)/m).
#include <string>
#include <vector>

#include "model/stone/mesh.hpp"
#include "verification/stones/parallel_runs.hpp"
#include "verification/stones/throw_problem.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

struct MeshVariant {
  int segments = 11;
  RimSplit split = RimSplit::diagonal;
  Stone stone;  // built from the base case's stone with these segments and this cut
};

struct MeshStudyOptions {
  std::vector<MeshVariant> meshes;          // at least 2, no two alike
  std::vector<double> spins_rev_s{-40, 0, 40};
  std::vector<double> attack_angles_deg{10, 20};
  int members = 16;                         // perturbed throws per mesh and throw (even, ≥ 2)
  double perturbation_smallest = 1e-9;
  double perturbation_largest = 1e-4;
  double family_confidence = 0.95;          // the cuts' verdicts, and the mirror pairs', each held together, (0, 1)
  bool valid(std::string* why = nullptr) const;
  // The reference of mesh m: the mesh of its cut with the largest N (m itself where it is that one).
  std::size_t reference_of(std::size_t m) const;
};

// One throw (spin, attack angle) on every mesh: counts[mesh][member], −1 where the solve failed.
struct MeshThrowRuns {
  double spin_rev_s = 0, attack_angle_deg = 0;
  std::vector<std::vector<double>> counts;
};

// Every throw on every mesh with the solver given (the base's parameters with each spin and attack
// angle; the base must give [throw] parameters), on the workers.
std::vector<MeshThrowRuns> run_mesh_study(const ThrowProblem& base, const SolverChoice& solver, const MeshStudyOptions& options,
                                          const ParallelOptions& parallel);

// The section's record: the meshes, every ensemble's mean and spread, a verdict per mesh and throw
// against its cut's reference, per throw between the two cuts' references (where they share N), per
// mesh and mirror pair, the tallies per mesh, and per cut the N from which no difference from the
// reference is established.
Record mesh_study_findings(const std::vector<MeshThrowRuns>& runs, const MeshStudyOptions& options,
                           const std::string& solver_label);

}  // namespace stoneskip
