// The cache of fitted modes (src/greens/fitted_modes_cache.hpp): a round trip keeps every bit; a
// different key or mode count, and any damaged file, is a miss, never a crash or a wrong fit.
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "greens/fitted_modes_cache.hpp"
#include "greens/sdof_oscillator.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

VectorFittingOptions tyre_like_options() {
  VectorFittingOptions o;
  o.real_poles = 2;
  o.target_rms_error = 3e-3;
  return o;
}

std::vector<PoleResidueResponse> some_fits() {
  std::vector<PoleResidueResponse> fits;
  for (int i = 0; i < 5; ++i) {
    PoleResidueResponse f = oscillator_poles(SdofOscillator{1.0 + i, 30.0 * (i + 1), 1e6 * (i + 1)});
    f.poles.push_back({-1e4 * (i + 1), 0.0});
    f.residues.push_back({3.5e-3 * (i + 1), 0.0});
    f.direct = 1e-9 * i;
    fits.push_back(f);
  }
  return fits;
}

struct Folder {
  fs::path path = fs::temp_directory_path() / ("rollnoise_fits_" + std::to_string(::getpid()));
  Folder() { fs::remove_all(path); }
  ~Folder() { fs::remove_all(path); }
};

TEST(FittedModesCache, RoundTripIsBitExact) {
  const Folder folder;
  const auto fits = some_fits();
  const std::string key = fitted_modes_key("two_layer-0123456789abcdef", tyre_like_options());
  store_cached_fits(folder.path, key, fits);
  const auto back = load_cached_fits(folder.path, key, fits.size());
  ASSERT_TRUE(back.has_value());
  for (std::size_t i = 0; i < fits.size(); ++i) {
    EXPECT_EQ((*back)[i].poles, fits[i].poles);
    EXPECT_EQ((*back)[i].residues, fits[i].residues);
    EXPECT_EQ((*back)[i].direct, fits[i].direct);
  }
  EXPECT_FALSE(load_cached_fits(folder.path, key, fits.size() + 1).has_value());  // other modes
  EXPECT_FALSE(load_cached_fits(folder.path, key + "x", fits.size()).has_value());  // absent
}

TEST(FittedModesCache, KeyDependsOnTheTableAndTheOptions) {
  VectorFittingOptions a = tyre_like_options(), b = a;
  b.target_rms_error *= 2;
  EXPECT_EQ(fitted_modes_key("t1", a), fitted_modes_key("t1", a));
  EXPECT_NE(fitted_modes_key("t1", a), fitted_modes_key("t2", a));
  EXPECT_NE(fitted_modes_key("t1", a), fitted_modes_key("t1", b));
}

TEST(FittedModesCache, DamagedFilesAreMisses) {
  const Folder folder;
  const auto fits = some_fits();
  const std::string key = "k";
  store_cached_fits(folder.path, key, fits);
  const fs::path file = folder.path / "k.fits";
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::mt19937_64 rng(7);
  int misses = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::string damaged = bytes;
    switch (trial % 3) {
      case 0: damaged.resize(rng() % bytes.size()); break;                        // truncated
      case 1: damaged[rng() % bytes.size()] ^= static_cast<char>(1 + rng() % 255); break;  // one byte
      case 2: for (char& c : damaged) c = static_cast<char>(rng()); break;          // garbage
    }
    std::ofstream(file, std::ios::binary | std::ios::trunc).write(damaged.data(), static_cast<std::streamsize>(damaged.size()));
    misses += load_cached_fits(folder.path, key, fits.size()).has_value() ? 0 : 1;
  }
  EXPECT_EQ(misses, 300);  // every damage is caught by the digest or the checks
}

// A table's content key changes with any value; fit_with_cache fits once, then reads the same
// poles back.
TEST(FittedModesCache, TableContentKeyAndFitWithCache) {
  const Folder folder;
  ModalReceptanceTable table;
  table.radius = 0.3;
  table.width = 0.2;
  table.lateral_orders = 1;
  table.orders = 1;
  table.frequency = default_fit_frequencies(60, 1.0, 2e4);
  table.source = "test";
  for (int m = 0; m <= 1; ++m) {
    const PoleResidueResponse mode = oscillator_poles(SdofOscillator{1.0, 40.0 * (m + 1), 4e6 * (m + 1)});
    Eigen::VectorXcd h(table.frequency.size());
    for (Eigen::Index k = 0; k < h.size(); ++k) h(k) = mode.receptance(2 * M_PI * table.frequency(k));
    table.modes.push_back(h);
  }
  const std::string key = modal_table_content_key(table);
  EXPECT_EQ(key, modal_table_content_key(table));
  ModalReceptanceTable changed = table;
  changed.modes[1](7) *= 1.0 + 1e-12;
  EXPECT_NE(key, modal_table_content_key(changed));
  const std::string fit_key = fitted_modes_key(key, tyre_mode_fit_options());
  bool from_cache = true;
  const FittedModalTyre first = fit_with_cache(table, "tabulated", folder.path, fit_key, from_cache);
  EXPECT_FALSE(from_cache);
  const FittedModalTyre second = fit_with_cache(table, "tabulated", folder.path, fit_key, from_cache);
  EXPECT_TRUE(from_cache);
  for (int m = 0; m <= 1; ++m) EXPECT_EQ(first.fitted(m, 0).poles, second.fitted(m, 0).poles);
  EXPECT_EQ(second.fit_report().unconverged, 0u);
  EXPECT_LT(second.fit_report().worst_rms_error, 3e-3);
}

}  // namespace
}  // namespace rollnoise
