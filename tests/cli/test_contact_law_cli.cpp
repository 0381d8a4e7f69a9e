// End-to-end tests of the contact law a tyre meets (`rollnoise road --contact-law` and
// `[rolling] contact_law = "texture"`): the real program in a fresh folder. A flat road's cells
// are flat punches, so the mean law is exactly linear with the punch's compliance and full
// contact; a library surface's law rises and spreads; every bad input is one message naming
// the file or option and what is allowed, exit status 2, with nothing written.
#include <cmath>
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

std::vector<std::vector<double>> csv_rows(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'a') continue;  // comment, header
    std::vector<double> row;
    std::istringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

TEST(ContactLawCli, FlatRoadGivesTheFlatPunchOfEveryCell) {
  Workspace ws;
  ws.write("flat.toml", "[road]\ntype = \"flat\"\n");
  const RunResult r = ws.run({"road", "flat.toml", "--length", "0.02", "--width", "0.014", "--contact-law",
                              "--tread-modulus", "4e6", "--cell", "0.002,0.007", "--out", "law"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_TRUE(contains(r.out, "contact_law.csv, contact_laws.h5")) << r.out;
  EXPECT_TRUE(fs::exists(ws.path("law") / "contact_laws.h5"));
  const nlohmann::json s = read_json(ws.path("law") / "summary.json");
  EXPECT_EQ(s["contact_law"]["cells"].get<int>(), 10 * 2);
  EXPECT_EQ(s["contact_law"]["pixels_along"].get<int>(), 4);
  EXPECT_EQ(s["contact_law"]["pixels_across"].get<int>(), 14);
  const double punch = s["contact_law"]["punch_compliance_m_per_N"].get<double>();
  // A rigid flat punch of 2 mm × 7 mm on E* = 4 MPa/(1 − 0.48²): 1/(E*·β·√A) with β ≈ 1.1
  // for a rectangle of this aspect (order of magnitude only: the rows below check the law).
  EXPECT_GT(punch, 2e-5);
  EXPECT_LT(punch, 8e-5);
  const auto rows = csv_rows(read_text(ws.path("law") / "contact_law.csv"));
  ASSERT_GT(rows.size(), 40u);  // 10 nm to the approach of the table's end (E*·A·c_punch ≈ 4 mm)
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 5u);
    EXPECT_NEAR(row[1], row[0] / punch, 1e-9 * row[1]);  // F = δ/c_punch
    EXPECT_NEAR(row[2], 0.002 * 0.007, 1e-12);            // every pixel in contact from the first touch
    EXPECT_NEAR(row[3], row[1], 1e-9 * row[1]);           // every cell alike
    EXPECT_NEAR(row[4], row[1], 1e-9 * row[1]);
  }
}

TEST(ContactLawCli, LibrarySurfaceLawRisesAndSpreads) {
  Workspace ws;
  const std::string dac11 = (source_dir / "models" / "surfaces" / "dac11.toml").string();
  const RunResult r = ws.run({"road", dac11, "--length", "0.2", "--contact-law", "--tread-modulus", "4e6", "--cell",
                              "0.00194,0.007", "--out", "law"});
  ASSERT_EQ(r.status, 0) << describe(r);
  const auto rows = csv_rows(read_text(ws.path("law") / "contact_law.csv"));
  ASSERT_GT(rows.size(), 30u);
  const double punch = read_json(ws.path("law") / "summary.json")["contact_law"]["punch_compliance_m_per_N"].get<double>();
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_GT(rows[i][1], rows[i - 1][1]);                         // the force rises with the approach
    EXPECT_GE(rows[i][2], rows[i - 1][2] * (1.0 - 1e-12));         // and the contact grows (the mean over cells)
    EXPECT_LE(rows[i][1], rows[i][0] / punch * (1.0 + 1e-9));      // never stiffer than the flat punch
    EXPECT_LE(rows[i][3], rows[i][4]);
  }
  // A textured cell is softer than the flat punch where it carries a tyre's share (about 3 N).
  for (const auto& row : rows)
    if (row[1] > 1.0 && row[1] < 10.0) {
      EXPECT_LT(row[1], 0.9 * row[0] / punch);
    }
}

