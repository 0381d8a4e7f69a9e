// End-to-end tests of `rollnoise calibrate` (issue 5): the real program, run as a user runs it,
// in a fresh folder per test, on the synthetic example measurements of data/mobility (whose true
// parameters are known). It must write calibrated.toml (a model file `simulate` takes),
// fit.csv, report.json and fit.png; recover the true parameters within two reported standard
// errors from CSV and from UFF 58/58b (the two-layer tyre's nine within three); give the same result whatever the frequency unit; be
// deterministic; and refuse bad data with one message and exit status 2, leaving nothing.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/cli_workspace.hpp"

namespace {
namespace fs = std::filesystem;

const fs::path source_dir{ROLLNOISE_SOURCE_DIR};
const fs::path mobility = source_dir / "data" / "mobility";

using namespace cli_test;

std::string data(const char* name) { return (mobility / name).string(); }
std::string model(const char* name) { return (source_dir / "models" / "tyres" / name).string(); }

// Checks |value − truth| < 2·std_error for each parameter in report.json.
void expect_recovered(const nlohmann::json& report, const std::vector<std::pair<std::string, double>>& truth) {
  for (const auto& [name, value] : truth) {
    ASSERT_TRUE(report["parameters"].contains(name)) << name;
    const double fitted = report["parameters"][name]["value"];
    const double std_error = report["parameters"][name]["std_error"];
    EXPECT_GT(std_error, 0.0) << name;
    EXPECT_LT(std::abs(fitted - value), 2.0 * std_error)
        << name << ": fitted " << fitted << " +- " << std_error << ", true " << value;
  }
}

// ---------------------------------------------------------------------------------------------

TEST(CalibrateCli, SdofFromCsvWritesEveryOutputAndSimulateTakesTheModel) {
  Workspace ws;
  const RunResult r = ws.run({"calibrate", model("larsson2000_sdof.toml"), "--data", data("sdof_point_mobility.csv"),
                              "--out", "cal"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_EQ(r.err, "") << "no notes, warnings or progress for clean data off a terminal";
  EXPECT_TRUE(contains(r.out, "wrote cal (calibrated.toml, fit.csv, report.json, fit.png)")) << r.out;
  for (const char* file : {"calibrated.toml", "fit.csv", "report.json", "fit.gp"})
    EXPECT_TRUE(fs::exists(ws.path("cal") / file)) << file;
  if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
    EXPECT_TRUE(fs::exists(ws.path("cal") / "fit.png"));
  }

  // report.json: the contract of the issue, and the truth within two standard errors.
  const nlohmann::json report = read_json(ws.path("cal") / "report.json");
  EXPECT_TRUE(report["cost"].is_number());
  EXPECT_TRUE(report["iterations"].is_number_integer());
  EXPECT_EQ(report["model"], "sdof");
  expect_recovered(report, {{"mass", 0.8}, {"damping", 40.0}, {"stiffness", 800.0}, {"contact_stiffness", 1.5e5}});
  const auto& names = report["correlations"]["parameters"];
  const auto& matrix = report["correlations"]["matrix"];
  ASSERT_EQ(names.size(), 4U);
  ASSERT_EQ(matrix.size(), 4U);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(matrix[i][i].get<double>(), 1.0);
    for (std::size_t j = 0; j < 4; ++j) EXPECT_LE(std::abs(matrix[i][j].get<double>()), 1.0 + 1e-12);
  }
  EXPECT_TRUE(report["warnings"].empty()) << report["warnings"].dump();

  // fit.csv: measured and fitted per line.
  const std::string csv = read_text(ws.path("cal") / "fit.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "frf,frequency_hz,measured_re,measured_im,fitted_re,fitted_im,measured_magnitude,measured_phase_deg,"
            "fitted_magnitude,fitted_phase_deg,weight");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1001);

