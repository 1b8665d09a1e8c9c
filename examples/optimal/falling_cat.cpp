// The falling cat (Kane & Scher 1969) turned over: two identical axisymmetric halves joined at a point by a
// ball joint with three motors, free floating at zero angular momentum, rotate as a whole by 180° about their
// spine by changing shape, at minimum effort ∫|τ|²dt, in rotation-matrix coordinates; with --no-twist the
// waist bends but does not twist (optimal::NoTwist).
//
// Each half is a cylinder (1 kg, 1 m, radius 0.2 m) along its body x, the waist at its +x end; the cat is
// bent into a V in the x–z plane, each half tilted by 0.5 rad from the spine (space x), centre of mass at the
// origin. Target: the same V turned by π about x, at rest, after 1 s. Solved on 6 intervals from the naive
// guess (or, with --no-twist, from the cat turned rigidly), then on 12 and 24 intervals, each from the
// previous mesh's solution; the 24-interval optimum is re-simulated by the projected RK4 from its control
// history. With --out DIR it writes DIR/falling_cat.csv (t, then per half x_space and R_space_body row-major
// at every collocation point), which examples/optimal/plot_falling_cat.py draws.
// Run: build/release/examples/example_falling_cat [--no-twist] [--out DIR]
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "poinsot/optimal/multibody_direct.hpp"

namespace {

using poinsot::Mat3;
using poinsot::Vec3;

constexpr double kBend = 0.5;  // rad, each half from the spine
constexpr double kTurn = std::numbers::pi;
constexpr double kTime = 1.0;  // s

poinsot::multibody::State bent(const Mat3& turn) {
  poinsot::multibody::State s;
  s.bodies.resize(2);
  const Mat3 Ra = Eigen::AngleAxisd(kBend, Vec3::UnitY()).toRotationMatrix();
  const Mat3 Rb = Eigen::AngleAxisd(std::numbers::pi, Vec3::UnitZ()).toRotationMatrix() * Ra;
  const Vec3 waist(0.0, 0.0, -0.5 * std::sin(kBend));
  s.bodies[0].R_space_body = turn * Ra;
  s.bodies[0].x_space = turn * (waist - Ra * Vec3(0.5, 0.0, 0.0));
  s.bodies[1].R_space_body = turn * Rb;
  s.bodies[1].x_space = turn * (waist - Rb * Vec3(0.5, 0.0, 0.0));
  return s;
}

Mat3 about_spine(double angle) {
  return Eigen::AngleAxisd(angle, Vec3::UnitX()).toRotationMatrix();
}

// The bent cat turned rigidly about the spine at the constant rate kTurn/kTime: an initial guess made of
// rotations that keep the joint (not a motion at zero angular momentum).
poinsot::optimal::MultibodyOptimum rigid_turn(int intervals) {
  poinsot::optimal::MultibodyOptimum guess;
  const Vec3 omega(kTurn / kTime, 0.0, 0.0);
  for (int p = 0; p <= 2 * intervals; ++p) {
    const double t = kTime * p / (2.0 * intervals);
    poinsot::multibody::State s = bent(about_spine(kTurn * t / kTime));
    s.time = t;
    for (auto& b : s.bodies) {
      b.omega_body = b.R_space_body.transpose() * omega;
      b.v_space = omega.cross(b.x_space);
    }
    guess.time.push_back(t);
    guess.states.push_back(s);
    guess.controls.push_back(Eigen::VectorXd::Zero(3));
  }
  return guess;
}

void write_csv(const std::filesystem::path& dir, const poinsot::optimal::MultibodyOptimum& o) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / "falling_cat.csv";
  const std::filesystem::path temp = dir / "falling_cat.csv.tmp";
  {
    std::ofstream out(temp);
    out << "# status: " << o.status << ", effort " << o.cost << " N^2 m^2 s\n";
    out << "t";
    for (const char* body : {"front", "back"}) {
      for (const char* c : {"x", "y", "z"})
        out << ',' << body << ".x_" << c;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          out << ',' << body << ".R" << r << c;
    }
    out << '\n';
    char buffer[32];
    for (std::size_t p = 0; p < o.time.size(); ++p) {
      out << o.time[p];
      for (const auto& b : o.states[p].bodies) {
        for (int k = 0; k < 3; ++k) {
          std::snprintf(buffer, sizeof buffer, ",%.17g", b.x_space(k));
          out << buffer;
        }
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) {
            std::snprintf(buffer, sizeof buffer, ",%.17g", b.R_space_body(r, c));
            out << buffer;
          }
      }
      out << '\n';
    }
  }
  std::filesystem::rename(temp, path);
  std::printf("  wrote %s\n", path.string().c_str());
}

}  // namespace

