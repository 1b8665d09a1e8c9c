#include "poinsot/optimal/problem.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/inertia/validity.hpp"
#include "poinsot/so3/distance.hpp"

namespace poinsot::optimal {

namespace {

struct ObjectiveEntry {
  Objective objective;
  std::string_view name;
};
constexpr ObjectiveEntry kObjectives[] = {{Objective::minimum_time, "minimum_time"},
                                          {Objective::minimum_energy, "minimum_energy"},
                                          {Objective::minimum_time_regularised, "minimum_time_regularised"}};

// ∫₀ᵀ min(a + ū t, b + ū (T − t), c) dt: the largest ∫‖L‖ dt (kg·m²·rad/s·s) the torque bound allows from
// ‖L_0‖ = a to ‖L_f‖ = b, capped at c (rate bound). Piecewise linear; integrated exactly on its breakpoints.
double largest_momentum_integral(double a, double b, double ubar, double c, double T) {
  std::vector<double> knots{0.0, T};
  const double cross = 0.5 * (b - a + ubar * T) / ubar;  // a + ū t = b + ū (T − t)
  if (cross > 0.0 && cross < T) knots.push_back(cross);
  const double up = (c - a) / ubar, down = T - (c - b) / ubar;
  if (up > 0.0 && up < T) knots.push_back(up);
  if (down > 0.0 && down < T) knots.push_back(down);
  std::sort(knots.begin(), knots.end());
  auto g = [&](double t) { return std::max(0.0, std::min({a + ubar * t, b + ubar * (T - t), c})); };
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < knots.size(); ++i)
    sum += 0.5 * (knots[i + 1] - knots[i]) * (g(knots[i]) + g(knots[i + 1]));
  return sum;
}

/// The smallest T ≥ 0 with feasible(T) (a monotone predicate, true for large T), by doubling from max(1,
/// start) and bisection to 1e-12 relative.
template <class Feasible>
double smallest_feasible_time(double start, const Feasible& feasible) {
  double hi = std::max(1.0, start);
  while (!feasible(hi))
    hi *= 2.0;
  double lo = 0.0;
  while (hi - lo > 1e-12 * hi) {
    const double mid = 0.5 * (lo + hi);
    (feasible(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

std::string_view objective_name(Objective objective) {
  for (const auto& e : kObjectives)
    if (e.objective == objective) return e.name;
  return "unknown";
}

Objective parse_objective(std::string_view name, std::string_view field) {
  for (const auto& e : kObjectives)
    if (e.name == name) return e.objective;
  throw InvalidInput(std::string(field) + ": unknown objective \"" + std::string(name) +
                     "\"; expected minimum_time, minimum_energy or minimum_time_regularised");
}

double ReorientationProblem::torque_norm_limit() const {
  return bound == TorqueBound::per_axis ? torque_max.norm() : torque_max[0];
}

Mat3 ReorientationProblem::bus_inertia() const {
  return wheels ? optimal::bus_inertia(inertia_body, *wheels) : inertia_body;
}

Vec3 ReorientationProblem::wheel_system_momentum() const {
  return wheels ? total_momentum_space(inertia_body, *wheels, attitude_initial, omega_initial,
                                       wheels->momentum_initial)
                : Vec3::Zero();
}

namespace {

/// minimum_duration_bound with reaction wheels: Θ λ_min(J_b) ≤ ∫ min(‖L‖ + m(t), c) dt with m = ‖A h‖,
/// |ṁ| ≤ ‖A‖ ū, m capped by ‖A‖ ‖h̄‖, c = √3 ω_max λ_max(J_b).
double wheel_duration_bound(const ReorientationProblem& p) {
  const double theta = p.free_final_attitude ? 0.0 : so3::angle_between(p.attitude_initial, p.attitude_final);
  const Mat3 Jb = p.bus_inertia();
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(Jb);
  const ReactionWheels& w = *p.wheels;
  const double sigma = w.axes_body.operatorNorm();
  const double ubar = sigma * p.torque_max.norm();
  const Vec3 L = p.wheel_system_momentum();
  const double a = (w.axes_body * w.momentum_initial).norm();
  // ‖A h_f‖: known with a final attitude; otherwise at least ‖L‖ − ‖J_b ω_f‖.
  const double b =
      p.free_final_attitude
          ? std::max(0.0, L.norm() - (Jb * p.omega_final).norm())
          : (w.axes_body * wheel_momentum(p.inertia_body, w, L, p.attitude_final, p.omega_final)).norm();
  const double cap_m =
      w.momentum_max.allFinite() ? sigma * w.momentum_max.norm() : std::numeric_limits<double>::infinity();
  const double c = p.has_rate_bound() ? std::sqrt(3.0) * p.rate_max * eig.eigenvalues()[2]
                                      : std::numeric_limits<double>::infinity();
  const double t_momentum = (p.free_final_attitude ? std::max(0.0, b - a) : std::abs(a - b)) / ubar;
  auto feasible = [&](double T) {
    const double reach =
        std::min(L.norm(), c) * T +
        largest_momentum_integral(a, b, ubar, std::min(cap_m, std::max(c - L.norm(), 0.0)), T);
    return T >= t_momentum && reach >= theta * eig.eigenvalues()[0];
  };
  return smallest_feasible_time(t_momentum, feasible);
}

}  // namespace

double minimum_duration_bound(const ReorientationProblem& p) {
  if (p.wheels) return wheel_duration_bound(p);
  const double theta = p.free_final_attitude ? 0.0 : so3::angle_between(p.attitude_initial, p.attitude_final);
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(p.inertia_body);
  const double j_min = eig.eigenvalues()[0];
  const double ubar = p.torque_norm_limit();
  const double a = (p.inertia_body * p.omega_initial).norm();
  const double b = (p.inertia_body * p.omega_final).norm();
  const double c = p.has_rate_bound() ? std::sqrt(3.0) * p.rate_max * eig.eigenvalues()[2]
                                      : std::numeric_limits<double>::infinity();
  const double t_momentum = std::abs(a - b) / ubar;
  auto feasible = [&](double T) {
    return T >= t_momentum && largest_momentum_integral(a, b, ubar, c, T) >= theta * j_min;
  };
  return smallest_feasible_time(t_momentum, feasible);
}

std::string pointing_field(const ReorientationProblem& p, std::size_t index) {
  std::size_t same_kind = 0;
  for (std::size_t i = 0; i <= index && i < p.pointing.size(); ++i)
    same_kind += p.pointing[i].kind == p.pointing[index].kind ? 1 : 0;
  return fmt::format("optimal_control.{}[{}]", pointing_kind_name(p.pointing[index].kind), same_kind);
}

namespace {

/// Each constraint well formed and met, with a positive margin, at the given end attitudes.
void validate_pointing(const ReorientationProblem& p) {
  for (std::size_t i = 0; i < p.pointing.size(); ++i) {
    const PointingConstraint& c = p.pointing[i];
    const std::string field = pointing_field(p, i);
    validate(c, field);
    const char* where =
        c.kind == PointingKind::keep_out ? "inside the keep-out cone" : "outside the keep-in cone";
    for (const auto& [q, end] :
         {std::pair{p.attitude_initial, "initial"}, std::pair{p.attitude_final, "final"}}) {
      if (std::string_view(end) == "final" && p.free_final_attitude) continue;
      if (!(c.margin(q) > 0.0))
        throw InvalidInput(fmt::format(
            "{}: the boresight {} is {} deg from the direction {} at the {} attitude, {} of half-angle {} "
            "deg; "
            "expected every constraint to hold at both ends",
            field, format_vector(c.boresight_body), format_number(c.angle(q) * 180.0 / std::numbers::pi, 6),
            format_vector(c.direction_space), end, where,
            format_number(c.half_angle * 180.0 / std::numbers::pi, 6)));
    }
  }
}

/// The wheels well formed, bounded per wheel, and able to hold the final state's momenta.
void validate_wheels(const ReorientationProblem& p) {
  const ReactionWheels& w = *p.wheels;
  validate(w, p.inertia_body);
  if (p.bound != TorqueBound::per_axis)
    throw InvalidInput(
        "optimal_control.torque_bound: norm; expected per_axis with reaction wheels (each "
        "wheel's motor torque has its own bound, torque_max)");
  if (p.free_final_attitude) return;
  const Vec3 hf =
      wheel_momentum(p.inertia_body, w, p.wheel_system_momentum(), p.attitude_final, p.omega_final);
  for (int k = 0; k < 3; ++k)
    if (std::abs(hf[k]) > w.momentum_max[k])
      throw InvalidInput(fmt::format(
          "optimal_control.reaction_wheels.momentum_max: {} N·m·s is below |h_{}| = {} N·m·s, the momentum "
          "wheel {} must hold at the final state (the slew's total angular momentum {} N·m·s); expected "
          "bounds the end meets",
          format_vector(w.momentum_max), k + 1, format_number(std::abs(hf[k]), 6), k + 1,
          format_vector(p.wheel_system_momentum())));
}

}  // namespace

void validate(const ReorientationProblem& p) {
  inertia::require_valid_inertia(p.inertia_body, "optimal_control.inertia");
  if (p.wheels) validate_wheels(p);
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(p.inertia_body);
  if (!(eig.eigenvalues()[0] > 1e-12 * eig.eigenvalues()[2]))
    throw InvalidInput("optimal_control.inertia: principal moments " + format_vector(eig.eigenvalues()) +
                       " kg·m² include a zero; expected an invertible inertia (no point masses or rods)");
  const int n_bounds = p.bound == TorqueBound::per_axis ? 3 : 1;
  for (int i = 0; i < n_bounds; ++i)
    if (!std::isfinite(p.torque_max[i]) || !(p.torque_max[i] > 0.0))
      throw InvalidInput("optimal_control.torque_max: " +
                         (n_bounds == 3 ? format_vector(p.torque_max) : format_number(p.torque_max[0])) +
                         " N·m; expected finite positive bounds");
  if (!(p.rate_max > 0.0) || std::isnan(p.rate_max))
    throw InvalidInput("optimal_control.rate_max: " + format_number(p.rate_max) +
                       " rad/s; expected a positive bound (or none)");
  for (const auto& [q, field] :
       {std::pair{p.attitude_initial, "initial attitude"}, std::pair{p.attitude_final, "final attitude"}})
    if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > 1e-9)
      throw InvalidInput(std::string("optimal_control.") + field + ": quaternion " + format_quaternion(q) +
                         " has norm " + format_number(q.norm()) + "; expected a unit quaternion");
  for (const auto& [w, field] :
       {std::pair{p.omega_initial, "omega_initial"}, std::pair{p.omega_final, "omega_final"}}) {
    if (!w.allFinite())
      throw InvalidInput(std::string("optimal_control.") + field + ": " + format_vector(w) +
                         " rad/s; expected finite values");
    if (w.cwiseAbs().maxCoeff() > p.rate_max)
      throw InvalidInput("optimal_control.rate_max: " + format_number(p.rate_max) + " rad/s is below |" +
                         field + "| = " + format_vector(w.cwiseAbs()) +
                         " rad/s; no manoeuvre can start or end there");
  }
  if (p.objective == Objective::minimum_time_regularised) {
    if (!std::isfinite(p.energy_weight) || !(p.energy_weight > 0.0))
      throw InvalidInput("optimal_control.energy_weight: " + format_number(p.energy_weight) +
                         " s/(N·m)²; expected a finite positive weight for minimum_time_regularised");
  } else if (p.energy_weight != 0.0) {
    throw InvalidInput("optimal_control.energy_weight: " + format_number(p.energy_weight) +
                       "; only minimum_time_regularised takes an energy weight");
  }
  if (p.objective == Objective::minimum_energy) {
    if (!std::isfinite(p.final_time) || !(p.final_time > 0.0))
      throw InvalidInput("optimal_control.final_time: " + format_number(p.final_time) +
                         " s; expected a finite positive final time for minimum_energy");
    const double t_min = minimum_duration_bound(p);
    if (p.final_time < t_min)
      throw InvalidInput(
          "optimal_control.final_time: " + format_number(p.final_time) +
          " s is too short: within these torque and rate bounds any manoeuvre needs at least " +
          format_number(t_min, 6) + " s");
  }
  validate_pointing(p);
}

}  // namespace poinsot::optimal
