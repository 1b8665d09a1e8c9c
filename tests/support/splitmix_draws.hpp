#pragma once
/// @file splitmix_draws.hpp
/// A fixed-seed SplitMix64 stream of uniform draws in [−1, 1), for tests whose ensemble must be the same
/// sequence from run to run and from test to test (the round-off growth ensembles, which
/// bench/brouwer_growth.cpp draws with the same generator and seed).

#include <cstdint>

#include "poinsot/core/types.hpp"

namespace poinsot::test {

struct SplitMixDraws {
  std::uint64_t s = 20;  ///< the state; 20 is the ensembles' seed
  /// The next draw, uniform in [−1, 1) with 53 random bits.
  double uniform() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return 2.0 * static_cast<double>(z >> 11) * 0x1.0p-53 - 1.0;
  }
  /// Three draws (x, y, z in that order) times `scale`.
  Vec3 vec(double scale) {
    const double a = uniform(), b = uniform(), c = uniform();
    return scale * Vec3(a, b, c);
  }
};

}  // namespace poinsot::test
