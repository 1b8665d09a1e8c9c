#include "arc_structure.hpp"

#include <algorithm>
#include <cmath>

#include "pmp_system.hpp"
#include "poinsot/core/format.hpp"
#include "switching_structure.hpp"

namespace poinsot::optimal::detail {

bool rate_bound_active(const ReorientationProblem& p, const DirectSolution& d, double& peak) {
  peak = 0.0;
  for (const auto& w : d.omega_body)
    peak = std::max(peak, w.cwiseAbs().maxCoeff());
  return p.has_rate_bound() && peak > p.rate_max * (1.0 - 1e-4);
}

namespace {

using Kind = ArcEvent::Kind;
using Arc = ArcEvent::Arc;

/// A stretch of direct samples [first, last] of one axis that is a boundary or a singular arc.
struct SampleArc {
  std::size_t first = 0, last = 0;
  Arc arc = Arc::boundary;
};

/// The boundary arcs of axis i: stretches of ≥ 2 samples with |ω_i| ≥ (1 − 1e-3) r; none where the rate bound
/// is not active (rate_bound_active).
std::vector<SampleArc> boundary_arcs(const ReorientationProblem& p, const DirectSolution& d, int i) {
  std::vector<SampleArc> arcs;
  if (double peak = 0.0; !rate_bound_active(p, d, peak)) return arcs;
  const double r = p.rate_max;
  const std::size_t N = d.time.size();
  for (std::size_t j = 0; j < N;) {
    if (std::abs(d.omega_body[j][i]) < (1.0 - 1e-3) * r) {
      ++j;
      continue;
    }
    std::size_t e = j;
    const double side = d.omega_body[j][i] > 0 ? 1.0 : -1.0;
    while (e + 1 < N && d.omega_body[e + 1][i] * side >= (1.0 - 1e-3) * r)
      ++e;
    if (e > j) arcs.push_back({j, e, Arc::boundary});
    j = e + 1;
  }
  return arcs;
}

/// The singular arcs of axis i off its boundary arcs: stretches longer than kShortestSingularArc of T of
/// samples with |u_i| < 0.95 u_max,i, bridging gaps of up to three samples (read_arc_structure).
std::vector<SampleArc> singular_arcs(const ReorientationProblem& p, const DirectSolution& d, int i,
                                     const std::vector<SampleArc>& boundary, double shortest) {
  auto on_boundary = [&](std::size_t j) {
    return std::any_of(boundary.begin(), boundary.end(),
                       [j](const SampleArc& a) { return j >= a.first && j <= a.last; });
  };
  auto inside = [&](std::size_t j) { return std::abs(d.torque_body[j][i]) < 0.95 * p.torque_max[i]; };
  std::vector<SampleArc> arcs;
  const std::size_t N = d.time.size();
  for (std::size_t j = 0; j < N;) {
    if (on_boundary(j) || !inside(j)) {
      ++j;
      continue;
    }
    std::size_t last = j;
    int gap = 0;
    for (std::size_t k = j + 1; k < N && !on_boundary(k); ++k) {
      if (inside(k)) {
        last = k;
        gap = 0;
      } else if (++gap > 3) {
        break;
      }
    }
    if (d.time[last] - d.time[j] > shortest * d.final_time) arcs.push_back({j, last, Arc::singular});
    j = last + 1;
  }
  return arcs;
}

/// Sets `pair` of every entry and exit in `events` (ascending in time): each entry with the next exit of its
/// axis.
void pair_arc_ends(std::vector<ArcEvent>& events) {
  for (std::size_t k = 0; k < events.size(); ++k)
    if (events[k].kind == Kind::entry)
      for (std::size_t l = k + 1; l < events.size(); ++l)
        if (events[l].kind == Kind::exit && events[l].axis == events[k].axis && events[l].pair < 0) {
          events[k].pair = static_cast<int>(l);
          events[l].pair = static_cast<int>(k);
          break;
        }
}

/// The end of a refusal for a singular arc of axis i of order two (u_i first enters the fourth derivative of
/// σ_i): such an arc cannot join a bang arc with finitely many switches; the control chatters at its
/// junctions (Fuller's phenomenon), which a shooting over a finite sequence of arcs cannot represent.
std::string order_two_reason(int i) {
  const std::string u = "u" + std::to_string(i + 1);
  return "a singular arc of order two (" + u + " does not enter the second derivative of σ" +
         std::to_string(i + 1) + "), whose junctions with bang arcs chatter; the shooting handles singular " +
         "arcs of order one only";
}

}  // namespace

ArcStructure read_arc_structure(const ReorientationProblem& p, const DirectSolution& d,
                                double shortest_singular_arc, double start_bang_sign) {
  ArcStructure s;
  if (p.objective != Objective::minimum_time || p.bound != TorqueBound::per_axis) {
    s.refused = "boundary and singular arcs are handled for minimum time with per-axis torque bounds only";
    return s;
  }
  const std::size_t N = d.time.size();
  const Mat3 J_inv = p.inertia_body.inverse();
  std::vector<std::vector<SampleArc>> boundary(3), singular(3);
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    boundary[k] = boundary_arcs(p, d, i);
    singular[k] = singular_arcs(p, d, i, boundary[k], shortest_singular_arc);
  }
  // Whether a singular arc of another axis shares a sample with `a` (axis i): C_SS of the pair may then be
  // regular though C_ii = 0.
  auto shared = [&](int i, const SampleArc& a) {
    for (int k = 0; k < 3; ++k)
      if (k != i)
        for (const SampleArc& b : singular[static_cast<std::size_t>(k)])
          if (b.first <= a.last && a.first <= b.last) return true;
    return false;
  };
  std::vector<ArcEvent> events;
  std::vector<std::pair<double, double>> boundary_spans, singular_spans;
  for (int i = 0; i < 3; ++i) {
    std::vector<SampleArc> arcs = boundary[static_cast<std::size_t>(i)];
    const bool principal = principal_axis(J_inv, i);
    for (const SampleArc& a : singular[static_cast<std::size_t>(i)]) {
      const std::string inside = inside_bound_message(i, d.time[a.first], d.time[a.last]) + ", ";
      if (principal && !shared(i, a)) {
        s.refused = inside + "about a principal axis: " + order_two_reason(i);
        return s;
      }
      const bool at_start = a.first == 0 && a.last + 1 < N;
      if (at_start) s.singular_at_start = i;
      if (a.last + 1 == N || (at_start && start_bang_sign == 0.0)) {
        s.refused =
            inside + "a singular arc at the " + (a.first == 0 ? "start" : "end") + " of the manoeuvre";
        return s;
      }
      arcs.push_back(a);
      if (at_start) arcs.back().first = 1;
    }
    std::sort(arcs.begin(), arcs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const SampleArc& a : arcs)
      (a.arc == Arc::boundary ? boundary_spans : singular_spans)
          .emplace_back(d.time[a.first], d.time[a.last]);
    auto on_arc = [&](std::size_t j) {
      return std::any_of(arcs.begin(), arcs.end(),
                         [j](const SampleArc& a) { return j >= a.first && j <= a.last; });
    };
    // Saturated samples off the arcs: the signs; an arc between two of them takes the place of a switch.
    const double umax = p.torque_max[i];
    int last = -1;
    std::size_t next_arc = 0;
    for (std::size_t j = 0; j < N; ++j) {
      if (on_arc(j)) continue;
      const double u = d.torque_body[j][i];
      if (std::abs(u) <= 0.5 * umax) continue;
      const double sign = u > 0 ? 1.0 : -1.0;
      // Arcs passed since the last saturated sample.
      bool crossed_arc = false;
      while (next_arc < arcs.size() && arcs[next_arc].last < j) {
        const SampleArc a = arcs[next_arc++];
        ArcEvent enter, leave;
        enter.kind = Kind::entry;
        leave.kind = Kind::exit;
        enter.arc = leave.arc = a.arc;
        enter.axis = leave.axis = i;
        enter.side = leave.side = a.arc == Arc::singular ? 0.0 : d.omega_body[a.first][i] > 0 ? 1.0 : -1.0;
        enter.time = d.time[a.first];
        leave.time = d.time[a.last];
        leave.sign_after = sign;
        events.push_back(enter);
        events.push_back(leave);
        crossed_arc = true;
      }
      if (last < 0) {
        s.initial_sign[i] = sign;
      } else if (!crossed_arc && (u > 0) != (d.torque_body[static_cast<std::size_t>(last)][i] > 0)) {
        ArcEvent e;
        e.axis = i;
        e.time = torque_sign_change(d, i, static_cast<std::size_t>(last), j);
        events.push_back(e);
      }
      last = static_cast<int>(j);
    }
    if (next_arc < arcs.size()) {
      s.refused = "the rate bound of axis " + std::to_string(i + 1) + " is active up to the final time";
      return s;
    }
    if (s.singular_at_start == i) s.initial_sign[i] = start_bang_sign;
  }
  for (const auto& [a, b] : singular_spans)
    for (const auto& [c, e] : boundary_spans)
      if (a <= e && c <= b) {
        s.refused = "a singular arc (t = " + format_number(a, 6) + " s to " + format_number(b, 6) +
                    " s) overlaps a boundary arc of the rate bound (t = " + format_number(c, 6) + " s to " +
                    format_number(e, 6) + " s)";
        return s;
      }
  std::stable_sort(events.begin(), events.end(),
                   [](const auto& a, const auto& b) { return a.time < b.time; });
  pair_arc_ends(events);
  s.events = events;
  return s;
}

}  // namespace poinsot::optimal::detail
