// The cost of one equivalent-source solve on the tyre mesh (the radiation stage does one per
// anchor frequency, ~30 per run): the regularised QR that the stage uses, against the SVD
// pseudo-inverse it replaced (the reference: same answer, to 1e-10, on this well-conditioned
// system); and on the simulations' mesh (graded, 16 across, ~2950 points, ~1475 sources) the
// mirror-split solve (EquivalentSources::Symmetry::automatic, two half-size QRs: ~1/4 of the
// work) against the full one.
#include <complex>
#include <numbers>

#include <Eigen/SVD>
#include <benchmark/benchmark.h>

#include "radiation/equivalent_sources.hpp"
#include "radiation/tyre_surface_mesh.hpp"

namespace {

using namespace rollnoise;
using Complex = std::complex<double>;

struct TyreProblem {
  explicit TyreProblem(const TyreSurfaceMeshSpec& spec = {},
                       EquivalentSources::Symmetry symmetry = EquivalentSources::Symmetry::automatic)
      : mesh(make_tyre_surface_mesh(spec)), model(mesh.sources, mesh.points, mesh.normals, true, Medium{}, symmetry) {}
  TyreSurfaceMesh mesh;
  EquivalentSources model;
  Eigen::Matrix3Xd receivers = (Eigen::Matrix3Xd(3, 3) << 0.2, -0.2, 0.0, 0.29, 0.29, 7.5, 0.1, 0.1, 1.2).finished();
  double omega = 2 * std::numbers::pi * 1000.0;
};

// The mesh of the simulations (tools/rollnoise/tyre_sound.cpp): 2 mm cells at the contact
// growing to 2.1 cm, 16 rows across, 12 rings per sidewall.
TyreSurfaceMeshSpec simulation_spec() {
  TyreSurfaceMeshSpec s;
  s.around = 96;
  s.contact_refinement = 10.0;
  s.across = 16;
  s.sidewall_rings = 12;
  return s;
}

void solve_tyre(benchmark::State& state, const TyreProblem& p) {
  for (auto _ : state) benchmark::DoNotOptimize(p.model.transfer(p.omega, p.receivers));
  state.counters["points"] = static_cast<double>(p.mesh.points.cols());
  state.counters["sources"] = static_cast<double>(p.mesh.sources.cols());
  state.counters["split"] = p.model.mirror_symmetric() ? 1.0 : 0.0;
}

// The default mesh (8 across, 1924 points, 962 sources).
void BM_AnchorSolveQr(benchmark::State& state) { solve_tyre(state, TyreProblem{}); }
BENCHMARK(BM_AnchorSolveQr)->Unit(benchmark::kMillisecond)->Iterations(3);
void BM_AnchorSolveQrFull(benchmark::State& state) {
  solve_tyre(state, TyreProblem({}, EquivalentSources::Symmetry::none));
}
BENCHMARK(BM_AnchorSolveQrFull)->Unit(benchmark::kMillisecond)->Iterations(2);

// The simulations' mesh, split and full; the split's relative difference to the full transfer
// (max |ΔT| / max |T|) as a counter.
void BM_SimulationMeshSolveSplit(benchmark::State& state) {
  const TyreProblem p(simulation_spec());
  solve_tyre(state, p);
  const TyreProblem full(simulation_spec(), EquivalentSources::Symmetry::none);
  const Eigen::MatrixXcd t = p.model.transfer(p.omega, p.receivers), reference = full.model.transfer(p.omega, p.receivers);
  state.counters["difference"] = (t - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}
BENCHMARK(BM_SimulationMeshSolveSplit)->Unit(benchmark::kMillisecond)->Iterations(3);
void BM_SimulationMeshSolveFull(benchmark::State& state) {
  solve_tyre(state, TyreProblem(simulation_spec(), EquivalentSources::Symmetry::none));
}
BENCHMARK(BM_SimulationMeshSolveFull)->Unit(benchmark::kMillisecond)->Iterations(2);

// The reference: P·V⁺ with V⁺ from the thin SVD (what EquivalentSources did before).
void BM_AnchorSolveSvdReference(benchmark::State& state) {
  const TyreProblem p{};
  const double k = p.omega / Medium{}.sound_speed;
  Eigen::MatrixXcd v(p.mesh.points.cols(), p.mesh.sources.cols());
  for (Eigen::Index s = 0; s < v.cols(); ++s)
    for (Eigen::Index m = 0; m < v.rows(); ++m)
      v(m, s) = -p.mesh.normals.col(m).cast<Complex>().dot(
          helmholtz_green_gradient(p.mesh.points.col(m), p.mesh.sources.col(s), k, true));
  const Eigen::MatrixXcd pressure = p.model.pressure_matrix(p.omega, p.receivers);
  for (auto _ : state) {
    const Eigen::BDCSVD<Eigen::MatrixXcd> svd(v, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd inverse = svd.singularValues().cwiseInverse();
    benchmark::DoNotOptimize(Eigen::MatrixXcd(pressure * svd.matrixV() * inverse.asDiagonal() * svd.matrixU().adjoint()));
  }
}
BENCHMARK(BM_AnchorSolveSvdReference)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
