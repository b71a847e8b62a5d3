#include "verification/study/ensemble_difference.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <boost/math/distributions/students_t.hpp>

namespace stoneskip {

namespace {

// The sample mean and standard deviation (n − 1) of x (at least 2 values).
void moments(const std::vector<double>& x, double& mean, double& sd) {
  mean = std::accumulate(x.begin(), x.end(), 0.0) / x.size();
  double ss = 0;
  for (double v : x) ss += (v - mean) * (v - mean);
  sd = std::sqrt(ss / (x.size() - 1));
}

// log C(n, k), for the hypergeometric laws below.
double log_choose(int n, int k) { return std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0); }

// The exact two-sided permutation p of two ensembles without spread, all of a equal to A and all
// of b equal to B ≠ A: the number k of A values that land in the first ensemble when the N = n_a +
// n_b labels are shuffled is hypergeometric, P(k) = C(n_a, k) C(n_b, n_a − k) / C(N, n_a), and the
// difference of the means is D(k) = (A − B)(k/n_a − (n_a − k)/n_b); p sums P(k) over the k with
// |D(k)| ≥ |D(n_a)| (the observed one).
double permutation_p(int na, int nb) {
  const double observed = 1.0;  // |D(n_a)| / |A − B|
  double p = 0;
  for (int k = std::max(0, na - nb); k <= na; ++k) {
    const double d = std::abs(static_cast<double>(k) / na - static_cast<double>(na - k) / nb);
    if (d >= observed * (1 - 1e-12)) p += std::exp(log_choose(na, k) + log_choose(nb, na - k) - log_choose(na + nb, na));
  }
  return std::min(1.0, p);
}

}  // namespace

std::vector<double> perturbation_factors(int members, double smallest, double largest) {
  std::vector<double> out;
  const int half = members / 2;
  for (int k = 0; k < half; ++k) {
    const double f = half > 1 ? static_cast<double>(k) / (half - 1) : 0.0;
    const double eps = std::pow(10.0, std::log10(smallest) + f * (std::log10(largest) - std::log10(smallest)));
    out.push_back(1 + eps);
    out.push_back(1 - eps);
  }
  return out;
}

MeanDifference welch_difference(const std::vector<double>& a, const std::vector<double>& b, double confidence) {
  MeanDifference d;
  d.n_a = static_cast<int>(a.size());
  d.n_b = static_cast<int>(b.size());
  if (d.n_a < 2 || d.n_b < 2) return d;
  d.valid = true;
  moments(a, d.mean_a, d.sd_a);
  moments(b, d.mean_b, d.sd_b);
  d.difference = d.mean_a - d.mean_b;
  const double va = d.sd_a * d.sd_a / d.n_a, vb = d.sd_b * d.sd_b / d.n_b;
  d.standard_error = std::sqrt(va + vb);
  d.alpha = 1 - confidence;
  if (!(d.standard_error > 0)) {
    d.low = d.high = d.difference;
    if (d.difference != 0) d.exact_p = permutation_p(d.n_a, d.n_b);
    return d;
  }
  // Welch–Satterthwaite: ν = (va + vb)² / (va²/(n_a − 1) + vb²/(n_b − 1)).
  d.dof = (va + vb) * (va + vb) / (va * va / (d.n_a - 1) + vb * vb / (d.n_b - 1));
  const boost::math::students_t dist(d.dof);
  const double t = boost::math::quantile(boost::math::complement(dist, 0.5 * (1 - confidence)));
  d.low = d.difference - t * d.standard_error;
  d.high = d.difference + t * d.standard_error;
  return d;
}

double fisher_exact_p(int failed_a, int n_a, int failed_b, int n_b) {
  const int n = n_a + n_b, k = failed_a + failed_b;
  if (n_a <= 0 || n_b <= 0 || failed_a < 0 || failed_b < 0 || failed_a > n_a || failed_b > n_b) return 1.0;
  auto prob = [&](int x) { return std::exp(log_choose(k, x) + log_choose(n - k, n_a - x) - log_choose(n, n_a)); };
  const double observed = prob(failed_a);
  double p = 0;
  for (int x = std::max(0, n_a - (n - k)); x <= std::min(k, n_a); ++x) {
    const double q = prob(x);
    if (q <= observed * (1 + 1e-7)) p += q;  // R's fisher.test: a relative tolerance of 1e-7
  }
  return std::min(1.0, p);
}

double bonferroni_confidence(double family_confidence, std::size_t comparisons) {
  return 1 - (1 - family_confidence) / static_cast<double>(std::max<std::size_t>(comparisons, 1));
}

MeanDifference paired_difference(const std::vector<double>& a, const std::vector<double>& b, double confidence) {
  MeanDifference d;
  d.alpha = 1 - confidence;
  d.n_a = static_cast<int>(a.size());
  d.n_b = static_cast<int>(b.size());
  if (a.size() != b.size() || d.n_a < 2) return d;
  d.valid = true;
  moments(a, d.mean_a, d.sd_a);
  moments(b, d.mean_b, d.sd_b);
  std::vector<double> diff(a.size());
  for (std::size_t k = 0; k < a.size(); ++k) diff[k] = a[k] - b[k];
  double sd = 0;
  moments(diff, d.difference, sd);
  d.standard_error = sd / std::sqrt(static_cast<double>(diff.size()));
  if (!(d.standard_error > 0)) {
    d.low = d.high = d.difference;
    if (d.difference != 0) d.exact_p = std::pow(2.0, 1.0 - static_cast<double>(diff.size()));  // all d_k of one sign
    return d;
  }
  d.dof = static_cast<double>(diff.size() - 1);
  const boost::math::students_t dist(d.dof);
  const double t = boost::math::quantile(boost::math::complement(dist, 0.5 * (1 - confidence)));
  d.low = d.difference - t * d.standard_error;
  d.high = d.difference + t * d.standard_error;
  return d;
}

}  // namespace stoneskip
