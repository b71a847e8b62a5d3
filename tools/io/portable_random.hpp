#pragma once
// Random draws that are the same whatever standard library built the program.
//
// The engines of <random> are specified to the bit (C++20 [rand.predef]: the 10 000th output of a
// default-constructed std::mt19937_64 is 9981545732273789042), the distributions are not:
// libstdc++, libc++ and Microsoft's library draw std::uniform_real_distribution and
// std::normal_distribution by different algorithms, so a seed gives other noise on another
// platform. PortableDraws follows libstdc++'s algorithms (GCC 12, bits/random.h and random.tcc), so
// what a seed gave where stoneskip was built so far (Debian, GCC) it still gives bit for bit, and it
// gives the same on every other library: exactly for unit() and uniform(); for gauss() up to the last
// bit of std::log, which IEEE 754 does not require to be correctly rounded.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace stoneskip {

template <class Engine>
class PortableDraws {
  static_assert(Engine::min() == 0, "an engine whose outputs start at 0");
  static_assert(Engine::max() == 0xffffffffULL || Engine::max() == std::numeric_limits<std::uint64_t>::max(),
                "an engine of 32 or 64 full bits (std::mt19937, std::mt19937_64)");
  static constexpr int kBits = std::bit_width(static_cast<std::uint64_t>(Engine::max()));
  // std::generate_canonical<double, 53>: as many outputs as hold 53 bits (libstdc++:
  // max(1, (b + log2 r − 1) / log2 r)), one of a 64-bit engine, two of a 32-bit one.
  static constexpr int kCalls = (std::numeric_limits<double>::digits + kBits - 1) / kBits;

 public:
  explicit PortableDraws(typename Engine::result_type seed) : engine_(seed) {}

  // A double in [0, 1): Σ_k x_k r^k / r^calls with r = 2^bits, the first output the lowest, in
  // double arithmetic; a sum that rounds up to 1 becomes the largest double below 1.
  double unit() {
    double sum = 0.0, scale = 1.0;
    for (int k = 0; k < kCalls; ++k) {
      sum += static_cast<double>(engine_()) * scale;
      scale *= kRadix;
    }
    const double u = sum / scale;
    return u < 1.0 ? u : std::nextafter(1.0, 0.0);
  }

  // A double in [lo, hi): std::uniform_real_distribution's (u (hi − lo)) + lo.
  double uniform(double lo, double hi) { return unit() * (hi - lo) + lo; }

  // A standard normal draw: Marsaglia's polar method as libstdc++ draws std::normal_distribution,
  // two uniforms on (−1, 1) inside the unit circle give two normals, the first (x) kept for the next
  // call. One PortableDraws stands for one engine shared by one normal and any uniform draws.
  double gauss() {
    if (saved_available_) {
      saved_available_ = false;
      return saved_;
    }
    double x, y, r2;
    do {
      x = 2.0 * unit() - 1.0;
      y = 2.0 * unit() - 1.0;
      r2 = x * x + y * y;
    } while (r2 > 1.0 || r2 == 0.0);
    const double mult = std::sqrt(-2 * std::log(r2) / r2);
    saved_ = x * mult;
    saved_available_ = true;
    return y * mult;
  }

 private:
  static constexpr double kRadix = kBits == 64 ? 0x1p64 : 0x1p32;
  Engine engine_;
  double saved_ = 0.0;
  bool saved_available_ = false;
};

}  // namespace stoneskip
