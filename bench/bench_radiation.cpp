// The cost of one equivalent-source solve on the tyre mesh (the radiation stage does one per
// anchor frequency, ~30 per run): the regularised QR that the stage uses, against the SVD
// pseudo-inverse it replaced (the reference: same answer, to 1e-10, on this well-conditioned
// system).
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
  TyreSurfaceMesh mesh = make_tyre_surface_mesh({});
  EquivalentSources model{mesh.sources, mesh.points, mesh.normals, true};
  Eigen::Matrix3Xd receivers = (Eigen::Matrix3Xd(3, 3) << 0.2, -0.2, 0.0, 0.29, 0.29, 7.5, 0.1, 0.1, 1.2).finished();
  double omega = 2 * std::numbers::pi * 1000.0;
};

void BM_AnchorSolveQr(benchmark::State& state) {
  const TyreProblem p;
  for (auto _ : state) benchmark::DoNotOptimize(p.model.transfer(p.omega, p.receivers));
  state.counters["points"] = static_cast<double>(p.mesh.points.cols());
  state.counters["sources"] = static_cast<double>(p.mesh.sources.cols());
}
BENCHMARK(BM_AnchorSolveQr)->Unit(benchmark::kMillisecond)->Iterations(3);

// The reference: P·V⁺ with V⁺ from the thin SVD (what EquivalentSources did before).
void BM_AnchorSolveSvdReference(benchmark::State& state) {
  const TyreProblem p;
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
