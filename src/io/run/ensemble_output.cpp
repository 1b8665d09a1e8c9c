#include <algorithm>
#include <cmath>
#include <iterator>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "poinsot/io/run/ensemble_output.hpp"
#include "poinsot/io/run/ensemble_table.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "poinsot/version.hpp"

namespace poinsot::io {
namespace {

using json = nlohmann::ordered_json;

json number(double x) {
  return std::isfinite(x) ? json(x) : json(nullptr);
}

}  // namespace

std::string ensemble_csv(const ensemble::EnsembleResult& r) {
  std::string out;
  auto it = std::back_inserter(out);
  const char* separator = "";
  for (const SampleColumn& c : sample_columns()) {
    for (const std::string& name : c.csv_names) {
      fmt::format_to(it, "{}{}", separator, name);
      separator = ",";
    }
  }
  out += "\n";
  for (const ensemble::SampleRow& row : r.rows) {
    separator = "";
    for (const SampleColumn& c : sample_columns()) {
      if (c.kind == SampleColumn::Kind::unsigned_integer) {
        fmt::format_to(it, "{}{}", separator, c.index(row));
        separator = ",";
        continue;
      }
      const std::array<double, 4> v = c.values(row);
      for (std::size_t k = 0; k < c.csv_names.size(); ++k) {
        if (c.kind == SampleColumn::Kind::integer) {
          fmt::format_to(it, "{}{}", separator, static_cast<long long>(v[k]));
        } else {
          fmt::format_to(it, "{}{}", separator, v[k]);
        }
        separator = ",";
      }
    }
    out += "\n";
  }
  return out;
}

std::string ensemble_summary_json(const EnsembleScenario& sc, const ensemble::EnsembleOptions& o,
                                  const ensemble::EnsembleResult& r) {
  json j;
  j["kind"] = "ensemble";
  j["poinsot_version"] = kVersion;
  j["scenario"] = sc.base.name;
  j["source"] = sc.base.source;
  j["method"] = o.method;
  j["path"] = r.path;
  j["samples"] = o.samples;
  j["completed"] = r.completed;
  j["interrupted"] = r.interrupted;
  j["seed"] = sc.seed;
  j["threads"] = o.threads;
  j["t_end"] = o.t_end;
  j["dt"] = o.dt;
  j["max_step"] = number(o.max_step);  // adaptive methods; null: none
  j["policy"] = ensemble::to_string(sc.dispersions.policy);
  j["rejected_draws"] = r.rejected;
  j["repaired_samples"] = r.repaired;
  j["body_steps"] = r.body_steps;
  j["wall_time_s"] = r.wall_time_s;
  j["body_steps_per_s"] = number(r.wall_time_s > 0 ? static_cast<double>(r.body_steps) / r.wall_time_s : NAN);
  j["samples_per_s"] = number(r.wall_time_s > 0 ? static_cast<double>(r.completed) / r.wall_time_s : NAN);
  j["percentile_method"] =
      r.rows.empty() ? fmt::format(
                           "relative-error sketch (per-sample output off): |P - exact| <= {} * max(|x_lo|, "
                           "|x_hi|), x_lo and x_hi the order statistics interpolated (Hyndman-Fan 7)",
                           ensemble::kQuantileRelativeAccuracy)
                     : "exact order statistics, linear interpolation (Hyndman-Fan 7)";
  if (o.slew) {
    const ensemble::SlewSpec& sp = o.slew->spec();
    const Quat qf = so3::quaternion_from_rotation(sp.target_attitude);
    const ensemble::RunningStats& m = r.stats[ensemble::meets_requirement];
    j["slew"] = {
        {"feedback_law",
         "u = sat(u_ref - kp e_theta - kd (omega - omega_ref)), e_theta = 2 sgn(w) v, (w, v) = q_ref* q"},
        {"kp", sp.kp},
        {"kd", sp.kd},
        {"torque_bound", ensemble::to_string(sp.limit)},
        {"torque_max", sp.limit == ensemble::SlewTorqueLimit::none ? json()
                       : sp.limit == ensemble::SlewTorqueLimit::norm
                           ? json(sp.torque_max[0])
                           : json{sp.torque_max[0], sp.torque_max[1], sp.torque_max[2]}},
        {"pointing_requirement", sp.pointing_requirement},
        {"attitude_final", {qf.w(), qf.x(), qf.y(), qf.z()}},
        {"omega_final", {sp.target_omega[0], sp.target_omega[1], sp.target_omega[2]}},
        {"steps_per_sample", o.slew->step_count()},
        {"share_meeting_requirement", number(m.count > 0 ? m.mean : NAN)}};
  }
  json outputs = json::object();
  for (int q = 0; q < ensemble::kOutputCount; ++q) {
    const ensemble::RunningStats& s = r.stats[static_cast<std::size_t>(q)];
    json o_j;
    o_j["unit"] = ensemble::kOutputUnits[q];
    o_j["count"] = s.count;
    o_j["nan_count"] = s.nan_count;
    o_j["mean"] = number(s.count > 0 ? s.mean : NAN);
    o_j["std"] = number(s.count > 1 ? std::sqrt(s.variance()) : NAN);
    o_j["min"] = number(s.count > 0 ? s.min : NAN);
    o_j["max"] = number(s.count > 0 ? s.max : NAN);
    o_j["nominal"] = number(r.nominal.out[static_cast<std::size_t>(q)]);
    if (!r.rows.empty() && s.count > 0) {
      std::vector<double> v;
      v.reserve(r.rows.size());
      for (const auto& row : r.rows)
        v.push_back(row.out[static_cast<std::size_t>(q)]);
      json p = json::object();
      for (double pc : ensemble::kPercentiles)
        p[fmt::format("P{}", pc)] = number(ensemble::percentile(v, pc));
      o_j["percentiles"] = p;
    } else if (const ensemble::QuantileSketch& sketch = r.sketches[static_cast<std::size_t>(q)];
               sketch.count() > 0) {
      json p = json::object();
      for (double pc : ensemble::kPercentiles)
        p[fmt::format("P{}", pc)] = number(sketch.percentile(pc));
      o_j["percentiles"] = p;
    }
    if (const ensemble::FixedHistogram& h = r.histograms[static_cast<std::size_t>(q)]; h.has_edges()) {
      json edges = json::array();
      for (int i = 0; i <= h.bins(); ++i)
        edges.push_back(h.edge(i));
      o_j["histogram"] = {{"edges_from", o.histograms.ranges[static_cast<std::size_t>(q)]
                                             ? "scenario"
                                             : fmt::format("pilot: samples 0 to {}",
                                                           std::min(o.samples, ensemble::kBlockSamples) - 1)},
                          {"edges", edges},
                          {"counts", h.counts()},
                          {"underflow", h.underflow()},
                          {"overflow", h.overflow()}};
    }
    outputs[ensemble::kOutputNames[q]] = o_j;
  }
  j["outputs"] = outputs;
  return j.dump(2) + "\n";
}

}  // namespace poinsot::io
