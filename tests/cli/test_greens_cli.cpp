// End-to-end tests of `rollnoise greens` (issue 11): the real program, run as a user runs it. The
// tables are checked against independent formulas (the SDOF's receptance and impulse response in
// closed form; the plate's static compliance as its modal sum written out here), against
// physics (a passive point mobility), and bad input gets one message naming the option, exit
// status 2, and nothing written.
#include <cmath>
#include <complex>
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
std::string tyre_file(const std::string& name) { return (source_dir / "models" / "tyres" / name).string(); }

struct Row {
  double f, d;
  std::complex<double> v;
};

std::vector<Row> read_rows(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "frequency_hz,distance_m,re,im");
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    Row r{};
    char c1, c2, c3;
    double re = 0.0, im = 0.0;
    fields >> r.f >> c1 >> r.d >> c2 >> re >> c3 >> im;
    EXPECT_FALSE(fields.fail()) << line;
    r.v = {re, im};
    rows.push_back(r);
  }
  return rows;
}

TEST(GreensCli, SdofTablesAreTheClosedFormReceptanceAndImpulseResponse) {
  Workspace ws;
  const RunResult r = ws.run({"greens", tyre_file("larsson2000_sdof.toml"), "--out", "g", "--frequencies", "0:200:41"});
  ASSERT_EQ(r.status, 0) << r.err;
  // larsson2000_sdof.toml: m = 1 kg, r = 50 N·s/m, k = 500 N/m, contact spring s = 1e5 N/m.
  const double m = 1.0, damping = 50.0, k = 500.0, s = 1e5;
  const std::vector<Row> receptance = read_rows(ws.path("g") / "receptance.csv");
  const std::vector<Row> mobility = read_rows(ws.path("g") / "mobility.csv");
  ASSERT_EQ(receptance.size(), 41u);
  ASSERT_EQ(mobility.size(), 41u);
  for (std::size_t i = 0; i < receptance.size(); ++i) {
    EXPECT_NEAR(receptance[i].f, 5.0 * static_cast<double>(i), 1e-9);
    EXPECT_EQ(receptance[i].d, 0.0);
    const double w = 2.0 * std::numbers::pi * receptance[i].f;
    const std::complex<double> expected = 1.0 / s + 1.0 / std::complex<double>(k - m * w * w, w * damping);
    EXPECT_LT(std::abs(receptance[i].v - expected), 1e-9 * std::abs(expected)) << receptance[i].f;
    EXPECT_LT(std::abs(mobility[i].v - std::complex<double>(0.0, w) * expected), 1e-9 * std::abs(expected) * (w + 1.0));
  }
  // The impulse response without the contact spring's δ/s. This SDOF is overdamped (ζ = 1.118):
  // h(t) = e^{−ζω₀t}·sinh(ω₀√(ζ²−1)·t)/(m·ω₀√(ζ²−1)).
  std::ifstream in(ws.path("g") / "green_time.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "time,g_1");
  const double w0 = std::sqrt(k / m), zeta = damping / (2.0 * std::sqrt(k * m)), wd = w0 * std::sqrt(zeta * zeta - 1.0);
  ASSERT_GT(zeta, 1.0);
  int rows = 0;
  while (std::getline(in, line)) {
    double t = 0.0, g = 0.0;
    char comma;
    std::istringstream(line) >> t >> comma >> g;
    const double h = std::exp(-zeta * w0 * t) * std::sinh(wd * t) / (m * wd);
    EXPECT_NEAR(g, h, 1e-9 * (1.0 / (m * wd))) << t;
    ++rows;
  }
  EXPECT_EQ(rows, 200);
  for (const char* name : {"greens.h5", "summary.json", "mobility.gp"}) EXPECT_TRUE(fs::exists(ws.path("g") / name)) << name;
}

TEST(GreensCli, PlateStaticCompliancePassivityAndTables) {
  Workspace ws;
  const RunResult r = ws.run({"greens", tyre_file("passenger_205_55R16.toml"), "--out", "g", "--frequencies",
                              "0:3000:301", "--distances", "0,0.1"});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<Row> receptance = read_rows(ws.path("g") / "receptance.csv");
  const std::vector<Row> mobility = read_rows(ws.path("g") / "mobility.csv");
  ASSERT_EQ(receptance.size(), 602u);
  // The static compliance at mid-width as the plate's modal sum (MODEL.md §4), written out here:
  // Σ_n Σ_m w_m cos(k_m d) sin²(k_n b/2) / (K_mn·L·b/2) (K_mn per unit area, N/m³), from the
  // model file's values.
  const double radius = 0.316, b = 0.18, tx = 6.0e4, ty = 9.0e3, bx = 7.0, by = 3.0, bxy = 4.6,
               sf = 3.2e6;
  const double length = 2.0 * std::numbers::pi * radius;
  for (const double d : {0.0, 0.1}) {
    double sum = 0.0;
    for (int n = 1; n <= 25; ++n) {
      const double kn = n * std::numbers::pi / b;
      const double s = std::sin(kn * b / 2.0);
      for (int m = 0; m <= 256; ++m) {
        const double km = 2.0 * std::numbers::pi * m / length;
        const double stiffness = bx * std::pow(km, 4) + 2.0 * bxy * km * km * kn * kn + by * std::pow(kn, 4) +
                                 tx * km * km + ty * kn * kn + sf;
        sum += (m == 0 ? 1.0 : 2.0) * std::cos(km * d) * s * s / (stiffness * length * b / 2.0);
      }
    }
    bool found = false;
    for (const Row& row : receptance)
      if (row.f == 0.0 && row.d == d) {
        found = true;
        EXPECT_NEAR(row.v.real(), sum, 1e-9 * sum) << d;
        EXPECT_EQ(row.v.imag(), 0.0);
      }
    EXPECT_TRUE(found) << d;
  }
  // A passive structure: the real part of the point mobility is never negative.
  for (const Row& row : mobility)
    if (row.d == 0.0) {
      EXPECT_GE(row.v.real(), -1e-12 * std::abs(row.v)) << row.f;
    }
  const nlohmann::json summary = nlohmann::json::parse(read_text(ws.path("g") / "summary.json"));
  EXPECT_EQ(summary["model"], "plate");
  EXPECT_NEAR(summary["circumference_m"].get<double>(), length, 1e-12);
  EXPECT_TRUE(fs::exists(ws.path("g") / "greens_circumference.csv"));
  if (gnuplot_installed()) {
    EXPECT_TRUE(fs::exists(ws.path("g") / "mobility.png"));
    EXPECT_TRUE(fs::exists(ws.path("g") / "greens_circumference.png"));
  }
}

TEST(GreensCli, BadInputIsOneMessageAndNothingWritten) {
  struct Bad {
    std::vector<std::string> args;
    std::string mentions;
  };
  const std::string plate = tyre_file("passenger_205_55R16.toml");
  const std::string sdof = tyre_file("larsson2000_sdof.toml");
  const std::vector<Bad> cases = {
      {{"greens", plate, "--frequencies", "100:10:5"}, "--frequencies"},
      {{"greens", plate, "--frequencies", "0:100"}, "F1:F2:N"},
      {{"greens", plate, "--frequencies", "0:100:0"}, "N must be"},
      {{"greens", plate, "--frequencies", "-5:100:3"}, "F1 >= 0"},
      {{"greens", plate, "--frequencies", "0:nan:3"}, "--frequencies"},
      {{"greens", plate, "--distances", "0,1.5"}, "half the circumference"},
      {{"greens", sdof, "--distances", "0.1"}, "not a point of the sdof model"},
      {{"greens", "missing.toml"}, "missing.toml"},
  };
  for (const Bad& bad : cases) {
    Workspace ws;
    std::vector<std::string> args = bad.args;
    args.insert(args.end(), {"--out", "g"});
    const RunResult r = ws.run(args);
    EXPECT_EQ(r.status, 2) << bad.mentions << ": " << r.err;
    EXPECT_TRUE(contains(r.err, bad.mentions)) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_FALSE(fs::exists(ws.path("g"))) << bad.mentions;
  }
  // A model file with an unknown key names it.
  Workspace ws;
  ws.write("bad.toml", read_text(sdof) + "\nstifness = 3.0\n");
  const RunResult r = ws.run({"greens", "bad.toml", "--out", "g"});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "stifness")) << r.err;
  EXPECT_TRUE(contains(r.err, "bad.toml")) << r.err;
}

