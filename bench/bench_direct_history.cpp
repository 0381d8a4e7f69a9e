// Per-step cost of the direct history engine (eq. 3) against the length of the history it
// sums, for the 1- and 2-point models of the paper.
#include <memory>

#include <benchmark/benchmark.h>

#include "contact/direct_history_engine.hpp"
#include "greens/discrete_kernel.hpp"
#include "greens/sdof_model.hpp"

namespace {

void BM_DirectHistoryStep(benchmark::State& state) {
  const auto history = static_cast<std::size_t>(state.range(0));
  const rollnoise::SdofParameters table1{1.0, 50.0, 500.0, 1e5};
  const std::unique_ptr<rollnoise::GreensModel> model =
      state.range(1) == 1 ? std::make_unique<rollnoise::SdofModel>(table1)
                          : std::make_unique<rollnoise::SdofModel>(table1, 0.4, 0.01);
  // A small time step so that the kernel has not decayed within `history` lags.
  auto kernel = std::make_shared<const rollnoise::DiscreteKernel>(rollnoise::make_discrete_kernel(
      *model, 1e-6, history + 1, rollnoise::Discretisation::step));
  const Eigen::Index n = model->point_count();
  const Eigen::VectorXd force = Eigen::VectorXd::Ones(n);
  // Fill the history, then time steps at that length (the step adds one more lag each time,
  // negligible against `history`).
  const std::size_t extra = 1u << 16;
  rollnoise::DirectHistoryEngine engine(kernel, history + extra, force);
  for (std::size_t i = 0; i < history; ++i) engine.advance(force);
  Eigen::VectorXd u0(n);
  std::size_t done = 0;
  for (auto _ : state) {
    engine.history(u0);
    benchmark::DoNotOptimize(u0.data());
    if (++done < extra) engine.advance(force);
  }
  state.counters["lags"] = static_cast<double>(history);
}
BENCHMARK(BM_DirectHistoryStep)
    ->ArgsProduct({{100, 1000, 10000, 100000, 1000000}, {1, 2}})
    ->ArgNames({"history", "points"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
