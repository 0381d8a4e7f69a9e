// The line laser reader (line_laser_csv.hpp) on the shipped CAPTIF transverse profiles
// (data/surfaces/captif-transverse) and on the corpus in tests/corpus/line_laser: what it reads,
// counted here by plain splitting of the text; the MPD of the nine lines against the second
// implementation of second_mpd.hpp; format detection; the file road; bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "road/file_road.hpp"
#include "road/line_laser_csv.hpp"
#include "road/mean_profile_depth.hpp"
#include "road/profile_analysis.hpp"
#include "road/profile_file.hpp"
#include "road/profile_format.hpp"
#include "second_mpd.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

const fs::path shipped{ROLLNOISE_SOURCE_DIR "/data/surfaces/captif-transverse/20231114_cpx_demo.csv"};
const fs::path corpus_dir{ROLLNOISE_LINE_LASER_CORPUS_DIR};

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The file's lines split at commas, with std::stod: the plain reading the reader must agree with.
std::vector<std::vector<double>> plain_lines(const fs::path& path) {
  std::vector<std::vector<double>> lines;
  std::istringstream text(read_bytes(path));
  std::string line;
  while (std::getline(text, line)) {
    if (line.empty()) continue;
    std::vector<double> values;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) values.push_back(std::stod(cell));
    lines.push_back(values);
  }
  return lines;
}

TEST(LineLaserCsv, ShippedFileHoldsNineProfilesOf656Points) {
  ASSERT_TRUE(fs::exists(shipped)) << shipped;
  const LineLaserProfiles p = read_line_laser_csv(shipped);
  const auto plain = plain_lines(shipped);
  ASSERT_EQ(plain.size(), 18u);
  ASSERT_EQ(p.z_lines.size(), 9u);
  ASSERT_EQ(p.x_m.size(), 656u);
  EXPECT_EQ(p.source, shipped.string());
  EXPECT_EQ(p.dropouts, 0u);
  for (std::size_t j = 0; j < 9; ++j) {
    ASSERT_EQ(plain[2 * j].size(), 657u);
    EXPECT_EQ(p.time_stamps[j], plain[2 * j][0]);
    ASSERT_EQ(p.z_lines[j].size(), 656u);
    for (std::size_t i = 0; i < 656; ++i) {
      EXPECT_EQ(p.x_m[i], plain[2 * j][i + 1] * 1e-3);  // every pair has the same positions
      ASSERT_EQ(p.z_lines[j][i], plain[2 * j + 1][i + 1] * 1e-3) << "line " << j << " point " << i;
    }
  }
  // 0.305 mm steps from -100.04 mm to +99.735 mm; heights (the laser's level) near -93 mm.
  EXPECT_NEAR(p.x_m.front(), -100.04e-3, 1e-12);
  EXPECT_NEAR(p.x_m.back(), 99.735e-3, 1e-12);
  for (const auto& z : p.z_lines) {
    const auto [lo, hi] = std::minmax_element(z.begin(), z.end());
    EXPECT_GT(*lo, -97e-3);
    EXPECT_LT(*hi, -90e-3);
  }
}

TEST(LineLaserCsv, ShippedFileIsRecognisedByContentAndLoadedAsNineLines) {
  EXPECT_EQ(detect_profile_format(shipped), ProfileFormat::line_laser);
  EXPECT_EQ(to_string(ProfileFormat::line_laser), "line laser csv");
  const LoadedProfile p = load_profile_file(shipped);
  ASSERT_EQ(p.z_lines.size(), 9u);
  ASSERT_EQ(p.x.size(), 656u);
  EXPECT_NEAR(p.spacing_m, 0.305e-3, 1e-12);
  EXPECT_EQ(p.x.front(), 0.0);  // from the first position
  EXPECT_NEAR(p.x.back(), 199.775e-3, 1e-12);
  EXPECT_EQ(p.y, (std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7, 8}));  // the lines' index
  EXPECT_EQ(p.dropouts, 0u);
  // A fine asphalt measured at 0.305 mm has no step of 3 spacings' height: nothing is a spike,
  // and the heights are the file's.
  EXPECT_EQ(p.spikes, 0u);
  const LineLaserProfiles raw = read_line_laser_csv(shipped);
  for (std::size_t j = 0; j < 9; ++j) EXPECT_EQ(p.z_lines[j], raw.z_lines[j]) << j;
}

