#pragma once
// How far a model is from the measurements: one number per quantity and their
// mean, the metric the stones report ranks the water laws by.
//
// A measured quantity is a range [low, high] (a single value when its source gives one; both ends
// of the same sign). The distance of a model value m from it is
//     0                                   when m lies in the range,
//     min(|ln(m/low)|, |ln(m/high)|)       otherwise (the factor to the nearer end, as a logarithm),
// capped at `miss` (a factor of e^miss), and `miss` itself where the model has no value (it does
// not bounce where the measurement bounces, its first contact never ends in a take-off, a fit has
// too few points) or a value of the other sign. The distance of a model is the mean over the
// quantities scored. A logarithm makes a factor of 2 too high and a factor of 2 too low equally far.
#include <string>
#include <vector>

namespace stoneskip {

struct MeasuredRange {
  double low = 0, high = 0;  // same sign, low ≤ high
};

struct ScoredValue {
  std::string key;           // the measured quantity ("clanet_min_speed", ...)
  bool has_value = false;    // false: the model cannot produce the quantity (scored `miss`)
  double model = 0;
  bool bound_only = false;   // the model value is only a bound (a bisection that bounced at its end):
                             // its distance is a lower bound
  std::string note;          // why there is no value, or what the bound is
};

double quantity_distance(const ScoredValue& v, const MeasuredRange& r, double miss);

struct ModelDistance {
  std::vector<double> distances;  // per quantity, in the order given
  double mean = 0;                // NaN when no quantity is scored
};

ModelDistance model_distance(const std::vector<ScoredValue>& values, const std::vector<MeasuredRange>& ranges, double miss);

}  // namespace stoneskip
