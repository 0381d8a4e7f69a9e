// End-to-end tests of `rollnoise road` on absorbing surfaces: absorption.csv and, with
// --ground-effect, ground_effect.csv and their summary; a rigid road is unchanged; bad
// absorption keys and geometries are one message naming the file and the key, exit status 2,
// with nothing written.
#include <cmath>
#include <complex>
#include <filesystem>
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

const std::string porous_road =
    "[road]\ntype = \"flat\"\n[road.absorption]\nmodel = \"hamet_berengier\"\nporosity = 0.2\n"
    "flow_resistivity = 5000\ntortuosity = 2.5\nthickness = 0.04\n";

std::vector<std::vector<double>> read_rows(const fs::path& path) {
  std::istringstream text(read_text(path));
  std::string line;
  std::getline(text, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(text, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST(AbsorbingRoadCli, WritesAbsorptionAndGroundEffect) {
  Workspace ws;
  ws.write("r.toml", porous_road);
  const RunResult r = ws.run({"road", "r.toml", "--out", "out", "--length", "0.5", "--ground-effect", "0.05,7.5,1.2"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_TRUE(contains(r.out, "absorption.csv")) << r.out;
  EXPECT_EQ(first_line(ws.path("out") / "absorption.csv"), "band_hz,alpha,z_re,z_im");
  EXPECT_EQ(first_line(ws.path("out") / "ground_effect.csv"), "band_hz,delta_dB,delta_band_dB");
  const auto absorption = read_rows(ws.path("out") / "absorption.csv");
  ASSERT_EQ(absorption.size(), 21u);  // the third octaves 100 Hz to 10 kHz
  // Exact mid-band frequencies, 1000·10^(3x/30) (IEC 61260-1): x = −10 … 10.
  for (std::size_t n = 0; n < absorption.size(); ++n) {
    const double exact = 1000.0 * std::pow(10.0, 0.1 * (static_cast<double>(n) - 10.0));
    EXPECT_NEAR(absorption[n][0], exact, 1e-9 * exact);
    const std::complex<double> z(absorption[n][2], absorption[n][3]);
    EXPECT_GT(z.real(), 0.0);
    EXPECT_NEAR(absorption[n][1], 1.0 - std::norm((z - 1.0) / (z + 1.0)), 1e-6);
  }
  const auto ground = read_rows(ws.path("out") / "ground_effect.csv");
  ASSERT_EQ(ground.size(), 21u);
  bool attenuates = false;
  for (const auto& row : ground) {
    EXPECT_TRUE(std::isfinite(row[1]) && std::isfinite(row[2]));
    attenuates = attenuates || row[2] < -3.0;
  }
  EXPECT_TRUE(attenuates);  // a porous road takes several dB out somewhere at 7.5 m
  const nlohmann::json s = read_json(ws.path("out") / "summary.json");
  EXPECT_EQ(s["absorption"]["model"], "hamet_berengier");
  EXPECT_NEAR(s["absorption"]["air"]["sound_speed_m_s"].get<double>(), 343.2, 0.1);
  EXPECT_NEAR(s["absorption"]["air"]["temperature_c"].get<double>(), 20.0, 0.0);
  EXPECT_EQ(s["absorption"]["layers"].size(), 1u);
  EXPECT_EQ(s["ground_effect"]["distance_m"].get<double>(), 7.5);
}

TEST(AbsorbingRoadCli, RigidRoadHasNoAbsorptionAndNoGroundEffect) {
  Workspace ws;
  ws.write("r.toml", "[road]\ntype = \"flat\"\n");
  const RunResult r = ws.run({"road", "r.toml", "--out", "out", "--length", "0.5", "--ground-effect", "0.05,7.5,1.2"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_FALSE(fs::exists(ws.path("out") / "absorption.csv"));
  for (const auto& row : read_rows(ws.path("out") / "ground_effect.csv")) {
    EXPECT_EQ(row[1], 0.0);
    EXPECT_EQ(row[2], 0.0);
  }
  EXPECT_FALSE(read_json(ws.path("out") / "summary.json").contains("absorption"));
}

TEST(AbsorbingRoadCli, LibraryPorousAsphaltsHaveTheirAbsorption) {
  for (const std::string name : {"pa16", "pa2l"}) {
    Workspace ws;
    const std::string file = (source_dir / "models" / "surfaces" / (name + ".toml")).string();
    const RunResult r = ws.run({"road", file, "--out", "out", "--length", "0.5"});
    ASSERT_EQ(r.status, 0) << name << ": " << describe(r);
    const nlohmann::json s = read_json(ws.path("out") / "summary.json");
    ASSERT_TRUE(s.contains("absorption")) << name;
    EXPECT_EQ(s["absorption"]["layers"].size(), name == "pa2l" ? 2u : 1u);
    EXPECT_GT(s["absorption"]["peak_alpha"].get<double>(), 0.5) << name;
  }
}

struct BadAbsorption {
  const char* what;
  std::string content;
  std::vector<std::string> options;
  const char* expected;  // part of the message
};

TEST(AbsorbingRoadCli, BadInputIsOneMessageAndExitStatusTwo) {
  const std::string head = "[road]\ntype = \"flat\"\n[road.absorption]\nmodel = \"hamet_berengier\"\n";
  const std::string rest = "flow_resistivity = 5000\ntortuosity = 2.5\nthickness = 0.04\n";
  const std::vector<BadAbsorption> cases{
      {"porosity above 1", head + "porosity = 1.5\n" + rest, {}, "[road.absorption] porosity: must lie strictly between 0 and 1"},
      {"porosity 0", head + "porosity = 0\n" + rest, {}, "[road.absorption] porosity"},
      {"flow resistivity 0", head + "porosity = 0.2\nflow_resistivity = 0\ntortuosity = 2.5\nthickness = 0.04\n", {},
       "[road.absorption] flow_resistivity: must be > 0"},
      {"tortuosity below 1", head + "porosity = 0.2\nflow_resistivity = 5000\ntortuosity = 0.5\nthickness = 0.04\n", {},
       "[road.absorption] tortuosity: must be >= 1"},
      {"thickness 0", head + "porosity = 0.2\nflow_resistivity = 5000\ntortuosity = 2.5\nthickness = 0\n", {},
       "[road.absorption] thickness: must be > 0"},
      {"unknown model", "[road]\ntype = \"flat\"\n[road.absorption]\nmodel = \"foam\"\n", {},
       "[road.absorption] model: unknown value \"foam\"; allowed values are \"rigid\", \"hamet_berengier\", \"jca\""},
      {"empty layers", head + "layers = []\n", {}, "[road.absorption] layers: is empty"},
      {"ground effect height 0", porous_road, {"--ground-effect", "0,7.5,1.2"}, "--ground-effect: must be three positive"},
      {"ground effect distance negative", porous_road, {"--ground-effect", "0.05,-7.5,1.2"}, "--ground-effect"},
      {"ground effect receiver 0", porous_road, {"--ground-effect", "0.05,7.5,0"}, "--ground-effect"},
  };
  for (const BadAbsorption& c : cases) {
    Workspace ws;
    ws.write("r.toml", c.content);
    std::vector<std::string> args{"road", "r.toml", "--out", "out", "--length", "0.5"};
    args.insert(args.end(), c.options.begin(), c.options.end());
    const RunResult r = ws.run(args);
    EXPECT_EQ(r.status, 2) << c.what << ": " << describe(r);
    EXPECT_TRUE(contains(r.err, c.expected)) << c.what << ": " << r.err;
    if (c.options.empty()) {
      EXPECT_TRUE(contains(r.err, "r.toml")) << c.what << ": " << r.err;
    }
    EXPECT_EQ(count_lines(r.err), 1u) << c.what << ": " << r.err;
    EXPECT_FALSE(fs::exists(ws.path("out"))) << c.what;
  }
}

}  // namespace
