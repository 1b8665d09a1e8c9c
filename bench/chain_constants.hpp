// The constants of the benchmark chain of ball-jointed thin rods (bench/rod_chain.hpp builds it in poinsot),
// kept free of poinsot's headers so that the peer adapters in bench/peers/ can use them in any C++ standard
// (Simbody's headers compile only as C++17).
#pragma once

namespace poinsot::bench {

inline constexpr double kRodMass = 1.0;     ///< kg
inline constexpr double kRodLength = 1.0;   ///< m
inline constexpr double kRodRadius = 0.01;  ///< m
inline constexpr double kGravity = 9.81;    ///< m/s², along -z
inline constexpr double kChainDt = 1e-3;    ///< s

/// Releasable potential energy of the chain falling from horizontal to hanging, J: m g l N²/2
/// (the centres of mass drop by (i + 1/2) l, summed over i < N).
inline double releasable_energy(int n) {
  return kRodMass * kGravity * kRodLength * n * n / 2.0;
}

}  // namespace poinsot::bench
