#pragma once
// Comparing two settings of a chaotic throw on ensembles (model/README.md §2.4, "Both"): the
// bounce count of a throw may change under a 1e-9 relative change of its speed, so one run of each
// setting shows nothing. Each setting runs an ensemble of throws whose speed is perturbed by
// relative amounts log-spaced over [smallest, largest], of both signs; the two ensembles' mean
// counts are compared by Welch's t interval (Welch 1947): difference of means ± t_{0.975, ν} · se,
// se² = s_a²/n_a + s_b²/n_b, ν by Welch–Satterthwaite. An interval that excludes 0 establishes a
// difference; one that contains it does not (and says so). Two ensembles without spread give the
// difference itself as the interval (the count did not depend on the perturbation), and then an
// exact permutation test decides instead of the t interval, whose zero width would otherwise
// establish {9, 9} against {8, 8, 8}: relabelling the members at random puts every 9 in the first
// ensemble with probability 1/C(5, 2) = 0.1 (Fisher 1935, The Design of Experiments, §21; the
// hypergeometric law of where the values fall), not below 0.05.
#include <cstddef>
#include <limits>
#include <vector>

namespace stoneskip {

// members factors 1 + ε, ε = ±10^(log-spaced from log10 smallest to log10 largest), members/2 of
// each sign (members even, ≥ 2).
std::vector<double> perturbation_factors(int members, double smallest, double largest);

struct MeanDifference {
  bool valid = false;           // both samples have ≥ 2 members
  double mean_a = 0, mean_b = 0;
  double sd_a = 0, sd_b = 0;    // sample standard deviations
  int n_a = 0, n_b = 0;
  double difference = 0;        // mean_a − mean_b
  double standard_error = 0;
  double dof = 0;               // Welch–Satterthwaite ν (infinite without spread: 0 stored)
  double low = 0, high = 0;     // 95 % (or the asked-for level's) interval of the difference
  // Where neither ensemble (paired: no difference) has spread and the means differ: the exact
  // permutation test's two-sided p (NaN where the t interval decides), and its level 1 − confidence.
  double exact_p = std::numeric_limits<double>::quiet_NaN();
  double alpha = 0.05;
  bool established() const { return valid && (low > 0 || high < 0) && !(exact_p > alpha); }
};

// `confidence`: the interval's two-sided level (0.95 for 95 %); a family of m comparisons held to
// 95 % together takes 1 − 0.05/m each (Bonferroni).
MeanDifference welch_difference(const std::vector<double>& a, const std::vector<double>& b, double confidence = 0.95);

// The same for two ensembles whose members are paired (a_k and b_k thrown with the same
// perturbation: two meshes, or a throw and its mirror image): the t interval of the mean of the
// differences d_k = a_k − b_k, se = sd(d)/√n, ν = n − 1 (Student 1908). Members without spread in
// d give the difference itself as the interval, decided by the exact sign-flip test: every d_k of
// one sign has p = 2 / 2^n under the null (Fisher 1935, §21). a and b must have one size (≥ 2 to be valid);
// mean_a, sd_a, mean_b, sd_b are each ensemble's own. `confidence` as for welch_difference.
MeanDifference paired_difference(const std::vector<double>& a, const std::vector<double>& b, double confidence = 0.95);

// The level of each of m comparisons held to `family_confidence` together (Bonferroni):
// 1 − (1 − family_confidence)/m, the family's own level where m is 0 or 1.
double bonferroni_confidence(double family_confidence, std::size_t comparisons);

// Fisher's exact test of two proportions (Fisher 1935, §12; the 2 × 2 table): failed_a of n_a
// against failed_b of n_b. Given the failures in all, the number in the first group is
// hypergeometric; the two-sided p sums the tables no more probable than the one observed (as R's
// fisher.test). For 3 of 16 against 12 of 16, p = 0.0038.
double fisher_exact_p(int failed_a, int n_a, int failed_b, int n_b);

}  // namespace stoneskip
