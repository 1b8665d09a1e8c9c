#include "switching_structure.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "poinsot/core/format.hpp"

namespace poinsot::optimal::detail {

// Built by appending: GCC 12 reports a false -Wrestrict for "literal" + std::string here.
std::string inside_bound_message(int axis, double t0, double t1) {
  std::string m = "u";
  m += std::to_string(axis + 1);
  m += " is inside its bound from t = ";
  m += format_number(t0, 6);
  m += " s to ";
  m += format_number(t1, 6);
  m += " s";
  return m;
}

std::vector<double> read_reversals(const ReorientationProblem& p, const DirectSolution& d) {
  std::vector<double> out;
  const double ubar = p.torque_max[0];
  std::size_t last = d.time.size();
  for (std::size_t j = 0; j < d.time.size(); ++j) {
    if (d.torque_body[j].norm() < 0.5 * ubar) continue;
    if (last < d.time.size() && d.torque_body[j].dot(d.torque_body[last]) < 0.0) {
      const Vec3 e = d.torque_body[last].normalized();
      double t0 = d.time[last];
      for (std::size_t k = last; k < j; ++k) {
        const double a = d.torque_body[k].dot(e), b = d.torque_body[k + 1].dot(e);
        if ((a > 0) != (b > 0)) {
          t0 = d.time[k] + (d.time[k + 1] - d.time[k]) * a / (a - b);
          break;
        }
      }
      out.push_back(t0);
    }
    last = j;
  }
  return out;
}

Eigen::Vector3i switching_sign_violations(const IndirectSolution& s) {
  double sigma_max = 0.0;
  for (const Vec3& sigma : s.switching_function)
    sigma_max = std::max(sigma_max, sigma.cwiseAbs().maxCoeff());
  Eigen::Vector3i violations = Eigen::Vector3i::Zero();
  for (std::size_t j = 0; j < s.time.size(); ++j)
    for (int i = 0; i < 3; ++i) {
      const double sigma = s.switching_function[j][i];
      if (s.torque_body[j][i] * sigma > 0.0 && std::abs(sigma) > kSwitchingSignDeadZone * sigma_max)
        ++violations[i];
    }
  return violations;
}

double torque_sign_change(const DirectSolution& d, int axis, std::size_t from, std::size_t to) {
  for (std::size_t k = from; k < to; ++k) {
    const double a = d.torque_body[k][axis], b = d.torque_body[k + 1][axis];
    if ((a > 0) != (b > 0)) return d.time[k] + (d.time[k + 1] - d.time[k]) * a / (a - b);
  }
  return d.time[from];
}

namespace {

/// The switches of axis i in `sw`, ascending.
std::vector<double> axis_switches(const SwitchGuess& sw, int i) {
  std::vector<double> times;
  for (std::size_t k = 0; k < sw.times.size(); ++k)
    if (sw.axes[k] == i) times.push_back(sw.times[k]);
  std::sort(times.begin(), times.end());
  return times;
}

/// `sw` without the `at_start[i]` earliest and `at_end[i]` latest switches of each axis i; an axis that
/// loses an odd number of its earliest starts with the opposite sign.
SwitchGuess without_end_switches(const SwitchGuess& sw, const Eigen::Vector3i& at_start,
                                 const Eigen::Vector3i& at_end) {
  SwitchGuess kept = sw;
  kept.times.clear();
  kept.axes.clear();
  for (int i = 0; i < 3; ++i) {
    const std::vector<double> times = axis_switches(sw, i);
    const auto first = std::min(static_cast<std::size_t>(at_start[i]), times.size()),
               end = std::max(first,
                              times.size() - std::min(static_cast<std::size_t>(at_end[i]), times.size()));
    for (std::size_t k = first; k < end; ++k) {
      kept.times.push_back(times[k]);
      kept.axes.push_back(i);
    }
    if (at_start[i] % 2 == 1) kept.initial_sign[i] = -kept.initial_sign[i];
  }
  return kept;
}

}  // namespace

bool without_vanishing_end_arcs(const SwitchGuess& sw, const IndirectSolution& shot, SwitchGuess& out) {
  const double T = shot.final_time;
  if (!(T > 0.0) || shot.switch_times.size() != sw.times.size()) return false;
  Eigen::Vector3i at_start = Eigen::Vector3i::Zero(), at_end = Eigen::Vector3i::Zero();
  for (std::size_t k = 0; k < shot.switch_times.size(); ++k) {
    const double t = shot.switch_times[k];
    const auto i = static_cast<Eigen::Index>(shot.switch_axes[k]);
    if (i < 0) return false;
    if (t < kVanishingEndArc * T) ++at_start[i];
    if (t > (1.0 - kVanishingEndArc) * T) ++at_end[i];
  }
  if (at_start.sum() + at_end.sum() == 0) return false;
  out = without_end_switches(sw, at_start, at_end);
  return true;
}

bool without_short_end_arcs(const SwitchGuess& sw, double T, SwitchGuess& out) {
  if (!(T > 0.0)) return false;
  Eigen::Vector3i at_start = Eigen::Vector3i::Zero(), at_end = Eigen::Vector3i::Zero();
  for (int i = 0; i < 3; ++i) {
    const std::vector<double> times = axis_switches(sw, i);
    if (times.empty()) continue;
    at_start[i] = times.front() < kShortEndArc * T ? 1 : 0;
    at_end[i] = times.back() > (1.0 - kShortEndArc) * T ? 1 : 0;
  }
  if (at_start.sum() + at_end.sum() == 0) return false;
  out = without_end_switches(sw, at_start, at_end);
  return true;
}

bool is_torque_dip(const DirectSolution& d, int axis, std::size_t first, std::size_t last) {
  const std::size_t N = d.time.size();
  if (first == 0 || last < first || last + 1 >= N) return false;
  const bool positive = d.torque_body[first - 1][axis] > 0;
  for (std::size_t k = first; k <= last + 1; ++k)
    if ((d.torque_body[k][axis] > 0) != positive) return false;
  return true;
}

bool with_switch_pairs_at_dips(const ReorientationProblem& p, const DirectSolution& d, const SwitchGuess& sw,
                               SwitchGuess& out) {
  SwitchGuess paired = sw;
  bool any = false;
  for (int i = 0; i < 3; ++i) {
    const double ubar = p.torque_max[i];
    for (const auto [j, last] : inside_bound_stretches(p, d, i, 0, [](std::size_t) { return false; })) {
      if (d.time[last] - d.time[j] < kShortestSingularArc * d.final_time && is_torque_dip(d, i, j, last)) {
        double deficit = 0.0, moment = 0.0;  // ∫ (ū − |u|) dt and ∫ t (ū − |u|) dt, trapezoidal
        for (std::size_t k = j - 1; k <= last; ++k) {
          const double h = d.time[k + 1] - d.time[k];
          const double f0 = ubar - std::abs(d.torque_body[k][i]),
                       f1 = ubar - std::abs(d.torque_body[k + 1][i]);
          deficit += 0.5 * h * (f0 + f1);
          moment += 0.5 * h * (f0 * d.time[k] + f1 * d.time[k + 1]);
        }
        if (deficit > 0.0) {
          const double centre = moment / deficit, width = deficit / (2.0 * ubar);
          for (const double t : {centre - 0.5 * width, centre + 0.5 * width}) {
            paired.times.push_back(t);
            paired.axes.push_back(i);
          }
          any = true;
        }
      }
    }
  }
  if (any) out = paired;
  return any;
}

SwitchGuess read_switch_guess(const ReorientationProblem& p, const DirectSolution& d) {
  SwitchGuess g;
  const double T = d.final_time;
  for (int i = 0; i < 3; ++i) {
    const double umax = p.torque_max[i];
    int last = -1;
    double inside_since = -1.0;
    for (std::size_t j = 0; j < d.time.size(); ++j) {
      const double u = d.torque_body[j][i];
      const bool saturated = std::abs(u) > 0.5 * umax;
      if (std::abs(u) < kInsideBound * umax) {
        if (inside_since < 0.0) inside_since = d.time[j];
        if (d.time[j] - inside_since > kShortestSingularArc * T && g.singular.empty())
          g.singular = inside_bound_message(i, inside_since, d.time[j]) + " (a singular arc?)";
      } else {
        inside_since = -1.0;
      }
      if (!saturated) continue;
      if (last < 0) {
        g.initial_sign[i] = u > 0 ? 1.0 : -1.0;
      } else if ((u > 0) != (d.torque_body[last][i] > 0)) {
        // zero of the piecewise-linear interpolant between the last two saturated samples
        g.times.push_back(torque_sign_change(d, i, static_cast<std::size_t>(last), j));
        g.axes.push_back(i);
      }
      last = static_cast<int>(j);
    }
  }
  return g;
}

}  // namespace poinsot::optimal::detail