TEST(GreensCli, HelpNamesTheOutputs) {
  Workspace ws;
  const RunResult r = ws.run({"greens", "--help"});
  EXPECT_EQ(r.status, 0);
  for (const char* word : {"receptance.csv", "--frequencies", "--distances", "greens.h5"})
    EXPECT_TRUE(contains(r.out, word)) << word;
}

}  // namespace

namespace {

// The two-layer tyre through the same verb (a reduced copy of the passenger file: 17 orders × 3
// lateral modes, so the test is quick): the tables are written, the static row is real and
// positive, and the point mobility is passive. The model itself is checked against its
// references in tests/greens/test_two_layer_*.cpp.
TEST(GreensCli, TwoLayerTyreTablesArePassiveAndConsistent) {
  Workspace ws;
  std::string text = read_text(tyre_file("passenger_205_55R16_two_layer.toml"));
  for (const auto& [key, value] : {std::pair<std::string, std::string>{"circumferential_modes = 256", "circumferential_modes = 16"},
                                   {"lateral_modes = 25", "lateral_modes = 3"}}) {
    const auto at = text.find(key);
    ASSERT_NE(at, std::string::npos) << key;
    text.replace(at, key.size(), value);
  }
  ws.write("two_layer.toml", text);
  const RunResult r = ws.run({"greens", "two_layer.toml", "--out", "g", "--frequencies", "0:2000:41", "--distances", "0,0.1"});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<Row> receptance = read_rows(ws.path("g") / "receptance.csv");
  const std::vector<Row> mobility = read_rows(ws.path("g") / "mobility.csv");
  ASSERT_EQ(receptance.size(), 82u);
  EXPECT_GT(receptance[0].v.real(), 0.0);
  EXPECT_LT(std::abs(receptance[0].v.imag()), 1e-12 * receptance[0].v.real());
  for (const Row& row : mobility) {
    if (row.d == 0.0) {
      EXPECT_GE(row.v.real(), -1e-12 * std::abs(row.v)) << row.f;
    }
  }
  const nlohmann::json summary = nlohmann::json::parse(read_text(ws.path("g") / "summary.json"));
  EXPECT_EQ(summary["model"], "two_layer");
  EXPECT_TRUE(contains(summary["description"].get<std::string>(), "cell"));
  EXPECT_TRUE(fs::exists(ws.path("g") / "greens.h5"));
  EXPECT_TRUE(fs::exists(ws.path("g") / "greens_circumference.csv"));
}

}  // namespace
