// The cost of the radiation stage's anchor solves (59 per run to the 5 kHz band's upper edge,
// 5623 Hz). On the runs' meshes (tyre_radiation.hpp): the base, the loaded tyre graded to 2 mm at
// the patch edges, 16 across, 12 sidewall rings (3204 points, 1602 sources), serving the anchors
// up to 4.15 kHz, and above that the same with the tread split in 2 and 21 rings (7874 points,
// 3970 sources). Each solve: the velocity matrix at the orbit representatives (monopoles up to
// 3 kHz, combined sources above, as the stage), split by the two mirrors into four blocks,
// factorised by the normal equations (OpenBLAS, single-threaded). Beside them the references it replaced: the QR of the same blocks, one
// mirror only (two blocks), no split, and the SVD pseudo-inverse of the first version.
// Performance lives here, never in timed unit tests. Run: build/bench/bench_radiation
#include <complex>
#include <numbers>
#include <optional>
#include <vector>

#include <Eigen/SVD>
#include <benchmark/benchmark.h>

#include "radiation/equivalent_sources.hpp"
#include "radiation/quantised_power_operator.hpp"
#include "radiation/tyre_radiation.hpp"
#include "radiation/tyre_surface_mesh.hpp"

namespace {

using namespace rollnoise;
using Complex = std::complex<double>;

// The runs' base mesh (tools/rollnoise/tyre_sound.cpp), deformed with the demo tyre's patch.
TyreSurfaceMeshSpec base_spec() {
  TyreSurfaceMeshSpec s;
  s.geometry = TyreGeometry::deformed;
  s.around = 96;
  s.contact_refinement = 10.0;
  s.across = 16;
  s.sidewall_rings = 12;
  return s;
}

// The mesh of the anchors above 4.15 kHz in a run to 5623 Hz.
TyreSurfaceMeshSpec split_spec() {
  TyreRadiationSettings settings;
  settings.mesh = base_spec();
  settings.max_frequency_hz = 5623.4;
  return radiation_mesh_levels(settings).back().spec;
}

std::optional<CombinedSources> layer(const TyreSurfaceMesh& mesh, bool combined) {
  if (!combined) return std::nullopt;
  return CombinedSources{mesh.source_normals, 1.0, 50.0};
}

struct TyreProblem {
  TyreProblem(const TyreSurfaceMeshSpec& spec, EquivalentSources::Symmetry symmetry, LeastSquaresMethod method,
              bool combined = true)
      : mesh(make_tyre_surface_mesh(spec)),
        model(mesh.sources, mesh.points, mesh.normals, true, Medium{}, symmetry, layer(mesh, combined)) {
    model.set_least_squares_method(method);
  }
  TyreSurfaceMesh mesh;
  EquivalentSources model;
  Eigen::Matrix3Xd receivers = (Eigen::Matrix3Xd(3, 3) << 0.2, -0.2, 0.0, 0.29, 0.29, 7.5, 0.1, 0.1, 1.2).finished();
};

// The solve and the transfer to three receivers at f (Hz).
void solve_tyre(benchmark::State& state, const TyreProblem& p, double f) {
  const double omega = 2 * std::numbers::pi * f;
  bool normal = true;
  for (auto _ : state) {
    const EquivalentSourceSolve solve = p.model.solve(omega);
    normal = solve.normal_equations();
    benchmark::DoNotOptimize(solve.transfer(p.model.pressure_matrix(omega, p.receivers)));
  }
  state.counters["points"] = static_cast<double>(p.mesh.points.cols());
  state.counters["sources"] = static_cast<double>(p.mesh.sources.cols());
  state.counters["blocks"] = static_cast<double>(p.model.symmetry_blocks());
  state.counters["normal_equations"] = normal ? 1.0 : 0.0;
}

using Symmetry = EquivalentSources::Symmetry;

void BM_BaseMesh1kHz(benchmark::State& state) {
  solve_tyre(state, TyreProblem(base_spec(), Symmetry::automatic, LeastSquaresMethod::automatic, false), 1000.0);
}
BENCHMARK(BM_BaseMesh1kHz)->Unit(benchmark::kMillisecond)->Iterations(3);
void BM_BaseMesh4kHz(benchmark::State& state) {
  solve_tyre(state, TyreProblem(base_spec(), Symmetry::automatic, LeastSquaresMethod::automatic), 4000.0);
}
BENCHMARK(BM_BaseMesh4kHz)->Unit(benchmark::kMillisecond)->Iterations(3);
void BM_SplitMesh5623Hz(benchmark::State& state) {
  solve_tyre(state, TyreProblem(split_spec(), Symmetry::automatic, LeastSquaresMethod::automatic), 5623.4);
}
BENCHMARK(BM_SplitMesh5623Hz)->Unit(benchmark::kMillisecond)->Iterations(2);

// The references on the base mesh at 4 kHz: the QR of the four blocks, one mirror (two
// blocks, as before issue 10 §3), no split.
void BM_BaseMesh4kHzQr(benchmark::State& state) {
  solve_tyre(state, TyreProblem(base_spec(), Symmetry::automatic, LeastSquaresMethod::qr), 4000.0);
}
BENCHMARK(BM_BaseMesh4kHzQr)->Unit(benchmark::kMillisecond)->Iterations(2);
void BM_BaseMesh4kHzOneMirror(benchmark::State& state) {
  solve_tyre(state, TyreProblem(base_spec(), Symmetry::centre_plane, LeastSquaresMethod::automatic), 4000.0);
}
BENCHMARK(BM_BaseMesh4kHzOneMirror)->Unit(benchmark::kMillisecond)->Iterations(2);
void BM_BaseMesh4kHzNoSplit(benchmark::State& state) {
  solve_tyre(state, TyreProblem(base_spec(), Symmetry::none, LeastSquaresMethod::automatic), 4000.0);
}
BENCHMARK(BM_BaseMesh4kHzNoSplit)->Unit(benchmark::kMillisecond)->Iterations(1);
// And the split mesh by QR (what a fallback would cost there).
void BM_SplitMesh5623HzQr(benchmark::State& state) {
  solve_tyre(state, TyreProblem(split_spec(), Symmetry::automatic, LeastSquaresMethod::qr), 5623.4);
}
BENCHMARK(BM_SplitMesh5623HzQr)->Unit(benchmark::kMillisecond)->Iterations(1);

// One anchor of the stage as TyreRadiation::radiate does it: the solve, the transfer, the
// strengths and powers of the 46 bins around it (0.23 s transform, anchors 100 Hz apart).
void BM_StageAnchorSplitMesh5623Hz(benchmark::State& state) {
  const TyreProblem p(split_spec(), Symmetry::automatic, LeastSquaresMethod::automatic);
  const double omega = 2 * std::numbers::pi * 5623.4;
  const Eigen::MatrixXcd velocities = Eigen::MatrixXcd::Random(p.mesh.points.cols(), 46);
  for (auto _ : state) {
    const EquivalentSourceSolve solve = p.model.solve(omega);
    benchmark::DoNotOptimize(solve.transfer(p.model.pressure_matrix(omega, p.receivers)));
    benchmark::DoNotOptimize(p.model.radiated_power(omega, solve.strengths(velocities)));
  }
}
BENCHMARK(BM_StageAnchorSplitMesh5623Hz)->Unit(benchmark::kMillisecond)->Iterations(2);

// What the cache stores at the top anchor (radiation/quantised_power_operator.hpp): the power
// operator's blocks as the solve gives them (the reference), and their rotation to the singular
// basis and rounding to 16 bits, which every cold anchor now adds. Counters: the numbers kept.
void BM_PowerOperatorSplitMesh5623Hz(benchmark::State& state) {
  const TyreProblem p(split_spec(), Symmetry::automatic, LeastSquaresMethod::automatic);
  const double omega = 2 * std::numbers::pi * 5623.4;
  const EquivalentSourceSolve solve = p.model.solve(omega);
  std::vector<Eigen::MatrixXcd> blocks;
  for (auto _ : state) blocks = p.model.power_operator(solve, omega, p.mesh.tread_points);
  double values = 0.0;
  for (const Eigen::MatrixXcd& b : blocks) values += static_cast<double>(b.size());
  state.counters["complex_values"] = values;
}
BENCHMARK(BM_PowerOperatorSplitMesh5623Hz)->Unit(benchmark::kMillisecond)->Iterations(2);
void BM_QuantisePowerOperatorSplitMesh5623Hz(benchmark::State& state) {
  const TyreProblem p(split_spec(), Symmetry::automatic, LeastSquaresMethod::automatic);
  const double omega = 2 * std::numbers::pi * 5623.4;
  const std::vector<Eigen::MatrixXcd> blocks = p.model.power_operator(p.model.solve(omega), omega, p.mesh.tread_points);
  QuantisedPower q;
  for (auto _ : state) q = quantise_power_operator(blocks);
  double values = 0.0;
  for (const Eigen::MatrixXcd& b : q.blocks) values += static_cast<double>(b.size());
  state.counters["complex_values"] = values;
}
BENCHMARK(BM_QuantisePowerOperatorSplitMesh5623Hz)->Unit(benchmark::kMillisecond)->Iterations(3);

// One cold anchor of a run to 5623 Hz exactly as the stage solves it before storing it in the
// cache (TyreRadiation::solve_anchor): the solve, the transfer to the three microphones, the power
// operator on the tread and its rotation and rounding. The top anchor (the split mesh, combined
// sources), one on the base mesh with combined sources and one with monopoles. This is what a
// profile of the cold radiation runs on (valgrind --tool=callgrind ... --benchmark_filter=ColdAnchor).
void cold_anchor(benchmark::State& state, double f) {
  TyreRadiationSettings settings;
  settings.mesh = base_spec();
  settings.max_frequency_hz = 5623.4;
  const Eigen::Matrix3Xd receivers = (Eigen::Matrix3Xd(3, 3) << 0.2, -0.2, 0.0, 0.29, 0.29, 7.5, 0.1, 0.1, 1.2).finished();
  const TyreRadiation radiation(settings, receivers);
  const std::size_t level = radiation.level_of(f);
  const Eigen::Index columns = radiation.level_mesh(level).tread_points;
  Eigen::Index rank = 0;
  for (auto _ : state) {
    const AnchorOperators operators = radiation.solve_anchor(level, f, columns);
    rank = operators.power_rank();
    benchmark::DoNotOptimize(operators.transfer.data());
  }
  state.counters["power_rank"] = static_cast<double>(rank);
}
void BM_ColdAnchorSplitMesh5623Hz(benchmark::State& state) { cold_anchor(state, 5623.4); }
BENCHMARK(BM_ColdAnchorSplitMesh5623Hz)->Unit(benchmark::kMillisecond)->Iterations(1);
void BM_ColdAnchorBaseMesh4kHz(benchmark::State& state) { cold_anchor(state, 4000.0); }
BENCHMARK(BM_ColdAnchorBaseMesh4kHz)->Unit(benchmark::kMillisecond)->Iterations(1);
void BM_ColdAnchorBaseMesh2kHz(benchmark::State& state) { cold_anchor(state, 2000.0); }
BENCHMARK(BM_ColdAnchorBaseMesh2kHz)->Unit(benchmark::kMillisecond)->Iterations(1);

// The first version's reference on the uniform mesh (96 × 8, monopoles): P·V⁺ from the thin SVD.
void BM_AnchorSolveSvdReference(benchmark::State& state) {
  const TyreSurfaceMesh mesh = make_tyre_surface_mesh({});
  const EquivalentSources model(mesh.sources, mesh.points, mesh.normals, true);
  const double omega = 2 * std::numbers::pi * 1000.0, k = omega / Medium{}.sound_speed;
  Eigen::MatrixXcd v(mesh.points.cols(), mesh.sources.cols());
  for (Eigen::Index s = 0; s < v.cols(); ++s)
    for (Eigen::Index m = 0; m < v.rows(); ++m)
      v(m, s) = -mesh.normals.col(m).cast<Complex>().dot(helmholtz_green_gradient(mesh.points.col(m), mesh.sources.col(s), k, true));
  const Eigen::Matrix3Xd receivers = (Eigen::Matrix3Xd(3, 3) << 0.2, -0.2, 0.0, 0.29, 0.29, 7.5, 0.1, 0.1, 1.2).finished();
  const Eigen::MatrixXcd pressure = model.pressure_matrix(omega, receivers);
  for (auto _ : state) {
    const Eigen::BDCSVD<Eigen::MatrixXcd> svd(v, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd inverse = svd.singularValues().cwiseInverse();
    benchmark::DoNotOptimize(Eigen::MatrixXcd(pressure * svd.matrixV() * inverse.asDiagonal() * svd.matrixU().adjoint()));
  }
}
BENCHMARK(BM_AnchorSolveSvdReference)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
