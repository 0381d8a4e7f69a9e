// End-to-end tests of `rollnoise simulate`: the real program, run as a user runs it, in a fresh
// folder per test. They check the contract of ARCHITECTURE.md and issue 2: exit statuses
// (0 success, 2 bad input), one message per bad input naming the file, the key and what is
// allowed, atomic output (no partial folder, ever), warnings, --help, and quiet progress.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>
#include <thread>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "audio/wav_file.hpp"
#include "cli/cli_workspace.hpp"
#include "core/csv.hpp"
#include "core/hdf5_reader.hpp"
#include "greens/fitted_modal_tyre.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/modal_receptance_table.hpp"
#include "greens/modal_table_hdf5.hpp"
#include "greens/passenger_plate.hpp"

namespace {
namespace fs = std::filesystem;

using namespace cli_test;


// ---------------------------------------------------------------------------------------------
// Case files: the project's own cases, shortened, with keys set or removed.

struct Edit {
  std::string section;
  std::string key;
  std::optional<std::string> value;  // the TOML text of the value; nullopt removes the key
};

// Sets (or removes) `key` in `[section]`: replaces its line, else adds it after the header,
// else appends the section.
std::string edit_case(const std::string& text, const Edit& edit) {
  std::vector<std::string> lines;
  {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
  }
  std::string section;
  std::optional<std::size_t> header;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    if (line[first] == '[') {
      section = line.substr(first + 1, line.find(']') - first - 1);
      if (section == edit.section) header = i;
      continue;
    }
    if (section != edit.section) continue;
    const std::string rest = line.substr(first);
    if (starts_with(rest, edit.key) &&
        (rest.size() == edit.key.size() || rest[edit.key.size()] == ' ' || rest[edit.key.size()] == '=')) {
      if (edit.value) {
        lines[i] = edit.key + " = " + *edit.value;
      } else {
        lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
      }
      header.reset();
      section = "\x01done";
      break;
    }
  }
  if (section != "\x01done" && edit.value) {
    const std::string line = edit.key + " = " + *edit.value;
    if (header) {
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(*header + 1), line);
    } else {
      lines.push_back("");
      lines.push_back("[" + edit.section + "]");
      lines.push_back(line);
    }
  }
  std::string out;
  for (const auto& line : lines) out += line + "\n";
  return out;
}

std::string edit_case(std::string text, const std::vector<Edit>& edits) {
  for (const auto& edit : edits) text = edit_case(text, edit);
  return text;
}

// One of models/cases/*.toml, shortened to 0.05 s (501 samples).
std::string project_case(const std::string& name = "larsson2000_sdof_sine.toml") {
  const fs::path path = fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "cases" / name;
  const std::string text = read_text(path);
  EXPECT_FALSE(text.empty()) << "cannot read " << path;
  return edit_case(text, {{"rolling", "duration", "0.05"}});
}

// The rough case's library surface by its absolute path: the case is copied out of the project.
Edit rough_surface() {
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on chains of string + string.
  std::string value = "\"";
  value += (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "surfaces" / "dac11.toml").string();
  value += '"';
  return {"road", "surface", value};
}

// [road] type = "file" reading `csv`: the sine road's keys go.
std::vector<Edit> file_road(const std::string& csv) {
  return {{"road", "type", "\"file\""},
          {"road", "amplitude", std::nullopt},
          {"road", "wavelength", std::nullopt},
          {"road", "file", "\"" + csv + "\""}};
}



// ---------------------------------------------------------------------------------------------
// Success.

