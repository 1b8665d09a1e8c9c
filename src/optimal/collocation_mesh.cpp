// The mesh of the Hermite–Simpson transcription (collocation_mesh.hpp).
#include "collocation_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "poinsot/core/error.hpp"

namespace poinsot::optimal::detail {

int refinement_pieces(double error, double tolerance) {
  if (!(error > tolerance)) return 1;
  return std::clamp(static_cast<int>(std::ceil(std::pow(error / tolerance, 0.25))), 2, 5);
}

CollocationMesh CollocationMesh::uniform(int intervals) {
  if (intervals < 1)
    throw InvalidInput("collocation mesh: " + std::to_string(intervals) + " intervals; expected at least 1");
  CollocationMesh m;
  m.uniform_ = true;
  m.dtau_.assign(static_cast<std::size_t>(intervals), 1.0 / intervals);
  for (int k = 0; k <= intervals; ++k)
    m.tau_.push_back(static_cast<double>(k) / intervals);
  m.index_phases({intervals});
  return m;
}

CollocationMesh CollocationMesh::from_fractions(std::vector<double> fractions) {
  if (fractions.empty()) throw InvalidInput("collocation mesh: no intervals; expected at least 1");
  CollocationMesh m;
  m.dtau_ = std::move(fractions);
  m.tau_.assign(1, 0.0);
  for (const double d : m.dtau_)
    m.tau_.push_back(m.tau_.back() + d);
  m.tau_.back() = 1.0;  // the last node at the phase's end exactly
  m.index_phases({static_cast<int>(m.dtau_.size())});
  return m;
}

CollocationMesh CollocationMesh::from_nodes(std::vector<double> tau, const std::vector<int>& intervals) {
  std::size_t nodes = 0;
  for (const int n : intervals) {
    if (n < 1)
      throw InvalidInput("collocation phases: a phase with " + std::to_string(n) +
                         " intervals; expected at least 1");
    nodes += static_cast<std::size_t>(n) + 1;
  }
  if (intervals.empty() || nodes != tau.size())
    throw InvalidInput("collocation phases: " + std::to_string(intervals.size()) + " phases with " +
                       std::to_string(tau.size()) + " mesh values; expected Σ(N_a + 1) values");
  CollocationMesh m;
  m.tau_ = std::move(tau);
  std::size_t first = 0;
  for (const int n : intervals) {
    for (int k = 0; k < n; ++k)
      m.dtau_.push_back(m.tau_[first + static_cast<std::size_t>(k) + 1] -
                        m.tau_[first + static_cast<std::size_t>(k)]);
    first += static_cast<std::size_t>(n) + 1;
  }
  m.index_phases(intervals);
  return m;
}

void CollocationMesh::index_phases(const std::vector<int>& intervals) {
  phase_first_interval_ = {0};
  for (const int n : intervals) {
    for (int k = 0; k < n; ++k)
      interval_phase_.push_back(static_cast<int>(phase_first_interval_.size()) - 1);
    phase_first_interval_.push_back(phase_first_interval_.back() + n);
  }
  for (int a = 0; a < phases(); ++a)
    for (int p = phase_first_point(a); p <= phase_last_point(a); ++p)
      point_phase_.push_back(a);
}

double CollocationMesh::point_fraction(int p) const {
  const int a = point_phase(p), l = p - phase_first_point(a);
  const int k = phase_first_interval(a) + l / 2;  // the interval whose left node or midpoint p is
  if (uniform_) return 0.5 * l / intervals();
  const auto node = static_cast<std::size_t>(k + a);
  if (l % 2 == 0) return tau_[node];
  return 0.5 * (tau_[node] + tau_[node + 1]);
}

double CollocationMesh::quadrature_weight(int p) const {
  const int a = point_phase(p), l = p - phase_first_point(a), k0 = phase_first_interval(a);
  if (l % 2 == 1) return 4.0 / 6.0 * step_fraction(k0 + l / 2);
  const int k = k0 + l / 2;  // the interval whose left node p is (when k < the phase's end)
  double w = 0.0;
  if (k > k0) w += step_fraction(k - 1) / 6.0;
  if (k < phase_first_interval(a + 1)) w += step_fraction(k) / 6.0;
  return w;
}

std::vector<double> CollocationMesh::point_times(const std::vector<double>& durations) const {
  std::vector<double> t;
  t.reserve(static_cast<std::size_t>(points()));
  double start = 0.0;
  for (int a = 0; a < phases(); ++a) {
    const double D = durations[static_cast<std::size_t>(a)];
    for (int p = phase_first_point(a); p < phase_last_point(a); ++p)
      t.push_back(uniform_ ? 0.5 * D / intervals() * p : start + point_fraction(p) * D);
    start += D;
    t.push_back(start);  // the phase's last node at its end exactly
  }
  return t;
}

}  // namespace poinsot::optimal::detail
