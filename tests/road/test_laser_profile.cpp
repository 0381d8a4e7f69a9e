// The stationary laser profilometer reader on the two real CAPTIF profiles in
// data/surfaces/captif and on the corpus in tests/corpus/laser; the MPD and texture spectrum of
// the real profiles, the MPD checked against a second implementation written here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "road/laser_profile.hpp"
#include "road/mean_profile_depth.hpp"
#include "road/texture_spectrum.hpp"
#include "second_mpd.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

const fs::path captif_dir{ROLLNOISE_SOURCE_DIR "/data/surfaces/captif"};
const fs::path corpus_dir{ROLLNOISE_LASER_CORPUS_DIR};
const char* const stations[] = {"20211011_aylesbury_dec_station_0.dat", "20211011_aylesbury_dec_station_1.dat"};

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The data rows of a file as (distance mm, depth text), by plain splitting: for counting.
std::vector<std::pair<double, std::string>> plain_rows(const std::string& text) {
  std::vector<std::pair<double, std::string>> rows;
  std::size_t pos = text.find("Depth (mm)");
  pos = text.find('\n', pos) + 1;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const auto t1 = line.find('\t');
    const auto t2 = line.find('\t', t1 + 1);
    rows.emplace_back(std::stod(line.substr(t1 + 1, t2 - t1 - 1)), line.substr(t2 + 1));
  }
  return rows;
}

TEST(LaserProfile, RealProfilesAreReadTrimmedAndCleaned) {
  for (const char* name : stations) {
    SCOPED_TRACE(name);
    const fs::path path = captif_dir / name;
    ASSERT_TRUE(fs::exists(path)) << path;
    const MeasuredProfile p = read_laser_profile(path);
    EXPECT_EQ(p.source, path.string());
    // The instrument steps 0.0375 mm; the file rounds distances to 1 µm, and its mean step
    // over ~1.9 m comes out at 0.03749 mm.
    EXPECT_NEAR(p.spacing_m, 0.0375e-6 * 1e3, 0.0375e-6 * 1e3 * 1e-3);
    const double length = static_cast<double>(p.z_m.size()) * p.spacing_m;
    // The plates' inner edges found here by a plain rule (CAPTIF's): in the first half, the row
    // after the last one above +30 mm (dropouts counting as the row before them); in the second
    // half, the first row above. The road kept starts 2 mm after the first and ends 2 mm
    // before the second, give or take the rounding to whole rows (2 steps, 0.075 mm).
    const auto rows = plain_rows(read_bytes(path));
    double start_edge = 0, end_edge = 0;
    bool plate = false;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (rows[i].second != "NaN") plate = std::stod(rows[i].second) > 30;
      if (i < rows.size() / 2 && plate) start_edge = rows[i + 1].first * 1e-3;
      if (i >= rows.size() / 2 && plate && end_edge == 0) end_edge = rows[i].first * 1e-3;
    }
    EXPECT_NEAR(p.x0_m, start_edge + 2e-3, 0.1e-3);
    EXPECT_NEAR(p.x0_m + length, end_edge - 2e-3, 0.1e-3);
    // About 1808 mm for both; CAPTIF's own software finds 62.32 … 1870.351 mm for station 0.
    EXPECT_NEAR(length, 1.808, 0.002);
    EXPECT_EQ(p.trimmed_points + p.z_m.size(), plain_rows(read_bytes(path)).size());
    for (double v : p.z_m) ASSERT_TRUE(std::isfinite(v));
    // Road only: no plate left (they stand ~47 mm above it); texture within ±10 mm.
    const auto [lo, hi] = std::minmax_element(p.z_m.begin(), p.z_m.end());
    EXPECT_LT(*hi - *lo, 20e-3);
    // Dropouts, counted independently: NaN depths among the kept rows.
    std::size_t nan_rows = 0;
    for (const auto& [x_mm, depth] : plain_rows(read_bytes(path))) {
      if (x_mm * 1e-3 >= p.x0_m - 1e-9 && x_mm * 1e-3 < p.x0_m + length - 0.5 * p.spacing_m) nan_rows += depth == "NaN";
    }
    EXPECT_EQ(p.dropouts, nan_rows);
    EXPECT_GT(p.dropouts, p.z_m.size() / 50);  // the laser misses a few percent of the road
    EXPECT_LT(p.dropouts, p.z_m.size() / 5);
    // Spikes judged at 0.5 mm with alpha = 6, as CAPTIF processes its own SLP profiles
    // (profile_cleaning.hpp): 120 and 588 samples, 0.25 and 1.2 %. The chips' steep faces are
    // texture and survive (with alpha = 3 they were flagged: 4.1 and 6.4 %), so a few per mille
    // to about a percent, not several percent. The standard's 5 % limit is per 100 mm segment on
    // the resampled profile and not applied here.
    EXPECT_GT(p.spikes, p.z_m.size() / 1000);
    EXPECT_LT(p.spikes, p.z_m.size() / 50);
    std::printf("  %s: %zu points at %.7g mm (%.2f mm from %.3f mm), %zu dropouts, %zu spikes, %zu trimmed\n", name,
                p.z_m.size(), p.spacing_m * 1e3, length * 1e3, p.x0_m * 1e3, p.dropouts, p.spikes, p.trimmed_points);
  }
}

