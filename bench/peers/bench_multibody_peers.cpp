// Side-by-side cost and accuracy of poinsot's RATTLE and the peer libraries (Bullet, ODE, MuJoCo, Simbody) on
// the benchmark chain of N ball-jointed thin rods (1 m, 1 kg, radius 1 cm) released from horizontal under
// gravity, dt = 1e-3 s, in one process. Each library is registered when CMake found it
// (POINSOT_PEER_<LIBRARY>); what each is configured with: its chain_<library>.cpp and
// docs/measurements/peers.md. After the runs, the growth exponent p of each library's CPU time per step, t ≈
// c N^p, fitted by least squares on log t against log N over N >= 16, and the slope between the two largest
// sizes. (Google Benchmark's BigO is not used: it only picks among N, N log N, N², ..., and the runs have
// fixed iteration counts, one family per N; see chain_bench.hpp.) Counters: energy_err_rel, max_gap_m,
// tip_z_1s_m (chain_bench.hpp). Run: bash scripts/bench-peers.sh, or
//   build/release/bench/peers/bench_multibody_peers --benchmark_counters_tabular=true
//   --benchmark_repetitions=3
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "chain_bench.hpp"

namespace {

/// The console reporter, remembering each (library, N, CPU time per step: steadier than the real time on a
/// shared machine) to fit the exponents at the end. With
/// repetitions, the median of the repetitions is used; without, the single run.
class ExponentReporter : public benchmark::ConsoleReporter {
 public:
  using benchmark::ConsoleReporter::ConsoleReporter;

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      const bool aggregate = run.run_type == Run::RT_Aggregate;
      if (run.error_occurred || run.run_name.args.empty() || (aggregate && run.aggregate_name != "median"))
        continue;
      Point& p = points_[run.run_name.function_name][std::stoll(run.run_name.args)];
      if (aggregate || !p.from_median) p = {run.GetAdjustedCPUTime(), aggregate};
    }
    ConsoleReporter::ReportRuns(runs);
  }

  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf("\nGrowth of the CPU time per step, t = c N^p (least squares on log t, log N, N >= 16):\n");
    for (const auto& [name, by_n] : points_) {
      double sx = 0, sy = 0, sxx = 0, sxy = 0;
      int k = 0;
      for (const auto& [n, p] : by_n) {
        if (n < 16) continue;
        const double x = std::log(static_cast<double>(n)), y = std::log(p.time);
        sx += x, sy += y, sxx += x * x, sxy += x * y, ++k;
      }
      if (k < 2) continue;
      const double slope = (k * sxy - sx * sy) / (k * sxx - sx * sx);
      const auto last = by_n.rbegin(), before = std::next(last);  // the slope between the two largest sizes
      const double local = std::log(last->second.time / before->second.time) /
                           std::log(static_cast<double>(last->first) / static_cast<double>(before->first));
      std::printf("  %-20s p = %.2f  (%d sizes; %.2f from N = %lld to %lld)\n", name.c_str(), slope, k, local,
                  static_cast<long long>(before->first), static_cast<long long>(last->first));
    }
    std::fflush(stdout);
  }

 private:
  struct Point {
    double time = 0.0;
    bool from_median = false;
  };
  std::map<std::string, std::map<std::int64_t, Point>> points_;
};

}  // namespace

int main(int argc, char** argv) {
  bool tabular = false;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--benchmark_counters_tabular=true") tabular = true;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  poinsot::bench::register_poinsot();
#ifdef POINSOT_PEER_BULLET
  poinsot::bench::register_bullet();
#endif
#ifdef POINSOT_PEER_ODE
  poinsot::bench::register_ode();
#endif
#ifdef POINSOT_PEER_MUJOCO
  poinsot::bench::register_mujoco();
#endif
#ifdef POINSOT_PEER_SIMBODY
  poinsot::bench::register_simbody();
#endif
  int options =
      isatty(STDOUT_FILENO) ? benchmark::ConsoleReporter::OO_Color : benchmark::ConsoleReporter::OO_None;
  if (tabular) options |= benchmark::ConsoleReporter::OO_Tabular;
  ExponentReporter reporter(static_cast<benchmark::ConsoleReporter::OutputOptions>(options));
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
