#pragma once
/// @file growth_exponent.hpp
/// The exponent p of a growth law y ∝ N^p, fitted by least squares on log y against log N: the round-off
/// growth tests and bench/brouwer_growth.cpp fit Brouwer's law (p = 1/2 for a random walk, 1 for a bias)
/// with it.

#include <cmath>
#include <cstddef>
#include <vector>

namespace poinsot::test {

/// The least-squares slope of log y against log n over the points with y > 0 (an error that is exactly 0
/// has no logarithm); NaN when fewer than two remain. `n` holds step counts (any arithmetic type).
template <class Count>
double growth_exponent(const std::vector<Count>& n, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int points = 0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!(y[i] > 0.0)) continue;
    const double lx = std::log(static_cast<double>(n[i])), ly = std::log(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
    ++points;
  }
  if (points < 2) return std::nan("");
  return (points * sxy - sx * sy) / (points * sxx - sx * sx);
}

}  // namespace poinsot::test
