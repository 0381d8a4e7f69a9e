// docs/reference/outputs.md against the program: each verb is run on small, cheap cases (a
// radiating tyre among them, on a coarse radiation mesh), and every file it writes, every
// column of every CSV and every top-level key of summary.json / report.json must be described
// in that verb's section of the page. Per-point and per-receiver names are matched in the
// documented form: force_1 as force_i, cpx_front.wav as <receiver>.wav, a study's varied key
// column as <key>, a cache entry's digest as <key>.
// Cost: 18-20 s wall, 10 s CPU for the eight tests (2026-11-27, 2 cores shared, load average 6-8).
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <regex>
#include <string>
#include <string_view>
#include <vector>

#include "cli_workspace.hpp"

namespace {
using namespace cli_test;

const fs::path kSource(ROLLNOISE_SOURCE_DIR);
const fs::path kOutputs = kSource / "docs" / "reference" / "outputs.md";

// Pieces joined by appending (GCC 12 warns falsely, -Wrestrict, on "text" + std::string).
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) out += p;
  return out;
}

std::string source_file(const std::string& relative) { return (kSource / relative).string(); }

// The text under "## TITLE" up to the next "## " heading; fails the test when it is missing.
std::string section(const std::string& title) {
  const std::string doc = read_text(kOutputs);
  const std::string heading = cat({"\n## ", title, "\n"});
  const std::size_t at = doc.find(heading);
  EXPECT_NE(at, std::string::npos) << "docs/reference/outputs.md has no heading '## " << title << "'";
  if (at == std::string::npos) return {};
  const std::size_t end = doc.find("\n## ", at + heading.size());
  return doc.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

// `name` written as code: a backtick, the name, and no further character of a longer name.
bool mentions(const std::string& text, const std::string& name) {
  const std::string code = cat({"`", name});
  for (std::size_t at = text.find(code); at != std::string::npos; at = text.find(code, at + 1)) {
    const std::size_t after = at + code.size();
    if (after >= text.size()) return true;
    const char c = text[after];
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) return true;
  }
  return false;
}

const std::vector<std::string> kReceivers = {"spb_passby", "cpx_front", "cpx_rear", "spb"};  // longest first

// The documented form of a name: receivers as <receiver>, a trailing per-point number as _i,
// varied study keys as <key>, digests as <key>.
std::string documented_form(std::string name, const std::vector<std::string>& varied_keys = {}) {
  for (const std::string& key : varied_keys)
    if (name == key) return "<key>";
  static const std::regex digest_fits(R"(^[A-Za-z_]+-[0-9a-f]{8,}-fit-[0-9a-f]{8,}\.fits$)");
  static const std::regex digest(R"(^([A-Za-z_]+)-[0-9a-f]{8,}\.h5$)");
  static const std::regex temporary(R"(^\..*\.tmp[0-9]+$)");
  if (std::regex_match(name, digest_fits)) return "<key>-fit-<key>.fits";
  if (std::regex_match(name, temporary)) return ".<name>.tmp<digits>";
  std::smatch m;
  if (std::regex_match(name, m, digest)) return cat({m[1].str(), "-<key>.h5"});
  static const std::regex speed(R"(^spectra_speed_[0-9.]+(\.[a-z]+)$)");
  if (std::regex_match(name, m, speed)) return cat({"spectra_speed_<speed>", m[1].str()});
  for (const std::string& r : kReceivers) {
    for (std::size_t at = name.find(r); at != std::string::npos; at = name.find(r, at + 1)) {
      const bool starts = at == 0 || name[at - 1] == '_';
      const bool ends = at + r.size() == name.size() || name[at + r.size()] == '_' || name[at + r.size()] == '.';
      if (starts && ends) {
        name.replace(at, r.size(), "<receiver>");
        break;
      }
    }
  }
  static const std::regex numbered(R"(^(.*_)[0-9]+$)");
  if (std::regex_match(name, m, numbered)) return cat({m[1].str(), "i"});
  return name;
}

// Checks a name: documented as it is, or in its documented form.
void expect_documented(const std::string& text, const std::string& name, const std::string& what,
                       const std::vector<std::string>& varied_keys = {}) {
  const std::string form = documented_form(name, varied_keys);
  EXPECT_TRUE(mentions(text, name) || mentions(text, form))
      << what << " '" << name << "' (documented form '" << form << "') is not described in docs/reference/outputs.md";
}

// The column names of a CSV: its first line that is not a comment.
std::vector<std::string> csv_columns(const fs::path& file) {
  std::istringstream in(read_text(file));
  std::string line;
  while (std::getline(in, line) && starts_with(line, "#")) {
  }
  std::vector<std::string> columns;
  std::istringstream cells(line);
  for (std::string cell; std::getline(cells, cell, ',');) columns.push_back(cell);
  return columns;
}

