// How `poinsot optimize` reports pointing constraints (optimal_pointing_output.hpp).
#include "optimal_pointing_output.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "poinsot/core/format.hpp"

namespace poinsot::io::detail {

std::string pointing_lines(std::string_view title, const optimal::ReorientationProblem& p,
                           const optimal::PointingMargins& m) {
  std::string out(title);
  for (std::size_t c = 0; c < p.pointing.size() && c < m.margin.size(); ++c)
    out += fmt::format("{} {} smallest margin {} rad at t = {} s", c == 0 ? ":" : ";", p.pointing[c].label(),
                       format_number(m.margin[c], 3), format_number(m.time[c], 6));
  return out + "\n";
}

std::string pointing_column(const optimal::ReorientationProblem& p, std::size_t index) {
  const optimal::PointingKind kind = p.pointing[index].kind;
  const auto same_kind =
      std::count_if(p.pointing.begin(), p.pointing.begin() + static_cast<std::ptrdiff_t>(index) + 1,
                    [&](const optimal::PointingConstraint& c) { return c.kind == kind; });
  return fmt::format("angle_{}_{}", optimal::pointing_kind_name(kind), same_kind);
}

nlohmann::ordered_json pointing_json(const OptimalRun& r) {
  const auto& p = r.scenario.problem;
  const auto& d = direct_optimum(r);
  const auto vector = [](const Vec3& v) { return nlohmann::ordered_json{v[0], v[1], v[2]}; };
  const auto margin_or_null = [](const optimal::PointingMargins& m, std::size_t i) {
    return i < m.margin.size() && std::isfinite(m.margin[i])
               ? nlohmann::ordered_json({{"margin", m.margin[i]}, {"t", m.time[i]}})
               : nlohmann::ordered_json();
  };
  auto out = nlohmann::ordered_json::array();
  for (std::size_t c = 0; c < p.pointing.size(); ++c) {
    const auto& pc = p.pointing[c];
    double multiplier = 0.0;
    if (c < d.pointing_multiplier.size())
      for (const double y : d.pointing_multiplier[c])
        multiplier = std::max(multiplier, y);
    out.push_back({{"name", pc.name},
                   {"kind", std::string(optimal::pointing_kind_name(pc.kind))},
                   {"column", pointing_column(p, c)},
                   {"boresight_body", vector(pc.boresight_body)},
                   {"direction_space", vector(pc.direction_space)},
                   {"half_angle", pc.half_angle},
                   {"widening", d.pointing_widening},
                   {"largest_multiplier", multiplier},
                   {"direct_replay", r.direct_replayed ? margin_or_null(r.direct_replay.pointing, c)
                                                       : nlohmann::ordered_json()},
                   {"indirect", margin_or_null(r.verification.pointing, c)}});
  }
  return out;
}

}  // namespace poinsot::io::detail
