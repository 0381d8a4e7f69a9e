// The radiation cache (issue 12, radiation/radiation_cache.hpp): the anchors' operators are
// what the stage solved before, the power operator gives the power matrix's power, a run from
// the cache equals a run without it bit for bit, damaged, truncated and foreign entries are
// recomputed with a warning, and writers of one entry at once leave a valid entry.
#include <algorithm>
#include <atomic>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "core/cache_folder.hpp"
#include "radiation/equivalent_sources.hpp"
#include "radiation/radiation_cache.hpp"
#include "radiation/tyre_radiation.hpp"
#include "radiation/tyre_surface_mesh.hpp"

namespace rollnoise {
namespace {
namespace fs = std::filesystem;
using Complex = std::complex<double>;

// A fresh folder, removed at the end.
class Folder {
 public:
  Folder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("rollnoise_radiation_cache_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~Folder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  Folder(const Folder&) = delete;
  Folder& operator=(const Folder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Captures what the code under test writes to stderr (the cache's warnings).
class StderrCapture {
 public:
  StderrCapture() { ::testing::internal::CaptureStderr(); }
  std::string text() { return ::testing::internal::GetCapturedStderr(); }
};

std::vector<fs::path> entries(const fs::path& folder) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(folder))
    if (e.path().extension() == ".h5") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// Two mesh levels (the base to 2.07 kHz, the tread split in 2 above), 9 anchors, deformed.
TyreRadiationSettings small_settings() {
  TyreRadiationSettings settings;
  settings.mesh.around = 48;
  settings.mesh.across = 4;
  settings.mesh.sidewall_rings = 4;
  settings.mesh.geometry = TyreGeometry::deformed;
  settings.max_frequency_hz = 2400.0;
  settings.anchor_spacing_hz = 400.0;
  settings.threads = 2;
  return settings;
}

Eigen::Matrix3Xd receivers() {
  Eigen::Matrix3Xd r(3, 2);
  r << 0.2, -0.2,  //
      0.29, 0.29,  //
      0.1, 0.1;
  return r;
}

Eigen::MatrixXd velocity(const TyreRadiation& radiation, Eigen::Index samples) {
  const Eigen::Index points = radiation.input_mesh().tread_points;
  Eigen::MatrixXd v(samples, points);
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (Eigen::Index n = 0; n < samples; ++n)
    for (Eigen::Index m = 0; m < points; ++m) v(n, m) = 1e-3 * normal(random);
  return v;
}

void expect_identical(const RadiatedSound& a, const RadiatedSound& b) {
  ASSERT_EQ(a.pressure.rows(), b.pressure.rows());
  EXPECT_TRUE(a.pressure == b.pressure) << "max difference " << (a.pressure - b.pressure).cwiseAbs().maxCoeff();
  EXPECT_TRUE(a.sound_power_w == b.sound_power_w)
      << "max difference " << (a.sound_power_w - b.sound_power_w).cwiseAbs().maxCoeff();
}

constexpr double kRate = 6000.0;

TEST(PivotedCholesky, ReconstructsALowRankHermitianMatrix) {
  std::mt19937 random(3);
  std::normal_distribution<double> normal;
  Eigen::MatrixXcd b(40, 6);
  for (Eigen::Index j = 0; j < b.cols(); ++j)
    for (Eigen::Index i = 0; i < b.rows(); ++i) b(i, j) = Complex(normal(random), normal(random));
  const Eigen::MatrixXcd s = b * b.adjoint();
  const Eigen::MatrixXcd l = pivoted_cholesky(s, 1e-14);
  EXPECT_EQ(l.cols(), 6) << "the rank";
  EXPECT_LE((l * l.adjoint() - s).norm(), 1e-12 * s.norm());
  EXPECT_EQ(pivoted_cholesky(Eigen::MatrixXcd::Zero(5, 5), 1e-14).cols(), 0);
  EXPECT_THROW(pivoted_cholesky(Eigen::MatrixXcd::Zero(5, 4), 1e-14), std::invalid_argument);
}

// The power factor gives the power matrix's power, ½‖Fq‖² = ½qᴴSq, split by symmetry or not,
// for monopoles and combined sources, with few rows at low frequency.
TEST(PowerFactor, GivesThePowerMatrixPower) {
  TyreSurfaceMeshSpec spec;
  spec.around = 32;
  spec.across = 4;
  spec.sidewall_rings = 3;
  spec.geometry = TyreGeometry::deformed;
  const TyreSurfaceMesh mesh = make_tyre_surface_mesh(spec);
  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  Eigen::MatrixXcd q(mesh.sources.cols(), 3);
  for (Eigen::Index j = 0; j < q.cols(); ++j)
    for (Eigen::Index i = 0; i < q.rows(); ++i) q(i, j) = Complex(normal(random), normal(random));
  for (const bool combined : {false, true}) {
    for (const auto symmetry : {EquivalentSources::Symmetry::automatic, EquivalentSources::Symmetry::none}) {
      std::optional<CombinedSources> layer;
      if (combined) layer = CombinedSources{mesh.source_normals, 1.0, 50.0};
      const EquivalentSources model(mesh.sources, mesh.points, mesh.normals, true, {}, symmetry, layer);
      for (const double f : {100.0, 1500.0}) {
        const double omega = 2 * std::numbers::pi * f;
        const Eigen::MatrixXcd factor = model.power_factor(omega);
        const Eigen::VectorXd expected = model.radiated_power(omega, q);
        for (Eigen::Index j = 0; j < q.cols(); ++j)
          EXPECT_NEAR(0.5 * (factor * q.col(j)).squaredNorm(), expected(j), 1e-10 * expected(j))
              << "combined " << combined << ", f " << f;
        if (f == 100.0) {
          EXPECT_LT(factor.rows(), mesh.sources.cols() / 2) << "few patterns radiate at 100 Hz";
        }
      }
    }
  }
}

// The stage through its operators gives the power the equivalent sources give for the same
// velocities (the operators are the solve, applied in another order).
TEST(RadiationCache, OperatorsGiveTheSolvesTransferAndPower) {
  const TyreRadiation radiation(small_settings(), receivers());
  const std::size_t level = 0;
  const double f = 800.0, omega = 2 * std::numbers::pi * f;
  const Eigen::Index columns = radiation.level_mesh(level).tread_points;
  const AnchorOperators ops = radiation.solve_anchor(level, f, columns);
  const EquivalentSources model = make_tyre_model(radiation.level_mesh(level));
  const EquivalentSourceSolve solve = model.solve(omega, 1e-10);
  Eigen::VectorXcd v = Eigen::VectorXcd::Zero(radiation.level_mesh(level).points.cols());
  for (Eigen::Index m = 0; m < columns; ++m) {
    const auto x = static_cast<double>(m);
    v(m) = Complex(std::sin(0.3 * x), std::cos(0.7 * x));
  }
  const Eigen::VectorXd expected = model.radiated_power(omega, solve.strengths(v));
  const std::vector<Eigen::MatrixXcd> x = model.point_coordinates(v.head(columns));
  ASSERT_EQ(x.size(), ops.power.size());
  EXPECT_EQ(ops.power.size(), 4u) << "the deformed mesh splits by both mirrors";
  double power = 0.0;
  Eigen::Index stored = 0;
  for (std::size_t c = 0; c < x.size(); ++c) {
    power += 0.5 * (ops.power[c] * x[c]).squaredNorm();
    stored += ops.power[c].size();
  }
  // Quantised (quantised_power_operator.hpp): within its rounding of the solve's power.
  EXPECT_NEAR(power, expected(0), 1e-4 * expected(0));
  RecordProperty("power_relative_error", std::to_string(std::abs(power / expected(0) - 1.0)));
  // The blocks hold less than a quarter of the operator on the points (rank × columns).
  EXPECT_LT(static_cast<double>(stored), 0.3 * static_cast<double>(ops.power_rank() * columns));
  const Eigen::VectorXcd p = model.transfer(omega, receivers()) * v;
  EXPECT_LE((ops.transfer * v.head(columns) - p).norm(), 1e-12 * p.norm());
}

// A run that stores, a run that loads: the same numbers as a run without the cache, bit for bit;
// one entry per anchor; the keys tell anchors, receivers and meshes apart.
TEST(RadiationCache, HitEqualsMissEqualsNoCacheBitForBit) {
  const Folder folder;
  const RadiationCache cache(folder.path());
  const TyreRadiation radiation(small_settings(), receivers());
  ASSERT_EQ(radiation.levels(), 2u) << "the test covers a coarser level carried to the input mesh";
  const Eigen::MatrixXd v = velocity(radiation, 300);
  const RadiatedSound none = radiation.radiate(v, kRate);
  const RadiatedSound cold = radiation.radiate(v, kRate, nullptr, &cache);
  const std::size_t anchors = radiation.anchors(kRate).size();
  EXPECT_EQ(entries(folder.path()).size(), anchors);
  const RadiatedSound warm = radiation.radiate(v, kRate, nullptr, &cache);
  expect_identical(none, cold);
  expect_identical(none, warm);
  EXPECT_EQ(std::count(cold.anchor_from_cache.begin(), cold.anchor_from_cache.end(), true), 0);
  EXPECT_EQ(std::count(warm.anchor_from_cache.begin(), warm.anchor_from_cache.end(), true), static_cast<long>(anchors));
  // A new object of the same settings finds them too (nothing held in memory).
  const RadiatedSound again = TyreRadiation(small_settings(), receivers()).radiate(v, kRate, nullptr, &cache);
  expect_identical(none, again);

  // Keys: different for another anchor, level, receiver set or deformation; the same for the
  // same inputs.
  const std::string key = radiation.anchor_key(0, 400.0, 100);
  EXPECT_EQ(key, TyreRadiation(small_settings(), receivers()).anchor_key(0, 400.0, 100));
  EXPECT_NE(key, radiation.anchor_key(0, 800.0, 100));
  EXPECT_NE(key, radiation.anchor_key(1, 400.0, 100));
  EXPECT_NE(key, radiation.anchor_key(0, 400.0, 99));
  Eigen::Matrix3Xd moved = receivers();
  moved(0, 0) += 1e-9;
  EXPECT_NE(key, TyreRadiation(small_settings(), moved).anchor_key(0, 400.0, 100));
  TyreRadiationSettings longer = small_settings();
  longer.mesh.deformation.patch_length += 1e-6;
  EXPECT_NE(key, TyreRadiation(longer, receivers()).anchor_key(0, 400.0, 100));
  TyreRadiationSettings regularised = small_settings();
  regularised.regularisation = 1e-9;
  EXPECT_NE(key, TyreRadiation(regularised, receivers()).anchor_key(0, 400.0, 100));
  // A higher sample rate changes only what depends on it: the anchors below the old top keep
  // their keys (so runs at other speeds share them).
  EXPECT_TRUE(is_cache_key(key));
  EXPECT_EQ(key.rfind(kRadiationCachePrefix, 0), 0u);
}

// Damaged entries: truncated, bytes flipped in the payload, a foreign file under an entry's
// name, garbage. Each is warned about once and solved again, and the results stay identical;
// the entry is then whole again.
TEST(RadiationCache, DamagedTruncatedOrForeignEntriesAreRecomputedWithAWarning) {
  const Folder folder;
  const RadiationCache cache(folder.path());
  const TyreRadiation radiation(small_settings(), receivers());
  const Eigen::MatrixXd v = velocity(radiation, 300);
  const RadiatedSound reference = radiation.radiate(v, kRate);
  (void)radiation.radiate(v, kRate, nullptr, &cache);
  const std::vector<fs::path> files = entries(folder.path());
  ASSERT_GE(files.size(), 5u);

  // 0: truncated to half; 1: a byte flipped in the last quarter (the compressed power blocks,
  // past HDF5's metadata at the start); 2: another entry's file under this name (a foreign key);
  // 3: not HDF5 at all.
  fs::resize_file(files[0], fs::file_size(files[0]) / 2);
  {
    std::fstream f(files[1], std::ios::in | std::ios::out | std::ios::binary);
    const auto size = static_cast<std::streamoff>(fs::file_size(files[1]));
    f.seekg(size - size / 4);
    char c = 0;
    f.get(c);
    f.seekp(size - size / 4);
    f.put(static_cast<char>(c ^ 0x5a));
  }
  fs::copy_file(files[4], files[2], fs::copy_options::overwrite_existing);
  {
    std::ofstream f(files[3], std::ios::binary | std::ios::trunc);
    f << "not a cache entry";
  }
  // 5: a whole entry under its own key, checksums right, whose content is not what the key asks
  // for (a transfer to one receiver instead of two, as a build with other receivers would
  // leave): its dimensions tell.
  ASSERT_GE(files.size(), 6u);
  {
    AnchorOperators wrong = radiation.solve_anchor(0, 400.0, radiation.level_mesh(0).tread_points);
    wrong.transfer = Eigen::MatrixXcd(wrong.transfer.topRows(1));
    cache.store(files[5].stem().string(), wrong, {400.0, 1, 1, 1, 1, "monopoles"});
  }
  StderrCapture err;
  const RadiatedSound repaired = radiation.radiate(v, kRate, nullptr, &cache);
  const std::string warnings = err.text();
  expect_identical(reference, repaired);
  for (const std::size_t i : {0u, 1u, 2u, 3u, 5u}) {
    const std::string name = files[i].string();
    std::size_t count = 0;
    std::istringstream lines(warnings);
    for (std::string line; std::getline(lines, line);) count += line.find(name) != std::string::npos ? 1 : 0;
    EXPECT_EQ(count, 1u) << "one warning for " << name << ":\n" << warnings;
  }
  EXPECT_NE(warnings.find("rollnoise: warning: the radiation cache entry"), std::string::npos) << warnings;
  EXPECT_EQ(std::count(repaired.anchor_from_cache.begin(), repaired.anchor_from_cache.end(), false), 5);
  // Stored again whole: the next run loads everything without a word.
  StderrCapture quiet;
  const RadiatedSound after = radiation.radiate(v, kRate, nullptr, &cache);
  EXPECT_EQ(quiet.text(), "");
  EXPECT_EQ(std::count(after.anchor_from_cache.begin(), after.anchor_from_cache.end(), true),
            static_cast<long>(files.size()));
  expect_identical(reference, after);
}

// Writers of one entry at once (threads with their own cache objects, as a study's cases; the
// temporary names differ per writer, not only per process), and a reader meanwhile: every store
// leaves a valid entry, the reader never sees a half-written one, and no temporary file is
// left behind.
TEST(RadiationCache, ConcurrentWritersOfOneEntryLeaveAValidEntry) {
  const Folder folder;
  const TyreRadiation radiation(small_settings(), receivers());
  const Eigen::Index columns = radiation.level_mesh(0).tread_points;
  const AnchorOperators ops = radiation.solve_anchor(0, 400.0, columns);
  const std::string key = radiation.anchor_key(0, 400.0, columns);
  const std::vector<Eigen::Index> counts = make_tyre_model(radiation.level_mesh(0)).point_coordinate_counts(columns);
  std::vector<std::thread> writers;
  std::atomic<int> valid_reads{0};
  for (int w = 0; w < 4; ++w) {
    writers.emplace_back([&] {
      const RadiationCache cache(folder.path());
      for (int i = 0; i < 10; ++i) cache.store(key, ops, {400.0, 1, 1, 1, 1, "monopoles"});
    });
  }
  // A reader meanwhile sees no entry or a whole one, never a damaged one.
  StderrCapture err;
  const RadiationCache reader(folder.path());
  for (int i = 0; i < 10; ++i)
    if (const auto entry = reader.load(key, 2, columns, counts)) valid_reads += entry->transfer == ops.transfer ? 1 : 0;
  for (std::thread& t : writers) t.join();
  EXPECT_EQ(err.text(), "") << "no reader saw a half-written entry";
  const std::optional<AnchorOperators> entry = RadiationCache(folder.path()).load(key, 2, columns, counts);
  ASSERT_TRUE(entry.has_value());
  EXPECT_TRUE(entry->transfer == ops.transfer);
  EXPECT_TRUE(entry->power == ops.power);
  for (const auto& e : fs::directory_iterator(folder.path()))
    EXPECT_FALSE(is_temporary_cache_file(e.path().filename().string())) << e.path();
  RecordProperty("valid_reads_during_writes", valid_reads.load());
}

// A cache that cannot store (its folder is a file) warns once and the results are unchanged.
TEST(RadiationCache, UnwritableFolderWarnsOnceAndChangesNothing) {
  const Folder folder;
  const fs::path file = folder.path() / "a_file";
  {
    std::ofstream f(file);
    f << "x";
  }
  const RadiationCache cache(file / "cache");
  const TyreRadiation radiation(small_settings(), receivers());
  const Eigen::MatrixXd v = velocity(radiation, 300);
  const RadiatedSound reference = radiation.radiate(v, kRate);
  StderrCapture err;
  const RadiatedSound run = radiation.radiate(v, kRate, nullptr, &cache);
  const std::string text = err.text();
  expect_identical(reference, run);
  EXPECT_EQ(text.find("rollnoise: warning: cannot store in the radiation cache"), 0u) << text;
  EXPECT_EQ(text.find("rollnoise: warning", 1), std::string::npos) << "one warning: " << text;
  EXPECT_NE(cache_folder_problem(file / "cache"), "");
  EXPECT_EQ(cache_folder_problem(folder.path() / "new" / "cache"), "");
}

}  // namespace
}  // namespace rollnoise
