// End-to-end tests of the air pumping (`[radiation] air_pumping`): the real program in a fresh
// folder, short runs on a coarse radiation mesh. A slick with the key off, or left to its default,
// writes what it wrote before the air pumping existed, bit for bit; a patterned tyre pumps by
// default, and its summary, budget and levels say so; a bad value is one message naming the file,
// the key and what is allowed, exit status 2, with nothing written.
#include <filesystem>
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
const std::string patterned = (source_dir / "models" / "tyres" / "passenger_205_55R16_patterned.toml").string();

// A short run on a flat road with a coarse radiation mesh (these tests check what is written and
// whether the air pumping is in it, not the levels' accuracy).
std::string short_case(const std::string& tyre, const std::string& radiation_extra = "") {
  return "[tyre]\nfile = \"" + tyre + "\"\n[road]\ntype = \"flat\"\n"
         "[rolling]\nspeed = 22.222\nduration = 0.01\nstatic_load = 3200.0\npoints_lateral = 10\ncontact_window = 0.2\n"
         "[radiation]\nreceivers = [\"cpx_front\", \"cpx_rear\"]\nmesh_around = 32\nmesh_across = 2\nsidewall_rings = 4\n"
         "anchor_spacing = 500\ncontact_refinement = 3\nmax_frequency = 2000\n" +
         radiation_extra + "[output]\nplots = false\nfields = \"none\"\n";
}

TEST(AirPumpingCli, ASlickWithTheKeyOffOrLeftOutWritesWhatItWroteBefore) {
  Workspace ws;
  ws.write("default.toml", short_case(slick));
  ws.write("off.toml", short_case(slick, "air_pumping = false\n"));
  const RunResult a = ws.run({"simulate", "default.toml", "--out", "default"});
  ASSERT_EQ(a.status, 0) << describe(a);
  const RunResult b = ws.run({"simulate", "off.toml", "--out", "off"});
  ASSERT_EQ(b.status, 0) << describe(b);
  for (const char* file : {"spectrum.csv", "sound_power.csv", "budget.csv", "contact.csv"})
    EXPECT_TRUE(read_text(ws.path("default") / file) == read_text(ws.path("off") / file)) << file;
  // The WAV's samples (its PEAK chunk holds the time it was written).
  const auto samples = [&](const char* run) {
    const std::string wav = read_text(ws.path(run) / "cpx_front.wav");
    return wav.substr(wav.find("data"));
  };
  EXPECT_TRUE(samples("default") == samples("off"));
  const nlohmann::json summary = read_json(ws.path("default") / "summary.json");
  EXPECT_FALSE(summary.contains("air_pumping"));
  EXPECT_FALSE(summary["stage_times_s"].contains("air_pumping"));
  EXPECT_EQ(summary["levels"], read_json(ws.path("off") / "summary.json")["levels"]);
  // The budget's columns are those of before: no air pumping line.
  EXPECT_FALSE(contains(first_line(ws.path("default") / "budget.csv"), "air_pumping"));
}

// Off by default (docs/physics/air-pumping.md, "The default"), for a patterned tyre too.
TEST(AirPumpingCli, APatternedTyrePumpsWhenTheKeyTurnsItOnAndNotByDefault) {
  Workspace ws;
  ws.write("on.toml", short_case(patterned, "air_pumping = true\n"));
  ws.write("off.toml", short_case(patterned));
  const RunResult a = ws.run({"simulate", "on.toml", "--out", "on"});
  ASSERT_EQ(a.status, 0) << describe(a);
  const RunResult b = ws.run({"simulate", "off.toml", "--out", "off"});
  ASSERT_EQ(b.status, 0) << describe(b);
  const nlohmann::json on = read_json(ws.path("on") / "summary.json");
  const nlohmann::json off = read_json(ws.path("off") / "summary.json");
  ASSERT_TRUE(on.contains("air_pumping")) << on.dump(1);
  EXPECT_FALSE(off.contains("air_pumping"));
  const nlohmann::json& air = on["air_pumping"];
  EXPECT_GT(air["total_W"].get<double>(), 0.0);
  EXPECT_EQ(air["source_positions_m"].size(), 2u);
  // The monopoles sit at the steady patch's edges, the front ahead of the axle.
  EXPECT_GT(air["front_edge_x_m"].get<double>(), 0.0);
  EXPECT_LT(air["rear_edge_x_m"].get<double>(), 0.0);
  EXPECT_GT(air["mean_enclosed_volume_m3"].get<double>(), 0.0);
  EXPECT_GE(air["time_s"].get<double>(), 0.0);
  // The contact is the same with and without (the air pumping only watches it); the sound is not.
  EXPECT_EQ(read_text(ws.path("on") / "contact.csv"), read_text(ws.path("off") / "contact.csv"));
  EXPECT_NE(on["levels"]["cpx_front"]["Leq_dB"], off["levels"]["cpx_front"]["Leq_dB"]);
  // Powers add: the sound power with the air pumping is the vibration's plus the air's.
  const double with_air = on["sound_power"]["total_W"].get<double>(), without = off["sound_power"]["total_W"].get<double>();
  EXPECT_NEAR(with_air, without + air["total_W"].get<double>(), 1e-9 * with_air);
  EXPECT_TRUE(contains(first_line(ws.path("on") / "budget.csv"), ",Lw_air_pumping_dB_re_1pW"));
  EXPECT_EQ(first_line(ws.path("on") / "air_pumping.csv"), "time,front_flow,rear_flow,closed_flow,thin_flow,closed_volume,enclosed_volume");
  EXPECT_EQ(count_lines(read_text(ws.path("on") / "air_pumping.csv")), count_lines(read_text(ws.path("on") / "contact.csv")));
  EXPECT_FALSE(fs::exists(ws.path("off") / "air_pumping.csv"));
  EXPECT_FALSE(contains(first_line(ws.path("off") / "budget.csv"), "air_pumping"));
}

TEST(AirPumpingCli, ABadValueIsOneMessageNamingTheFileAndTheKey) {
  Workspace ws;
  for (const std::string value : {"\"yes\"", "1"}) {
    ws.write("case.toml", short_case(slick, "air_pumping = " + value + "\n"));
    const RunResult r = ws.run({"simulate", "case.toml", "--out", "out"});
    EXPECT_EQ(r.status, 2) << describe(r);
    EXPECT_TRUE(contains(r.err, "case.toml")) << r.err;
    EXPECT_TRUE(contains(r.err, "[radiation] air_pumping")) << r.err;
    EXPECT_TRUE(contains(r.err, "true or false")) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_FALSE(fs::exists(ws.path("out")));
  }
}

}  // namespace