TEST(LaserProfile, RealProfilesMpdAgreesWithASecondImplementation) {
  for (const char* name : stations) {
    SCOPED_TRACE(name);
    const MeasuredProfile p = read_laser_profile(captif_dir / name);
    const MpdResult r = mean_profile_depth(p.z_m, p.spacing_m);
    const double second = test::second_mpd(p.z_m, p.spacing_m);
    std::printf("  %s: MPD %.4f mm (second implementation %.4f mm), ETD %.4f mm, %zu segments\n", name,
                r.mpd_m * 1e3, second * 1e3, r.etd_m * 1e3, r.segments);
    EXPECT_EQ(r.segments, 18u);  // 1808 mm
    // A coarse chip seal: about 3 mm (the data's description).
    EXPECT_GT(r.mpd_m, 2.5e-3);
    EXPECT_LT(r.mpd_m, 3.6e-3);
    // The two differ only in how the filter treats the profile's two ends (odd reflection and
    // steady start vs constant extension): that moves the filtered heights in the first and
    // last ~2 mm by at most ~0.1 mm, which can shift the first or last segment's MSD by that
    // (if its peak lies there) and the MPD by 1/18 of it: 0.01 mm.
    EXPECT_NEAR(r.mpd_m, second, 0.01e-3);
  }
}

TEST(LaserProfile, RealProfilesTextureSpectrumPeaksAtChipSizeWavelengths) {
  // A 1.8 m profile resolves bands up to 125 mm (edge 141 mm <= 1808/12). One band of one
  // profile scatters: m = 0.2316 L/λ DFT bins give a relative standard deviation of
  // sqrt(1.94/m) (see test_texture_spectrum.cpp), ±1.8 dB at 40 mm (m = 10.5). So the checks:
  //  - each profile: 5 mm and 125 mm at least 4 dB below its highest band, which lies between
  //    12.5 and 63 mm; the 31.5 and 40 mm bands together (m = 21: ±1.3 dB) within 2 dB of it;
  //  - the two profiles' mean (energy average, the surface's estimate) peaks at 25 to 40 mm.
  std::vector<TextureBand> mean;
  for (const char* name : stations) {
    SCOPED_TRACE(name);
    const MeasuredProfile p = read_laser_profile(captif_dir / name);
    const auto bands = texture_spectrum(p.z_m, p.spacing_m);
    ASSERT_FALSE(bands.empty());
    EXPECT_NEAR(bands.front().nominal_wavelength_m, 0.5e-3, 1e-12);
    EXPECT_NEAR(bands.back().nominal_wavelength_m, 125e-3, 1e-12);
    auto level = [&](double nominal) {
      for (const auto& b : bands)
        if (std::abs(b.nominal_wavelength_m - nominal) < 1e-3 * nominal) return b.level_db;
      ADD_FAILURE() << "no band " << nominal;
      return 0.0;
    };
    const auto peak = *std::max_element(bands.begin(), bands.end(),
                                        [](const TextureBand& a, const TextureBand& b) { return a.level_db < b.level_db; });
    EXPECT_GE(peak.nominal_wavelength_m, 12.5e-3 * 0.99);
    EXPECT_LE(peak.nominal_wavelength_m, 63e-3 * 1.01);
    const double chip = 10 * std::log10(std::pow(10, level(31.5e-3) / 10) + std::pow(10, level(40e-3) / 10)) - 10 * std::log10(2.0);
    EXPECT_GT(chip, peak.level_db - 2.0);
    EXPECT_LT(level(5e-3), peak.level_db - 4.0);
    EXPECT_LT(level(125e-3), peak.level_db - 4.0);
    std::printf("  %s: L_tx (dB re 1 um)", name);
    for (double w : {5e-3, 10e-3, 20e-3, 31.5e-3, 40e-3, 80e-3, 100e-3}) std::printf("  %g mm %.2f", w * 1e3, level(w));
    std::printf("  (highest %g mm %.2f)\n", peak.nominal_wavelength_m * 1e3, peak.level_db);
    if (mean.empty()) {
      mean = bands;
      for (auto& b : mean) b.level_db = std::pow(10, b.level_db / 10) / 2;
    } else {
      ASSERT_EQ(mean.size(), bands.size());
      for (std::size_t i = 0; i < bands.size(); ++i) mean[i].level_db += std::pow(10, bands[i].level_db / 10) / 2;
    }
  }
  const auto peak = *std::max_element(mean.begin(), mean.end(),
                                      [](const TextureBand& a, const TextureBand& b) { return a.level_db < b.level_db; });
  std::printf("  mean of both: highest band %g mm, %.2f dB\n", peak.nominal_wavelength_m * 1e3, 10 * std::log10(peak.level_db));
  EXPECT_GE(peak.nominal_wavelength_m, 25e-3 * 0.99);
  EXPECT_LE(peak.nominal_wavelength_m, 40e-3 * 1.01);
}

