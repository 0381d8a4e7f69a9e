// The tutorials work as written. Each page docs/tutorials/<name>.md has a script
// docs/tutorials/<name>.sh that runs its commands:
// - the page and the script agree: every line of the page's ```sh blocks is a line of the
//   script, in the page's order (the script writes `rollnoise` or "$ROLLNOISE" for the page's
//   build/tools/rollnoise/rollnoise and "$OUT" for out/tutorials/<name>), and every rollnoise or
//   mpirun command of the script is on the page;
// - each script, run in its quick mode (ROLLNOISE_TUTORIAL_QUICK=1: the same commands on short
//   runs) in a fresh folder, ends with status 0 and writes the files the page says it writes,
//   with sane contents.
// Blocks fenced otherwise (```toml, ```text, ```python, ```bash for a file shown but not run)
// are not commands. Getting started names the demo's folders: each is one tools/demo.sh writes.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "markdown_pages.hpp"

namespace {
namespace fs = std::filesystem;
using namespace cli_test;
using docs_test::source_dir;

const std::vector<std::string> tutorials = {"laser-profile", "compare-surfaces", "calibrate-tyre",
                                            "auralise-pass-by", "mpi-study"};

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

// Runs of spaces and tabs as one space, the ends trimmed.
std::string squeeze(const std::string& text) {
  std::string out;
  for (char c : trim(text)) {
    if ((c == ' ' || c == '\t') && !out.empty() && out.back() == ' ') continue;
    out += c == '\t' ? ' ' : c;
  }
  return out;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// The lines of a page's ```sh blocks, squeezed, without blank and comment lines.
std::vector<std::string> page_commands(const std::string& page) {
  std::vector<std::string> lines;
  std::istringstream in(page);
  bool in_sh = false, fenced = false;
  for (std::string line; std::getline(in, line);) {
    const std::string t = trim(line);
    if (t.rfind("```", 0) == 0) {
      if (!fenced) {
        fenced = true;
        in_sh = t == "```sh";
      } else {
        fenced = in_sh = false;
      }
      continue;
    }
    if (!in_sh) continue;
    const std::string s = squeeze(line);
    if (s.empty() || s[0] == '#') continue;
    lines.push_back(s);
  }
  return lines;
}

const std::string program = "build/tools/rollnoise/rollnoise";

// The script's lines as the page writes them: the program by its path and the output root as
// out/tutorials/<name>. Squeezed; blank and comment lines left out.
std::vector<std::string> script_lines(const std::string& script, const std::string& name) {
  std::vector<std::string> lines;
  std::istringstream in(script);
  for (std::string line; std::getline(in, line);) {
    std::string s = squeeze(line);
    if (s.empty() || s[0] == '#') continue;
    s = replace_all(s, "\"$ROLLNOISE\"", program);
    s = replace_all(s, "\"$OUT\"", "out/tutorials/" + name);
    if (s.rfind("rollnoise ", 0) == 0) s = program + s.substr(9);
    lines.push_back(s);
  }
  return lines;
}

std::string page_text(const std::string& name) {
  return read_text(source_dir() / "docs" / "tutorials" / (name + ".md"));
}
std::string script_text(const std::string& name) {
  return read_text(source_dir() / "docs" / "tutorials" / (name + ".sh"));
}

// Where the page and the script part: "" when every page command is a script line, in order,
// and every rollnoise or mpirun command of the script is on the page.
std::string disagreement(const std::string& name, const std::string& page, const std::string& script) {
  const std::vector<std::string> commands = page_commands(page);
  const std::vector<std::string> lines = script_lines(script, name);
  std::ostringstream out;
  if (commands.empty()) return "the page has no ```sh block";
  std::size_t next = 0;
  for (const std::string& command : commands) {
    std::size_t k = next;
    while (k < lines.size() && lines[k] != command) ++k;
    if (k == lines.size()) {
      out << "the page's line\n    " << command << "\nis not a line of the script after line \"" 
          << (next > 0 ? lines[next - 1] : std::string("(start)")) << "\"\n";
      return out.str();
    }
    next = k + 1;
  }
  const std::set<std::string> on_page(commands.begin(), commands.end());
  for (const std::string& line : lines)
    if ((line.rfind(program + " ", 0) == 0 || line.rfind("mpirun ", 0) == 0) && !on_page.count(line))
      out << "the script's command\n    " << line << "\nis not on the page\n";
  return out.str();
}

TEST(Tutorials, EachPageHasItsScriptAndTheyAgree) {
  for (const std::string& name : tutorials) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(fs::exists(source_dir() / "docs" / "tutorials" / (name + ".md")));
    ASSERT_TRUE(fs::exists(source_dir() / "docs" / "tutorials" / (name + ".sh")));
    const std::string page = page_text(name), script = script_text(name);
    EXPECT_EQ(disagreement(name, page, script), "");
    // The page says where its script is.
    EXPECT_TRUE(contains(page, "docs/tutorials/" + name + ".sh")) << "the page does not name its script";
  }
}

// The check can fail: a command changed on either side, or out of order, is found.
TEST(Tutorials, TheAgreementCheckFindsADifference) {
  const std::string page = "text\n```sh\nbuild/tools/rollnoise/rollnoise road a.dat --out out/tutorials/t/a\n"
                           "awk 1 x \\\n  > y\n```\n```toml\nnot = \"a command\"\n```\n";
  const std::string script = "source common.sh\n# a comment\nrollnoise road a.dat --out \"$OUT\"/a\n"
                             "awk 1 x \\\n    > y\n";
  EXPECT_EQ(disagreement("t", page, script), "");
  EXPECT_NE(disagreement("t", page, replace_all(script, "a.dat", "b.dat")), "");
  EXPECT_NE(disagreement("t", page + "```sh\nrollnoise cache list\n```\n", script), "");
  EXPECT_NE(disagreement("t", page, script + "rollnoise cache list\n"), "");
  const std::string swapped = "```sh\nawk 1 x \\\n> y\nbuild/tools/rollnoise/rollnoise road a.dat --out out/tutorials/t/a\n```\n";
  EXPECT_NE(disagreement("t", swapped, script), "");
  EXPECT_NE(disagreement("t", "no commands", script), "");
}

struct ScriptRun {
  int status = -1;
  std::string log;
  fs::path out;
};

// Runs docs/tutorials/<name>.sh in quick mode from the source folder, writing under the
// workspace; stdout and stderr together in the log.
ScriptRun run_tutorial(const Workspace& ws, const std::string& name) {
  ScriptRun run;
  run.out = ws.path("out");
  const fs::path log = ws.path("log.txt");
  std::string command = "cd ";
  command += shell_quote(source_dir().string());
  command += " && ROLLNOISE=";
  command += shell_quote(ROLLNOISE_BINARY);
  command += " OUT=";
  command += shell_quote(run.out.string());
  command += " ROLLNOISE_TUTORIAL_QUICK=1 bash docs/tutorials/";
  command += name;
  command += ".sh </dev/null >";
  command += shell_quote(log.string());
  command += " 2>&1";
  const int raw = std::system(command.c_str());
  if (raw != -1 && WIFEXITED(raw)) run.status = WEXITSTATUS(raw);
  run.log = read_text(log);
  return run;
}

std::vector<std::vector<std::string>> csv_rows(const fs::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read_text(file));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

double number(const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    return used == text.size() ? value : NAN;
  } catch (const std::exception&) {
    return NAN;
  }
}