// Every file in `folder` (not in its subfolders, not hidden), its CSV columns and its JSON keys
// against `text`. Returns how many names were checked.
std::size_t check_folder(const fs::path& folder, const std::string& text, const std::string& verb,
                         const std::vector<std::string>& varied_keys = {}) {
  std::size_t checked = 0;
  EXPECT_TRUE(fs::is_directory(folder)) << folder;
  if (!fs::is_directory(folder)) return 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || starts_with(name, ".")) continue;
    ++checked;
    expect_documented(text, name, cat({verb, " writes the file"}));
    const std::string ext = entry.path().extension().string();
    if (ext == ".csv") {
      const std::vector<std::string> columns = csv_columns(entry.path());
      EXPECT_FALSE(columns.empty()) << entry.path();
      for (const std::string& column : columns) {
        ++checked;
        expect_documented(text, column, cat({verb, ": ", name, " has the column"}), varied_keys);
      }
    }
    if (name == "summary.json" || name == "report.json") {
      const nlohmann::json json = read_json(entry.path());
      EXPECT_TRUE(json.is_object()) << entry.path();
      for (const auto& [key, value] : json.items()) {
        ++checked;
        expect_documented(text, key, cat({verb, ": ", name, " has the key"}));
      }
    }
  }
  return checked;
}

std::vector<std::string> with(std::vector<std::string> args, std::initializer_list<std::string> more) {
  args.insert(args.end(), more);
  return args;
}

// A radiating plate tyre kept cheap: the coarse radiation mesh of tests/cli, anchors every 250 Hz
// to 1.5 kHz, the 512-cell grid (band_top = 0). `plots` false drops the PNGs and their data.
std::vector<std::string> cheap_sound(bool plots) {
  return {"--set", "radiation.mesh_around=32",      "--set", "radiation.mesh_across=4",
          "--set", "radiation.sidewall_rings=4",    "--set", "radiation.max_frequency=1500",
          "--set", "radiation.anchor_spacing=250",  "--set", "radiation.contact_refinement=3",
          "--set", "rolling.band_top=0",            "--set", plots ? "output.plots=true" : "output.plots=false"};
}

// The passenger two-layer tyre cut to 16 orders and 3 lateral modes: its modes in a second.
std::string small_two_layer() {
  std::string text = read_text(kSource / "models" / "tyres" / "passenger_205_55R16_two_layer.toml");
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"circumferential_modes = 256", "circumferential_modes = 16"},
                                 {"lateral_modes = 25", "lateral_modes = 3"}}) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  return text;
}

TEST(OutputReference, SimulatePointModels) {
  Workspace ws;
  const std::string text = section("simulate");
  std::size_t checked = 0;
  for (const char* name : {"larsson2000_sdof_sine", "larsson2000_coupled_sine"}) {
    const RunResult r = ws.run({"simulate", source_file(cat({"models/cases/", name, ".toml"})), "--out", name, "--set",
                                "rolling.duration=0.02"});
    ASSERT_EQ(r.status, 0) << describe(r);
    checked += check_folder(ws.path(name), text, "simulate (point model)");
  }
  EXPECT_TRUE(contains(first_line(ws.path("larsson2000_coupled_sine") / "contact.csv"), "force_2"));
  EXPECT_GE(checked, 20u);
}

// Every file a tyre can write: the sound with the budget and the WAV files, a whole revolution
// (0.05 s at 40 m/s), contact.h5 with every field; its own cache, whose entries are checked too.
TEST(OutputReference, SimulateTyreWithSound) {
  Workspace ws;
  std::vector<std::string> args = {"simulate", source_file("models/cases/plate_rough_80kmh.toml"), "--out", "tyre",
                                   "--cache", "cache", "--set", "rolling.duration=0.05", "--set", "rolling.speed=40",
                                   "--set", "output.fields=all"};
  const std::vector<std::string> sound = cheap_sound(true);
  args.insert(args.end(), sound.begin(), sound.end());
  const RunResult r = ws.run(args);
  ASSERT_EQ(r.status, 0) << describe(r);
  for (const char* file : {"budget.csv", "revolution.csv", "spb_passby.wav", "cpx_front.wav", "contact.h5", "sound_power.csv"})
    EXPECT_TRUE(fs::exists(ws.path("tyre") / file)) << file << " was expected from this case";
  EXPECT_GE(check_folder(ws.path("tyre"), section("simulate"), "simulate (tyre)"), 100u);
  EXPECT_GE(check_folder(ws.path("cache"), section("The cache folder"), "the cache"), 1u);
}

