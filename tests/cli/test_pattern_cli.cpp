// End-to-end tests of the tread pattern (`[tyre.pattern]`): the real program in a fresh folder.
// The library's patterned tyre rolls and names its tones; a tread map rolls like the grooves it
// tabulates; every bad input is one message naming the file, the key and what is allowed, exit
// status 2, with nothing written. Runs of a few steps without radiation.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/cli_workspace.hpp"

namespace {
namespace fs = std::filesystem;
using namespace cli_test;

const fs::path source_dir{ROLLNOISE_SOURCE_DIR};
const std::string slick = (source_dir / "models" / "tyres" / "passenger_205_55R16.toml").string();
const std::string short_run =
    "[road]\ntype = \"flat\"\n[rolling]\nspeed = 22.222\nduration = 0.002\nstatic_load = 3200.0\n"
    "[radiation]\nenabled = false\n[output]\nplots = false\n";

// The slick's model file with `pattern` as its [pattern] table, and a case that rolls it.
void write_patterned(const Workspace& ws, const std::string& pattern, const std::string& rolling_extra = "") {
  ws.write("tyre.toml", read_text(slick) + "\n[pattern]\n" + pattern + "\n");
  ws.write("case.toml", "[tyre]\nfile = \"tyre.toml\"\n" + short_run + rolling_extra);
}

TEST(PatternCli, BadPatternsAreOneMessageNamingTheFileAndTheKey) {
  Workspace ws;
  struct Case {
    std::string pattern;
    std::vector<std::string> expected;  // in the message, besides the file
  };
  const std::vector<Case> cases = {
      // 64 pitches of 31 mm: a 40 mm groove is wider than a pitch.
      {"pitches = 64\ngroove_width = 0.04\ngroove_depth = 0.008", {"[tyre.pattern] groove_width", "narrower than a pitch"}},
      {"pitches = 64\ngroove_width = 0.005\ngroove_depth = -0.008", {"[tyre.pattern] groove_depth", ">= 0"}},
      {"pitch_sequence = [1.0, 1.2, 0.0, 0.8]\ngroove_width = 0.005\ngroove_depth = 0.008",
       {"[tyre.pattern] pitch_sequence", "item 3", "> 0"}},
      {"pitch_sequence = [1.0, -1.2]\ngroove_width = 0.005\ngroove_depth = 0.008", {"[tyre.pattern] pitch_sequence", "item 2"}},
      {"ribs = [{position = 0.068, width = 0.009, depth = 0.008}]", {"ribs[1]] position", "outside the tread", "0.07"}},
      {"ribs = [{position = 0.0, width = 0.009, depth = -0.001}]", {"ribs[1]] depth", ">= 0"}},
      {"pitches = 64\npitch_sequence = [1.0]\ngroove_width = 0.005\ngroove_depth = 0.008", {"pitch_sequence", "pitches"}},
      {"groove_width = 0.005", {"[tyre.pattern] groove_width", "pitches"}},
      {"pitches = 64\ngroove_width = 0.005\ngroove_depth = 0.008\ngroove_angle = 85", {"groove_angle", "80"}},
      {"pitches = 64\ngroove_width = 0.005\ngroove_depth = 0.008\nzz_typo = 1", {"zz_typo", "unknown key"}},
      {"file = \"map.csv\"", {"[tyre.pattern] file", "covers x from 0 m to 1 m", "2πR"}},
      {"file = \"map.csv\"\npitches = 8", {"[tyre.pattern] pitches", "file"}},
  };
  // A map 1 m around (not the tyre's 1.985 m) and across the tread.
  std::ostringstream map;
  map << "x,y,z\n";
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 2; ++j) map << 0.1 * i << ',' << -0.07 + 0.07 * j << ",0\n";
  ws.write("map.csv", map.str());
  for (const Case& c : cases) {
    write_patterned(ws, c.pattern);
    const RunResult r = ws.run({"simulate", "case.toml", "--out", "out"});
    EXPECT_EQ(r.status, 2) << c.pattern << "\n" << describe(r);
    EXPECT_TRUE(contains(r.err, "tyre.toml")) << r.err;
    for (const std::string& e : c.expected) EXPECT_TRUE(contains(r.err, e)) << "expected \"" << e << "\" in " << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_FALSE(fs::exists(ws.path("out"))) << c.pattern;
  }
  // The texture contact law cannot take a pattern.
  write_patterned(ws, "pitches = 64\ngroove_width = 0.005\ngroove_depth = 0.008", "");
  const RunResult r = ws.run({"simulate", "case.toml", "--out", "out", "--set", "rolling.contact_law=\"texture\""});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "[tyre.pattern]")) << r.err;
  EXPECT_TRUE(contains(r.err, "contact_law")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
}