TEST(LineLaserCsv, MpdOfTheNineLinesAgreesWithASecondImplementation) {
  const LoadedProfile p = load_profile_file(shipped);
  double library = 0.0;
  double second = 0.0;
  std::size_t segments = 0;
  for (const auto& z : p.z_lines) {
    const MpdResult r = mean_profile_depth(z, p.spacing_m);
    segments += r.segments;
    library += r.mpd_m / 9.0;
    second += test::second_mpd(z, p.spacing_m) / 9.0;
  }
  const ProfileAnalysis analysis = analyse_profile(p.z_lines, p.spacing_m);
  ASSERT_TRUE(analysis.mpd.has_value());
  std::printf("  MPD of the nine lines: %.4f mm (second implementation %.4f mm), %zu segments, RMS %.3f mm\n",
              analysis.mpd->mpd_m * 1e3, second * 1e3, segments, analysis.rms_m * 1e3);
  for (const TextureBand& b : analysis.texture)
    std::printf("  L_tx %6.2f mm  %5.1f dB\n", b.nominal_wavelength_m * 1e3, b.level_db);
  EXPECT_EQ(segments, 18u);  // two 100 mm segments in each 200 mm line
  EXPECT_NEAR(analysis.mpd->mpd_m, library, 1e-15);  // the analysis is the mean of the lines'
  // The data's description: a fine dense asphalt of MPD about 0.5 mm (ISO 10844 asks 0.5 ± 0.2).
  EXPECT_GT(analysis.mpd->mpd_m, 0.4e-3);
  EXPECT_LT(analysis.mpd->mpd_m, 0.6e-3);
  // The two implementations differ only at a line's two ends (the low-pass filter's start:
  // odd reflection and steady state vs constant extension), which moves the filtered heights of
  // the first and last ~2 mm by up to about a tenth of the texture's amplitude. With 200 mm
  // lines every segment touches an end, so a segment whose peak lies there shifts its MSD by up
  // to ~0.05 mm: over 18 segments, the MPD by at most ~0.01 mm.
  EXPECT_NEAR(analysis.mpd->mpd_m, second, 0.01e-3);
}

TEST(LineLaserCsv, CorpusSeedsParseAndBadInputsAreInputErrorsNamingTheFile) {
  std::size_t ok = 0, bad = 0;
  for (const auto& entry : fs::directory_iterator(corpus_dir)) {
    const std::string name = entry.path().filename().string();
    SCOPED_TRACE(name);
    const std::string text = read_bytes(entry.path());
    if (name.rfind("ok_", 0) == 0) {
      ++ok;
      const LineLaserProfiles p = parse_line_laser_csv(text, name);
      EXPECT_GE(p.z_lines.size(), 1u);
      EXPECT_TRUE(looks_like_line_laser_csv(text));
      EXPECT_EQ(detect_profile_format(entry.path()), ProfileFormat::line_laser);
      const LoadedProfile loaded = load_profile_file(entry.path());
      EXPECT_EQ(loaded.z_lines.size(), p.z_lines.size());
      for (const auto& z : loaded.z_lines)
        for (double v : z) ASSERT_TRUE(std::isfinite(v));
    } else if (name.rfind("bad_", 0) == 0) {
      ++bad;
      try {
        (void)parse_line_laser_csv(text, name);
        ADD_FAILURE() << "parsed";
      } catch (const InputError& e) {
        EXPECT_EQ(e.source(), name);
        EXPECT_FALSE(e.problem().empty());
      }
      try {
        (void)load_profile_file(entry.path());
        ADD_FAILURE() << "loaded";
      } catch (const InputError& e) {
        EXPECT_EQ(e.source(), entry.path().string());
      }
    }
  }
  EXPECT_GE(ok, 5u);
  EXPECT_GE(bad, 15u);
}