void expect_plot(const fs::path& dir, const std::string& stem) {
  EXPECT_TRUE(fs::exists(dir / (stem + ".gp"))) << dir / (stem + ".gp");
  if (gnuplot_installed()) {
    EXPECT_GT(fs::file_size(dir / (stem + ".png")), 1000u) << dir / (stem + ".png");
  }
}

// A tyre run's sound: spectrum.csv per receiver with finite levels, the levels in summary.json,
// and the WAV files (unless the run was told not to write them).
void expect_tyre_sound(const fs::path& dir, bool wav = true) {
  SCOPED_TRACE(dir.string());
  const auto rows = csv_rows(dir / "spectrum.csv");
  ASSERT_GT(rows.size(), 1u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"receiver", "band_hz", "Lp_dB", "LpA_dB"}));
  std::set<std::string> receivers;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), 4u);
    receivers.insert(rows[r][0]);
    EXPECT_TRUE(std::isfinite(number(rows[r][2])) && std::isfinite(number(rows[r][3]))) << rows[r][1];
  }
  EXPECT_EQ(receivers, (std::set<std::string>{"cpx_front", "cpx_rear", "spb", "spb_passby"}));
  const nlohmann::json summary = read_json(dir / "summary.json");
  for (const std::string receiver : {"cpx_front", "cpx_rear", "spb", "spb_passby"}) {
    const double laeq = summary["levels"][receiver]["LAeq_dB"].get<double>();
    EXPECT_TRUE(laeq > 40 && laeq < 140) << receiver << " LAeq " << laeq;
    if (wav) {
      EXPECT_GT(fs::file_size(dir / (receiver + ".wav")), 5u * 48000u * 4u) << receiver;
    }
  }
  // Loud beside the tyre, quieter 7.5 m away.
  EXPECT_GT(summary["levels"]["cpx_front"]["LAeq_dB"].get<double>(), summary["levels"]["spb"]["LAeq_dB"].get<double>() + 15);
  EXPECT_TRUE(fs::exists(dir / "contact.h5"));
  EXPECT_TRUE(fs::exists(dir / "sound_power.csv"));
  expect_plot(dir, "spectrum");
}

