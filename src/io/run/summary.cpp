// summary.json (see summary.hpp and docs/run.md).
#include "poinsot/io/run/summary.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "run_json.hpp"

namespace poinsot::io {
namespace {

using detail::json;
using detail::mat;
using detail::num;
using detail::opt;
using detail::vec;

json state_json(const dynamics::State& s) {
  const Quat q = s.quaternion();
  return {{"t", s.time},
          {"omega_body", vec(s.omega_body)},
          {"omega_space", vec(s.omega_space())},
          {"R", mat(s.R_space_body)},
          {"quaternion", json::array({q.w(), q.x(), q.y(), q.z()})}};
}

}  // namespace

std::string summary_json(const RunSummary& s) {
  const auto& r = s.result;
  json j;
  j["scenario"] = s.scenario;
  j["source"] = s.source;
  j["title"] = s.title;
  j["method"] = s.method;
  j["torque"] = s.torque;
  j["t_end"] = s.t_end;
  j["sample_dt"] = s.sample_dt;
  j["status"] = detail::run_status(s.failure, r.interrupted);
  j["interrupted"] = r.interrupted;
  j["failure"] = detail::text_or_null(s.failure);
  j["body"] = {{"description", s.body_description},
               {"principal_moments", vec(s.principal_moments)},
               {"inertia", mat(s.inertia)},
               {"symmetry", s.symmetry}};
  j["initial"] = state_json(s.initial);
  j["initial"]["energy"] = s.energy0;
  j["initial"]["L_space"] = vec(s.L_space0);
  j["initial"]["L_norm"] = s.L_space0.norm();
  j["final"] = state_json(r.final_state);
  j["invariants"] = {{"energy_rel_error_max", num(r.errors.energy_rel_max)},
                     {"L_space_rel_error_max", num(r.errors.L_space_rel_max)},
                     {"L_norm_rel_error_max", num(r.errors.L_norm_rel_max)},
                     {"orthogonality_error_max", num(r.errors.orthogonality_max)}};
  json events;
  events["flip_times"] = r.flip_times;
  events["flip_count"] = r.flip_times.size();
  events["flip_interval_mean"] =
      r.flip_times.size() >= 2
          ? num((r.flip_times.back() - r.flip_times.front()) / static_cast<double>(r.flip_times.size() - 1))
          : json(nullptr);
  events["flip_interval_theory"] = opt(s.flip_interval_theory);
  events["period_theory"] = opt(s.period_theory);
  events["free_body_regime"] = detail::text_or_null(s.free_body_regime);
  json top = nullptr;
  if (s.top) {
    const auto& t = *s.top;
    top = {{"kind", std::string(dynamics::to_string(t.kind))},
           {"axis_body", vec(t.axis_body)},
           {"direction_space", vec(t.direction_space)},
           {"spin", t.spin},
           {"moment_axial", t.moment_axial},
           {"moment_transverse", t.moment_transverse},
           {"theta_min", t.theta_min},
           {"theta_max", t.theta_max},
           {"theta_min_theory", opt(t.theta_min_theory)},
           {"theta_max_theory", opt(t.theta_max_theory)},
           {"sleeping_criterion", t.sleeping ? json(*t.sleeping) : json(nullptr)}};
    events["precession_rate_mean"] = opt(t.precession_rate_mean);
    events[t.kind == dynamics::TopKind::heavy ? "precession_rate_fast_top" : "precession_rate_theory"] =
        opt(t.precession_rate_theory);
    if (t.kind == dynamics::TopKind::heavy) events["precession_rate_exact"] = opt(t.precession_rate_exact);
    events["nutation_frequency"] = opt(t.nutation_frequency);
    events["nutation_frequency_theory"] = opt(t.nutation_frequency_theory);
    if (t.kind == dynamics::TopKind::heavy)
      events["nutation_frequency_fast_top"] = opt(t.nutation_frequency_fast_top);
  }
  j["events"] = events;
  j["top"] = top;
  // Λ: the keys of `poinsot lambda --json` (lambda_json.hpp), and Λ(t0) under the name summary.json has
  // always used.
  json lam = nullptr;
  if (s.lambda) {
    lam = json{{"lambda_initial_body", mat(s.lambda->lambda_initial)}};
    lam.update(detail::lambda_properties_value(*s.lambda));
  }
  j["lambda"] = lam;
  j["steps"] = r.steps;
  j["rejected_steps"] = r.rejected_steps;
  j["samples"] = s.samples;
  j["wall_time_s"] = r.wall_time_s;
  j["steps_per_second"] =
      r.wall_time_s > 0.0 ? num(static_cast<double>(r.steps) / r.wall_time_s) : json(nullptr);
  j["files"] = {{"trajectory", detail::text_or_null(s.trajectory_file)},
                {"summary", detail::text_or_null(s.summary_file)}};
  return j.dump(2) + "\n";
}

void write_file_atomic(const std::string& path, const std::string& content) {
  const std::filesystem::path p(path);
  const std::string tmp = (p.parent_path() / fmt::format(".{}.tmp", p.filename().string())).string();
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw ComputationFailed(fmt::format("output: cannot create \"{}\": {}", tmp, std::strerror(errno)));
  }
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      ::unlink(tmp.c_str());
      throw ComputationFailed(fmt::format("output: writing \"{}\" failed: {}", tmp, std::strerror(err)));
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  ::fsync(fd);
  ::close(fd);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw ComputationFailed(
        fmt::format("output: cannot rename \"{}\" to \"{}\": {}", tmp, path, std::strerror(err)));
  }
}

}  // namespace poinsot::io