TEST(LaserProfile, CorpusFilesBehaveAsNamed) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(corpus_dir)) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 10u) << corpus_dir;
  for (const auto& path : files) {
    const std::string name = path.filename().string();
    SCOPED_TRACE(name);
    if (name.rfind("ok_", 0) == 0) {
      const MeasuredProfile p = read_laser_profile(path);
      EXPECT_GE(p.z_m.size(), 2u);
      EXPECT_NEAR(p.spacing_m, 0.5e-3, 1e-12);
      for (double v : p.z_m) EXPECT_TRUE(std::isfinite(v));
      EXPECT_TRUE(looks_like_laser_profile(read_bytes(path)));
    } else {
      try {
        read_laser_profile(path);
        ADD_FAILURE() << "no error";
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        EXPECT_EQ(e.source(), path.string());
      }
    }
  }
}

TEST(LaserProfile, CorpusDetailsAreRead) {
  // 4 dropouts, a 10 mm plate with 2 mm of dropouts on it, 110 mm of road, a 10 mm plate,
  // 3 mm of dropouts: the road kept is 2 mm inside each plate, 106 mm (212 rows) from 12 mm.
  const MeasuredProfile both = read_laser_profile(corpus_dir / "ok_plates_both_ends_crlf.dat");
  EXPECT_EQ(both.z_m.size(), 212u);
  EXPECT_EQ(both.trimmed_points, 270u - 212u);
  EXPECT_NEAR(both.x0_m, 14e-3, 1e-12);
  EXPECT_EQ(both.dropouts, 13u);  // every 17th road row from the 6th: all 13 lie in the kept rows
  EXPECT_EQ(both.spikes, 0u);
  const MeasuredProfile none = read_laser_profile(corpus_dir / "ok_no_plates_lf.dat");
  EXPECT_EQ(none.z_m.size(), 240u);
  EXPECT_EQ(none.trimmed_points, 0u);
  EXPECT_NEAR(none.z_m[1], 1e-3 * 0.4 * std::sin(0.9) + 1e-3 * 1.5 * std::sin(2 * std::numbers::pi * 0.5 / 12.5), 1e-6);
  const MeasuredProfile start = read_laser_profile(corpus_dir / "ok_start_plate_only.dat");
  EXPECT_EQ(start.trimmed_points, 24u);  // 20 plate rows and the 2 mm buffer
  const MeasuredProfile empty_depth = read_laser_profile(corpus_dir / "ok_empty_depth_is_dropout.dat");
  EXPECT_EQ(empty_depth.dropouts, 1u);
  EXPECT_DOUBLE_EQ(empty_depth.z_m[0], 1e-3);  // the start takes the nearest valid value
}

TEST(LaserProfile, ContentDetection) {
  EXPECT_TRUE(looks_like_laser_profile(read_bytes(captif_dir / stations[0])));
  EXPECT_TRUE(looks_like_laser_profile(read_bytes(captif_dir / stations[1])));
  EXPECT_FALSE(looks_like_laser_profile("x,z\n0,0\n1,1\n"));
  EXPECT_FALSE(looks_like_laser_profile(""));
  EXPECT_FALSE(looks_like_laser_profile("*****DATA*****\nsomething else\n"));
  EXPECT_FALSE(looks_like_laser_profile(std::string(70000, 'a') + "\n*****DATA*****\nNo\tDistance (mm)\tDepth (mm)\n"));
}

TEST(LaserProfile, MissingFileAndBadTextAreInputErrorsNamingTheSource) {
  EXPECT_THROW(read_laser_profile(corpus_dir / "no_such_file.dat"), InputError);
  try {
    parse_laser_profile("*****DATA*****\nDistance (mm)\tDepth (mm)\n0\tNaN\n0.5\tNaN\n", "mine");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "mine");
    EXPECT_EQ(e.key(), "profile");  // all dropouts
  }
}

}  // namespace
}  // namespace rollnoise