int main(int argc, char** argv) {
  using namespace poinsot;
  using namespace poinsot::optimal;
  bool no_twist = false;
  std::string out_dir;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--no-twist") {
      no_twist = true;
    } else if (arg == "--out" && i + 1 < argc) {
      out_dir = argv[++i];
    } else {
      std::fprintf(stderr, "example_falling_cat: got \"%s\"; expected --no-twist or --out DIR\n",
                   arg.c_str());
      return 2;
    }
  }
  MultibodyProblem p;
  const Mat3 J = Vec3(0.5 * 0.04, (3.0 * 0.04 + 1.0) / 12.0, (3.0 * 0.04 + 1.0) / 12.0).asDiagonal();
  const int front = p.system.add_body_from_inertia("front", 1.0, J);
  const int back = p.system.add_body_from_inertia("back", 1.0, J);
  const int waist = p.system.add_ball("waist", front, Vec3(0.5, 0, 0), back, Vec3(0.5, 0, 0));
  p.initial_state = bent(Mat3::Identity());
  p.final_state = bent(about_spine(kTurn));
  p.final_time = kTime;
  p.actuators = {{ActuatorKind::ball_torque, waist, 100.0}};
  // The straight cat's halves face each other (a half-turn about body z); a bend turns about an axis
  // perpendicular to the spine (body x).
  if (no_twist)
    p.no_twist = {
        {waist, Vec3::UnitX(), Eigen::AngleAxisd(std::numbers::pi, Vec3::UnitZ()).toRotationMatrix()}};
  std::printf("falling cat turned over%s (R-coordinates):\n", no_twist ? ", no twist" : "");
  MultibodyOptimum previous;
  const MultibodyOptimum guess = rigid_turn(6);
  std::vector<double> effort;
  for (const int n : {6, 12, 24}) {
    p.intervals = n;
    MultibodyOptions options;
    options.warm_start = n > 6 ? &previous : no_twist ? &guess : nullptr;
    options.stabilisation_step = 0.05;  // |S|, |μ| ≤ 0.05/h: no free jump across a half-turn
    const MultibodyOptimum o = solve_multibody(p, options);
    std::printf("  N = %2d: %s, effort %.10f N²·m²·s, %d Ipopt iterations, stabilisation step %.2g\n", n,
                o.status.c_str(), o.cost, o.nlp_iterations, o.stabilisation_step);
    effort.push_back(o.cost);
    previous = o;
  }
  if (!previous.converged) {
    std::printf("falling cat: not solved on 24 intervals: %s\n", previous.status.c_str());
    return 1;
  }
  const double d1 = effort[1] - effort[0], d2 = effort[2] - effort[1];
  if (d1 * d2 > 0.0)
    std::printf("  effort differences %.3g, %.3g: observed order %.2f\n", d1, d2, std::log2(d1 / d2));
  else
    std::printf("  effort differences %.3g, %.3g: of opposite signs, no order\n", d1, d2);
  const MultibodyReplay replay = replay_controls(p, previous, 256);
  std::printf(
      "  re-simulated (256 steps per interval): attitude error %.2e rad, joint gap %.2e m, momentum change "
      "%.2e\n",
      replay.attitude_error, replay.max_joint_gap, replay.max_momentum_change);
  if (!out_dir.empty()) write_csv(out_dir, previous);
  return 0;
}