TEST(Tutorials, LaserProfileRunsAsWritten) {
  Workspace ws;
  const ScriptRun run = run_tutorial(ws, "laser-profile");
  ASSERT_EQ(run.status, 0) << run.log;
  const fs::path& out = run.out;
  // The measured profile: the CAPTIF chip seal's MPD (ISO 13473-1) and its texture spectrum.
  const nlohmann::json profile = read_json(out / "profile" / "summary.json");
  EXPECT_NEAR(profile["mpd_m"].get<double>(), 3.21e-3, 0.01e-3);
  const auto texture = csv_rows(out / "profile" / "texture.csv");
  ASSERT_EQ(texture.size(), 26u) << "the bands 0.5 to 125 mm and the header";
  EXPECT_EQ(texture[0], (std::vector<std::string>{"wavelength_m", "Ltx_dB"}));
  expect_plot(out / "profile", "texture");
  // The surface file: the bands from 2.5 to 125 mm with the measured levels.
  const std::string surface = read_text(out / "my_surface.toml");
  EXPECT_TRUE(contains(surface, "type = \"texture\"")) << surface;
  EXPECT_TRUE(contains(surface, "wavelengths = [0.0025, 0.00315, ")) << surface;
  EXPECT_TRUE(contains(surface, ", 0.1, 0.125]")) << surface;
  // The synthesised surface has the measured spectrum (a 7 m line scatters by a dB or two).
  std::map<std::string, double> target, analysed;
  for (const auto& row : csv_rows(out / "surface" / "target.csv")) target[row[0]] = number(row[1]);
  for (const auto& row : csv_rows(out / "surface" / "texture.csv")) analysed[row[0]] = number(row[1]);
  std::size_t compared = 0;
  for (const auto& [band, level] : target) {
    const double w = number(band);
    if (!(w >= 0.004 && w <= 0.1)) continue;
    ASSERT_TRUE(analysed.count(band)) << band;
    EXPECT_NEAR(analysed[band], level, 3.0) << band;
    ++compared;
  }
  EXPECT_EQ(compared, 15u);
  expect_plot(out / "surface", "texture");
  // The tyre on it and on the dense asphalt, and the side-by-side table.
  expect_tyre_sound(out / "noise");
  expect_tyre_sound(out / "dac11");
  const std::string table = read_text(out / "compare_cpx_front.txt");
  EXPECT_TRUE(starts_with(table, " band_Hz my_surface      dac11\n")) << table;
  std::size_t bands = 0;
  for (const auto& row : csv_rows(out / "noise" / "spectrum.csv")) bands += row[0] == "cpx_front";
  EXPECT_EQ(count_lines(table), bands + 2) << table;
  EXPECT_TRUE(contains(table, "\n     sum ")) << table;
}

