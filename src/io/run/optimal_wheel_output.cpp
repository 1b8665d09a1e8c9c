// How `poinsot optimize` reports reaction wheels (optimal_wheel_output.hpp).
#include "optimal_wheel_output.hpp"

#include <cmath>

#include <fmt/format.h>

#include "poinsot/core/format.hpp"
#include "poinsot/optimal/direct_replay.hpp"

namespace poinsot::io::detail {

namespace {

nlohmann::ordered_json vector_json(const Vec3& v) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (int i = 0; i < 3; ++i)
    out.push_back(std::isfinite(v[i]) ? nlohmann::ordered_json(v[i]) : nlohmann::ordered_json());
  return out;
}

}  // namespace

std::string wheel_lines(const OptimalRun& r) {
  const auto& p = r.scenario.problem;
  if (!p.wheels) return {};
  const optimal::ReactionWheels& w = *p.wheels;
  std::string out = fmt::format(
      "reaction wheels: axes {}, {}, {} (body); spin inertia {} kg·m²; motor torque bound {} N·m; momentum "
      "bound {} N·m·s; initial momenta {} N·m·s; total angular momentum {} N·m·s (space, conserved)\n",
      format_vector(w.axes_body.col(0)), format_vector(w.axes_body.col(1)), format_vector(w.axes_body.col(2)),
      format_vector(w.spin_inertia), format_vector(p.torque_max),
      w.has_momentum_bound() ? format_vector(w.momentum_max) : std::string("none"),
      format_vector(w.momentum_initial), format_vector(p.wheel_system_momentum()));
  if (r.direct_replayed) {
    const auto& d = r.direct_replay;
    out += fmt::format("wheels on the direct re-simulation: peak |h| {} N·m·s, h(T) {} N·m·s",
                       format_vector(d.peak_wheel_momentum), format_vector(d.final_wheel_momentum));
    if (w.has_momentum_bound())
      out += fmt::format(", largest |h_k|/h̄_k − 1 = {}", format_number(d.wheel_momentum_excess, 3));
    out +=
        fmt::format("; drift of the total angular momentum {} N·m·s\n", format_number(d.momentum_drift, 3));
  }
  if (direct_optimum(r).wheel_momentum_margin > 0.0)
    out += fmt::format(
        "  momentum bounds tightened by {} (relative) at the collocation points so that they "
        "hold between them\n",
        format_number(direct_optimum(r).wheel_momentum_margin, 3));
  return out;
}

std::string control_columns(const optimal::ReorientationProblem& p) {
  return p.wheels ? "u1,u2,u3" : "ux,uy,uz";
}

std::string wheel_momentum_columns(const optimal::ReorientationProblem& p) {
  return p.wheels ? ",h1,h2,h3" : "";
}

std::string wheel_momentum_values(const optimal::DirectSolution& d, std::size_t k) {
  std::string out;
  for (int i = 0; i < 3 && k < d.wheel_momentum.size(); ++i)
    out.append(",").append(format_number(d.wheel_momentum[k][i]));
  return out;
}

bool wheel_bounds_held(const optimal::ReorientationProblem& problem, const optimal::DirectReplay& replay) {
  const auto& w = problem.wheels;
  return !(w && w->has_momentum_bound()) ||
         replay.wheel_momentum_excess <= optimal::wheel_momentum_replay_tolerance;
}

nlohmann::ordered_json wheels_json(const OptimalRun& r) {
  const auto& p = r.scenario.problem;
  if (!p.wheels) return nullptr;
  const optimal::ReactionWheels& w = *p.wheels;
  nlohmann::ordered_json axes = nlohmann::ordered_json::array();
  for (int k = 0; k < 3; ++k)
    axes.push_back(vector_json(w.axes_body.col(k)));
  const auto& d = direct_optimum(r);
  nlohmann::ordered_json j = {
      {"axes_body", axes},
      {"spin_inertia", vector_json(w.spin_inertia)},
      {"torque_max", vector_json(p.torque_max)},
      {"momentum_max", vector_json(w.momentum_max)},
      {"momentum_initial", vector_json(w.momentum_initial)},
      {"total_momentum_space", vector_json(p.wheel_system_momentum())},
      {"momentum_final",
       d.wheel_momentum.empty() ? nlohmann::ordered_json() : vector_json(d.wheel_momentum.back())},
      {"bound_tightening", d.wheel_momentum_margin}};
  if (r.direct_replayed) {
    const auto& rp = r.direct_replay;
    j["replay"] = {{"peak_momentum", vector_json(rp.peak_wheel_momentum)},
                   {"final_momentum", vector_json(rp.final_wheel_momentum)},
                   {"bound_excess", std::isfinite(rp.wheel_momentum_excess)
                                        ? nlohmann::ordered_json(rp.wheel_momentum_excess)
                                        : nlohmann::ordered_json()},
                   {"momentum_drift", rp.momentum_drift}};
  } else {
    j["replay"] = nullptr;
  }
  return j;
}

}  // namespace poinsot::io::detail
