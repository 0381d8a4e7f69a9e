// TyreStepOutputs (src/simulation/tyre_step_outputs.hpp): what a tyre run takes from each step
// of the response stage. The steps that wait for the radiating body run as a two-thread
// pipeline (issue 12); it must give what responding step by step gives, bit for bit.
#include <cmath>
#include <filesystem>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "acoustics/band_power.hpp"
#include "contact/rolling_tyre.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/tread_compliance.hpp"
#include "road/road_surface.hpp"
#include "simulation/tyre_step_outputs.hpp"
#include "response_test_road_and_plate.hpp"

namespace rollnoise {
namespace {

using response_test::Texture;
using response_test::test_grid;
using response_test::test_plate;

struct Outputs {
  Eigen::MatrixXd tread_velocity;
  std::vector<double> psd, revolution;
  RadiatingPatch patch;
};

// sink: the radiating velocity handed on step by step (TyreStepOutputSettings::tread_sink, as a
// long run streams it) instead of kept; gathered here into the same matrix.
Outputs run(bool pipelined, const std::filesystem::path& h5, bool sink = false) {
  const KroppPlate plate(test_plate(64));
  const TyreGrid grid = test_grid(128, 8);
  const double speed = 20.0;
  const RollingModes rolling(plate, grid, grid.dx() / speed);
  const Eigen::MatrixXd local = winkler_compliance(grid.points(), grid.dx(), grid.dy(), 5e8);
  TyreRunSettings settings{speed, 200 * grid.dx() / speed, 3000.0, HistoryKind::modal};
  settings.keep_fields = false;
  const auto samples = static_cast<std::size_t>(std::llround(settings.duration / (grid.dx() / speed))) + 1;
  const auto cells = static_cast<std::size_t>(grid.circumferential) * static_cast<std::size_t>(grid.lateral);
  PointAveragedPsd psd(cells, speed / grid.dx(), 32, {std::vector<double>(cells, 1.0)});
  Outputs out;
  TyreStepOutputSettings step{ContactFields::contact, h5, samples, speed, 3000.0, {}, {}, &psd, {}, true, {}};
  // Some belt cells, weighted: a stand-in for the radiation mesh's sampling.
  step.tread_sampling = [&](const RadiatingPatch& patch) {
    out.patch = patch;
    Eigen::SparseMatrix<double> s(5, static_cast<Eigen::Index>(cells));
    for (int r = 0; r < 5; ++r) s.insert(r, 37 * r + 3) = 0.5 + r;
    s.makeCompressed();
    return s;
  };
  step.pipelined = pipelined;
  std::vector<std::vector<double>> rows;
  if (sink) step.tread_sink = [&](std::span<const double> v) { rows.emplace_back(v.begin(), v.end()); };
  TyreStepOutputs outputs(rolling, std::move(step));
  simulate_rolling_tyre(rolling, local, Texture(), settings, nullptr, nullptr, &outputs);
  outputs.finish();
  out.tread_velocity = outputs.tread_velocity();
  if (sink) {
    EXPECT_EQ(out.tread_velocity.size(), 0);  // nothing kept
    out.tread_velocity.resize(static_cast<Eigen::Index>(rows.size()), rows.empty() ? 0 : static_cast<Eigen::Index>(rows[0].size()));
    for (std::size_t n = 0; n < rows.size(); ++n)
      for (std::size_t m = 0; m < rows[n].size(); ++m)
        out.tread_velocity(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m)) = rows[n][m];
  }
  out.psd = psd.average(0).density;
  out.revolution = outputs.revolution();
  return out;
}

TEST(TyreStepOutputs, PipelinedWaitingStepsEqualStepByStep) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "rollnoise_test_step_outputs";
  std::filesystem::create_directories(dir);
  const Outputs pipelined = run(true, dir / "pipelined.h5");
  const Outputs reference = run(false, dir / "reference.h5");
  std::filesystem::remove_all(dir);
  ASSERT_GT(pipelined.tread_velocity.rows(), 100);
  EXPECT_GT(pipelined.tread_velocity.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_TRUE(pipelined.tread_velocity == reference.tread_velocity);
  EXPECT_EQ(pipelined.psd, reference.psd);
  ASSERT_FALSE(pipelined.revolution.empty());
  EXPECT_EQ(pipelined.revolution, reference.revolution);
  EXPECT_EQ(pipelined.patch.length, reference.patch.length);
}

// The rows handed to a tread_sink (issue 13: a long run streams them to the radiation) are the
// record a run keeps otherwise, bit for bit, in step order.
TEST(TyreStepOutputs, TreadSinkTakesTheRowsInOrder) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "rollnoise_test_step_outputs_sink";
  std::filesystem::create_directories(dir);
  const Outputs kept = run(true, dir / "kept.h5");
  const Outputs sunk = run(true, dir / "sunk.h5", true);
  std::filesystem::remove_all(dir);
  ASSERT_GT(kept.tread_velocity.rows(), 100);
  ASSERT_EQ(sunk.tread_velocity.rows(), kept.tread_velocity.rows());
  EXPECT_TRUE(sunk.tread_velocity == kept.tread_velocity);
  EXPECT_EQ(sunk.psd, kept.psd);
}

}  // namespace
}  // namespace rollnoise