TEST(Tutorials, CompareSurfacesRunsAsWritten) {
  Workspace ws;
  const ScriptRun run = run_tutorial(ws, "compare-surfaces");
  ASSERT_EQ(run.status, 0) << run.log;
  const fs::path study = run.out / "study";
  const auto results = csv_rows(study / "results.csv");
  ASSERT_EQ(results.size(), 10u) << read_text(study / "results.csv");
  EXPECT_EQ(results[0], (std::vector<std::string>{"road.surface", "rolling.speed", "LAeq_cpx_front_dB",
                                                  "LAeq_cpx_rear_dB", "LAeq_spb_dB", "LAeq_spb_passby_dB", "LWA_dB",
                                                  "rolling_resistance_N", "wall_time_s", "status"}));
  std::set<std::string> cases;
  for (std::size_t r = 1; r < results.size(); ++r) {
    ASSERT_EQ(results[r].size(), 10u);
    cases.insert(results[r][0] + "@" + results[r][1]);
    EXPECT_EQ(results[r][9], "ok");
    for (std::size_t c = 2; c <= 6; ++c) {
      const double level = number(results[r][c]);
      EXPECT_TRUE(level > 40 && level < 140) << results[r][0] << " " << results[r][1] << " " << results[0][c];
    }
  }
  EXPECT_EQ(cases.size(), 9u);
  for (const std::string surface : {"dac11", "sma11", "chipseal"})
    for (const std::string speed : {"13.889", "22.222", "30.556"}) EXPECT_TRUE(cases.count(surface + "@" + speed));
  EXPECT_EQ(first_line(study / "spectra.csv"), "road.surface,rolling.speed,receiver,band_hz,Lp_dB,LpA_dB");
  for (const std::string stem : {"level_speed_cpx_front", "difference_to_reference", "spectra_speed_22.222"}) {
    expect_plot(study, stem);
    EXPECT_TRUE(fs::exists(study / (stem + ".dat"))) << stem;
  }
  const nlohmann::json summary = read_json(study / "summary.json");
  EXPECT_EQ(summary["cases"]["ok"], 9);
  // The second run kept every case; the case rerun alone gave the study's spectrum.
  EXPECT_TRUE(contains(run.log, "9 cases, 9 ok (9 from an earlier run), 0 failed")) << run.log;
  EXPECT_TRUE(contains(run.log, "the same spectrum")) << run.log;
  expect_tyre_sound(run.out / "sma11_80kmh", false);
}

TEST(Tutorials, CalibrateTyreRunsAsWritten) {
  Workspace ws;
  const ScriptRun run = run_tutorial(ws, "calibrate-tyre");
  ASSERT_EQ(run.status, 0) << run.log;
  // The synthetic data were made with these values (data/mobility/README.md): the fit finds
  // them within a few standard errors, from the CSV files and from the UFF file alike.
  const std::map<std::string, double> truth = {
      {"tension_x", 5.2e4}, {"bending_x", 5.5}, {"foundation_stiffness", 2.7e6}, {"loss_factor", 0.08}};
  const nlohmann::json csv = read_json(run.out / "from_csv" / "report.json");
  const nlohmann::json uff = read_json(run.out / "from_uff" / "report.json");
  for (const auto& [name, value] : truth) {
    const double fitted = csv["parameters"][name]["value"].get<double>();
    const double error = csv["parameters"][name]["std_error"].get<double>();
    EXPECT_LT(std::abs(fitted - value), 4 * error) << name << " " << fitted << " +- " << error;
    EXPECT_NEAR(uff["parameters"][name]["value"].get<double>(), fitted, 1e-6 * std::abs(fitted)) << name;
  }
  for (const std::string dir : {"from_csv", "from_uff"}) {
    EXPECT_TRUE(starts_with(read_text(run.out / dir / "calibrated.toml"), "# Calibrated by `rollnoise calibrate`"));
    EXPECT_EQ(first_line(run.out / dir / "fit.csv").rfind("frf,", 0), 0u) << first_line(run.out / dir / "fit.csv");
    expect_plot(run.out / dir, "fit");
  }
  EXPECT_TRUE(contains(run.log, "#   tension_x = ")) << run.log;
  expect_tyre_sound(run.out / "rough_calibrated");
  expect_tyre_sound(run.out / "rough_estimated");
  // The calibrated belt is another tyre: its levels differ from the estimated one's.
  const double calibrated = read_json(run.out / "rough_calibrated" / "summary.json")["levels"]["cpx_front"]["LAeq_dB"];
  const double estimated = read_json(run.out / "rough_estimated" / "summary.json")["levels"]["cpx_front"]["LAeq_dB"];
  EXPECT_GT(std::abs(calibrated - estimated), 0.01);
}