  // calibrated.toml is a model file that simulate runs with.
  const std::string calibrated = read_text(ws.path("cal") / "calibrated.toml");
  EXPECT_TRUE(contains(calibrated, "model = \"sdof\"")) << calibrated;
  EXPECT_TRUE(contains(calibrated, "# kg, m")) << "the original's comments stay";
  EXPECT_FALSE(contains(calibrated, "mass = 1.0 ")) << "the fitted mass replaces the file's";
  write_text(ws.path("case.toml"),
             "[tyre]\nfile = \"cal/calibrated.toml\"\n[road]\ntype = \"sine\"\namplitude = 1.0e-3\nwavelength = 0.1\n"
             "[rolling]\nspeed = 1.0\nduration = 0.02\ntime_step = 1.0e-4\nstatic_load = 4.0\n[output]\nplots = false\n");
  const RunResult sim = ws.run({"simulate", "case.toml", "--out", "sim"});
  ASSERT_EQ(sim.status, 0) << describe(sim);
  EXPECT_TRUE(fs::exists(ws.path("sim") / "contact.csv"));
}

TEST(CalibrateCli, TyreFromUffNodesMatchesTheCsvAndSimulateRunsTheCalibratedTyre) {
  Workspace ws;
  const std::vector<std::pair<std::string, double>> truth = {
      {"tension_x", 5.2e4}, {"bending_x", 5.5}, {"foundation_stiffness", 2.7e6}, {"loss_factor", 0.08}};
  // UFF 58b (binary, mobility) with node positions; one start: the model file's values.
  RunResult r = ws.run({"calibrate", model("passenger_205_55R16.toml"), "--data", data("tyre_frfs_58b.uff"), "--node",
                        "1=0,0.09", "--node", "2=0.1,0.09", "--starts", "1", "--out", "uff"});
  ASSERT_EQ(r.status, 0) << describe(r);
  const nlohmann::json uff = read_json(ws.path("uff") / "report.json");
  expect_recovered(uff, truth);
  EXPECT_EQ(uff["data"][1]["response_dof"]["node"], 2);
  EXPECT_EQ(uff["data"][1]["response"], nlohmann::json::array({0.1, 0.09}));
  // The same measurement from the CSV files (positions in their comment lines).
  r = ws.run({"calibrate", model("passenger_205_55R16.toml"), "--data", data("tyre_point_mobility.csv"),
              data("tyre_transfer_mobility.csv"), "--fit", "tension_x,bending_x,foundation_stiffness,loss_factor",
              "--starts", "1", "--out", "csv"});
  ASSERT_EQ(r.status, 0) << describe(r);
  const nlohmann::json csv = read_json(ws.path("csv") / "report.json");
  for (const auto& [name, value] : truth) {
    const double a = uff["parameters"][name]["value"];
    const double b = csv["parameters"][name]["value"];
    EXPECT_NEAR(a / b, 1.0, 1e-9) << name;
  }
  // The calibrated tyre rolls.
  const std::string case_text = read_text(source_dir / "models" / "cases" / "plate_smooth_80kmh.toml");
  write_text(ws.path("case.toml"), case_text);
  r = ws.run({"simulate", "case.toml", "--set", "tyre.file=" + (ws.path("uff") / "calibrated.toml").string(), "--set",
              "rolling.duration=0.002", "--set", "output.plots=false", "--out", "sim"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_TRUE(fs::exists(ws.path("sim") / "summary.json"));
}

TEST(CalibrateCli, FrequencyUnitAndRepeatedRunsGiveTheSameNumbers) {
  Workspace ws;
  // The sdof measurement with its frequencies in kHz.
  std::istringstream in(read_text(mobility / "sdof_point_mobility.csv"));
  std::ostringstream khz;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') {
      khz << line << '\n';
    } else if (line.rfind("frequency_hz", 0) == 0) {
      khz << "frequency_khz,re,im\n";
    } else {
      const auto comma = line.find(',');
      khz << std::stod(line.substr(0, comma)) / 1000.0 << line.substr(comma) << '\n';
    }
  }
  write_text(ws.path("khz.csv"), khz.str());
  const std::vector<std::string> common = {"calibrate", model("larsson2000_sdof.toml"), "--data"};
  auto args = common;
  args.insert(args.end(), {data("sdof_point_mobility.csv"), "--out", "a"});
  ASSERT_EQ(ws.run(args).status, 0);
  args = common;
  args.insert(args.end(), {data("sdof_point_mobility.csv"), "--out", "b"});
  ASSERT_EQ(ws.run(args).status, 0);
  args = common;
  args.insert(args.end(), {"khz.csv", "--out", "c"});
  const RunResult r = ws.run(args);
  ASSERT_EQ(r.status, 0) << describe(r);
  nlohmann::json a = read_json(ws.path("a") / "report.json");
  nlohmann::json b = read_json(ws.path("b") / "report.json");
  const nlohmann::json c = read_json(ws.path("c") / "report.json");
  for (nlohmann::json* j : {&a, &b}) {
    j->erase("wall_time_s");
    (*j)["data"][0].erase("name");
  }
  EXPECT_EQ(a, b) << "same data and seed, same report";
  EXPECT_EQ(read_text(ws.path("a") / "fit.csv"), read_text(ws.path("b") / "fit.csv"));
  for (const char* name : {"mass", "damping", "stiffness", "contact_stiffness"}) {
    const double x = a["parameters"][name]["value"];
    const double y = c["parameters"][name]["value"];
    EXPECT_NEAR(x / y, 1.0, 1e-9) << name << " in Hz and in kHz";
  }
}