// A tyre with a tread pattern: its map and tones (a few steps, no sound).
TEST(OutputReference, SimulateTyreWithPattern) {
  Workspace ws;
  const RunResult r = ws.run({"simulate", source_file("models/cases/plate_patterned_rough_80kmh.toml"), "--out", "tyre",
                              "--set", "rolling.duration=0.002", "--set", "radiation.enabled=false"});
  ASSERT_EQ(r.status, 0) << describe(r);
  for (const char* file : {"tread_pattern.csv", "tread_pattern.gp"})
    EXPECT_TRUE(fs::exists(ws.path("tyre") / file)) << file << " was expected from this case";
  check_folder(ws.path("tyre"), section("simulate"), "simulate (patterned tyre)");
}

// A two-layer tyre: its mode fit in summary.json, and its table and fits in the cache.
TEST(OutputReference, SimulateTwoLayerTyre) {
  Workspace ws;
  ws.write("two_layer.toml", small_two_layer());
  const RunResult r = ws.run({"simulate", source_file("models/cases/two_layer_smooth_80kmh.toml"), "--out", "tyre",
                              "--cache", "cache", "--set", cat({"tyre.file=\"", ws.path("two_layer.toml").string(), "\""}),
                              "--set", "rolling.duration=0.003", "--set", "rolling.band_top=0"});
  ASSERT_EQ(r.status, 0) << describe(r);
  ASSERT_TRUE(read_json(ws.path("tyre") / "summary.json").contains("mode_fit"));
  check_folder(ws.path("tyre"), section("simulate"), "simulate (two_layer)");
  EXPECT_GE(check_folder(ws.path("cache"), section("The cache folder"), "the cache"), 2u);
}

// A 1 kHz tone as a 16-bit WAV without rollnoise's comment, so --full-scale gives the scale.
void write_tone_wav(const fs::path& path) {
  constexpr std::uint32_t rate = 48000, frames = 48000;
  std::string bytes;
  const auto u32 = [&bytes](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes += static_cast<char>((v >> (8 * i)) & 0xff);
  };
  const auto u16 = [&bytes](std::uint32_t v) {
    for (int i = 0; i < 2; ++i) bytes += static_cast<char>((v >> (8 * i)) & 0xff);
  };
  bytes += "RIFF";
  u32(36 + 2 * frames);
  bytes += "WAVEfmt ";
  u32(16);
  u16(1);  // PCM
  u16(1);  // mono
  u32(rate);
  u32(2 * rate);
  u16(2);
  u16(16);
  bytes += "data";
  u32(2 * frames);
  for (std::uint32_t n = 0; n < frames; ++n) {
    const double s = 0.5 * std::sin(2.0 * 3.141592653589793 * 1000.0 * n / rate);
    u16(static_cast<std::uint32_t>(static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(s * 32767.0)))));
  }
  write_text(path, bytes);
}