TEST(ContactLawCli, BadInputIsOneMessageAndWritesNothing) {
  Workspace ws;
  const std::string chipseal = (source_dir / "models" / "surfaces" / "chipseal.toml").string();
  const std::string captif = (source_dir / "data" / "surfaces" / "captif" / "20211011_aylesbury_dec_station_0.dat").string();
  struct Case {
    std::vector<std::string> args;
    std::vector<std::string> says;
  };
  const std::vector<Case> cases = {
      // A road sampled at 1 mm under 2 mm cells: the spacing needed.
      {{"road", chipseal, "--length", "0.05", "--contact-law", "--tread-modulus", "4e6", "--cell", "0.002,0.007"},
       {"chipseal.toml", "[road] sample_spacing", "at most 0.0005 m"}},
      // A measured line has no width.
      {{"road", captif, "--contact-law", "--tread-modulus", "4e6", "--cell", "0.002,0.007"},
       {"--contact-law", "--width", "profile_surface"}},
      {{"road", chipseal, "--contact-law", "--cell", "0.002,0.007"}, {"--tread-modulus", "needed"}},
      {{"road", chipseal, "--contact-law", "--tread-modulus", "4e6"}, {"--cell", "needed"}},
      {{"road", chipseal, "--tread-modulus", "4e6"}, {"--tread-modulus", "--contact-law only"}},
      {{"road", chipseal, "--contact-law", "--tread-modulus", "-1", "--cell", "0.002,0.007"}, {"--tread-modulus"}},
      {{"road", chipseal, "--contact-law", "--tread-modulus", "4e6", "--tread-poisson", "0.5", "--cell", "0.002,0.007"},
       {"--tread-poisson"}},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = c.args;
    args.insert(args.end(), {"--out", "out"});
    const RunResult r = ws.run(args);
    EXPECT_EQ(r.status, 2) << describe(r);
    for (const std::string& s : c.says) EXPECT_TRUE(contains(r.err, s)) << s << " not in: " << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_FALSE(fs::exists(ws.path("out")));
  }
}

TEST(ContactLawCli, TyreCaseNeedsTheTreadModulusAndAFineEnoughRoad) {
  Workspace ws;
  const std::string plate = (source_dir / "models" / "tyres" / "passenger_205_55R16.toml").string();
  const std::string chipseal = (source_dir / "models" / "surfaces" / "chipseal.toml").string();
  // The library plate names its rubber; a tread without it cannot take the texture law.
  ws.write("tyre.toml", read_text(plate).replace(read_text(plate).find("youngs_modulus = 4.0e6"),
                                                  std::string("youngs_modulus = 4.0e6").size(), ""));
  const std::string rolling =
      "[rolling]\nspeed = 22.222\nduration = 0.002\nstatic_load = 3200.0\ncontact_law = \"texture\"\n"
      "[radiation]\nenabled = false\n";
  ws.write("no_modulus.toml", "[tyre]\nfile = \"tyre.toml\"\n[road]\ntype = \"flat\"\n" + rolling);
  RunResult r = ws.run({"simulate", "no_modulus.toml", "--out", "out"});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "[tyre.tread] youngs_modulus")) << r.err;
  EXPECT_TRUE(contains(r.err, "contact_law")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  // The chip seal at 1 mm under the 80 km/h grid's 1.94 mm cells.
  ws.write("coarse.toml", "[tyre]\nfile = \"" + plate + "\"\n[road]\nsurface = \"" + chipseal + "\"\n" + rolling);
  r = ws.run({"simulate", "coarse.toml", "--out", "out"});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "chipseal.toml")) << r.err;
  EXPECT_TRUE(contains(r.err, "sample_spacing")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  // road_sampling belongs to the rigid cells.
  ws.write("both.toml", "[tyre]\nfile = \"" + plate + "\"\n[road]\ntype = \"flat\"\n" + rolling);
  r = ws.run({"simulate", "both.toml", "--set", "rolling.road_sampling=\"point\"", "--out", "out"});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "road_sampling")) << r.err;
  EXPECT_FALSE(fs::exists(ws.path("out")));
}

}  // namespace
