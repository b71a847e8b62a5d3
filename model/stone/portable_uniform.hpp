#pragma once
// A portable uniform generator for the stone tests' random states (SplitMix64, Steele, Lea & Flood
// 2014): the same numbers on every platform and standard library, where <random>'s distributions
// are not.
#include <cstdint>

namespace stoneskip {

struct PortableUniform {
  std::uint64_t x;  // the state; the seed to begin with
  // A double uniform in [lo, hi): the top 53 bits of the next output.
  double operator()(double lo, double hi) {
    std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return lo + (hi - lo) * (static_cast<double>(z >> 11) * 0x1.0p-53);
  }
};

}  // namespace stoneskip