TEST(OutputReference, Analyse) {
  Workspace ws;
  write_tone_wav(ws.path("tone.wav"));
  const RunResult r = ws.run({"analyse", "tone.wav", "--full-scale", "2", "--out", "tone"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_GE(check_folder(ws.path("tone"), section("analyse"), "analyse"), 10u);
}

TEST(OutputReference, Calibrate) {
  Workspace ws;
  const RunResult r = ws.run({"calibrate", source_file("models/tyres/larsson2000_sdof.toml"), "--data",
                              source_file("data/mobility/sdof_point_mobility.csv"), "--out", "fit"});
  ASSERT_EQ(r.status, 0) << describe(r);
  EXPECT_GE(check_folder(ws.path("fit"), section("calibrate"), "calibrate"), 30u);
}

// A texture surface on three lines (target.csv, z_i, [about]); a long ISO 8608 road (the class
// and G_d(n0)); a road shorter than one MPD segment (mpd_note); a measured laser profile; a porous
// road with its ground effect (absorption.csv, ground_effect.csv).
TEST(OutputReference, Road) {
  Workspace ws;
  ws.write("uneven.toml", "type = \"iso8608\"\nclass = \"C\"\nseed = 3\n");
  const std::vector<std::vector<std::string>> runs = {
      {"road", source_file("models/surfaces/chipseal.toml"), "--out", "texture", "--length", "1", "--lines", "3"},
      {"road", "uneven.toml", "--out", "uneven", "--length", "60", "--spacing", "0.001"},
      {"road", source_file("models/surfaces/dac11.toml"), "--out", "short", "--length", "0.05"},
      {"road", source_file("data/surfaces/captif/20211011_aylesbury_dec_station_0.dat"), "--out", "laser"},
      {"road", source_file("models/surfaces/pa16.toml"), "--out", "porous", "--length", "0.5", "--ground-effect",
       "0.05,7.5,1.2"}};
  const std::string text = section("road");
  for (const auto& args : runs) {
    const RunResult r = ws.run(args);
    ASSERT_EQ(r.status, 0) << describe(r);
    check_folder(ws.path(args[3]), text, "road");
  }
  EXPECT_TRUE(fs::exists(ws.path("texture") / "target.csv"));
  EXPECT_TRUE(read_json(ws.path("uneven") / "summary.json").contains("gd_n0_m3"));
  EXPECT_TRUE(read_json(ws.path("short") / "summary.json").contains("mpd_note"));
  EXPECT_TRUE(fs::exists(ws.path("porous") / "ground_effect.csv"));
}

// A point model (green_time.csv), the plate (the circumference), a small two-layer tyre
// (modal_receptance.h5, dispersion.csv) and that table read back as a tabulated tyre.
TEST(OutputReference, Greens) {
  Workspace ws;
  ws.write("two_layer.toml", small_two_layer());
  ws.write("tabulated.toml", "model = \"tabulated\"\nfile = \"two_layer/modal_receptance.h5\"\n");
  const std::vector<std::string> grid = {"--frequencies", "0:2000:21", "--cache", "cache"};
  const std::vector<std::vector<std::string>> runs = {
      with({"greens", source_file("models/tyres/larsson2000_sdof.toml"), "--out", "sdof"}, {"--frequencies", "0:200:21"}),
      with({"greens", source_file("models/tyres/passenger_205_55R16.toml"), "--out", "plate"}, {"--distances", "0,0.1"}),
      with({"greens", "two_layer.toml", "--out", "two_layer"}, {"--distances", "0,0.1"}),
      with({"greens", "tabulated.toml", "--out", "tabulated"}, {"--distances", "0,0.1"})};
  const std::string text = section("greens");
  for (std::size_t k = 0; k < runs.size(); ++k) {
    std::vector<std::string> args = runs[k];
    if (k > 0) args.insert(args.end(), grid.begin(), grid.end());
    const RunResult r = ws.run(args);
    ASSERT_EQ(r.status, 0) << describe(r);
    check_folder(ws.path(args[3]), text, "greens");
  }
  EXPECT_TRUE(fs::exists(ws.path("sdof") / "green_time.csv"));
  EXPECT_TRUE(fs::exists(ws.path("two_layer") / "dispersion.csv"));
  EXPECT_TRUE(read_json(ws.path("tabulated") / "summary.json").contains("table"));
  check_folder(ws.path("cache"), section("The cache folder"), "the cache");
}

// Two surfaces (one the reference) at two speeds: every plot a study draws. The cases' own
// folders are simulate's outputs with their case.toml.
TEST(OutputReference, Study) {
  Workspace ws;
  std::string study = cat({"[study]\nname = \"tiny\"\ncase = \"", source_file("models/cases/plate_rough_80kmh.toml"),
                           "\"\nreference_surface = \"", source_file("models/surfaces/dac11.toml"), "\"\n[set]\n",
                           "rolling.duration = 0.01\nrolling.band_top = 0\noutput.wav = false\noutput.plots = false\n",
                           "radiation.mesh_around = 32\nradiation.mesh_across = 4\nradiation.sidewall_rings = 4\n",
                           "radiation.max_frequency = 1500\nradiation.anchor_spacing = 250\nradiation.contact_refinement = 3\n",
                           "[vary]\nroad.surface = [\"", source_file("models/surfaces/dac11.toml"), "\", \"",
                           source_file("models/surfaces/tined.toml"), "\"]\nrolling.speed = [20.0, 30.0]\n"});
  ws.write("tiny.toml", study);
  const RunResult r = ws.run({"study", "tiny.toml", "--out", "study", "--cache", "cache"});
  ASSERT_EQ(r.status, 0) << describe(r);
  const std::vector<std::string> varied = {"road.surface", "rolling.speed"};
  EXPECT_GE(check_folder(ws.path("study"), section("study"), "study", varied), 40u);
  for (const char* file : {"difference_to_reference.dat", "level_speed_cpx_front.dat", "spectra_speed_20.dat"})
    EXPECT_TRUE(fs::exists(ws.path("study") / file)) << file << " was expected from this study";
  // cases/<id>/: documented under simulate (case.toml there too), the folder under study.
  const std::string simulate = section("simulate");
  std::size_t cases = 0;
  for (const auto& entry : fs::directory_iterator(ws.path("study") / "cases")) {
    if (starts_with(entry.path().filename().string(), ".")) continue;
    ++cases;
    check_folder(entry.path(), simulate, "a study case");
  }
  EXPECT_EQ(cases, 4u);
  EXPECT_TRUE(mentions(section("study"), "cases/<id>/"));
}

}  // namespace
