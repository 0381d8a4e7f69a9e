// End-to-end tests of `rollnoise greens` (issue 11): the real program, run as a user runs it. The
// tables are checked against independent formulas (the SDOF's receptance and impulse response in
// closed form; the plate's static compliance as its modal sum written out here), against
// physics (a passive point mobility), and bad input gets one message naming the option, exit
// status 2, and nothing written.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <complex>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
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
  for (const char* word : {"receptance.csv", "--frequencies", "--distances", "greens.h5", "modal_receptance.h5", "tabulated"})
    EXPECT_TRUE(contains(r.out, word)) << word;
}

}  // namespace

namespace {

// A reduced copy of the passenger two-layer file: orders m = 0 … 16 and `lateral` lateral modes,
// so that a test is quick.
std::string small_two_layer(int lateral) {
  std::string text = read_text(tyre_file("passenger_205_55R16_two_layer.toml"));
  for (const auto& [key, value] :
       {std::pair<std::string, std::string>{"circumferential_modes = 256", "circumferential_modes = 16"},
        {"lateral_modes = 25", "lateral_modes = " + std::to_string(lateral)}}) {
    const auto at = text.find(key);
    EXPECT_NE(at, std::string::npos) << key;
    if (at != std::string::npos) text.replace(at, key.size(), value);
  }
  return text;
}

// The two-layer tables are computed here, not taken from the user's cache.
std::string own_cache(const Workspace& ws) { return "ROLLNOISE_CACHE=" + shell_quote(ws.path("cache").string()) + " "; }

// The two-layer tyre through the same verb (17 orders × 3 lateral modes): the tables are
// written, the static row is real and positive, and the point mobility is passive. The model
// itself is checked against its references in tests/greens/test_two_layer_*.cpp.
TEST(GreensCli, TwoLayerTyreTablesArePassiveAndConsistent) {
  Workspace ws;
  ws.write("two_layer.toml", small_two_layer(3));
  const RunResult r = ws.run({"greens", "two_layer.toml", "--out", "g", "--frequencies", "0:2000:41", "--distances", "0,0.1"},
                             own_cache(ws));
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

// The round trip two_layer → greens → modal_receptance.h5 → tabulated → greens: the two-layer
// run writes its modal table (17 orders × 4 lateral orders at the pole fit's 161 frequencies),
// a `tabulated` model file beside it names it, and greens on that file writes the same tables
// and reproduces the two-layer receptance within the pole fit (1 % of the larger of the value and
// the point receptance; the per-mode fit is 3e-3 RMS, 3e-2 at worst). The tabulated view and the fit are checked further in tests/greens/test_modal_table.cpp.
TEST(GreensCli, TabulatedRoundTripReproducesTheTwoLayerReceptance) {
  Workspace ws;
  ws.write("two_layer.toml", small_two_layer(4));
  const std::vector<std::string> grid{"--frequencies", "0:4000:41", "--distances", "0,0.05,0.1,0.2"};
  std::vector<std::string> args{"greens", "two_layer.toml", "--out", "layered"};
  args.insert(args.end(), grid.begin(), grid.end());
  RunResult r = ws.run(args, own_cache(ws));
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_TRUE(contains(r.out, "modal_receptance.h5")) << r.out;
  ASSERT_TRUE(fs::exists(ws.path("layered") / "modal_receptance.h5"));
  // The free waves' map (the dispersion curves as its ridges): one row per order and frequency
  // in 20 Hz–6 kHz.
  ASSERT_TRUE(fs::exists(ws.path("layered") / "dispersion.csv"));
  EXPECT_EQ(first_line(ws.path("layered") / "dispersion.csv"),
            "wavenumber_rad_per_m,frequency_hz,log10_abs_receptance_m_per_pa");
  if (gnuplot_installed()) {
    EXPECT_TRUE(fs::exists(ws.path("layered") / "dispersion.png"));
  }
  const nlohmann::json layered = read_json(ws.path("layered") / "summary.json");
  ASSERT_TRUE(layered.contains("modal_table")) << layered.dump(2);
  EXPECT_EQ(layered["modal_table"]["file"], "modal_receptance.h5");
  EXPECT_EQ(layered["modal_table"]["orders"], 16);
  EXPECT_EQ(layered["modal_table"]["lateral_orders"], 4);
  EXPECT_EQ(layered["modal_table"]["frequencies"], 161);
  EXPECT_EQ(layered["modal_table"]["from_cache"], false);
  // Again: the table now comes from the cache that `simulate` shares.
  r = ws.run({"greens", "two_layer.toml", "--out", "again", "--frequencies", "0:100:2"}, own_cache(ws));
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_EQ(read_json(ws.path("again") / "summary.json")["modal_table"]["from_cache"], true);

  // The table named from a model file in another folder (relative to that file).
  fs::create_directories(ws.path("models"));
  ws.write("models/tabulated.toml", "model = \"tabulated\"\nfile = \"../layered/modal_receptance.h5\"\n");
  args = {"greens", "models/tabulated.toml", "--out", "tabulated"};
  args.insert(args.end(), grid.begin(), grid.end());
  r = ws.run(args);
  ASSERT_EQ(r.status, 0) << describe(r);
  for (const char* name : {"receptance.csv", "mobility.csv", "greens.h5", "summary.json", "greens_circumference.csv"})
    EXPECT_TRUE(fs::exists(ws.path("tabulated") / name)) << name;
  EXPECT_FALSE(fs::exists(ws.path("tabulated") / "modal_receptance.h5"));  // it has one already
  const nlohmann::json tabulated = read_json(ws.path("tabulated") / "summary.json");
  EXPECT_EQ(tabulated["model"], "tabulated");
  EXPECT_TRUE(contains(tabulated["description"].get<std::string>(), "cell")) << tabulated["description"];
  EXPECT_TRUE(contains(tabulated["table"]["file"].get<std::string>(), "modal_receptance.h5"));
  EXPECT_EQ(tabulated["mode_fit"]["modes"], 68);
  EXPECT_EQ(tabulated["mode_fit"]["unconverged_modes"], 0);
  EXPECT_NEAR(tabulated["circumference_m"].get<double>(), layered["circumference_m"].get<double>(), 1e-15);

  const std::vector<Row> exact = read_rows(ws.path("layered") / "receptance.csv");
  const std::vector<Row> fitted = read_rows(ws.path("tabulated") / "receptance.csv");
  const std::vector<Row> mobility = read_rows(ws.path("tabulated") / "mobility.csv");
  ASSERT_EQ(exact.size(), 164u);
  ASSERT_EQ(exact[40].d, 0.0);
  ASSERT_EQ(exact[41].d, 0.05);
  ASSERT_EQ(fitted.size(), exact.size());
  ASSERT_EQ(mobility.size(), exact.size());
  // Rows by distance, then frequency: row i of distance 0 is row i % 41.
  double worst = 0.0, worst_own = 0.0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    ASSERT_EQ(fitted[i].f, exact[i].f);
    ASSERT_EQ(fitted[i].d, exact[i].d);
    // A transfer receptance near a node is small beside the point receptance at that frequency,
    // and the fit's error there is a share of the modes' sum, not of the value: measured
    // against the larger of the value and the point receptance.
    const double point = std::abs(exact[i % 41].v);
    const double difference = std::abs(fitted[i].v - exact[i].v);
    const double error = difference / std::max(std::abs(exact[i].v), point);
    worst = std::max(worst, error);
    worst_own = std::max(worst_own, difference / std::abs(exact[i].v));
    EXPECT_LT(error, 0.01) << exact[i].f << " Hz, " << exact[i].d << " m";
    const double w = 2.0 * std::numbers::pi * fitted[i].f;
    EXPECT_LT(std::abs(mobility[i].v - std::complex<double>(0.0, w) * fitted[i].v), 1e-12 * std::abs(fitted[i].v) * (w + 1.0));
  }
  std::printf("round trip two_layer -> tabulated over %zu values: worst difference %.2e of max(|value|, |point|), "
              "%.2e of the value itself\n",
              exact.size(), worst, worst_own);
  const nlohmann::json& statics = tabulated["static_compliance_m_per_N"];
  ASSERT_EQ(statics.size(), 4u);
  for (std::size_t j = 0; j < statics.size(); ++j) {
    const double a = statics[j]["value"].get<double>(), b = layered["static_compliance_m_per_N"][j]["value"].get<double>();
    EXPECT_NEAR(a, b, 0.01 * std::abs(b)) << j;
  }
}

// A tabulated model file whose table is missing, or is not a table: one message naming the
// file, exit status 2, nothing written.
TEST(GreensCli, TabulatedModelWithoutAGoodTableIsOneMessage) {
  struct Bad {
    std::string table;     // what to write as the table (empty: none)
    std::string mentions;  // in the message
  };
  for (const Bad& bad : {Bad{"", "absent.h5"}, Bad{"not an HDF5 file\n", "garbage.h5"},
                         Bad{std::string("\x89HDF\r\n\x1a\n", 8) + std::string(200, '\0'), "truncated.h5"}}) {
    Workspace ws;
    if (!bad.table.empty()) ws.write(bad.mentions, bad.table);
    ws.write("tabulated.toml", "model = \"tabulated\"\nfile = \"" + bad.mentions + "\"\n");
    const RunResult r = ws.run({"greens", "tabulated.toml", "--out", "g"});
    EXPECT_EQ(r.status, 2) << describe(r);
    EXPECT_TRUE(contains(r.err, bad.mentions)) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_FALSE(fs::exists(ws.path("g"))) << bad.mentions;
    EXPECT_TRUE(ws.leftovers().empty()) << bad.mentions;
  }
}

}  // namespace
