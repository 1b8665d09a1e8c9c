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

/// The singular arcs of axis i off its boundary arcs: stretches longer than `shortest` of T of samples with
/// |u_i| < kInsideBound u_max,i, bridging gaps of up to three samples; with `dips`, also the shorter
/// stretches that are dips (is_torque_dip; read_arc_structure).
std::vector<SampleArc> singular_arcs(const ReorientationProblem& p, const DirectSolution& d, int i,
                                     const std::vector<SampleArc>& boundary, double shortest, bool dips) {
  auto on_boundary = [&](std::size_t j) {
    return std::any_of(boundary.begin(), boundary.end(),
                       [j](const SampleArc& a) { return j >= a.first && j <= a.last; });
  };
  std::vector<SampleArc> arcs;
  for (const auto [first, last] : inside_bound_stretches(p, d, i, 3, on_boundary))
    if (d.time[last] - d.time[first] > shortest * d.final_time || (dips && is_torque_dip(d, i, first, last)))
      arcs.push_back({first, last, Arc::singular});
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

/// A sign change of u_i at time t (s).
ArcEvent sign_change(int i, double t) {
  return ArcEvent{.kind = Kind::sign_change, .axis = i, .time = t};
}

/// An entry or exit (`kind`) of axis i at time t (s): of a boundary arc on side `side`, or of a singular arc
/// (side 0), with the sign of u_i after an exit.
ArcEvent arc_end(Kind kind, Arc arc_kind, int i, double side, double t, double sign_after = 1.0) {
  return ArcEvent{
      .kind = kind, .arc = arc_kind, .axis = i, .side = side, .time = t, .sign_after = sign_after};
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
                                double shortest_singular_arc, double start_bang_sign, double end_bang_sign,
                                bool dips) {
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
    singular[k] = singular_arcs(p, d, i, boundary[k], shortest_singular_arc, dips);
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
      const bool at_start = a.first == 0, at_end = a.last + 1 == N;
      if (at_start && at_end) {
        s.refused = inside + "a singular arc over the whole manoeuvre";
        return s;
      }
      if (at_start) s.singular_at_start = i;
      if (at_end) s.singular_at_end = i;
      if ((at_start && start_bang_sign == 0.0) || (at_end && end_bang_sign == 0.0)) {
        s.refused = inside + "a singular arc at the " + (at_start ? "start" : "end") + " of the manoeuvre";
        return s;
      }
      arcs.push_back(a);
      if (at_start) arcs.back().first = 1;
      if (at_end) arcs.back().last = N - 2;
    }
    std::sort(arcs.begin(), arcs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const SampleArc& a : arcs)
      (a.arc == Arc::boundary ? boundary_spans : singular_spans)
          .emplace_back(d.time[a.first], d.time[a.last]);
    auto on_arc = [&](std::size_t j) {
      return std::any_of(arcs.begin(), arcs.end(),
                         [j](const SampleArc& a) { return j >= a.first && j <= a.last; });
    };
    // The entry and exit of arc `a`, with the sign of u_i after it; a dip of one sample from the midpoint
    // before it to the midpoint after it.
    auto add_arc = [&](const SampleArc& a, double sign_after) {
      const double side = a.arc == Arc::singular ? 0.0 : d.omega_body[a.first][i] > 0 ? 1.0 : -1.0;
      const bool one_sample = a.first == a.last && a.first > 0 && a.last + 1 < N;
      events.push_back(arc_end(Kind::entry, a.arc, i, side,
                               one_sample ? 0.5 * (d.time[a.first - 1] + d.time[a.first]) : d.time[a.first]));
      events.push_back(arc_end(Kind::exit, a.arc, i, side,
                               one_sample ? 0.5 * (d.time[a.last] + d.time[a.last + 1]) : d.time[a.last],
                               sign_after));
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
        add_arc(arcs[next_arc++], sign);
        crossed_arc = true;
      }
      if (last < 0) {
        s.initial_sign[i] = sign;
      } else if (!crossed_arc && (u > 0) != (d.torque_body[static_cast<std::size_t>(last)][i] > 0)) {
        events.push_back(sign_change(i, torque_sign_change(d, i, static_cast<std::size_t>(last), j)));
      }
      last = static_cast<int>(j);
    }
    // A singular arc read as left at the last sample but one, before a bang arc of sign end_bang_sign (the
    // last sample, where saturated, has passed it already: its exit takes that sign).
    if (s.singular_at_end == i) {
      if (next_arc + 1 == arcs.size() && arcs[next_arc].last + 2 == N) {
        add_arc(arcs[next_arc++], end_bang_sign);
      } else {
        const auto last_exit = std::find_if(events.rbegin(), events.rend(), [i](const ArcEvent& e) {
          return e.axis == i && e.kind == Kind::exit;
        });
        if (last_exit != events.rend()) last_exit->sign_after = end_bang_sign;
      }
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

bool with_bounded_singular_torque(const ReorientationProblem& p, const ArcStructure& s,
                                  const std::vector<double>& times, const IndirectSolution& shot,
                                  ArcStructure& out) {
  std::vector<ArcEvent> events = s.events;
  for (std::size_t k = 0; k < events.size(); ++k)
    events[k].time = times[k];
  // The sign of u_i before each event, from the initial signs (events ascending in time).
  std::vector<std::size_t> order(events.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return events[a].time < events[b].time; });
  std::vector<double> sign_before(events.size());
  Vec3 sign = s.initial_sign;
  for (const std::size_t k : order) {
    const ArcEvent& e = events[k];
    sign_before[k] = sign[e.axis];
    if (e.kind == Kind::sign_change) sign[e.axis] = -sign[e.axis];
    if (e.kind == Kind::exit) sign[e.axis] = e.sign_after;
  }
  std::vector<ArcEvent> added;
  bool mended = false;
  const std::size_t n = events.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (events[k].kind != Kind::entry || events[k].arc != Arc::singular || events[k].pair < 0) continue;
    const auto exit_index = static_cast<std::size_t>(events[k].pair);
    const int i = events[k].axis;
    const double t_entry = events[k].time, t_exit = events[exit_index].time;
    const double ubar = p.torque_max[i];
    // The samples of the arc, with the excess |ũ_i|/ū_i − 1.
    std::vector<std::size_t> on_arc;
    for (std::size_t j = 0; j < shot.time.size(); ++j)
      if (shot.time[j] >= t_entry && shot.time[j] <= t_exit) on_arc.push_back(j);
    auto excess = [&](std::size_t j) { return std::abs(shot.torque_body[j][i]) / ubar - 1.0; };
    auto outside = [&](std::size_t j) { return excess(j) > kSingularTorqueExcess; };
    // The time between samples j and j+1 (one outside, one not) where |ũ_i| crosses ū_i.
    auto crossing = [&](std::size_t j) {
      const double a = excess(j), b = excess(j + 1);
      return shot.time[j] + (shot.time[j + 1] - shot.time[j]) * a / (a - b);
    };
    for (std::size_t q = 0; q < on_arc.size();) {
      if (!outside(on_arc[q])) {
        ++q;
        continue;
      }
      std::size_t r = q;
      while (r + 1 < on_arc.size() && outside(on_arc[r + 1]))
        ++r;
      // The samples at t_entry (t_exit) before (after) the arc's own are the bang arc's next to it.
      const bool from_entry = q == 0 || shot.time[on_arc[q - 1]] <= t_entry;
      const bool to_exit = r + 1 == on_arc.size() || shot.time[on_arc[r + 1]] >= t_exit;
      if (from_entry && to_exit) return false;
      const double u_sign = shot.torque_body[on_arc[q]][i] > 0 ? 1.0 : -1.0;
      const double a = from_entry ? t_entry : crossing(on_arc[q] - 1);
      const double b = to_exit ? t_exit : crossing(on_arc[r]);
      if (from_entry) {
        if (u_sign != sign_before[k]) {
          added.push_back(sign_change(i, t_entry));
        }
        events[k].time = b;
      } else if (to_exit) {
        const double after = events[exit_index].sign_after;
        events[exit_index].time = a;
        events[exit_index].sign_after = u_sign;
        if (u_sign != after) {
          added.push_back(sign_change(i, t_exit));
        }
      } else {
        added.push_back(arc_end(Kind::exit, Arc::singular, i, 0.0, a, u_sign));
        added.push_back(arc_end(Kind::entry, Arc::singular, i, 0.0, b));
      }
      mended = true;
      q = r + 1;
    }
  }
  if (!mended) return false;
  events.insert(events.end(), added.begin(), added.end());
  std::stable_sort(events.begin(), events.end(),
                   [](const auto& a, const auto& b) { return a.time < b.time; });
  for (ArcEvent& e : events)
    e.pair = -1;
  pair_arc_ends(events);
  out = s;
  out.events = events;
  return true;
}

}  // namespace poinsot::optimal::detail