// Runs a calibration that must fail with exit status 2 and a message holding `expected`,
// leaving nothing behind.
void expect_bad_input(const Workspace& ws, const std::vector<std::string>& args, const std::string& expected) {
  const std::set<std::string> before = ws.entries();
  std::vector<std::string> all = {"calibrate"};
  all.insert(all.end(), args.begin(), args.end());
  all.insert(all.end(), {"--out", "never"});
  const RunResult r = ws.run(all);
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "rollnoise: error: ")) << r.err;
  EXPECT_TRUE(contains(r.err, expected)) << "expected: " << expected << "\n" << describe(r);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one message:\n" << r.err;
  EXPECT_EQ(ws.entries(), before) << "a failed run leaves nothing";
}

TEST(CalibrateCli, BadDataIsOneMessageAndExitStatusTwo) {
  Workspace ws;
  const std::string sdof = model("larsson2000_sdof.toml");
  write_text(ws.path("nan.csv"), "frequency_hz,re,im\n10,1e-4,2e-5\n20,nan,1e-5\n");
  expect_bad_input(ws, {sdof, "--data", "nan.csv"}, "nan.csv: line 3, column \"re\": must be a finite number");
  write_text(ws.path("negative.csv"), "# hammer test\nfrequency_hz,re,im\n-5,1e-4,2e-5\n20,1e-4,1e-5\n");
  expect_bad_input(ws, {sdof, "--data", "negative.csv"},
                   "negative.csv: line 3: frequency -5 Hz is negative; frequencies must be >= 0");
  expect_bad_input(ws, {sdof, "--data", data("sdof_point_mobility.csv"), "--frequency-range", "600:700"},
                   "sdof_point_mobility.csv: no frequency overlap: the data spans 0.5 to 500 Hz, the band to fit is 600 "
                   "to 700 Hz");
  // A tyre model with few modes reaches some 300 Hz: no overlap with data above it.
  write_text(ws.path("coarse.toml"), read_text(model("passenger_205_55R16.toml")) + "\n");
  {
    std::string text = read_text(ws.path("coarse.toml"));
    text.replace(text.find("circumferential_modes = 256"), 27, "circumferential_modes = 2");
    text.replace(text.find("lateral_modes = 25"), 18, "lateral_modes = 1");
    write_text(ws.path("coarse.toml"), text);
  }
  write_text(ws.path("high.csv"), "# response_x = 0\n# response_y = 0.09\n# excitation_x = 0\n# excitation_y = 0.09\n"
                                  "frequency_hz,re,im\n2000,1e-3,1e-3\n3000,1e-3,2e-3\n");
  expect_bad_input(ws, {"coarse.toml", "--data", "high.csv"}, "no frequency overlap");
  // An FRF of the wrong quantity: force over acceleration (apparent mass), records 9 and 10
  // of the example file swapped.
  {
    std::istringstream in(read_text(mobility / "tyre_frfs.uff"));
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    for (std::size_t i = 0; i + 1 < lines.size(); ++i)
      if (lines[i].rfind("        12    1    0    0 Acceleration", 0) == 0) {
        std::swap(lines[i], lines[i + 1]);
        ++i;
      }
    std::string text;
    for (const auto& line : lines) text += line + "\n";
    write_text(ws.path("apparent_mass.uff"), text);
  }
  expect_bad_input(ws, {model("passenger_205_55R16.toml"), "--data", "apparent_mass.uff", "--node", "1=0,0.09", "--node",
                        "2=0.1,0.09"},
                   "apparent_mass.uff: dataset 1 (58, line 1), records 9-10: the FRF is excitation force (specific data "
                   "type 13, units 'N') over acceleration");
  // A file with no dataset 58, and UFF files of time data and PSDs.
  expect_bad_input(ws, {sdof, "--data", (source_dir / "tests" / "corpus" / "uff" / "ok_only_dataset_151.uff").string()},
                   "ok_only_dataset_151.uff: holds no dataset 58");
  const fs::path real = source_dir / ".." / "shared" / "data" / "uff";
  if (fs::exists(real / "sample_dataset58_psd.uff")) {
    expect_bad_input(ws, {sdof, "--data", (real / "sample_dataset58_psd.uff").string()},
                     "holds no frequency response function (dataset 58, function type 4); found: dataset 1 (58, line "
                     "1): power spectral density (PSD) (function type 9)");
  }
  // An explicit --data-type the file contradicts.
  expect_bad_input(ws, {model("passenger_205_55R16.toml"), "--data", data("tyre_frfs.uff"), "--data-type", "mobility"},
                   "the record holds accelerance");
  // A tyre FRF without positions; a UFF node without one.
  write_text(ws.path("nowhere.csv"), "frequency_hz,re,im\n100,1e-3,1e-3\n");
  expect_bad_input(ws, {model("passenger_205_55R16.toml"), "--data", "nowhere.csv"},
                   "nowhere.csv: a plate FRF needs the response and excitation positions");
  expect_bad_input(ws, {model("passenger_205_55R16.toml"), "--data", "nowhere.csv", "--response", "0,0", "--excitation",
                        "0,0.09"},
                   "nowhere.csv: positions: the plate model's receptance from (0, 0.09) m to (0, 0) m is 0 with the "
                   "model file's values: a simply supported belt edge");
  expect_bad_input(ws, {model("passenger_205_55R16.toml"), "--data", data("tyre_frfs.uff"), "--node", "1=0,0.09"},
                   "node 2 has no position: give --node 2=X,Y");
  // Settings.
  expect_bad_input(ws, {sdof, "--data", data("sdof_point_mobility.csv"), "--fit", "mass,tension_x"},
                   "--fit: tension_x: is not a parameter of the sdof model that calibrate can fit; allowed: mass, "
                   "damping, stiffness, contact_stiffness, transducer_mass");
  expect_bad_input(ws, {sdof, "--data", data("sdof_point_mobility.csv"), "--frequency-range", "100"},
                   "--frequency-range: 100: expected LO:HI in Hz");
  expect_bad_input(ws, {sdof, "--data", "missing.csv"}, "missing.csv: file not found");
  expect_bad_input(ws, {"missing.toml", "--data", data("sdof_point_mobility.csv")}, "missing.toml");
  expect_bad_input(ws,
                   {(source_dir / "models" / "cases" / "larsson2000_sdof_sine.toml").string(), "--data",
                    data("sdof_point_mobility.csv")},
                   "larsson2000_sdof_sine.toml: tyre: calibrate takes a model file");
}

