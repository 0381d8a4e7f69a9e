// The texture road (type = "texture", texture_road.hpp): its 1-D profiles and 2-D maps against
// the third-octave texture spectrum they are made from (ISO 13473-4 band levels by
// texture_spectrum), isotropy and the tining options, determinism, and the rejection of bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "core/config_table.hpp"
#include "road/sampled_road.hpp"
#include "road/texture_road.hpp"
#include "road/texture_band_psd.hpp"
#include "road/texture_spectrum.hpp"
#include "road_generator_helpers.hpp"

namespace rollnoise {
namespace {

using test::BandAverage;

struct Target {
  std::vector<double> wavelengths;  // nominal, m
  std::vector<double> levels;       // dB re 1 µm
};

std::string list(const std::vector<double>& values) {
  std::ostringstream out;
  out.precision(17);
  out << "[";
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << values[i];
  out << "]";
  return out.str();
}

// Nominal band centres from `first` to `last` (m), both included.
std::vector<double> bands(double first, double last) { return texture_band_nominal_wavelengths(first, last); }

// A texture-like spectrum over the whole ISO 13473-4 band set, 0.5 mm .. 500 mm: rising 1.5 dB
// per band to a peak at 31.5 mm, then falling 2 dB per band (not realisable by an isotropic
// surface; fine for a profile).
Target profile_target() {
  Target t;
  t.wavelengths = bands(0.5e-3, 0.5);
  double level = 30.0;
  for (double w : t.wavelengths) {
    t.levels.push_back(level);
    level += (w < 31e-3) ? 1.5 : -2.0;
  }
  return t;
}

// For the 2-D map: 2.5 mm .. 50 mm, rising 1 dB per band to 31.5 mm, then falling 0.5 dB per
// band: the line density does not increase with wavenumber, so the isotropic map is realisable.
Target surface_target() {
  Target t;
  t.wavelengths = bands(2.5e-3, 50e-3);
  double level = 40.0;
  for (double w : t.wavelengths) {
    t.levels.push_back(level);
    level += (w < 31e-3) ? 1.0 : -0.5;
  }
  return t;
}

std::string road_table(const Target& t, const std::string& extra) {
  return "type = \"texture\"\nwavelengths = " + list(t.wavelengths) + "\nlevels = " + list(t.levels) + "\n" + extra;
}

// Largest |mean level - target| over the target's bands; prints the table.
double worst_band_error(const BandAverage& average, const Target& t, const char* what) {
  double worst = 0.0;
  for (std::size_t b = 0; b < t.wavelengths.size(); ++b) {
    EXPECT_TRUE(average.has(t.wavelengths[b])) << what << ": band " << t.wavelengths[b] << " not analysed";
    if (!average.has(t.wavelengths[b])) continue;
    const double error = average.level(t.wavelengths[b]) - t.levels[b];
    std::printf("  %-22s %7.2f mm  target %5.1f dB  mean of 8 seeds %5.1f dB  error %+5.2f dB\n", what,
                t.wavelengths[b] * 1e3, t.levels[b], average.level(t.wavelengths[b]), error);
    worst = std::max(worst, std::abs(error));
  }
  std::printf("  %-22s max |error| %.2f dB\n", what, worst);
  return worst;
}

const SampledSurface& as_map(const RoadSurface& s) { return dynamic_cast<const SampledSurface&>(s); }

// The whole map of a [road] table (make_texture_surface): the factory's surface is the same road
// made in tiles (TextureRoad.RollingSurfaceIsTheMapInTiles).
std::unique_ptr<SampledSurface> map_from(const std::string& table, double x_max = 0.0, double half_width = 0.0) {
  toml::table t = toml::parse("[road]\n" + table);
  const ConfigTable road(*t["road"].as_table(), "case.toml", "road");
  TextureRoadSpec spec;
  read_texture_keys(road, spec, true, 20.0);
  spec.x_max = x_max;
  spec.half_width = half_width;
  return make_texture_surface(spec);
}
const SampledProfile& as_line(const RoadProfile& p) { return dynamic_cast<const SampledProfile&>(p); }

TEST(TextureRoad, ProfileReproducesTheBandLevels) {
  const Target t = profile_target();
  BandAverage average;
  for (int seed = 1; seed <= 8; ++seed) {
    const auto road = test::profile_from(road_table(t, "length = 40.0\nlead_in = 0.0\nseed = " + std::to_string(seed)));
    const SampledProfile& p = as_line(*road);
    EXPECT_EQ(p.type(), "texture");
    average.add(p.samples(), p.spacing());
  }
  EXPECT_LE(worst_band_error(average, t, "profile"), 1.0);
}

TEST(TextureRoad, IsotropicMapHasTheBandLevelsAlongAndAcross) {
  const Target t = surface_target();
  BandAverage along;
  BandAverage across;
  // A road of 10 m, as long as a tyre run: the surface is one oblique wave per spectral line
  // along x (texture_waves.hpp), so a line across gets its band levels from the road's waves,
  // a sample that is the finer the longer the road (a 1.2 m road missed the 8 mm band across
  // by 1.1 dB over 8 seeds). 1.2 m across: the 50 mm band holds 5.5 lines of a line across.
  for (int seed = 1; seed <= 8; ++seed) {
    const auto road = map_from(
        road_table(t, "length = 10.0\nwidth = 1.2\nsample_spacing = 0.001\nlead_in = 0.0\nseed = " +
                          std::to_string(seed)),
        0.5, 0.2);
    const SampledSurface& s = as_map(*road);
    for (std::size_t j = 0; j < s.y_count(); j += 40) along.add(s.column(j), s.spacing());
    for (std::size_t i = 0; i < s.x_count(); i += 250) across.add(s.row(i), s.spacing());
  }
  EXPECT_LE(worst_band_error(along, t, "isotropic, along x"), 1.0);
  EXPECT_LE(worst_band_error(across, t, "isotropic, across (y)"), 1.0);
}

TEST(TextureRoad, TransverseTiningVariesAlongTheRoadOnly) {
  const Target t = surface_target();
  BandAverage along;
  for (int seed = 1; seed <= 8; ++seed) {
    const auto road = map_from(
        road_table(t, "anisotropy = \"transverse\"\nlength = 10.0\nwidth = 0.05\nlead_in = 0.0\nseed = " +
                          std::to_string(seed)));
    const SampledSurface& s = as_map(*road);
    along.add(s.column(0), s.spacing());
    if (seed == 1) {
      // r(x, y) = p(x): every longitudinal line is the same, every transverse line constant.
      for (std::size_t j = 1; j < s.y_count(); ++j) ASSERT_EQ(s.column(j), s.column(0));
    }
  }
  EXPECT_LE(worst_band_error(along, t, "transverse, along x"), 1.0);
}

TEST(TextureRoad, LongitudinalTiningVariesAcrossTheRoadOnly) {
  const Target t = surface_target();
  BandAverage across;
  for (int seed = 1; seed <= 8; ++seed) {
    const auto road = map_from(
        road_table(t, "anisotropy = \"longitudinal\"\nlength = 0.1\nwidth = 10.0\nlead_in = 0.05\nseed = " +
                          std::to_string(seed)));
    const SampledSurface& s = as_map(*road);
    const std::size_t last = s.x_count() - 1;
    across.add(s.row(last), s.spacing());
    if (seed == 1) {
      // r(x, y) = p(y) beyond the lead-in: every transverse line is the same.
      const auto first_full = static_cast<std::size_t>(std::ceil(0.05 / s.spacing()));
      for (std::size_t i = first_full; i < s.x_count(); ++i) ASSERT_EQ(s.row(i), s.row(last));
      for (std::size_t j = 0; j < s.y_count(); ++j) EXPECT_EQ(s.sample(0, j), 0.0);
    }
  }
  EXPECT_LE(worst_band_error(across, t, "longitudinal, across"), 1.0);
}

TEST(TextureRoad, SameSeedIdenticalOtherSeedDiffers) {
  const Target t = surface_target();
  const auto a = test::profile_from(road_table(t, "length = 2.0\nseed = 5"));
  const auto b = test::profile_from(road_table(t, "length = 2.0\nseed = 5"));
  const auto c = test::profile_from(road_table(t, "length = 2.0\nseed = 6"));
  EXPECT_EQ(as_line(*a).samples(), as_line(*b).samples());
  EXPECT_NE(as_line(*a).samples(), as_line(*c).samples());
  const auto sa = map_from(road_table(t, "length = 0.3\nwidth = 0.2\nseed = 5"));
  const auto sb = map_from(road_table(t, "length = 0.3\nwidth = 0.2\nseed = 5"));
  const auto sc = map_from(road_table(t, "length = 0.3\nwidth = 0.2\nseed = 6"));
  double max_diff = 0.0;
  for (std::size_t i = 0; i < as_map(*sa).x_count(); ++i) {
    EXPECT_EQ(as_map(*sa).row(i), as_map(*sb).row(i));
    for (std::size_t j = 0; j < as_map(*sa).y_count(); ++j) {
      max_diff = std::max(max_diff, std::abs(as_map(*sa).sample(i, j) - as_map(*sc).sample(i, j)));
    }
  }
  EXPECT_GT(max_diff, 1e-6);
}

TEST(TextureRoad, FlatLeadInAndFixedStretch) {
  const Target t = surface_target();
  const auto short_run = test::profile_from(road_table(t, "length = 3.0\nseed = 2"), 1.0);
  const auto long_run = test::profile_from(road_table(t, "length = 3.0\nseed = 2"), 2.5);
  EXPECT_EQ(short_run->height(-0.1), 0.0);
  EXPECT_EQ(short_run->height(0.0), 0.0);
  for (double x : {0.01, 0.3, 1.7, 2.9}) EXPECT_EQ(short_run->height(x), long_run->height(x));
}

TEST(TextureRoad, NominalAndExactCentresGiveTheSameRoad) {
  const auto nominal = test::profile_from(
      "type = \"texture\"\nwavelengths = [0.008, 0.0315]\nlevels = [45.0, 50.0]\nlength = 1.0\n");
  const auto exact = test::profile_from(
      "type = \"texture\"\nwavelengths = [0.0079433, 0.031623]\nlevels = [45.0, 50.0]\nlength = 1.0\n");
  EXPECT_EQ(as_line(*nominal).samples(), as_line(*exact).samples());
}

TEST(TextureRoad, BadInputNamesTheKey) {
  const std::string w = "type = \"texture\"\nwavelengths = [0.004, 0.005, 0.0063]\n";
  std::string m = test::profile_error(w + "levels = [40.0, nan, 42.0]\n");
  EXPECT_MENTIONS(m, "[road] levels");
  EXPECT_MENTIONS(m, "item 2");
  m = test::profile_error(w + "levels = [40.0, 41.0]\n");
  EXPECT_MENTIONS(m, "[road] levels");
  EXPECT_MENTIONS(m, "one level");
  m = test::profile_error("type = \"texture\"\nwavelengths = [0.0004, 0.0005]\nlevels = [30.0, 31.0]\n");
  EXPECT_MENTIONS(m, "[road] wavelengths");
  EXPECT_MENTIONS(m, "0.5 mm to 500 mm");
  m = test::profile_error("type = \"texture\"\nwavelengths = [0.4, 0.63]\nlevels = [30.0, 31.0]\n");
  EXPECT_MENTIONS(m, "[road] wavelengths");
  EXPECT_MENTIONS(m, "0.5 mm to 500 mm");
  m = test::profile_error("type = \"texture\"\nwavelengths = [0.005, 0.004]\nlevels = [30.0, 31.0]\n");
  EXPECT_MENTIONS(m, "[road] wavelengths");
  EXPECT_MENTIONS(m, "increasing");
  m = test::profile_error("type = \"texture\"\nwavelengths = [0.004, 0.004]\nlevels = [30.0, 31.0]\n");
  EXPECT_MENTIONS(m, "[road] wavelengths");
  EXPECT_MENTIONS(m, "increasing");
  m = test::profile_error("type = \"texture\"\nwavelengths = [0.0045]\nlevels = [30.0]\n");
  EXPECT_MENTIONS(m, "[road] wavelengths");
  EXPECT_MENTIONS(m, "not a third-octave band centre");
  // The 4 mm band's lower edge is 3.56 mm: the spacing may be at most 1.78 mm.
  m = test::profile_error(w + "levels = [40.0, 41.0, 42.0]\nsample_spacing = 0.002\n");
  EXPECT_MENTIONS(m, "[road] sample_spacing");
  EXPECT_MENTIONS(m, "shortest band");
  EXPECT_EQ(test::profile_error(w + "levels = [40.0, 41.0, 42.0]\nsample_spacing = 0.0017\nlength = 1.0\n"), "");
  m = test::profile_error(w + "levels = \"loud\"\n");
  EXPECT_MENTIONS(m, "[road] levels");
  m = test::profile_error(w);
  EXPECT_MENTIONS(m, "[road] levels");
  m = test::profile_error(w + "levels = [40.0, 41.0, 42.0]\nanisotropy = \"transverse\"\n");
  EXPECT_MENTIONS(m, "anisotropy");  // a profile has no anisotropy: an unknown key
  m = test::surface_error(w + "levels = [40.0, 41.0, 42.0]\nanisotropy = \"diagonal\"\nlength = 0.2\n");
  EXPECT_MENTIONS(m, "[road] anisotropy");
  m = test::surface_error(w + "levels = [40.0, inf, 42.0]\nlength = 0.2\n");
  EXPECT_MENTIONS(m, "[road] levels");
}

TEST(TextureBandPsd, IsotropicDensityIntegratesBackToTheLineDensity) {
  // The Abel relation of texture_band_psd.hpp checked by quadrature: ∫ S(sqrt(n^2 + ny^2)) dny
  // = G(n)/2 inside the bands, for a realisable target.
  const Target t = surface_target();
  std::vector<double> centres;
  for (double w : t.wavelengths) centres.push_back(texture_band_centre_wavelength(w));
  const TextureBandPsd psd(centres, t.levels);
  for (double w : {3e-3, 7e-3, 14e-3, 30e-3, 45e-3}) {
    const double n = 1.0 / w;
    const double dq = 0.01;  // cycles/m
    double sum = 0.0;
    for (double ny = 0.5 * dq; ny < 600.0; ny += dq) {
      const double q = std::sqrt(n * n + ny * ny);
      sum += 2.0 * psd.isotropic_density(std::max(0.0, q - 0.5 * dq), q + 0.5 * dq) * dq;
    }
    EXPECT_NEAR(sum / (psd.line_density(n) / 2.0), 1.0, 0.02) << "wavelength " << w;
  }
}

}  // namespace
}  // namespace rollnoise
