// LCP solve time against the number of contact points, cold (empty active set) and warm
// (the previous step's active set, after a small change of q as between time steps).
#include <random>

#include <benchmark/benchmark.h>

#include "contact/lcp_solver.hpp"

namespace {

// A contact-like compliance: local diagonal plus a smooth coupling that decays with distance
// along a line of points, as for a tread on a belt.
Eigen::MatrixXd contact_compliance(Eigen::Index n) {
  Eigen::MatrixXd a(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      a(i, j) = 0.5 * std::exp(-static_cast<double>(std::abs(i - j)) / 8.0);
  a.diagonal().array() += 1.0;
  return a;
}

// About half the points in contact: a parabola pressed into the road plus roughness.
Eigen::VectorXd gap_vector(Eigen::Index n, std::mt19937_64& rng, double roughness) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd q(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double x = 2.0 * static_cast<double>(i) / static_cast<double>(n) - 1.0;
    q(i) = 2.0 * x * x - 0.5 + roughness * normal(rng);
  }
  return q;
}

void BM_LcpCold(benchmark::State& state) {
  const Eigen::Index n = state.range(0);
  std::mt19937_64 rng(1);
  rollnoise::LcpSolver solver(contact_compliance(n));
  const Eigen::VectorXd q = gap_vector(n, rng, 0.05);
  long changes = 0;
  for (auto _ : state) {
    solver.reset();
    benchmark::DoNotOptimize(solver.solve(q).data());
    changes += solver.iterations();
  }
  state.counters["active"] = static_cast<double>(solver.active_count());
  state.counters["changes"] = benchmark::Counter(static_cast<double>(changes), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_LcpCold)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Arg(1000)->Arg(2000)->Unit(benchmark::kMicrosecond);

void BM_LcpWarm(benchmark::State& state) {
  const Eigen::Index n = state.range(0);
  std::mt19937_64 rng(2);
  rollnoise::LcpSolver solver(contact_compliance(n));
  const Eigen::VectorXd base = gap_vector(n, rng, 0.05);
  // Consecutive steps differ by a little roughness.
  std::vector<Eigen::VectorXd> steps;
  std::normal_distribution<double> normal;
  for (int i = 0; i < 16; ++i) {
    Eigen::VectorXd q = base;
    for (Eigen::Index j = 0; j < n; ++j) q(j) += 0.002 * normal(rng);
    steps.push_back(q);
  }
  solver.solve(steps[0]);
  std::size_t i = 0;
  long changes = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(solver.solve(steps[++i % steps.size()]).data());
    changes += solver.iterations();
  }
  state.counters["active"] = static_cast<double>(solver.active_count());
  state.counters["changes"] = benchmark::Counter(static_cast<double>(changes), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_LcpWarm)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Arg(1000)->Arg(2000)->Unit(benchmark::kMicrosecond);

}  // namespace
