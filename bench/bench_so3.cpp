// SO(3) operations, one core, double precision. Run: build/release/bench/bench_so3
// Each benchmark cycles through a fixed set of random inputs so the branch predictor sees varied angles.
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "poinsot/so3/cayley.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot/so3/euler_angles.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace {
using poinsot::Mat3;
using poinsot::Quat;
using poinsot::Vec3;
constexpr std::size_t kN = 1024;

std::vector<Vec3> random_vectors(double scale) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-scale, scale);
  std::vector<Vec3> out(kN);
  for (auto& v : out)
    v = Vec3(u(rng), u(rng), u(rng));
  return out;
}

std::vector<Mat3> random_rotations() {
  std::vector<Mat3> out;
  for (const Vec3& v : random_vectors(1.8))
    out.push_back(poinsot::so3::exp(v));
  return out;
}

void BM_Exp(benchmark::State& state) {
  const auto vs = random_vectors(1.8);
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(poinsot::so3::exp(vs[i++ % kN]));
}
BENCHMARK(BM_Exp);

// Baseline in the same process: Eigen's AngleAxis → matrix (the same rotation as exp, by another route).
void BM_Baseline_EigenAngleAxisToMatrix(benchmark::State& state) {
  const auto vs = random_vectors(1.8);
  std::size_t i = 0;
  for (auto _ : state) {
    const Vec3& v = vs[i++ % kN];
    const double n = v.norm();
    benchmark::DoNotOptimize(Eigen::AngleAxisd(n, v / n).toRotationMatrix());
  }
}
BENCHMARK(BM_Baseline_EigenAngleAxisToMatrix);

// Baseline in the same process: Eigen's matrix → AngleAxis (acos-free, via its quaternion), as log's peer.
void BM_Baseline_EigenMatrixToAngleAxis(benchmark::State& state) {
  const auto rs = random_rotations();
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(Eigen::AngleAxisd(rs[i++ % kN]));
}
BENCHMARK(BM_Baseline_EigenMatrixToAngleAxis);

void BM_Log(benchmark::State& state) {
  const auto rs = random_rotations();
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(poinsot::so3::log(rs[i++ % kN]));
}
BENCHMARK(BM_Log);

void BM_QuaternionFromRotation(benchmark::State& state) {
  const auto rs = random_rotations();
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(poinsot::so3::quaternion_from_rotation(rs[i++ % kN]));
}
BENCHMARK(BM_QuaternionFromRotation);

void BM_RotationFromQuaternion(benchmark::State& state) {
  std::vector<Quat> qs;
  for (const auto& R : random_rotations())
    qs.emplace_back(R);
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(poinsot::so3::rotation_from_quaternion(qs[i++ % kN]));
}
BENCHMARK(BM_RotationFromQuaternion);

void BM_Cayley(benchmark::State& state) {
  const auto vs = random_vectors(1.0);
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(poinsot::so3::cayley(vs[i++ % kN]));
}
BENCHMARK(BM_Cayley);

void BM_EulerZXZFromRotation(benchmark::State& state) {
  const auto rs = random_rotations();
  const auto seq = poinsot::so3::EulerSequence::ZXZ();
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(poinsot::so3::euler_from_rotation(seq, rs[i++ % kN]));
}
BENCHMARK(BM_EulerZXZFromRotation);

void BM_ProjectToSO3(benchmark::State& state) {
  auto rs = random_rotations();
  for (auto& R : rs)
    R(0, 1) += 1e-6;
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(poinsot::so3::project_to_so3(rs[i++ % kN]));
}
BENCHMARK(BM_ProjectToSO3);

void BM_AngleBetween(benchmark::State& state) {
  const auto rs = random_rotations();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(poinsot::so3::angle_between(rs[i % kN], rs[(i + 1) % kN]));
    ++i;
  }
}
BENCHMARK(BM_AngleBetween);

}  // namespace