TEST(SimulateCli, SdofSineWritesContactCsvSummaryAndPlotScript) {
  Workspace ws;
  ws.write("sdof.toml", project_case());
  const RunResult r = ws.run({"simulate", "sdof.toml", "--out", "result"});
  ASSERT_EQ(r.status, 0) << describe(r);
  if (gnuplot_installed()) {
    EXPECT_EQ(r.err, "") << "no warnings and no progress expected";
  } else {
    EXPECT_TRUE(contains(r.err, "gnuplot")) << "only the missing-gnuplot warning expected:\n" << r.err;
  }

  const fs::path out = ws.path("result");
  ASSERT_TRUE(fs::is_directory(out));
  EXPECT_TRUE(fs::is_regular_file(out / "contact.gp"));
  EXPECT_EQ(first_line(out / "contact.csv"), "time,road_1,displacement_1,force_1");
  // 0.05 s at 1e-4 s: 500 steps, 501 samples, plus the header.
  EXPECT_EQ(count_lines(read_text(out / "contact.csv")), 502u);

  const nlohmann::json summary = read_json(out / "summary.json");
  ASSERT_TRUE(summary.contains("points"));
  ASSERT_TRUE(summary["points"].is_array());
  ASSERT_EQ(summary["points"].size(), 1u);
  const nlohmann::json& point = summary["points"][0];
  for (const char* key : {"max_force_N", "mean_force_N", "contact_fraction", "min_gap_m"}) {
    ASSERT_TRUE(point.contains(key)) << key;
    EXPECT_TRUE(point[key].is_number()) << key << " = " << point[key];
  }
  EXPECT_GT(point["max_force_N"].get<double>(), 0.0);
  EXPECT_GE(point["contact_fraction"].get<double>(), 0.0);
  EXPECT_LE(point["contact_fraction"].get<double>(), 1.0);
  // Static load 4 N: the sine road lifts the peak above it.
  EXPECT_GT(point["max_force_N"].get<double>(), 4.0);
  EXPECT_TRUE(summary.contains("lcp_iterations"));
  ASSERT_TRUE(summary.contains("wall_time_s"));
  EXPECT_GE(summary["wall_time_s"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(summary["settings"]["static_load_N"].get<double>(), 4.0);
  EXPECT_EQ(summary["settings"]["steps"].get<long>(), 500);
  EXPECT_EQ(summary["model"], "sdof");
  EXPECT_EQ(summary["road"], "sine");

  EXPECT_TRUE(ws.leftovers().empty()) << "hidden folder left: " << ws.leftovers().front();
  std::set<std::string> entries = ws.entries();
  entries.erase("result/contact.png");  // drawn only when gnuplot is installed
  EXPECT_EQ(entries, (std::set<std::string>{"sdof.toml", "result/", "result/contact.csv",
                                            "result/summary.json", "result/contact.gp"}))
      << "only the case and the output folder";
}

TEST(SimulateCli, GeneratedRoadReachesTheLastStepOfARunThatRoundsUp) {
  // The run samples t = n·dt up to n = round(duration/dt), up to half a step past the duration.
  // A generated road made exactly as long as the run needs (length shorter than the run) must
  // reach that last sample: 100 km/h once failed 1.1 mm short of the end of an aggregate map.
  // dt = (2π·0.316 m / 512) / V; the duration is 20.51 steps, so the run takes 21.
  Workspace ws;
  const std::string model = (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "tyres" / "passenger_205_55R16.toml").string();
  const double speed = 27.7778;
  const double dt = 2.0 * M_PI * 0.316 / 512.0 / speed;
  ws.write("tyre.toml", edit_case(project_case("plate_rough_80kmh.toml"),
                                  {{"tyre", "file", "\"" + model + "\""},
                                   {"road", "surface", std::nullopt},
                                   {"road", "type", "\"aggregate\""},
                                   {"road", "max_chip_size", "0.011"},
                                   {"road", "length", "0.01"},
                                   {"rolling", "speed", std::to_string(speed)},
                                   {"rolling", "duration", std::to_string(20.51 * dt)},
                                   {"rolling", "band_top", "0"},  // one step per cell
                                   {"radiation", "enabled", "false"}}));
  const RunResult r = ws.run({"simulate", "tyre.toml", "--out", "tyre"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_EQ(read_json(ws.path("tyre") / "summary.json")["settings"]["steps"].get<long>(), 21);
}

TEST(SimulateCli, PlateTyreWritesTotalsFieldsSummaryAndPlots) {
  Workspace ws;
  const std::string model = (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "tyres" / "passenger_205_55R16.toml").string();
  ws.write("tyre.toml", edit_case(project_case("plate_rough_80kmh.toml"),
                                  {{"tyre", "file", "\"" + model + "\""}, rough_surface(), {"rolling", "duration", "0.01"},
                                   {"radiation", "enabled", "false"}}));
  const RunResult r = ws.run({"simulate", "tyre.toml", "--out", "tyre"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_FALSE(fs::exists(ws.path("tyre") / "spectrum.csv")) << "[radiation] enabled = false";
  EXPECT_EQ(first_line(ws.path("tyre") / "contact.csv"), "time,total_force,contact_area,contact_length");
  const nlohmann::json summary = read_json(ws.path("tyre") / "summary.json");
  for (const char* key : {"mean_total_force_N", "max_total_force_N", "mean_contact_area_m2", "patch_length_m",
                          "patch_width_m", "rolling_resistance_N", "wall_time_s"}) {
    EXPECT_TRUE(summary.contains(key) && summary[key].is_number()) << key;
  }
  EXPECT_EQ(summary["history_engine"], "modal");  // auto picks the modal engine for the plate
  // The library files, as named: the case's, and --set's over it.
  EXPECT_EQ(summary["tyre_file"], model);
  EXPECT_EQ(summary["surface_file"], (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "surfaces" / "dac11.toml").string());
  const std::string other = (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "tyres" / "passenger_205_55R16_patterned.toml").string();
  const RunResult set = ws.run({"simulate", "tyre.toml", "--out", "set", "--set", "tyre.file=" + other});
  ASSERT_EQ(set.status, 0) << describe(set);
  EXPECT_EQ(read_json(ws.path("set") / "summary.json")["tyre_file"], other);
  EXPECT_GT(fs::file_size(ws.path("tyre") / "contact.h5"), 100000u);
  // The HDF5 signature: the file is HDF5, not a stub.
  EXPECT_EQ(read_text(ws.path("tyre") / "contact.h5").substr(0, 8), std::string("\x89HDF\r\n\x1a\n"));
  if (gnuplot_installed()) {
    for (const char* plot : {"pressure_map", "total_force", "greens_circumference"}) {
      EXPECT_TRUE(fs::exists(ws.path("tyre") / (std::string(plot) + ".png"))) << plot;
      EXPECT_TRUE(fs::exists(ws.path("tyre") / (std::string(plot) + ".gp"))) << plot;
    }
  }
  EXPECT_TRUE(ws.leftovers().empty());
}

// [output] fields (issue 13): what contact.h5 holds. Checked against the run's own other outputs
// and against each other: the default file's force sums to contact.csv's total force at every
// step; the road strip holds exactly what "all" writes over the window (road[n][j][i] =
// strip[j][i·p + n]); the default belt velocity is the block mean of the full field "all" writes.
TEST(SimulateCli, ContactFieldsChooseWhatContactH5Holds) {
  Workspace ws;
  const std::string model = (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "tyres" / "passenger_205_55R16.toml").string();
  const auto write_case = [&](const std::string& name, std::optional<std::string> fields) {
    ws.write(name, edit_case(project_case("plate_rough_80kmh.toml"),
                             {{"tyre", "file", "\"" + model + "\""}, rough_surface(), {"rolling", "duration", "0.004"},
                              {"radiation", "enabled", "false"}, {"output", "plots", "false"}, {"output", "fields", fields}}));
  };
  write_case("default.toml", std::nullopt);
  write_case("all.toml", "\"all\"");
  write_case("none.toml", "\"none\"");
  write_case("bogus.toml", "\"everything\"");
  for (const char* name : {"default", "all", "none"}) {
    const RunResult r = ws.run({"simulate", std::string(name) + ".toml", "--out", name});
    ASSERT_EQ(r.status, 0) << describe(r);
  }
  const RunResult bad = ws.run({"simulate", "bogus.toml", "--out", "bogus"});
  EXPECT_EQ(bad.status, 2) << describe(bad);
  EXPECT_NE(bad.err.find("[output] fields"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("\"none\""), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(ws.path("none") / "contact.h5"));
  EXPECT_EQ(read_json(ws.path("none") / "summary.json")["contact_h5_fields"], "none");

  const rollnoise::Hdf5Reader standard(ws.path("default") / "contact.h5"), all(ws.path("all") / "contact.h5");
  const nlohmann::json summary = read_json(ws.path("default") / "summary.json");
  const auto steps = static_cast<std::size_t>(summary["settings"]["steps"].get<long>()) + 1;
  const auto lateral = static_cast<std::size_t>(summary["grid"]["points_lateral"].get<int>());
  const auto window = static_cast<std::size_t>(summary["grid"]["contact_window_points"].get<int>());
  const auto around = static_cast<std::size_t>(summary["grid"]["points_circumferential"].get<int>());
  const auto p = static_cast<std::size_t>(summary["settings"]["substeps"].get<int>());
  EXPECT_FALSE(standard.exists("/contact/displacement"));
  EXPECT_FALSE(standard.exists("/contact/road"));
  EXPECT_TRUE(all.exists("/contact/displacement"));
  EXPECT_TRUE(all.exists("/surface/displacement"));

  // Force against contact.csv's totals (float32 against double: 1e-5 relative).
  const rollnoise::Hdf5Array force = standard.read_numbers("/contact/force", 3, 1u << 26);
  ASSERT_EQ(force.dims, (std::vector<std::size_t>{steps, lateral, window}));
  std::ifstream csv(ws.path("default") / "contact.csv");
  std::string line;
  std::getline(csv, line);
  for (std::size_t n = 0; n < steps; ++n) {
    ASSERT_TRUE(std::getline(csv, line));
    const double total = std::stod(line.substr(line.find(',') + 1));
    double sum = 0.0;
    for (std::size_t k = 0; k < lateral * window; ++k) sum += force.values[n * lateral * window + k];
    EXPECT_NEAR(sum, total, 1e-5 * total) << "step " << n;
  }
  // The road strip against the road over the window.
  const rollnoise::Hdf5Array strip = standard.read_numbers("/contact/road_strip", 2, 1u << 26);
  const std::size_t length = (window - 1) * p + steps;
  ASSERT_EQ(strip.dims, (std::vector<std::size_t>{lateral, length}));
  const rollnoise::Hdf5Array road = all.read_numbers("/contact/road", 3, 1u << 26);
  ASSERT_EQ(road.dims, (std::vector<std::size_t>{steps, lateral, window}));
  for (std::size_t n = 0; n < steps; ++n)
    for (std::size_t j = 0; j < lateral; ++j)
      for (std::size_t i = 0; i < window; ++i)
        ASSERT_EQ(road.values[(n * lateral + j) * window + i], strip.values[j * length + i * p + n]) << n << ' ' << j << ' ' << i;
  // The belt velocity: block means of 8 cells around over the whole width.
  const rollnoise::Hdf5Array blocks = standard.read_numbers("/surface/velocity", 3, 1u << 26);
  const rollnoise::Hdf5Array full = all.read_numbers("/surface/velocity", 3, 1u << 28);
  const std::size_t columns = (around + 7) / 8;
  ASSERT_EQ(blocks.dims, (std::vector<std::size_t>{steps, 1, columns}));
  ASSERT_EQ(full.dims, (std::vector<std::size_t>{steps, lateral, around}));
  double largest = 0.0;
  for (double v : full.values) largest = std::max(largest, std::abs(v));
  ASSERT_GT(largest, 0.0);
  for (std::size_t n = 0; n < steps; ++n)
    for (std::size_t b = 0; b < columns; ++b) {
      double sum = 0.0;
      std::size_t cells = 0;
      for (std::size_t g = 8 * b; g < std::min(around, 8 * b + 8); ++g)
        for (std::size_t j = 0; j < lateral; ++j, ++cells) sum += full.values[(n * lateral + j) * around + g];
      EXPECT_NEAR(blocks.values[n * columns + b], sum / static_cast<double>(cells), 1e-6 * largest) << n << ' ' << b;
    }
}

// The sound of a tyre run: spectra, levels, sound power and calibrated WAV files, on a coarse
// radiation mesh to keep the test short. The WAV files analysed by `rollnoise analyse` give
// back the levels `simulate` reported: the two verbs process sound the same way, and the WAV
// keeps the level (float samples, the full scale in the comment).
TEST(SimulateCli, PlateTyreWritesSoundThatAnalyseReadsBack) {
  Workspace ws;
  const std::string model = (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "tyres" / "passenger_205_55R16.toml").string();
  ws.write("tyre.toml", edit_case(project_case("plate_rough_80kmh.toml"),
                                  {{"tyre", "file", "\"" + model + "\""}, rough_surface(),
                                   {"rolling", "duration", "0.02"},
                                   {"radiation", "mesh_around", "32"},
                                   {"radiation", "mesh_across", "4"},
                                   {"radiation", "sidewall_rings", "4"},
                                   {"radiation", "max_frequency", "1500"},
                                   {"radiation", "anchor_spacing", "250"},
                                   {"radiation", "contact_refinement", "3"}}));
  const RunResult r = ws.run({"simulate", "tyre.toml", "--out", "tyre"});
  ASSERT_EQ(r.status, 0) << describe(r);
  const fs::path out = ws.path("tyre");
  EXPECT_EQ(first_line(out / "spectrum.csv"), "receiver,band_hz,Lp_dB,LpA_dB");
  EXPECT_EQ(first_line(out / "sound_power.csv"), "band_hz,Lw_dB,LwA_dB");
  const nlohmann::json summary = read_json(out / "summary.json");
  ASSERT_TRUE(summary.contains("levels")) << summary.dump(1);
  for (const char* receiver : {"cpx_front", "cpx_rear", "spb", "spb_passby"}) {
    ASSERT_TRUE(summary["levels"].contains(receiver)) << receiver;
    for (const char* key : {"Leq_dB", "LAeq_dB", "LAFmax_dB"})
      EXPECT_TRUE(summary["levels"][receiver][key].is_number()) << receiver << " " << key;
    EXPECT_TRUE(fs::exists(out / (std::string(receiver) + ".wav"))) << receiver;
  }
  // A rolling tyre is loud beside it and quiet 7.5 m away.
  EXPECT_GT(summary["levels"]["cpx_front"]["LAeq_dB"].get<double>(), summary["levels"]["spb"]["LAeq_dB"].get<double>() + 15);
  EXPECT_GT(summary["full_scale_pa"].get<double>(), 0.0);
  EXPECT_GE(summary["wav_duration_s"].get<double>(), 5.0);
  EXPECT_TRUE(summary["sound_power"]["LwA_dB"].is_number());
  // The radiating body is the loaded tyre (issue 10 §2): flat over the run's mean contact patch
  // (a run of up to 4096 steps is measured whole), to the mesh's cell size (the patch's edges are
  // cell edges: equal to rounding).
  EXPECT_EQ(summary["radiation"]["geometry"], "deformed");
  EXPECT_NEAR(summary["radiation"]["flat_length_m"].get<double>(), summary["patch_length_m"].get<double>(), 1e-9);
  EXPECT_NEAR(summary["radiation"]["flat_width_m"].get<double>(), summary["patch_width_m"].get<double>(), 1e-9);
  EXPECT_EQ(summary["radiation"]["patch_length_m"], summary["patch_length_m"]);
  EXPECT_NEAR(summary["radiation"]["axle_height_m"].get<double>(), 0.316 + 0.002 - summary["indentation_m"].get<double>(), 1e-9);

  // The energy budget (issue 10 §1): one row per third-octave band from 100 Hz to the top of the
  // radiated band (1.25 kHz here), the stages and their estimates, a level per receiver.
  EXPECT_EQ(first_line(out / "budget.csv"),
            "band_hz,wavelength_m,texture_centre_dB_re_1um,texture_patch_dB_re_1um,force_dB_re_1N,"
            "force_est_point_dB_re_1N,force_est_patch_dB_re_1N,force_est_rigid_patch_dB_re_1N,v2_tread_dB_re_1nm_s,v2_contact_dB_re_1nm_s,"
            "v2_tread_est_dB_re_1nm_s,v2_contact_est_dB_re_1nm_s,v2_radiating_dB_re_1nm_s,Lw_dB_re_1pW,sigma,"
            "sigma_piston,sigma_cylinder,Lp_cpx_front_dB_re_20uPa,Lp_cpx_front_hemi_est_dB_re_20uPa,"
            "Lp_cpx_rear_dB_re_20uPa,Lp_cpx_rear_hemi_est_dB_re_20uPa,Lp_spb_dB_re_20uPa,"
            "Lp_spb_hemi_est_dB_re_20uPa,horn_gain_dB");
  {
    std::ifstream in(out / "budget.csv");
    std::string line;
    std::vector<std::string> bands;
    std::getline(in, line);
    while (std::getline(in, line)) bands.push_back(line.substr(0, line.find(',')));
    ASSERT_FALSE(bands.empty());
    EXPECT_EQ(bands.front(), "100");
    EXPECT_EQ(bands.back(), "1250");
    EXPECT_EQ(bands.size(), 12u);
  }
  EXPECT_EQ(summary["energy_budget"]["file"], "budget.csv");
  if (gnuplot_installed()) {
    EXPECT_TRUE(fs::exists(out / "budget.png"));
  }
  EXPECT_TRUE(fs::exists(out / "budget.gp"));

  const RunResult a = ws.run({"analyse", (out / "cpx_front.wav").string(), "--out", "heard"});
  ASSERT_EQ(a.status, 0) << describe(a);
  const nlohmann::json heard = read_json(ws.path("heard") / "summary.json");
  EXPECT_EQ(heard["full_scale_pa"].get<double>(), summary["full_scale_pa"].get<double>()) << "from the WAV's comment";
  for (const char* key : {"Leq_dB", "LAeq_dB", "LAFmax_dB"}) {
    EXPECT_NEAR(heard["levels"]["ch1"][key].get<double>(), summary["levels"]["cpx_front"][key].get<double>(), 0.01) << key;
  }
  EXPECT_TRUE(ws.leftovers().empty());
}

// Bad radiation and sound settings: one message naming the key and what is allowed, exit 2,
// nothing written, before any contact is solved.
TEST(SimulateCli, PlateTyreBadSoundSettingsAreNamed) {
  const std::string model = (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "tyres" / "passenger_205_55R16.toml").string();
  struct Bad {
    Edit edit;
    std::vector<std::string> expect;
  };
  const std::vector<Bad> cases{
      {{"radiation", "max_frequency", "-1"}, {"[radiation] max_frequency"}},
      {{"radiation", "max_frequency", "nan"}, {"[radiation] max_frequency", "finite"}},
      {{"radiation", "anchor_spacing", "0"}, {"[radiation] anchor_spacing"}},
      {{"radiation", "mesh_around", "3"}, {"[radiation] mesh_around"}},
      {{"radiation", "contact_refinement", "0.5"}, {"[radiation] contact_refinement"}},
      {{"radiation", "geometry", "\"round\""}, {"[radiation] geometry", "deformed", "undeformed"}},
      {{"radiation", "colour", "\"red\""}, {"[radiation] colour", "unknown key"}},
      {{"radiation", "receivers", "[{name = \"in\", x = 0.0, y = 0.0, z = 0.3}]"}, {"[radiation] receivers", "inside the tyre"}},
      {{"radiation", "receivers", "[\"cpx_middle\"]"}, {"[radiation] receivers", "cpx_middle", "cpx_front"}},
      {{"output", "audio_rate", "22050"}, {"[output] audio_rate", "48000 or 44100"}},
      {{"radiation", "receivers", "[{name = \"spb_passby\", x = 1.0, y = 2.0, z = 1.0}]"},
       {"[radiation] receivers", "spb_passby", "pass-by"}},
      {{"output", "wav_duration", "2.0"}, {"[output] wav_duration"}},
      {{"output", "wav", "\"yes\""}, {"[output] wav"}},
  };
  for (const Bad& bad : cases) {
    Workspace ws;
    ws.write("tyre.toml", edit_case(project_case("plate_rough_80kmh.toml"), {{"tyre", "file", "\"" + model + "\""}, rough_surface(), bad.edit}));
    const RunResult r = ws.run({"simulate", "tyre.toml", "--out", "tyre"});
    EXPECT_EQ(r.status, 2) << bad.edit.key << ": " << describe(r);
    for (const std::string& text : bad.expect) EXPECT_TRUE(contains(r.err, text)) << bad.edit.key << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_FALSE(fs::exists(ws.path("tyre")));
  }
  // Point models have no surface to radiate from.
  Workspace ws;
  ws.write("sdof.toml", edit_case(project_case(), {{"radiation", "receivers", "[\"spb\"]"}}));
  const RunResult r = ws.run({"simulate", "sdof.toml", "--out", "out"});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "[radiation]") || contains(r.err, "radiation")) << r.err;
  EXPECT_TRUE(contains(r.err, "plate")) << r.err;
}

// The last band of spectrum.csv (cpx_front) and of budget.csv.
std::pair<std::string, std::string> last_bands(const fs::path& out) {
  std::string last_front, last_budget, line;
  std::ifstream spectrum(out / "spectrum.csv");
  while (std::getline(spectrum, line))
    if (line.rfind("cpx_front,", 0) == 0) last_front = line.substr(10, line.find(',', 10) - 10);
  std::ifstream budget(out / "budget.csv");
  std::getline(budget, line);
  while (std::getline(budget, line)) last_budget = line.substr(0, line.find(','));
  return {last_front, last_budget};
}

// The case's radiation, made coarse and quick (these tests check bands and settings, not levels).
std::vector<Edit> quick_radiation() {
  return {{"radiation", "mesh_around", "32"},       {"radiation", "mesh_across", "2"},
          {"radiation", "sidewall_rings", "4"},     {"radiation", "anchor_spacing", "500"},
          {"radiation", "contact_refinement", "3"}, {"output", "plots", "false"}};
}

// Issue 10 §3: by default (band_top = 5000) the grid is made fine enough that one step per cell
// carries the third octaves up to 5 kHz: at 130 km/h, 630 cells (rolling_settings.hpp: the least
// count, 626, rounded up to a fast transform length), no sub-steps, a Nyquist frequency of 5.73 kHz, the radiated band to the 5 kHz band's upper edge
// (5623 Hz), and spectrum.csv and budget.csv to 5 kHz.
TEST(SimulateCli, PlateTyreGridCarriesTheBandTo5kHzByDefault) {
  Workspace ws;
  const std::string model = (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "tyres" / "passenger_205_55R16.toml").string();
  std::vector<Edit> edits = {{"tyre", "file", "\"" + model + "\""}, rough_surface(),
                                 {"rolling", "speed", "36.111"},
                                 {"rolling", "band_top", std::nullopt},
                                 {"rolling", "duration", "0.01"}};
  for (const auto& e : quick_radiation()) edits.push_back(e);
  ws.write("tyre.toml", edit_case(project_case("plate_rough_80kmh.toml"), edits));
  const RunResult r = ws.run({"simulate", "tyre.toml", "--out", "tyre"});
  ASSERT_EQ(r.status, 0) << describe(r);
  const fs::path out = ws.path("tyre");
  const nlohmann::json summary = read_json(out / "summary.json");
  EXPECT_EQ(summary["grid"]["points_circumferential"].get<int>(), 630) << summary["grid"].dump();
  EXPECT_EQ(summary["settings"]["substeps"].get<int>(), 1) << summary["settings"].dump();
  EXPECT_NEAR(summary["settings"]["band_top_hz"].get<double>(), 5000.0, 1e-9);
  // v/(2·dx) = 36.111·630/(2·2π·0.316) = 5729.0 Hz.
  EXPECT_NEAR(summary["settings"]["contact_nyquist_hz"].get<double>(), 5729.0, 1.0);
  EXPECT_NEAR(summary["radiation"]["band_hz"][1].get<double>(), 5623.4, 0.1);
  EXPECT_EQ(last_bands(out), std::make_pair(std::string("5000"), std::string("5000")));
}

// A given grid too coarse for the band takes sub-steps instead (with the cell-passing artefact
// docs/physics/contact.md describes). At 30 km/h on 512 cells that takes p = 6 sub-steps per cell (Nyquist
// 6.45 kHz), the radiated band ends at the 5 kHz band's upper edge (5623 Hz), and spectrum.csv and
// budget.csv end at 5 kHz.
TEST(SimulateCli, PlateTyreOnAGivenCoarseGridCarriesTheBandTo5kHzBySubSteps) {
  Workspace ws;
  const std::string model = (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "tyres" / "passenger_205_55R16.toml").string();
  const std::string text = project_case("plate_rough_80kmh.toml");
  ASSERT_EQ(text.find("max_frequency = "), std::string::npos) << "the case leaves max_frequency to its default";
  std::vector<Edit> edits = {{"tyre", "file", "\"" + model + "\""}, rough_surface(),
                                 {"rolling", "speed", "8.3333"},
                                 {"rolling", "points_circumferential", "512"},
                                 {"rolling", "band_top", "5000"},
                                 {"rolling", "duration", "0.02"}};
  for (const auto& e : quick_radiation()) edits.push_back(e);
  ws.write("tyre.toml", edit_case(text, edits));
  const RunResult r = ws.run({"simulate", "tyre.toml", "--out", "tyre"});
  ASSERT_EQ(r.status, 0) << describe(r);
  const fs::path out = ws.path("tyre");
  const nlohmann::json summary = read_json(out / "summary.json");
  EXPECT_EQ(summary["settings"]["substeps"].get<int>(), 6) << summary["settings"].dump();
  EXPECT_EQ(summary["settings"]["road_sampling"].get<std::string>(), "lowpass");
  EXPECT_NEAR(summary["settings"]["contact_nyquist_hz"].get<double>(), 6446.8, 1.0);
  EXPECT_NEAR(summary["radiation"]["band_hz"][1].get<double>(), 5623.4, 0.1);
  EXPECT_EQ(last_bands(out), std::make_pair(std::string("5000"), std::string("5000")));
}

TEST(SimulateCli, PlateTyreRejectsAGivenTimeStep) {
  Workspace ws;
  const std::string model = (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "tyres" / "passenger_205_55R16.toml").string();
  ws.write("tyre.toml", edit_case(project_case("plate_smooth_80kmh.toml"),
                                  {{"tyre", "file", "\"" + model + "\""}, {"rolling", "time_step", "1e-4"}}));
  const RunResult r = ws.run({"simulate", "tyre.toml", "--out", "tyre"});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "[rolling] time_step")) << r.err;
  EXPECT_TRUE(contains(r.err, "derived from the grid")) << r.err;
  EXPECT_FALSE(fs::exists(ws.path("tyre")));
}

TEST(SimulateCli, CoupledSdofWritesColumnsForBothPoints) {
  Workspace ws;
  ws.write("coupled.toml",
           edit_case(project_case("larsson2000_coupled_sine.toml"), {{"output", "plots", "false"}}));
  const RunResult r = ws.run({"simulate", "coupled.toml", "--out", "coupled"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_EQ(first_line(ws.path("coupled") / "contact.csv"),
            "time,road_1,displacement_1,force_1,road_2,displacement_2,force_2");
  const nlohmann::json summary = read_json(ws.path("coupled") / "summary.json");
  ASSERT_EQ(summary["points"].size(), 2u);
  for (const auto& point : summary["points"]) {
    for (const char* key : {"max_force_N", "mean_force_N", "contact_fraction", "min_gap_m"}) {
      EXPECT_TRUE(point.contains(key) && point[key].is_number()) << key;
    }
  }
  EXPECT_EQ(summary["model"], "coupled_sdof");
  EXPECT_FALSE(fs::exists(ws.path("coupled") / "contact.gp")) << "plots = false";
  EXPECT_TRUE(ws.leftovers().empty());
}

TEST(SimulateCli, SetOverridesStaticLoad) {
  Workspace ws;
  ws.write("sdof.toml", edit_case(project_case(), {{"output", "plots", "false"}}));
  const RunResult r = ws.run({"simulate", "sdof.toml", "--out", "out", "--set", "rolling.static_load=3"});
  ASSERT_EQ(r.status, 0) << describe(r);
  const nlohmann::json summary = read_json(ws.path("out") / "summary.json");
  EXPECT_DOUBLE_EQ(summary["settings"]["static_load_N"].get<double>(), 3.0);
  EXPECT_NEAR(summary["points"][0]["static_force_N"].get<double>(), 3.0, 1e-9);
}

TEST(SimulateCli, SameCaseAndSeedGiveTheSameNumbers) {
  // Determinism: two runs of the random-road case write byte-identical contact.csv files.
  Workspace ws;
  ws.write("random.toml", edit_case(project_case("larsson2000_coupled_random.toml"), {{"output", "plots", "false"}}));
  ASSERT_EQ(ws.run({"simulate", "random.toml", "--out", "a"}).status, 0);
  ASSERT_EQ(ws.run({"simulate", "random.toml", "--out", "b"}).status, 0);
  const std::string a = read_text(ws.path("a") / "contact.csv");
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, read_text(ws.path("b") / "contact.csv"));
  // Another seed gives another road.
  ASSERT_EQ(ws.run({"simulate", "random.toml", "--out", "c", "--set", "road.seed=7"}).status, 0);
  EXPECT_NE(a, read_text(ws.path("c") / "contact.csv"));
}

TEST(SimulateCli, RunningTwiceReplacesTheEarlierOutput) {
  Workspace ws;
  ws.write("sdof.toml", edit_case(project_case(), {{"output", "plots", "false"}}));
  RunResult r = ws.run({"simulate", "sdof.toml", "--out", "out"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_DOUBLE_EQ(read_json(ws.path("out") / "summary.json")["settings"]["static_load_N"].get<double>(), 4.0);
  ws.write("out/stale.txt", "from an earlier run\n");

  r = ws.run({"simulate", "sdof.toml", "--out", "out", "--set", "rolling.static_load=3"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_DOUBLE_EQ(read_json(ws.path("out") / "summary.json")["settings"]["static_load_N"].get<double>(), 3.0);
  EXPECT_FALSE(fs::exists(ws.path("out") / "stale.txt")) << "the earlier output is replaced, not merged";
  EXPECT_TRUE(ws.leftovers().empty()) << "hidden folder left: " << ws.leftovers().front();
  EXPECT_EQ(ws.entries(), (std::set<std::string>{"sdof.toml", "out/", "out/contact.csv", "out/summary.json"}));
}

TEST(SimulateCli, OutputDirectoryFromTheCaseFile) {
  Workspace ws;
  ws.write("sdof.toml", edit_case(project_case(), {{"output", "plots", "false"},
                                                   {"output", "directory", "\"from_case\""}}));
  const RunResult r = ws.run({"simulate", "sdof.toml"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_TRUE(fs::is_regular_file(ws.path("from_case") / "summary.json"));
}

TEST(SimulateCli, FileRoadRuns) {
  Workspace ws;
  std::string csv = "# a ramp, x and z in m\nx,z\n";
  for (int i = 0; i <= 100; ++i) csv += std::to_string(i * 0.001) + "," + std::to_string(i * 1e-5) + "\n";
  ws.write("ramp.csv", csv);
  ws.write("ramp.toml", edit_case(project_case(), file_road("ramp.csv")));
  const RunResult r = ws.run({"simulate", "ramp.toml", "--out", "out"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_EQ(read_json(ws.path("out") / "summary.json")["road"], "file");
}

TEST(SimulateCli, CoarseTimeStepWarnsAndRuns) {
  Workspace ws;
  ws.write("coarse.toml",
           edit_case(project_case(), {{"rolling", "time_step", "5e-3"}, {"output", "plots", "false"}}));
  const RunResult r = ws.run({"simulate", "coarse.toml", "--out", "out"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_TRUE(starts_with(r.err, "rollnoise: warning: ")) << r.err;
  EXPECT_TRUE(contains(r.err, "time_step")) << r.err;
  EXPECT_TRUE(contains(r.err, "coarse.toml")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  const nlohmann::json summary = read_json(ws.path("out") / "summary.json");
  ASSERT_TRUE(summary["warnings"].is_array());
  EXPECT_FALSE(summary["warnings"].empty()) << "summary.json keeps the warning";
}

TEST(SimulateCli, ProgressIsQuietWhenStderrIsNotATerminal) {
  // Long enough (some 80 000 steps) that a terminal would show progress.
  Workspace ws;
  ws.write("long.toml",
           edit_case(project_case(), {{"rolling", "duration", "8.0"}, {"output", "plots", "false"}}));
  const RunResult r = ws.run({"simulate", "long.toml", "--out", "out"}, "env -u CI ");
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_EQ(r.err, "") << "progress must stay off when stderr is a file";
}

TEST(SimulateCli, ProgressIsShownOnATerminalForLongRunsOnly) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "needs script(1) for a terminal";
  // Containers and chroots may have no pseudo-terminals at all.
  if (std::system("script -qec true /dev/null >/dev/null 2>&1") != 0) GTEST_SKIP() << "no pseudo-terminal here";
  Workspace ws;
  ws.write("case.toml", edit_case(project_case(), {{"output", "plots", "false"}}));
  ws.write("long.toml",
           edit_case(project_case(), {{"rolling", "duration", "8.0"}, {"output", "plots", "false"}}));
  // script(1) runs the program on a pseudo-terminal and copies what it shows to stdout.
  const auto on_terminal = [&](const std::string& case_name, const std::string& out) {
    const std::string inner = "env -u CI " + shell_quote(ROLLNOISE_BINARY) + " simulate " +
                              shell_quote(case_name) + " --out " + shell_quote(out);
    const std::string command = "cd " + shell_quote(ws.work().string()) + " && script -qec " +
                                shell_quote(inner) + " /dev/null > ../terminal.txt 2>&1";
    const auto start = std::chrono::steady_clock::now();
    const int raw = std::system(command.c_str());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_TRUE(raw != -1 && WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << read_text(ws.work() / ".." / "terminal.txt");
    return std::make_pair(read_text(ws.work() / ".." / "terminal.txt"), seconds);
  };
  const auto [short_text, short_seconds] = on_terminal("case.toml", "short");
  if (short_seconds < 0.8) {
    EXPECT_FALSE(contains(short_text, "elapsed")) << "a short run shows no progress:\n" << short_text;
    EXPECT_FALSE(contains(short_text, "done in")) << short_text;
  }
  const auto [long_text, long_seconds] = on_terminal("long.toml", "long");
  if (long_seconds < 1.5) GTEST_SKIP() << "the long run took only " << long_seconds << " s on this machine";
  EXPECT_TRUE(contains(long_text, "simulate long.toml")) << long_text;
  EXPECT_TRUE(contains(long_text, "done in")) << long_text;
}

// ---------------------------------------------------------------------------------------------
// Help and verbs.

TEST(SimulateCli, HelpOnTheProgramAndOnSimulate) {
  Workspace ws;
  RunResult r = ws.run({"--help"});
  EXPECT_EQ(r.status, 0) << describe(r);
  EXPECT_TRUE(contains(r.out, "simulate")) << r.out;

  r = ws.run({"simulate", "--help"});
  EXPECT_EQ(r.status, 0) << describe(r);
  EXPECT_TRUE(contains(r.out, "--out")) << r.out;
  EXPECT_TRUE(contains(r.out, "--set")) << r.out;
  EXPECT_TRUE(ws.entries().empty()) << "--help writes nothing";
}

TEST(SimulateCli, NoVerbIsBadInput) {
  Workspace ws;
  const RunResult r = ws.run({});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_FALSE(r.err.empty());
}

TEST(SimulateCli, UnknownVerbIsBadInput) {
  Workspace ws;
  const RunResult r = ws.run({"simulat", "case.toml"});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_FALSE(r.err.empty());
}

// Each --set takes one value: the case file after it is the case, not another override.
TEST(SimulateCli, CaseFileAfterSetIsTheCase) {
  Workspace ws;
  ws.write("sdof.toml", project_case());
  const RunResult r = ws.run({"simulate", "--set", "rolling.static_load=3", "sdof.toml", "--out", "out"});
  EXPECT_EQ(r.status, 0) << describe(r);
  const auto summary = nlohmann::json::parse(read_text(ws.path("out/summary.json")));
  EXPECT_DOUBLE_EQ(summary["settings"]["static_load_N"].get<double>(), 3.0) << summary["settings"];
}

TEST(SimulateCli, SimulateWithoutCaseIsBadInput) {
  Workspace ws;
  const RunResult r = ws.run({"simulate"});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "case")) << r.err;
}

// ---------------------------------------------------------------------------------------------
// Output folders that must not be touched.

TEST(SimulateCli, ForeignFolderAsOutIsLeftAlone) {
  Workspace ws;
  ws.write("sdof.toml", project_case());
  fs::create_directory(ws.path("mine"));
  ws.write("mine/thesis.tex", "do not lose me\n");
  const RunResult r = ws.run({"simulate", "sdof.toml", "--out", "mine"});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(starts_with(r.err, "rollnoise: error: ")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_TRUE(contains(r.err, "mine")) << r.err;
  EXPECT_EQ(read_text(ws.path("mine/thesis.tex")), "do not lose me\n");
  EXPECT_EQ(ws.entries(), (std::set<std::string>{"sdof.toml", "mine/", "mine/thesis.tex"}));
}

TEST(SimulateCli, FileAsOutIsLeftAlone) {
  Workspace ws;
  ws.write("sdof.toml", project_case());
  ws.write("notes.txt", "keep\n");
  const RunResult r = ws.run({"simulate", "sdof.toml", "--out", "notes.txt"});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "notes.txt")) << r.err;
  EXPECT_EQ(read_text(ws.path("notes.txt")), "keep\n");
  EXPECT_EQ(ws.entries(), (std::set<std::string>{"sdof.toml", "notes.txt"}));
}

// A failure found only while simulating (after the staging folder exists) must still leave
// nothing: neither the staging folder nor the parent folders made for a nested --out.
TEST(SimulateCli, LateFailureWithNestedOutLeavesNothing) {
  Workspace ws;
  ws.write("modal.toml", edit_case(project_case(), {{"rolling", "history", "\"modal\""}}));
  const RunResult r = ws.run({"simulate", "modal.toml", "--out", "results/today/run1"});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_EQ(ws.entries(), (std::set<std::string>{"modal.toml"}))
      << "a failed run leaves no folders behind";
}

// `--out .` in an empty folder: either the results go there (exit 0) or a clear bad-input
// message (exit 2); never an internal failure.
TEST(SimulateCli, OutIsTheCurrentEmptyFolder) {
  Workspace ws;
  ws.write("../sdof.toml", edit_case(project_case(), {{"output", "plots", "false"}}));
  const RunResult r = ws.run({"simulate", "../sdof.toml", "--out", "."});
  EXPECT_TRUE(r.status == 0 || r.status == 2) << describe(r);
  if (r.status == 0) {
    EXPECT_TRUE(fs::is_regular_file(ws.path("summary.json")));
  } else {
    EXPECT_TRUE(starts_with(r.err, "rollnoise: error: ")) << r.err;
    EXPECT_TRUE(ws.entries().empty());
  }
}

// ---------------------------------------------------------------------------------------------
// Bad input: exit status 2, one line "rollnoise: error: FILE: KEY: what is allowed", and no
// output folder (nor a hidden partial one) afterwards.

struct BadInput {
  std::string name;
  std::string base = "larsson2000_sdof_sine.toml";  // in models/cases; empty: `raw` is the case
  std::vector<Edit> edits = {};
  std::string raw = "";
  std::vector<std::pair<std::string, std::string>> files = {};  // more files beside the case
  std::vector<std::string> args = {};                            // after the default ones
  bool write_case = true;
  std::string case_name = "bad_case.toml";
  std::vector<std::string> expect = {};  // parts of the message
  std::vector<std::string> reject = {};  // text the message must not hold
};

void PrintTo(const BadInput& input, std::ostream* os) { *os << input.name; }

const char* const kCase = "bad_case.toml";

const std::vector<BadInput>& bad_inputs() {
  static const std::vector<BadInput> inputs = {
      {.name = "mass_negative", .edits = {{"tyre", "mass", "-1"}}, .expect = {kCase, "[tyre] mass", "> 0"}},
      {.name = "mass_zero", .edits = {{"tyre", "mass", "0"}}, .expect = {kCase, "[tyre] mass", "> 0"}},
      {.name = "mass_nan", .edits = {{"tyre", "mass", "nan"}}, .expect = {kCase, "[tyre] mass", "finite"}},
      {.name = "mass_inf", .edits = {{"tyre", "mass", "inf"}}, .expect = {kCase, "[tyre] mass", "finite"}},
      {.name = "mass_string", .edits = {{"tyre", "mass", "\"1 kg\""}}, .expect = {kCase, "[tyre] mass", "number"}},
      {.name = "mass_missing", .edits = {{"tyre", "mass", std::nullopt}}, .expect = {kCase, "[tyre] mass", "required"}},
      {.name = "stiffness_zero", .edits = {{"tyre", "stiffness", "0"}}, .expect = {kCase, "[tyre] stiffness", "> 0"}},
      {.name = "damping_negative", .edits = {{"tyre", "damping", "-50"}}, .expect = {kCase, "[tyre] damping", "> 0"}},
      {.name = "contact_stiffness_zero",
       .edits = {{"tyre", "contact_stiffness", "0"}},
       .expect = {kCase, "[tyre] contact_stiffness", "> 0"}},
      {.name = "time_step_zero", .edits = {{"rolling", "time_step", "0"}}, .expect = {kCase, "[rolling] time_step", "> 0"}},
      {.name = "time_step_negative",
       .edits = {{"rolling", "time_step", "-1e-4"}},
       .expect = {kCase, "[rolling] time_step", "> 0"}},
      {.name = "time_step_longer_than_run",
       .edits = {{"rolling", "time_step", "0.1"}},
       .expect = {kCase, "[rolling] time_step", "duration"}},
      // 1e35 steps: the message must give a sensible count (the cast to long long overflows).
      {.name = "step_count_huge",
       .edits = {{"rolling", "duration", "1e30"}, {"rolling", "time_step", "1e-5"}},
       .expect = {kCase, "[rolling] time_step", "2e7"},
       .reject = {"-9223372036854775808"}},
      {.name = "speed_zero", .edits = {{"rolling", "speed", "0"}}, .expect = {kCase, "[rolling] speed", "> 0"}},
      {.name = "static_load_negative",
       .edits = {{"rolling", "static_load", "-1"}},
       .expect = {kCase, "[rolling] static_load", ">= 0"}},
      {.name = "model_unknown",
       .edits = {{"tyre", "model", "\"bogus\""}},
       .expect = {kCase, "[tyre] model", "bogus", "allowed", "\"sdof\""}},
      {.name = "road_type_unknown",
       .edits = {{"road", "type", "\"bogus\""}},
       .expect = {kCase, "[road] type", "bogus", "allowed", "\"sine\""}},
      {.name = "history_unknown",
       .edits = {{"rolling", "history", "\"bogus\""}},
       .expect = {kCase, "[rolling] history", "allowed", "\"direct\""}},
      // No engine of that name exists: refused as unknown at once, not by every model later.
      {.name = "history_fft_unknown",
       .edits = {{"rolling", "history", "\"fft\""}},
       .expect = {kCase, "[rolling] history", "unknown value \"fft\"", "\"modal\""}},
      {.name = "history_modal_not_for_point_models",
       .edits = {{"rolling", "history", "\"modal\""}},
       .expect = {kCase, "[rolling] history", "modal", "allowed"}},
      {.name = "discretisation_unknown",
       .edits = {{"rolling", "discretisation", "\"trapezoid\""}},
       .expect = {kCase, "[rolling] discretisation", "allowed", "\"rectangle\""}},
      {.name = "unknown_key_in_tyre",
       .edits = {{"tyre", "colour", "\"black\""}},
       .expect = {kCase, "[tyre] colour", "unknown key", "allowed", "mass"}},
      {.name = "unknown_key_in_rolling",
       .edits = {{"rolling", "sped", "1.0"}},
       .expect = {kCase, "[rolling] sped", "unknown key", "allowed", "speed"}},
      {.name = "unknown_key_in_road",
       .edits = {{"road", "phase", "0.5"}},
       .expect = {kCase, "[road] phase", "unknown key", "allowed"}},
      {.name = "unknown_key_in_output",
       .edits = {{"output", "wav", "true"}},
       .expect = {kCase, "[output] wav", "unknown key", "allowed"}},
      {.name = "unknown_section",
       .edits = {{"tyres", "mass", "1.0"}},
       .expect = {kCase, "tyres", "unknown section", "allowed", "[tyre]"}},
      {.name = "rolling_section_missing",
       .raw = "[tyre]\nmodel = \"sdof\"\nmass = 1.0\ndamping = 50.0\nstiffness = 500.0\n"
              "contact_stiffness = 1.0e5\n[road]\ntype = \"flat\"\n",
       .expect = {kCase, "[rolling]", "required"}},
      {.name = "tyre_not_a_table", .raw = "tyre = 3\n", .expect = {kCase, "tyre", "table"}},
      {.name = "case_file_missing", .write_case = false, .case_name = "no_such_case.toml",
       .expect = {"no_such_case.toml", "not found"}},
      {.name = "case_file_is_a_folder", .files = {{"folder_case.toml/x", ""}}, .write_case = false,
       .case_name = "folder_case.toml", .expect = {"folder_case.toml", "folder"}},
      {.name = "malformed_toml",
       .base = "",
       .raw = "[tyre]\nmodel = \"sdof\"\nmass = 1.0 kg\n",
       .expect = {kCase, "line 3", "malformed TOML"}},
      {.name = "tyre_model_file_missing",
       .edits = {{"tyre", "file", "\"no_such_model.toml\""}},
       .expect = {"no_such_model.toml", "not found"}},
      // A bad value in a model file named by `[tyre] file`: the message names the model file.
      {.name = "model_file_mass_negative",
       .edits = {{"tyre", "file", "\"bad_model.toml\""}, {"tyre", "mass", std::nullopt}},
       .files = {{"bad_model.toml", "mass = -1.0\n"}},
       .expect = {"bad_model.toml", "[tyre] mass", "> 0"}},
      {.name = "model_file_unknown_key",
       .edits = {{"tyre", "file", "\"odd_model.toml\""}},
       .files = {{"odd_model.toml", "colour = \"black\"\n"}},
       .expect = {"odd_model.toml", "[tyre] colour", "unknown key", "allowed"}},
      {.name = "coupling_not_positive_definite",
       .base = "larsson2000_coupled_sine.toml",
       .edits = {{"tyre", "coupling", "1.5"}},
       .expect = {kCase, "[tyre] coupling", "between -1 and 1"}},
      {.name = "coupling_singular",
       .base = "larsson2000_coupled_sine.toml",
       .edits = {{"tyre", "coupling", "-1.0"}},
       .expect = {kCase, "[tyre] coupling", "between -1 and 1"}},
      {.name = "random_road_seed_negative",
       .base = "larsson2000_sdof_random.toml",
       .edits = {{"road", "seed", "-1"}},
       .expect = {kCase, "[road] seed", "integer"}},
      // speed x duration overflows to inf: the road cannot cover the run.
      {.name = "road_length_overflow_random",
       .base = "larsson2000_sdof_random.toml",
       .edits = {{"rolling", "speed", "1e300"}, {"rolling", "duration", "1e300"}, {"rolling", "time_step", "1e296"}},
       .expect = {kCase, "[rolling]"}},
      {.name = "road_length_overflow_sine",
       .edits = {{"rolling", "speed", "1e300"}, {"rolling", "duration", "1e300"}, {"rolling", "time_step", "1e296"}},
       .expect = {kCase, "[rolling]"}},
      {.name = "road_file_missing", .edits = file_road("missing_road.csv"), .expect = {"missing_road.csv", "not found"}},
      {.name = "road_file_nan",
       .edits = file_road("nan_road.csv"),
       .files = {{"nan_road.csv", "x,z\n0,0\n0.025,nan\n0.1,0\n"}},
       .expect = {"nan_road.csv", "line 3", "finite"}},
      {.name = "road_file_x_not_increasing",
       .edits = file_road("decreasing_road.csv"),
       .files = {{"decreasing_road.csv", "x,z\n0,0\n0.05,0.001\n0.04,0\n0.1,0\n"}},
       .expect = {"decreasing_road.csv", "data row 3", "strictly increasing"}},
      {.name = "road_file_x_repeated",
       .edits = file_road("repeated_road.csv"),
       .files = {{"repeated_road.csv", "x,z\n0,0\n0.05,0.001\n0.05,0\n0.1,0\n"}},
       .expect = {"repeated_road.csv", "data row 3", "strictly increasing"}},
      {.name = "road_file_too_short",
       .edits = file_road("short_road.csv"),
       .files = {{"short_road.csv", "x,z\n0,0\n0.01,0\n"}},
       .expect = {"short_road.csv", "0.05"}},
      {.name = "road_file_without_z",
       .edits = file_road("no_z_road.csv"),
       .files = {{"no_z_road.csv", "x,height\n0,0\n0.1,0\n"}},
       .expect = {"no_z_road.csv", "\"z\""}},
      {.name = "road_file_not_numeric",
       .edits = file_road("text_road.csv"),
       .files = {{"text_road.csv", "x,z\n0,0\n0.05,high\n0.1,0\n"}},
       .expect = {"text_road.csv", "line 3", "not a number"}},
      {.name = "set_without_equals",
       .args = {"--set", "rolling.static_load"},
       .expect = {"--set", "rolling.static_load", "section.key=value"}},
      {.name = "set_nan_mass",
       .args = {"--set", "tyre.mass=nan"},
       .expect = {"--set", "[tyre] mass", "finite"}},
      {.name = "set_into_a_value",
       .args = {"--set", "tyre.mass.kg=1"},
       .expect = {"--set", "tyre.mass", "not a table"}},
      {.name = "set_unknown_key",
       .args = {"--set", "rolling.sped=2"},
       .expect = {"[rolling] sped", "unknown key", "allowed"}},
      // A device as model file would block (/dev/stdin) or never end (/dev/zero).
      {.name = "model_file_is_a_device",
       .args = {"--set", "tyre.file=/dev/null"},
       .expect = {"/dev/null", "not a regular file"}},
      // Each value is positive, but together they leave double range.
      {.name = "parameters_beyond_double_range",
       .args = {"--set", "tyre.damping=1e300"},
       .expect = {"[tyre] mass, damping", "range"}},
  };
  return inputs;
}

class SimulateBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(SimulateBadInput, ExitsTwoWithOneMessageAndNoOutput) {
  const BadInput& input = GetParam();
  Workspace ws;
  for (const auto& [name, text] : input.files) {
    fs::create_directories(ws.path(name).parent_path());
    ws.write(name, text);
  }
  if (input.write_case) {
    std::string text = input.raw.empty() ? project_case(input.base) : input.raw;
    if (input.raw.empty()) text = edit_case(text, input.edits);
    ws.write(input.case_name, text);
  }
  const std::set<std::string> before = ws.entries();

  std::vector<std::string> args{"simulate", input.case_name, "--out", "out"};
  args.insert(args.end(), input.args.begin(), input.args.end());
  const RunResult r = ws.run(args);

  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(starts_with(r.err, "rollnoise: error: ")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << "exactly one line on stderr:\n" << r.err;
  for (const auto& part : input.expect) {
    EXPECT_TRUE(contains(r.err, part)) << "the message lacks \"" << part << "\":\n" << r.err;
  }
  for (const auto& part : input.reject) {
    EXPECT_FALSE(contains(r.err, part)) << "the message holds \"" << part << "\":\n" << r.err;
  }
  EXPECT_FALSE(fs::exists(ws.path("out"))) << "--out folder made by a failed run";
  EXPECT_EQ(ws.entries(), before) << "a failed run leaves nothing behind (no partial folder)";
}

INSTANTIATE_TEST_SUITE_P(Cases, SimulateBadInput, ::testing::ValuesIn(bad_inputs()),
                         [](const ::testing::TestParamInfo<BadInput>& param_info) { return param_info.param.name; });

}  // namespace

// The two-layer tyre through `simulate` (issue 11): a small version of the passenger file (few
// modes, so the test is quick) on the smooth road. The run tabulates and fits its modes into the
// cache; a second run takes both from the cache and gives the same contact.
std::string small_two_layer_model() {
  std::string text = read_text(fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "tyres" / "passenger_205_55R16_two_layer.toml");
  for (const auto& [key, value] : {std::pair<std::string, std::string>{"circumferential_modes", "24"}, {"lateral_modes", "5"}}) {
    const std::size_t at = text.find("\n" + key + " = ");
    const std::size_t end = text.find('\n', at + 1);
    text.replace(at + 1, end - at - 1, key + " = " + value);
  }
  return text;
}

TEST(SimulateCli, TwoLayerTyreRollsThroughTheCommonPathAndCachesItsModes) {
  Workspace ws;
  ws.write("two_layer.toml", small_two_layer_model());
  // A coarse grid (512 cells around, 8 across, one step per cell) keeps the run short.
  ws.write("case.toml", edit_case(project_case("two_layer_smooth_80kmh.toml"),
                                  {{"tyre", "file", "\"two_layer.toml\""}, {"rolling", "duration", "0.003"},
                                   {"rolling", "points_circumferential", "512"}, {"rolling", "points_lateral", "8"},
                                   {"rolling", "band_top", "0"}}));
  const std::string cache = "ROLLNOISE_CACHE=" + ws.path("cache").string() + " ";
  const RunResult first = ws.run({"simulate", "case.toml", "--out", "first"}, cache);
  ASSERT_EQ(first.status, 0) << describe(first);
  const nlohmann::json a = read_json(ws.path("first") / "summary.json");
  EXPECT_EQ(a["model"], "two_layer");
  EXPECT_EQ(a["tread"], "included in the model");
  EXPECT_EQ(a["mode_fit"]["modes"].get<int>(), 25 * 5);
  EXPECT_EQ(a["mode_fit"]["unconverged_modes"].get<int>(), 0);
  EXPECT_FALSE(a["mode_fit"]["table_from_cache"].get<bool>());
  EXPECT_FALSE(a["mode_fit"]["fits_from_cache"].get<bool>());
  // Smooth road: steady rolling under the load from the first step.
  EXPECT_NEAR(a["mean_total_force_N"].get<double>(), 3200.0, 1e-6 * 3200.0);
  EXPECT_NEAR(a["max_total_force_N"].get<double>(), 3200.0, 1e-6 * 3200.0);
  const RunResult second = ws.run({"simulate", "case.toml", "--out", "second"}, cache);
  ASSERT_EQ(second.status, 0) << describe(second);
  const nlohmann::json b = read_json(ws.path("second") / "summary.json");
  EXPECT_TRUE(b["mode_fit"]["table_from_cache"].get<bool>());
  EXPECT_TRUE(b["mode_fit"]["fits_from_cache"].get<bool>());
  EXPECT_EQ(read_text(ws.path("first") / "contact.csv"), read_text(ws.path("second") / "contact.csv"));
}

// A wrong key in any table but the road's is reported before the two-layer tyre's modes are
// tabulated and fitted (tens of seconds without the cache): nothing reaches the cache folder.
TEST(SimulateCli, TwoLayerCaseWithABadKeyFailsBeforeItsModesAreComputed) {
  Workspace ws;
  ws.write("two_layer.toml", small_two_layer_model());
  for (const auto& [section, key, value, named] :
       {std::tuple<const char*, const char*, const char*, const char*>{"output", "bogus", "1", "[output] bogus"},
        {"rolling", "speed", "-3.0", "[rolling] speed"},
        {"radiation", "receivers", "3", "[radiation] receivers"},
        {"road", "bogus", "1", "[road] bogus"}}) {
    ws.write("case.toml", edit_case(project_case("two_layer_smooth_80kmh.toml"),
                                    {{"tyre", "file", "\"two_layer.toml\""}, {section, key, value}}));
    const RunResult r = ws.run({"simulate", "case.toml", "--out", "out"}, "ROLLNOISE_CACHE=" + ws.path("cache").string() + " ");
    EXPECT_EQ(r.status, 2) << describe(r);
    EXPECT_TRUE(contains(r.err, named)) << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(ws.path("out")));
    EXPECT_TRUE(!fs::exists(ws.path("cache")) || fs::is_empty(ws.path("cache"))) << "the modes were computed first";
  }
}

TEST(SimulateCli, TwoLayerTyreWithASeparateTreadIsAnError) {
  Workspace ws;
  ws.write("two_layer.toml", small_two_layer_model() + "\n[tread]\ntype = \"winkler\"\nstiffness_per_area = 5e8\n");
  ws.write("case.toml", edit_case(project_case("two_layer_smooth_80kmh.toml"), {{"tyre", "file", "\"two_layer.toml\""}}));
  const RunResult r = ws.run({"simulate", "case.toml", "--out", "out"}, "ROLLNOISE_CACHE=" + ws.path("cache").string() + " ");
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "two_layer.toml")) << r.err;
  EXPECT_TRUE(contains(r.err, "tread")) << r.err;
  EXPECT_TRUE(contains(r.err, "includes the tread")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_FALSE(fs::exists(ws.path("out")));
}

// ---------------------------------------------------------------------------------------------
// The radiation cache (issue 12): --cache, --no-cache, `rollnoise cache list|clear`.

namespace {

// A short plate run with sound on a coarse mesh: 0.01 s, anchors every 250 Hz to 1.5 kHz.
std::string short_sound_case(const Edit& surface) {
  const std::string model = (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "tyres" / "passenger_205_55R16.toml").string();
  return edit_case(project_case("plate_rough_80kmh.toml"),
                   {{"tyre", "file", "\"" + model + "\""}, surface,
                    {"rolling", "duration", "0.01"},
                    {"radiation", "mesh_around", "32"},
                    {"radiation", "mesh_across", "4"},
                    {"radiation", "sidewall_rings", "4"},
                    {"radiation", "max_frequency", "1500"},
                    {"radiation", "anchor_spacing", "250"},
                    {"radiation", "contact_refinement", "3"},
                    {"output", "plots", "false"}});
}

Edit library_surface(const std::string& name) {
  std::string value = "\"";
  value += (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / "surfaces" / name).string();
  value += '"';
  return {"road", "surface", value};
}

std::vector<fs::path> radiation_entries(const fs::path& folder) {
  std::vector<fs::path> out;
  if (!fs::is_directory(folder)) return out;
  for (const auto& e : fs::directory_iterator(folder))
    if (starts_with(e.path().filename().string(), "radiation-")) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// What must not change with the cache: levels, spectra and sound power to the byte, every WAV's
// samples and header bit for bit. (Not the WAV files' bytes: libsndfile's PEAK chunk records
// the time of writing, so two runs without the cache differ there too.)
void expect_same_sound(const fs::path& a, const fs::path& b) {
  for (const char* file : {"spectrum.csv", "sound_power.csv", "budget.csv"}) {
    const std::string x = read_text(a / file);
    EXPECT_FALSE(x.empty()) << a / file;
    EXPECT_TRUE(x == read_text(b / file)) << file << " differs between " << a << " and " << b;
  }
  for (const char* file : {"cpx_front.wav", "cpx_rear.wav", "spb.wav", "spb_passby.wav"}) {
    const rollnoise::WavData x = rollnoise::read_wav(a / file), y = rollnoise::read_wav(b / file);
    ASSERT_EQ(x.channels.size(), 1u) << a / file;
    ASSERT_EQ(y.channels.size(), 1u) << b / file;
    EXPECT_GT(x.channels[0].size(), 0);
    EXPECT_TRUE(x.channels[0] == y.channels[0]) << file << ": the samples differ between " << a << " and " << b;
    EXPECT_EQ(x.comment, y.comment) << file;
    EXPECT_EQ(x.sample_rate, y.sample_rate) << file;
  }
  const nlohmann::json sa = read_json(a / "summary.json"), sb = read_json(b / "summary.json");
  EXPECT_EQ(sa["levels"], sb["levels"]);
  EXPECT_EQ(sa["sound_power"], sb["sound_power"]);
  EXPECT_EQ(sa["full_scale_pa"], sb["full_scale_pa"]);
}

}  // namespace

// A run from the cache gives the same levels, spectra and WAVs, bit for bit, as one without it;
// another surface, whose mean contact patch differs, has a body of its own; a damaged entry is
// warned about once and solved again, with the same result.
TEST(CacheCli, HitEqualsNoCacheAndDamagedEntriesAreRecomputed) {
  Workspace ws;
  ws.write("dac.toml", short_sound_case(library_surface("dac11.toml")));
  ws.write("sma.toml", short_sound_case(library_surface("sma11.toml")));
  const std::string cache = ws.path("cache").string();
  const RunResult none = ws.run({"simulate", "dac.toml", "--out", "none", "--no-cache"});
  ASSERT_EQ(none.status, 0) << describe(none);
  EXPECT_FALSE(fs::exists(ws.path("cache")));
  EXPECT_EQ(read_json(ws.path("none") / "summary.json")["radiation"]["cache"], "");

  const RunResult cold = ws.run({"simulate", "dac.toml", "--out", "cold", "--cache", cache});
  ASSERT_EQ(cold.status, 0) << describe(cold);
  const nlohmann::json cold_summary = read_json(ws.path("cold") / "summary.json");
  const auto anchors = cold_summary["radiation"]["anchors"].get<std::size_t>();
  EXPECT_EQ(cold_summary["radiation"]["anchors_from_cache"].get<std::size_t>(), 0u);
  EXPECT_EQ(radiation_entries(cache).size(), anchors);
  expect_same_sound(ws.path("none"), ws.path("cold"));

  const RunResult warm = ws.run({"simulate", "dac.toml", "--out", "warm", "--cache", cache});
  ASSERT_EQ(warm.status, 0) << describe(warm);
  EXPECT_EQ(read_json(ws.path("warm") / "summary.json")["radiation"]["anchors_from_cache"].get<std::size_t>(), anchors);
  EXPECT_TRUE(warm.err.empty()) << warm.err;
  expect_same_sound(ws.path("none"), ws.path("warm"));

  // Another surface: the key covers the deformed body, flat over the run's mean patch, which
  // the texture changes; a different patch finds nothing and stores its own entries.
  const RunResult other = ws.run({"simulate", "sma.toml", "--out", "other", "--cache", cache});
  ASSERT_EQ(other.status, 0) << describe(other);
  const nlohmann::json other_radiation = read_json(ws.path("other") / "summary.json")["radiation"];
  const bool same_body = other_radiation["patch_length_m"] == cold_summary["radiation"]["patch_length_m"] &&
                         other_radiation["patch_width_m"] == cold_summary["radiation"]["patch_width_m"];
  EXPECT_EQ(other_radiation["anchors_from_cache"].get<std::size_t>(), same_body ? anchors : 0u);
  EXPECT_EQ(radiation_entries(cache).size(), same_body ? anchors : 2 * anchors);
  RecordProperty("same_body_on_both_surfaces", same_body ? "yes" : "no");
  std::vector<fs::path> own_entries;
  for (const fs::path& entry : radiation_entries(cache))
    if (fs::last_write_time(entry) <= fs::last_write_time(ws.path("warm") / "summary.json")) own_entries.push_back(entry);

  // Damage: two of dac.toml's entries, one truncated, another with bytes flipped in its middle.
  const std::vector<fs::path> entries = own_entries;
  ASSERT_GE(entries.size(), 2u);
  fs::resize_file(entries[0], fs::file_size(entries[0]) - 100);
  {
    std::fstream f(entries[1], std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(fs::file_size(entries[1]) / 2));
    f.write("\xff\x00\xff\x00", 4);
  }
  const RunResult repaired = ws.run({"simulate", "dac.toml", "--out", "repaired", "--cache", cache});
  ASSERT_EQ(repaired.status, 0) << describe(repaired);
  for (const fs::path& damaged : {entries[0], entries[1]}) {
    const std::string line = "rollnoise: warning: the radiation cache entry " + damaged.string();
    const auto at = repaired.err.find(line);
    EXPECT_NE(at, std::string::npos) << repaired.err;
    EXPECT_EQ(repaired.err.find(line, at + 1), std::string::npos) << "warned once: " << repaired.err;
  }
  EXPECT_EQ(read_json(ws.path("repaired") / "summary.json")["radiation"]["anchors_from_cache"].get<std::size_t>(), anchors - 2);
  expect_same_sound(ws.path("none"), ws.path("repaired"));
  // The damaged entries were stored again whole: the next run finds every anchor, silently.
  const RunResult again = ws.run({"simulate", "dac.toml", "--out", "again", "--cache", cache});
  ASSERT_EQ(again.status, 0) << describe(again);
  EXPECT_TRUE(again.err.empty()) << again.err;
  EXPECT_EQ(read_json(ws.path("again") / "summary.json")["radiation"]["anchors_from_cache"].get<std::size_t>(), anchors);
  expect_same_sound(ws.path("none"), ws.path("again"));
  EXPECT_TRUE(ws.leftovers().empty());
}

// `cache list` names each entry with its size, age and content, `cache clear` removes the
// entries and nothing else; both default to the same folder as simulate ($ROLLNOISE_CACHE here).
TEST(CacheCli, ListAndClear) {
  Workspace ws;
  ws.write("dac.toml", short_sound_case(library_surface("dac11.toml")));
  const std::string cache = ws.path("cache").string();
  const std::string env = "ROLLNOISE_CACHE=" + shell_quote(cache) + " ";
  const RunResult run = ws.run({"simulate", "dac.toml", "--out", "out"}, env);
  ASSERT_EQ(run.status, 0) << describe(run);
  const std::size_t anchors = radiation_entries(cache).size();
  ASSERT_GT(anchors, 0u) << "simulate used $ROLLNOISE_CACHE without --cache";
  ws.write("cache/notes.txt", "a user's file in the folder");

  const RunResult list = ws.run({"cache", "list"}, env);
  ASSERT_EQ(list.status, 0) << describe(list);
  EXPECT_EQ(count_lines(list.out), anchors + 1) << list.out;
  EXPECT_TRUE(contains(list.out, "radiation operators at 1500 Hz: 3 receivers, power rank")) << list.out;
  EXPECT_TRUE(contains(list.out, std::to_string(anchors) + " entries")) << list.out;
  EXPECT_FALSE(contains(list.out, "notes.txt")) << list.out;
  EXPECT_TRUE(contains(list.out, " s  radiation: ")) << "the age: " << list.out;
  // Damage shows in the listing.
  {
    std::ofstream f(radiation_entries(cache).front(), std::ios::binary | std::ios::trunc);
    f << "garbage";
  }
  const RunResult damaged = ws.run({"cache", "list", "--cache", cache});
  EXPECT_TRUE(contains(damaged.out, "damaged or foreign")) << damaged.out;

  const RunResult clear = ws.run({"cache", "clear"}, env);
  ASSERT_EQ(clear.status, 0) << describe(clear);
  EXPECT_TRUE(contains(clear.out, "removed " + std::to_string(anchors) + " entries")) << clear.out;
  EXPECT_TRUE(radiation_entries(cache).empty());
  EXPECT_TRUE(fs::exists(ws.path("cache/notes.txt"))) << "clear leaves files that are not entries";
  const RunResult empty = ws.run({"cache", "list", "--cache", cache});
  EXPECT_TRUE(contains(empty.out, "0 entries")) << empty.out;

  for (const std::vector<std::string>& help :
       {std::vector<std::string>{"cache", "--help"}, {"cache", "list", "--help"}, {"cache", "clear", "--help"}}) {
    const RunResult h = ws.run(help);
    EXPECT_EQ(h.status, 0) << describe(h);
    EXPECT_TRUE(contains(h.out, "--cache") || contains(h.out, "list")) << h.out;
  }
  const RunResult verb = ws.run({"cache"});
  EXPECT_EQ(verb.status, 2) << describe(verb);
  for (const char* command : {"simulate", "study", "greens"}) {
    const RunResult h = ws.run({command, "--help"});
    EXPECT_TRUE(contains(h.out, "--cache") && contains(h.out, "--no-cache")) << h.out;
  }
  const RunResult both = ws.run({"simulate", "dac.toml", "--cache", cache, "--no-cache"});
  EXPECT_EQ(both.status, 2) << describe(both);
}

namespace {

// The bytes of the radiation entries in `folder` (not the unfinished writes), and the largest.
struct FolderSize {
  std::uintmax_t total = 0, largest = 0;
  std::size_t entries = 0;
};
FolderSize radiation_size(const fs::path& folder) {
  FolderSize size;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!starts_with(name, "radiation-")) continue;
    std::error_code gone;
    const std::uintmax_t bytes = fs::file_size(it->path(), gone);
    if (gone) continue;  // removed by a trim while listed
    size.total += bytes;
    size.largest = std::max(size.largest, bytes);
    ++size.entries;
  }
  return size;
}

}  // namespace

// Two processes fill one cache folder at once, on two bodies (dac11 and sma11 patches), under a
// limit of half of one body's entries. The folder never holds more than the limit plus the one
// entry each process may have renamed in and not yet trimmed (radiation threads = 1), and ends
// within the limit; both runs give what they give without the cache. Without eviction the
// folder would end at two bodies' worth, four times the limit.
TEST(CacheCli, TheLimitIsKeptWhileTwoProcessesWriteToTheFolder) {
  Workspace first, second;
  const Edit one_thread{"radiation", "threads", "1"};
  first.write("dac.toml", edit_case(short_sound_case(library_surface("dac11.toml")), one_thread));
  second.write("sma.toml", edit_case(short_sound_case(library_surface("sma11.toml")), one_thread));
  // One body's entries, measured in a folder of their own.
  const fs::path sizing = first.path("sizing");
  const RunResult alone = first.run({"simulate", "dac.toml", "--out", "alone", "--cache", sizing.string()});
  ASSERT_EQ(alone.status, 0) << describe(alone);
  const FolderSize body = radiation_size(sizing);
  ASSERT_GE(body.entries, 5u);
  const std::uintmax_t limit = body.total / 2;
  const RunResult none_sma = second.run({"simulate", "sma.toml", "--out", "none", "--no-cache"});
  ASSERT_EQ(none_sma.status, 0) << describe(none_sma);

  const fs::path shared = first.path("shared");
  const std::string limit_text = std::to_string(limit);
  std::atomic<int> running{2};
  RunResult dac, sma;
  std::thread a([&] {
    dac = first.run({"simulate", "dac.toml", "--out", "shared_run", "--cache", shared.string(), "--cache-limit", limit_text});
    --running;
  });
  std::thread b([&] {
    sma = second.run({"simulate", "sma.toml", "--out", "shared_run", "--cache", shared.string(), "--cache-limit", limit_text});
    --running;
  });
  std::uintmax_t most = 0;
  std::size_t samples = 0;
  while (running > 0) {
    most = std::max(most, radiation_size(shared).total);
    ++samples;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  a.join();
  b.join();
  ASSERT_EQ(dac.status, 0) << describe(dac);
  ASSERT_EQ(sma.status, 0) << describe(sma);
  EXPECT_EQ(dac.err.find("damaged"), std::string::npos) << dac.err;
  EXPECT_EQ(sma.err.find("damaged"), std::string::npos) << sma.err;
  const FolderSize end = radiation_size(shared);
  EXPECT_LE(end.total, limit) << end.entries << " entries at the end";
  EXPECT_GT(end.entries, 0u);
  EXPECT_LE(most, limit + 2 * body.largest) << "largest total seen in " << samples << " samples";
  RecordProperty("folder_samples", static_cast<int>(samples));
  RecordProperty("most_seen_over_limit", static_cast<int>(most > limit ? most - limit : 0));
  // Eviction never changes a result: each run equals its run without the cache.
  expect_same_sound(first.path("alone"), first.path("shared_run"));
  expect_same_sound(second.path("none"), second.path("shared_run"));
  EXPECT_TRUE(first.leftovers().empty());
  for (const auto& e : fs::directory_iterator(shared))
    EXPECT_FALSE(starts_with(e.path().filename().string(), ".")) << "an unfinished write left: " << e.path();
}

// The limit's sources: --cache-limit, else [radiation] cache_limit, else 4 GB; what is not a size
// is refused (exit status 2) naming the option or the key. A run trims a folder over its limit
// before it starts, the least recently used entries first (a hit counts as a use).
TEST(CacheCli, TheLimitComesFromTheOptionOrTheKeyAndTheOldestEntriesGoFirst) {
  Workspace ws;
  ws.write("dac.toml", short_sound_case(library_surface("dac11.toml")));
  const std::string cache = ws.path("cache").string();
  const RunResult filled = ws.run({"simulate", "dac.toml", "--out", "filled", "--cache", cache});
  ASSERT_EQ(filled.status, 0) << describe(filled);
  std::vector<fs::path> entries = radiation_entries(cache);
  ASSERT_GE(entries.size(), 4u);
  // Ages: the first entry the oldest, then the others in order, an hour apart.
  const auto now = fs::file_time_type::clock::now();
  for (std::size_t i = 0; i < entries.size(); ++i)
    fs::last_write_time(entries[i], now - std::chrono::hours(static_cast<int>(entries.size() - i)));
  const std::uintmax_t total = radiation_size(cache).total;
  // A limit one byte short of the total: the oldest entry goes when the run starts. The warm run
  // finds the others (each hit marks its entry used) and solves that anchor again; its store
  // trims once more, the entry first used in this run.
  const RunResult trimmed = ws.run({"simulate", "dac.toml", "--out", "trimmed", "--cache", cache, "--cache-limit",
                                    std::to_string(total - 1)});
  ASSERT_EQ(trimmed.status, 0) << describe(trimmed);
  const nlohmann::json radiation = read_json(ws.path("trimmed") / "summary.json")["radiation"];
  EXPECT_EQ(radiation["anchors_from_cache"].get<std::size_t>(), entries.size() - 1);
  ASSERT_TRUE(fs::exists(entries[0])) << "solved again and stored";
  EXPECT_GT(fs::last_write_time(entries[0]), now - std::chrono::minutes(10)) << "stored by this run";
  std::size_t kept = 0;
  for (std::size_t i = 1; i < entries.size(); ++i) {
    if (!fs::exists(entries[i])) continue;
    ++kept;
    EXPECT_GT(fs::last_write_time(entries[i]), now - std::chrono::minutes(10)) << "a hit marks the entry used";
  }
  EXPECT_EQ(kept, entries.size() - 2) << "one more went after the store";
  EXPECT_LE(radiation_size(cache).total, total - 1);
  expect_same_sound(ws.path("filled"), ws.path("trimmed"));

  // The case's key, when the option is not given: a limit below every entry empties the folder
  // and stores nothing more (each entry alone is over it: one warning).
  ws.write("small.toml", edit_case(short_sound_case(library_surface("dac11.toml")), {"radiation", "cache_limit", "\"1 kB\""}));
  const RunResult small = ws.run({"simulate", "small.toml", "--out", "small", "--cache", cache});
  ASSERT_EQ(small.status, 0) << describe(small);
  EXPECT_TRUE(radiation_entries(cache).empty());
  EXPECT_TRUE(contains(small.err, "is larger than the cache's limit (1 kB): not stored")) << small.err;
  EXPECT_EQ(count_lines(small.err), 1u) << small.err;
  expect_same_sound(ws.path("filled"), ws.path("small"));
  // The option overrides the key.
  const RunResult option = ws.run({"simulate", "small.toml", "--out", "option", "--cache", cache, "--cache-limit", "1GB"});
  ASSERT_EQ(option.status, 0) << describe(option);
  EXPECT_EQ(radiation_entries(cache).size(), entries.size());

  // Not sizes.
  const RunResult bad_option = ws.run({"simulate", "dac.toml", "--out", "bad", "--cache", cache, "--cache-limit", "lots"});
  EXPECT_EQ(bad_option.status, 2) << describe(bad_option);
  EXPECT_TRUE(contains(bad_option.err, "command line: --cache-limit: must be a size such as \"4 GB\"")) << bad_option.err;
  EXPECT_EQ(count_lines(bad_option.err), 1u) << bad_option.err;
  ws.write("bad.toml", edit_case(short_sound_case(library_surface("dac11.toml")), {"radiation", "cache_limit", "\"-3 GB\""}));
  const RunResult bad_key = ws.run({"simulate", "bad.toml", "--out", "bad", "--cache", cache});
  EXPECT_EQ(bad_key.status, 2) << describe(bad_key);
  EXPECT_TRUE(contains(bad_key.err, "bad.toml: [radiation] cache_limit: must be a size such as")) << bad_key.err;
  EXPECT_FALSE(fs::exists(ws.path("bad")));
  const RunResult both = ws.run({"simulate", "dac.toml", "--no-cache", "--cache-limit", "1GB"});
  EXPECT_EQ(both.status, 2) << describe(both);
}

// A cache folder that cannot be written (here a path under a regular file, which even root
// cannot create): one warning, and the run goes on without the cache.
TEST(CacheCli, UnwritableCacheFolderWarnsOnceAndTheRunSucceeds) {
  Workspace ws;
  ws.write("dac.toml", short_sound_case(library_surface("dac11.toml")));
  ws.write("file", "not a folder");
  const RunResult r = ws.run({"simulate", "dac.toml", "--out", "out", "--cache", ws.path("file/cache").string()});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_TRUE(starts_with(r.err, "rollnoise: warning: the cache folder ")) << r.err;
  EXPECT_TRUE(contains(r.err, "running without the cache")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_EQ(read_json(ws.path("out") / "summary.json")["radiation"]["cache"], "");
}

// ---------------------------------------------------------------------------------------------
// A tabulated tyre rolls with the tread its table lacks ([tyre.tread]). The reference is the plate
// itself: its modes written as a table (H_mn = L·N_n·h_mn, modal_receptance_table.hpp), fitted
// with poles and rolled with the plate's tread must give the plate's contact forces.

namespace {

std::string small_plate_tread() {
  return "[tread]\ntype = \"winkler\"\nstiffness_per_area = 5.0e8\nyoungs_modulus = 4.0e6\npoisson_ratio = 0.48\n";
}

// The model file of plate `p` with that tread, flat across and in contact over its whole width,
// as a table can only be (a tabulated tyre has no crown and meets the road over its width).
std::string plate_model(const rollnoise::PlateParameters& p) {
  std::ostringstream out;
  out.precision(17);
  out << "model = \"plate\"\nradius = " << p.radius << "\nwidth = " << p.width << "\nmass_per_area = " << p.mass_per_area
      << "\ntension_x = " << p.tension_x << "\ntension_y = " << p.tension_y << "\nbending_x = " << p.bending_x
      << "\nbending_y = " << p.bending_y << "\nbending_xy = " << p.bending_xy
      << "\nfoundation_stiffness = " << p.foundation_stiffness << "\nloss_factor = " << p.loss_factor
      << "\ncircumferential_modes = " << p.circumferential_modes << "\nlateral_modes = " << p.lateral_modes << "\n"
      << small_plate_tread();
  return out.str();
}

std::vector<double> total_forces(const fs::path& csv) {
  const rollnoise::NumericCsv table = rollnoise::read_numeric_csv(csv);
  return table.columns[table.column("total_force", csv.string())];
}

}  // namespace

TEST(SimulateCli, TabulatedTyreRollsWithItsTreadAsThePlateItTabulates) {
  const rollnoise::PlateParameters p = rollnoise::test::passenger_plate(24, 4);
  const rollnoise::KroppPlate plate(p);
  rollnoise::ModalReceptanceTable table;
  table.radius = p.radius;
  table.width = p.width;
  table.lateral_shape = rollnoise::LateralShape::sine;
  table.first_lateral_order = 1;
  table.lateral_orders = p.lateral_modes;
  table.orders = p.circumferential_modes;
  table.frequency = rollnoise::tyre_mode_fit_frequencies();
  table.source = "the plate";
  for (int n = 1; n <= p.lateral_modes; ++n)
    for (int m = 0; m <= p.circumferential_modes; ++m) {
      const rollnoise::PoleResidueResponse h = plate.mode_response(m, n - 1, 0.0, 0.0);
      Eigen::VectorXcd values(table.frequency.size());
      for (Eigen::Index f = 0; f < values.size(); ++f)
        values(f) = table.modal_norm(n) * h.receptance(2.0 * std::numbers::pi * table.frequency(f));
      table.modes.push_back(values);
    }
  Workspace ws;
  rollnoise::write_modal_table(ws.path("plate_table.h5"), table);
  ws.write("plate.toml", plate_model(p));
  ws.write("tabulated.toml", "model = \"tabulated\"\nfile = \"plate_table.h5\"\n" + small_plate_tread());
  const auto run = [&](const std::string& model, const std::string& out) {
    ws.write("case.toml", edit_case(project_case("plate_rough_80kmh.toml"),
                                    {{"tyre", "file", "\"" + model + "\""}, library_surface("dac11.toml"),
                                     {"rolling", "duration", "0.02"},
                                     {"rolling", "band_top", "0"},
                                     {"radiation", "enabled", "false"},
                                     {"output", "plots", "false"}}));
    return ws.run({"simulate", "case.toml", "--out", out}, "ROLLNOISE_CACHE=" + ws.path("cache").string() + " ");
  };
  const RunResult a = run("plate.toml", "plate");
  ASSERT_EQ(a.status, 0) << describe(a);
  const RunResult b = run("tabulated.toml", "tabulated");
  ASSERT_EQ(b.status, 0) << describe(b);
  const std::vector<double> fa = total_forces(ws.path("plate") / "contact.csv");
  const std::vector<double> fb = total_forces(ws.path("tabulated") / "contact.csv");
  ASSERT_EQ(fa.size(), fb.size());
  ASSERT_GT(fa.size(), 100u);
  double mean = 0.0, square = 0.0, difference = 0.0;
  for (double f : fa) mean += f / static_cast<double>(fa.size());
  for (std::size_t i = 0; i < fa.size(); ++i) {
    square += (fa[i] - mean) * (fa[i] - mean);
    difference += (fa[i] - fb[i]) * (fa[i] - fb[i]);
  }
  const double relative = std::sqrt(difference / square);
  std::printf("  total force: mean %.1f N, fluctuation %.1f N rms; tabulated against plate %.2e of the fluctuation\n", mean,
              std::sqrt(square / static_cast<double>(fa.size())), relative);
  // What may differ: the pole fit (one oscillator a mode, fitted to its relative RMS target of
  // 3e-3) and the fitted tyre's cell averages of its modes, sinc²(k·Δ/2) ≤ 1 − 1.1e-2 for the
  // highest lateral order on the 512-cell grid, which the plate's point modes leave out: 2 % of
  // the fluctuation holds both with room (measured 8.0e-3).
  EXPECT_LT(relative, 0.02);
}

TEST(SimulateCli, TabulatedTyreWithoutATreadIsAnError) {
  Workspace ws;
  ws.write("tabulated.toml", "model = \"tabulated\"\nfile = \"table.h5\"\n");
  ws.write("case.toml", edit_case(project_case("plate_rough_80kmh.toml"),
                                  {{"tyre", "file", "\"tabulated.toml\""}, library_surface("dac11.toml")}));
  const RunResult r = ws.run({"simulate", "case.toml", "--out", "out"}, "ROLLNOISE_CACHE=" + ws.path("cache").string() + " ");
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "tabulated.toml")) << r.err;
  EXPECT_TRUE(contains(r.err, "tread")) << r.err;
  EXPECT_TRUE(contains(r.err, "no local compliance")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_FALSE(fs::exists(ws.path("out")));
}