// The library's patterned tyre: 64 pitches, its fundamental N·v/(2πR) and harmonics named with
// their bands; the map written.
TEST(PatternCli, TheReferenceTyreNamesItsTones) {
  Workspace ws;
  const std::string tyre = (source_dir / "models" / "tyres" / "passenger_205_55R16_patterned.toml").string();
  ws.write("case.toml", "[tyre]\nfile = \"" + tyre + "\"\n" + short_run);
  const RunResult r = ws.run({"simulate", "case.toml", "--out", "out"});
  ASSERT_EQ(r.status, 0) << describe(r);
  const nlohmann::json summary = nlohmann::json::parse(read_text(ws.path("out") / "summary.json"));
  const nlohmann::json& p = summary.at("tread_pattern");
  EXPECT_EQ(p.at("pitches").get<int>(), 64);
  EXPECT_EQ(p.at("tone_order").get<int>(), 64);
  const double f1 = 64 * 22.222 / (2.0 * std::numbers::pi * 0.316);
  EXPECT_NEAR(p.at("fundamental_hz").get<double>(), f1, 1e-9 * f1);
  ASSERT_EQ(p.at("tones").size(), 4u);
  EXPECT_NEAR(p.at("tones")[1].at("frequency_hz").get<double>(), 2 * f1, 1e-9 * f1);
  EXPECT_EQ(p.at("tones")[0].at("band_hz").get<double>(), 800.0);  // 716 Hz, above the band's lower edge 708 Hz
  EXPECT_TRUE(fs::exists(ws.path("out") / "tread_pattern.csv"));
  // The grooves take force off the slick's load.
  EXPECT_LT(summary.at("mean_total_force_N").get<double>(), 3200.0);
}

// A tread map of 64 equal lateral grooves rolls as the same grooves given by keys: the same
// pattern, read from a CSV, gives the same forces to the interpolation's accuracy.
TEST(PatternCli, AMapRollsLikeTheGroovesItTabulates) {
  Workspace ws;
  const double length = 2.0 * std::numbers::pi * 0.316;
  const int around = 64 * 40;  // 40 lines a pitch
  std::ofstream map(ws.path("map.csv"));
  map << "x,y,z\n";
  map.precision(17);
  for (int i = 0; i < around; ++i) {
    // A groove 5 mm wide (about 6.45 lines) centred at each pitch start, as the keys' grooves.
    const double s = i * length / around;
    const double pitch = length / 64.0;
    const double d = std::fmod(s, pitch);
    const double z = std::min(d, pitch - d) < 0.0025 ? -0.008 : 0.0;
    for (int j = 0; j <= 2; ++j) map << s << ',' << -0.07 + 0.07 * j << ',' << z << '\n';
  }
  map.close();
  write_patterned(ws, "file = \"map.csv\"");
  RunResult r = ws.run({"simulate", "case.toml", "--out", "map"});
  ASSERT_EQ(r.status, 0) << describe(r);
  write_patterned(ws, "pitches = 64\ngroove_width = 0.005\ngroove_depth = 0.008");
  r = ws.run({"simulate", "case.toml", "--out", "keys"});
  ASSERT_EQ(r.status, 0) << describe(r);
  const nlohmann::json a = nlohmann::json::parse(read_text(ws.path("map") / "summary.json"));
  const nlohmann::json b = nlohmann::json::parse(read_text(ws.path("keys") / "summary.json"));
  EXPECT_EQ(a.at("tread_pattern").at("tone_order").get<int>(), 64);
  EXPECT_NEAR(a.at("mean_total_force_N").get<double>(), b.at("mean_total_force_N").get<double>(),
              0.02 * b.at("mean_total_force_N").get<double>());
}

}  // namespace