// What each bad input of the brief is told: the line (and field) and what is allowed.
TEST(LineLaserCsv, BadInputMessagesSayWhatIsWrongAndWhere) {
  struct Case {
    const char* file;
    const char* key;      // part of the key
    const char* problem;  // part of the problem
  };
  const std::vector<Case> cases{
      {"bad_truncated_pair.csv", "line 3", "without its line of heights"},
      {"bad_mismatched_lengths.csv", "line 2", "has 21 heights but line 1 has 24 positions"},
      {"bad_too_many_heights.csv", "line 2", "has more heights but line 1 has 24 positions"},
      {"bad_not_a_number.csv", "line 2, field 8", "\"1.2.3\" is not a finite number (a height in mm"},
      {"bad_positions_not_increasing.csv", "line 1, field 10", "positions must increase"},
      {"bad_all_dropouts.csv", "line 2", "every height is a dropout"},
      {"bad_stamp_mismatch.csv", "line 2, field 1 (time stamp)", "differs from the time stamp"},
      {"bad_positions_differ.csv", "line 3, field 2", "every profile must be sampled at the same positions"},
      {"bad_empty_position.csv", "line 1, field 5", "(a position in mm)"},
      {"bad_infinite_height.csv", "line 2, field 3", "not a finite number"},
      {"bad_one_position.csv", "line 1", "a profile needs at least 2"},
      {"bad_empty.csv", "", "holds no profile"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    try {
      (void)parse_line_laser_csv(read_bytes(corpus_dir / c.file), c.file);
      ADD_FAILURE() << "parsed";
    } catch (const InputError& e) {
      EXPECT_NE(e.key().find(c.key), std::string::npos) << e.what();
      EXPECT_NE(e.problem().find(c.problem), std::string::npos) << e.what();
      std::printf("  %s\n", e.what());
    }
  }
}

TEST(LineLaserCsv, DetectionTellsItFromTheOtherFormats) {
  EXPECT_FALSE(looks_like_line_laser_csv("x,z\n0,1\n0.001,2\n"));                // a profile CSV
  EXPECT_FALSE(looks_like_line_laser_csv("# y = 0, 1\nx,z_1,z_2\n0,1,2\n"));     // with lines
  EXPECT_FALSE(looks_like_line_laser_csv("0,1,2\n1,1,2\n"));                     // other first fields
  EXPECT_FALSE(looks_like_line_laser_csv("5,1\n5,2\n"));                         // two fields only
  EXPECT_FALSE(looks_like_line_laser_csv("5,1,2"));                              // no second line
  EXPECT_FALSE(looks_like_line_laser_csv(""));
  EXPECT_TRUE(looks_like_line_laser_csv("5,1,2\n5,0.1,0.2\n"));
  EXPECT_TRUE(looks_like_line_laser_csv("\xEF\xBB\xBF" "5,1,2\r\n\r\n5,,0.2\r\n"));
  const fs::path laser{ROLLNOISE_SOURCE_DIR "/data/surfaces/captif/20211011_aylesbury_dec_station_0.dat"};
  EXPECT_EQ(detect_profile_format(laser), ProfileFormat::laser);
}

TEST(LineLaserCsv, AsAFileRoadOneProfileIsRolledAndSeveralAreRefused) {
  // Nine lines: a 1-D road takes one, and says how to see them all.
  try {
    FileRoad road(shipped, 0.0, 0.1);
    ADD_FAILURE() << "accepted nine lines";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), shipped.string());
    EXPECT_NE(e.problem().find("holds 9 height lines"), std::string::npos) << e.what();
  }
  // One pair: the profile from x = 0 (its first position), heights in m.
  const fs::path one = corpus_dir / "ok_one_pair_blank_lines.csv";
  const LineLaserProfiles raw = read_line_laser_csv(one);
  const double end = raw.x_m.back() - raw.x_m.front();
  const FileRoad road(one, 0.0, end);
  EXPECT_EQ(road.x_first(), 0.0);
  EXPECT_NEAR(road.x_last(), end, 1e-12);
  for (std::size_t i = 0; i < raw.x_m.size(); ++i)
    EXPECT_NEAR(road.height(raw.x_m[i] - raw.x_m.front()), raw.z_lines[0][i], 1e-12) << i;
}

}  // namespace
}  // namespace rollnoise
