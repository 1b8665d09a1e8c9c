#include "collocation_solution.hpp"

#include <algorithm>

namespace poinsot::optimal::detail {

namespace {}  // namespace

IntervalSample sample_interval(const CollocationNlp& nlp, const std::vector<double>& z, int k, double s) {
  const auto pt = [&](int p) { return Eigen::Map<const Vec11>(z.data() + kP * p); };
  const int b = nlp.interval_first_point(k);
  const Vec11 z0 = pt(b), z1 = pt(b + 1), z2 = pt(b + 2);
  const double h = nlp.interval_step(z.data(), k);
  const Vec7 f0 = nlp.dynamics().rhs(z0), f2 = nlp.dynamics().rhs(z2);
  const double s2 = s * s, s3 = s2 * s;
  IntervalSample r;
  r.x = (2 * s3 - 3 * s2 + 1) * z0.head<7>() + (s3 - 2 * s2 + s) * h * f0 +
        (-2 * s3 + 3 * s2) * z2.head<7>() + (s3 - s2) * h * f2;
  r.xdot = ((6 * s2 - 6 * s) * z0.head<7>() + (-6 * s2 + 6 * s) * z2.head<7>()) / h +
           (3 * s2 - 4 * s + 1) * f0 + (3 * s2 - 2 * s) * f2;
  r.v = 2 * (s - 0.5) * (s - 1) * z0.tail<4>() - 4 * s * (s - 1) * z1.tail<4>() +
        2 * s * (s - 0.5) * z2.tail<4>();
  return r;
}

std::vector<double> mesh_errors(const CollocationNlp& nlp, const std::vector<double>& z) {
  static const double gx[5] = {0.0469100770306680, 0.2307653449471585, 0.5, 0.7692346550528415,
                               0.9530899229693320};
  static const double gw[5] = {0.1184634425280945, 0.2393143352496832, 0.2844444444444444, 0.2393143352496832,
                               0.1184634425280945};
  Vec7 scale = Vec7::Ones();
  for (int p = 0; p < nlp.points(); ++p)
    scale = scale.cwiseMax(Eigen::Map<const Vec7>(z.data() + kP * p).cwiseAbs() + Vec7::Ones());
  std::vector<double> err(nlp.intervals());
  for (int k = 0; k < nlp.intervals(); ++k) {
    const double h = nlp.interval_step(z.data(), k);
    Vec7 sum = Vec7::Zero();
    for (int i = 0; i < 5; ++i) {
      const IntervalSample s = sample_interval(nlp, z, k, gx[i]);
      Vec11 zz;
      zz << s.x, s.v;
      sum += gw[i] * h * (s.xdot - nlp.dynamics().rhs(zz)).cwiseAbs();
    }
    err[k] = sum.cwiseQuotient(scale).maxCoeff();
  }
  return err;
}

DirectSolution extract_solution(const CollocationNlp& nlp, const std::vector<double>& z,
                                const std::vector<double>& y) {
  DirectSolution s;
  s.final_time = nlp.final_time(z.data());
  s.cost = nlp.objective(z.data());
  const std::vector<double> t = nlp.point_times(z.data());
  for (int pt = 0; pt < nlp.points(); ++pt) {
    const double* zp = z.data() + kP * pt;
    s.time.push_back(t[pt]);
    s.attitude.push_back(Quat(zp[0], zp[1], zp[2], zp[3]).normalized());
    s.omega_body.emplace_back(zp[4], zp[5], zp[6]);
    s.torque_body.emplace_back(zp[7], zp[8], zp[9]);
    if (const auto& p = nlp.problem(); p.wheels)
      s.wheel_momentum.push_back(optimal::wheel_momentum(p.inertia_body, *p.wheels, p.wheel_system_momentum(),
                                                         s.attitude.back(), s.omega_body.back()));
  }
  for (int k = 0; k < nlp.intervals(); ++k)
    s.node_time.push_back(t[nlp.interval_first_point(k)]);
  s.node_time.push_back(t.back());
  if (!y.empty())
    for (int k = 0; k < nlp.intervals(); ++k) {
      const Vec7 lambda = nlp.costate(y, k);
      const IntervalSample mid = sample_interval(nlp, z, k, 0.5);
      const Vec4 q = mid.x.head<4>();
      s.costate_time.push_back(t[nlp.interval_first_point(k) + 1]);
      s.costate_attitude_body.push_back(0.5 * quaternion_omega_matrix(q).transpose() * lambda.head<4>());
      s.costate_omega.push_back(lambda.tail<3>());
    }
  const auto& pointing = nlp.problem().pointing;
  s.pointing_multiplier.assign(pointing.size(), std::vector<double>(nlp.points(), 0.0));
  if (!y.empty())
    for (std::size_t c = 0; c < pointing.size(); ++c) {
      const double sign = pointing[c].kind == PointingKind::keep_out ? 1.0 : -1.0;
      for (int pt = 0; pt < nlp.points(); ++pt)
        if (const int row = nlp.pointing_row(pt, static_cast<int>(c)); row >= 0)
          s.pointing_multiplier[c][pt] = sign * y[row];
    }
  s.mesh_error = mesh_errors(nlp, z);
  s.max_mesh_error = *std::max_element(s.mesh_error.begin(), s.mesh_error.end());
  return s;
}

}  // namespace poinsot::optimal::detail