// The two-layer tyre (issue 11), as the calibration tutorial runs it: four FRFs on 10 mm cells of
// the tread from one UFF file, nine parameters 15–40 % off in the model file, one start by
// frequency continuation. About 25 s on two shared cores.
TEST(CalibrateCli, TwoLayerFromUffRecoversItsNineParameters) {
  Workspace ws;
  const auto started = std::chrono::steady_clock::now();
  RunResult r = ws.run({"calibrate", model("passenger_205_55R16_two_layer.toml"), "--data", data("two_layer_frfs.uff"),
                        "--node", "1=0,0.09", "--node", "2=0.1,0.09", "--node", "3=0,0.045", "--out", "cal"});
  ASSERT_EQ(r.status, 0) << describe(r);
  std::printf("  two_layer walkthrough: %.1f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  EXPECT_EQ(r.err, "") << "no notes or warnings for clean data off a terminal";
  EXPECT_TRUE(contains(r.out, "conditioning: singular values of the weighted Jacobian")) << r.out;
  const nlohmann::json report = read_json(ws.path("cal") / "report.json");
  EXPECT_EQ(report["model"], "two_layer");
  const std::vector<std::pair<std::string, double>> truth = {
      {"belt_youngs_modulus_x", 3.6e9}, {"belt_youngs_modulus_y", 1.1e9}, {"tension_x", 7.5e4},
      {"tension_y", 1.05e4},           {"foundation_stiffness", 1.8e6},  {"tread_youngs_modulus", 5.0e6},
      {"belt_loss_factor", 0.07},      {"tread_loss_factor", 0.13},      {"foundation_loss_factor", 0.06}};
  ASSERT_EQ(report["parameters"].size(), truth.size()) << "the nine default parameters";
  for (const auto& [name, value] : truth) {
    const double fitted = report["parameters"][name]["value"];
    const double std_error = report["parameters"][name]["std_error"];
    // Nine parameters: within three standard errors (two would miss one a third of the time).
    EXPECT_LT(std::abs(fitted - value), 3.0 * std_error) << name << ": fitted " << fitted << " +- " << std_error;
    EXPECT_LT(std_error / fitted, 0.05) << name;
  }
  EXPECT_TRUE(report["warnings"].empty()) << report["warnings"].dump();
  EXPECT_EQ(report["settings"]["starts"], 1) << "two_layer's default: one start";
  EXPECT_EQ(report["settings"]["stage_tops_hz"].size(), 2U) << "a first stage, then the whole band";
  EXPECT_EQ(report["settings"]["model_valid_up_to_hz"], 400.0) << "the modes are chosen for the data's top";
  EXPECT_EQ(report["conditioning"]["singular_values"].size(), 9U);
  EXPECT_LT(report["conditioning"]["condition_number"].get<double>(), 1e3);
  EXPECT_EQ(report["residual"]["lines"], 308);
  // calibrated.toml is a two_layer model file with the fitted values: calibrating it again over
  // the lowest band, with one parameter free, reads it and stays where it was.
  const std::string calibrated = read_text(ws.path("cal") / "calibrated.toml");
  EXPECT_TRUE(contains(calibrated, "model = \"two_layer\"")) << calibrated.substr(0, 2000);
  r = ws.run({"calibrate", (ws.path("cal") / "calibrated.toml").string(), "--data", data("two_layer_frfs.uff"), "--node",
              "1=0,0.09", "--node", "2=0.1,0.09", "--node", "3=0,0.045", "--fit", "tension_x", "--frequency-range",
              "20:120", "--out", "again"});
  ASSERT_EQ(r.status, 0) << describe(r);
  const nlohmann::json again = read_json(ws.path("again") / "report.json");
  EXPECT_NEAR(again["parameters"]["tension_x"]["value"].get<double>() /
                  report["parameters"]["tension_x"]["value"].get<double>(),
              1.0, 0.01);
  // A cell over the belt's edge, and a parameter the model does not fit.
  expect_bad_input(ws, {model("passenger_205_55R16_two_layer.toml"), "--data", data("two_layer_point_mobility.csv"),
                        "--response", "0,0.002", "--excitation", "0,0.002"},
                   "two_layer_point_mobility.csv: positions: the response position y = 0.002 m: the 10 mm transducer "
                   "cell centred there must lie on the belt, y from 0.005 to 0.175 m");
  expect_bad_input(ws, {model("passenger_205_55R16_two_layer.toml"), "--data", data("two_layer_point_mobility.csv"),
                        "--fit", "tension_x,tread_poisson_ratio"},
                   "--fit: tread_poisson_ratio: is not a parameter of the two_layer model that calibrate can fit");
}

TEST(CalibrateCli, ProgressOnATerminalOnly) {
  Workspace ws;
  // stderr a file, CI unset: no progress.
  const RunResult quiet = ws.run({"calibrate", model("passenger_205_55R16.toml"), "--data",
                                  data("tyre_point_mobility.csv"), data("tyre_transfer_mobility.csv"), "--starts", "2",
                                  "--frequency-range", "20:1500", "--out", "quiet"},
                                 "env -u CI ");
  ASSERT_EQ(quiet.status, 0) << describe(quiet);
  EXPECT_EQ(quiet.err, "");
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "needs script(1) for a terminal";
  if (std::system("script -qec true /dev/null >/dev/null 2>&1") != 0) GTEST_SKIP() << "no pseudo-terminal here";
  std::string inner = "env -u CI ";
  inner += shell_quote(ROLLNOISE_BINARY);
  for (const std::string& arg : {std::string("calibrate"), model("passenger_205_55R16.toml"), std::string("--data"),
                                 data("tyre_point_mobility.csv"), data("tyre_transfer_mobility.csv"),
                                 std::string("--starts"), std::string("2"), std::string("--frequency-range"),
                                 std::string("20:1500"), std::string("--out"), std::string("shown")}) {
    inner += ' ';
    inner += shell_quote(arg);
  }
  std::string command = "cd ";
  command += shell_quote(ws.work().string());
  command += " && script -qec ";
  command += shell_quote(inner);
  command += " /dev/null > ../terminal.txt 2>&1";
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(std::system(command.c_str()), 0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string shown = read_text(ws.work() / ".." / "terminal.txt");
  if (seconds < 1.5) GTEST_SKIP() << "the run took only " << seconds << " s on this machine";
  EXPECT_TRUE(contains(shown, "calibrate passenger_205_55R16.toml:")) << shown;
  EXPECT_TRUE(contains(shown, "done in")) << shown;
}

TEST(CalibrateCli, HelpAndVerbs) {
  Workspace ws;
  RunResult r = ws.run({"calibrate", "--help"});
  EXPECT_EQ(r.status, 0) << describe(r);
  for (const char* option : {"--data", "--fit", "--out", "--data-type", "--response", "--excitation", "--node",
                             "--transducer-mass", "--frequency-range", "--starts", "--seed"})
    EXPECT_TRUE(contains(r.out, option)) << option << "\n" << r.out;
  EXPECT_TRUE(ws.entries().empty()) << "--help writes nothing";
  r = ws.run({"calibrat"});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "verbs are: simulate, analyse, calibrate")) << r.err;
  r = ws.run({"calibrate", model("larsson2000_sdof.toml")});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "--data")) << r.err;
}

}  // namespace