TEST(Tutorials, AuralisePassByRunsAsWritten) {
  Workspace ws;
  const ScriptRun run = run_tutorial(ws, "auralise-pass-by");
  ASSERT_EQ(run.status, 0) << run.log;
  expect_tyre_sound(run.out / "80kmh");
  expect_tyre_sound(run.out / "50kmh");
  // The WAV files, measured as recordings, give back the levels simulate reported.
  const nlohmann::json simulated = read_json(run.out / "80kmh" / "summary.json");
  const nlohmann::json analysed = read_json(run.out / "cpx_front_80kmh" / "summary.json");
  EXPECT_EQ(analysed["full_scale_pa"], simulated["full_scale_pa"]);
  EXPECT_NEAR(analysed["levels"]["ch1"]["LAeq_dB"].get<double>(), simulated["levels"]["cpx_front"]["LAeq_dB"].get<double>(), 0.01);
  const double fast = read_json(run.out / "passby_80kmh" / "summary.json")["levels"]["ch1"]["LAFmax_dB"];
  const double slow = read_json(run.out / "passby_50kmh" / "summary.json")["levels"]["ch1"]["LAFmax_dB"];
  EXPECT_NEAR(fast, simulated["levels"]["spb_passby"]["LAFmax_dB"].get<double>(), 0.01);
  EXPECT_GT(fast, slow) << "the faster pass-by is the louder";
  for (const std::string dir : {"cpx_front_80kmh", "passby_80kmh", "passby_50kmh"}) {
    EXPECT_EQ(first_line(run.out / dir / "spectrum.csv"), "receiver,band_hz,Lp_dB,LpA_dB");
    expect_plot(run.out / dir, "spectrum");
  }
}

TEST(Tutorials, MpiStudyRunsAsWritten) {
#if ROLLNOISE_TEST_MPI
  Workspace ws;
  const ScriptRun run = run_tutorial(ws, "mpi-study");
  ASSERT_EQ(run.status, 0) << run.log;
  ASSERT_FALSE(contains(run.log, "mpi-study: skipped")) << run.log;
  const nlohmann::json summary = read_json(run.out / "mpi" / "summary.json");
  EXPECT_EQ(summary["ranks"], 2);
  const auto results = csv_rows(run.out / "mpi" / "results.csv");
  ASSERT_EQ(results.size(), 5u);
  for (std::size_t r = 1; r < results.size(); ++r) EXPECT_EQ(results[r].back(), "ok");
  EXPECT_TRUE(contains(run.log, "the same results")) << run.log;
  // The rerun after one case was removed ran that case alone.
  EXPECT_TRUE(contains(run.log, "4 cases, 4 ok (3 from an earlier run), 0 failed")) << run.log;
  EXPECT_TRUE(fs::exists(run.out / "mpi" / "cases" / "surface-pa16_speed-30.556" / "summary.json"));
#else
  GTEST_SKIP() << "built without MPI (ROLLNOISE_MPI=OFF): the MPI tutorial is not run";
#endif
}

// The folders of out/demo/ that Getting started names are those tools/demo.sh writes.
TEST(Tutorials, GettingStartedNamesTheDemosOutputs) {
  const std::string page = read_text(source_dir() / "docs" / "getting-started.md");
  const std::string demo = read_text(source_dir() / "tools" / "demo.sh");
  std::set<std::string> written;
  static const std::regex literal(R"(\$out/([A-Za-z0-9_]+))");
  for (std::sregex_iterator it(demo.begin(), demo.end(), literal), end; it != end; ++it) written.insert((*it)[1]);
  // `for case in models/cases/PATTERN.toml`: each case into $out/<its name>.
  static const std::regex loop(R"(models/cases/([A-Za-z0-9_]*)\*\.toml)");
  for (std::sregex_iterator it(demo.begin(), demo.end(), loop), end; it != end; ++it)
    for (const auto& entry : fs::directory_iterator(source_dir() / "models" / "cases")) {
      const std::string stem = entry.path().stem().string();
      if (entry.path().extension() == ".toml" && stem.rfind((*it)[1].str(), 0) == 0) written.insert(stem);
    }
  // A case named in full (models/cases/NAME.toml) into $out/NAME.
  static const std::regex named_case(R"(models/cases/([A-Za-z0-9_]+)\.toml)");
  for (std::sregex_iterator it(demo.begin(), demo.end(), named_case), end; it != end; ++it) written.insert((*it)[1]);
  ASSERT_TRUE(written.count("plate_rough_80kmh") && written.count("figures")) << "tools/demo.sh changed its form";
  std::set<std::string> named;
  static const std::regex on_page(R"(out/demo/([A-Za-z0-9_]+))");
  for (std::sregex_iterator it(page.begin(), page.end(), on_page), end; it != end; ++it) named.insert((*it)[1]);
  EXPECT_GE(named.size(), 5u);
  for (const std::string& name : named) EXPECT_TRUE(written.count(name)) << "out/demo/" << name << " is not written by tools/demo.sh";
}

}  // namespace
