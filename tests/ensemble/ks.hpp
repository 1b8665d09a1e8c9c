#pragma once
// The one-sample Kolmogorov–Smirnov test for the ensemble's distribution tests.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace poinsot::test {

/// D = sup |F_n(x) − F(x)| of the sample against the CDF F.
inline double ks_statistic(std::vector<double> x, const std::function<double(double)>& cdf) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double d = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double f = cdf(x[i]);
    d = std::max({d, static_cast<double>(i + 1) / n - f, f - static_cast<double>(i) / n});
  }
  return d;
}

/// The asymptotic critical value of D at significance 0.001: √(−ln(0.0005)/2)/√n = 1.9495/√n (Kolmogorov's
/// distribution; accurate to 1 % for n ≥ 100). A correct sampler fails with probability 0.001; the seeds are
/// fixed, so a test either always passes or always fails.
inline double ks_critical_0001(std::size_t n) {
  return 1.9495 / std::sqrt(static_cast<double>(n));
}

/// Φ, the standard normal CDF.
inline double normal_cdf(double z) {
  return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

}  // namespace poinsot::test
