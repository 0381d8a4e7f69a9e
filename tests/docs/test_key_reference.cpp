// The input-file reference cannot drift from the readers. The program is asked, as a user would
// meet it, for the keys each configuration accepts: a case (or study, or calibration) with a key
// it does not know, `zz_probe`, fails with exit status 2 and a message that lists the allowed
// keys (core/config_table.cpp: every key a reader looked up). Each listed key must be documented
// under the heading of that configuration in docs/reference/, and each key documented there must
// be accepted by some configuration the heading covers. Likewise the values of every key that
// takes one of a list (from an unknown value), the models, treads and road types that make the
// configurations, what `rollnoise calibrate` fits, and what `rollnoise study` knows.
//
// The pages' convention (stated at the end of case-files.md): a key is the first cell of a table
// row, in backticks (| `speed` | m/s | ...); the rows belong to the nearest heading above them.
// A row whose first cell also says "(library file)" names a file merged into the section when the
// case is loaded ([tyre] file, [road] surface): no section reader lists it, so it is exempt from
// the check for stale keys.
//
// Every probe fails before any heavy work: the readers reject unknown keys as they read their
// table, before the road is generated or the contact solved (a tyre's [road] is read last, after
// the tyre's modes are set up on a 1 ms run: about 0.1 s); they run four at a time. On 2 cores
// (AMD EPYC) under a load of 6-8, 2026-11-27: 3.4-4.7 s for the 8 tests in one process, 6-7 s
// run one test per process as ctest does.
#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "markdown_pages.hpp"

namespace {
namespace fs = std::filesystem;
using cli_test::contains;
using cli_test::describe;
using cli_test::read_text;
using cli_test::RunResult;
using cli_test::Workspace;

// ---------------------------------------------------------------------------------------------
// The pages

struct Row {
  std::string key;
  bool library_file = false;
  std::size_t line = 0;
  std::vector<std::string> cells;  // all of them, the key's first
};

struct Heading {
  std::string text;  // without the #s
  std::size_t line = 0;
  std::vector<Row> rows;  // the key rows directly under it (before the next heading)
};

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

// The headings of a page (outside fenced code) with their key rows.
std::vector<Heading> read_page(const std::string& text) {
  std::vector<Heading> headings{{"", 0, {}}};  // rows before the first heading
  std::istringstream in(text);
  std::string line;
  bool fenced = false;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    const std::string t = trim(line);
    if (t.rfind("```", 0) == 0 || t.rfind("~~~", 0) == 0) {
      fenced = !fenced;
      continue;
    }
    if (fenced) continue;
    std::size_t level = 0;
    while (level < line.size() && line[level] == '#') ++level;
    if (level >= 1 && level <= 6 && level < line.size() && line[level] == ' ') {
      headings.push_back({trim(line.substr(level + 1)), n, {}});
      continue;
    }
    if (t.empty() || t[0] != '|') continue;
    // The first cell: up to the first unescaped '|' after the opening one.
    std::size_t end = 1;
    while (end < t.size() && !(t[end] == '|' && t[end - 1] != '\\')) ++end;
    const std::string cell = t.substr(1, end - 1);
    const auto open = cell.find('`');
    if (open == std::string::npos) continue;  // a header or separator row
    const auto close = cell.find('`', open + 1);
    if (close == std::string::npos) continue;
    Row row{cell.substr(open + 1, close - open - 1), contains(cell, "(library file)"), n, {}};
    for (std::size_t from = 1; from < t.size();) {
      std::size_t to = from;
      while (to < t.size() && !(t[to] == '|' && t[to - 1] != '\\')) ++to;
      row.cells.push_back(trim(t.substr(from, to - from)));
      from = to + 1;
    }
    headings.back().rows.push_back(std::move(row));
  }
  return headings;
}

const std::vector<Heading>& page(const std::string& name) {
  static std::map<std::string, std::vector<Heading>> pages;
  auto it = pages.find(name);
  if (it == pages.end()) {
    const fs::path file = docs_test::source_dir() / "docs" / "reference" / name;
    EXPECT_TRUE(fs::is_regular_file(file)) << file;
    it = pages.emplace(name, read_page(read_text(file))).first;
  }
  return it->second;
}

// ---------------------------------------------------------------------------------------------
// Asking the program

// The items after `marker` on its line: the quoted strings ("a", "b") when there are any, else
// the plain list "a, b and c".
std::vector<std::string> list_after(const std::string& text, const std::string& marker) {
  const auto at = text.find(marker);
  if (at == std::string::npos) return {};
  const auto start = at + marker.size();
  std::string rest = text.substr(start, text.find('\n', start) - start);
  std::vector<std::string> items;
  if (contains(rest, "\"")) {
    static const std::regex quoted("\"([^\"]*)\"");
    for (auto m = std::sregex_iterator(rest.begin(), rest.end(), quoted); m != std::sregex_iterator(); ++m)
      items.push_back((*m)[1].str());
    return items;
  }
  for (std::size_t and_at; (and_at = rest.find(" and ")) != std::string::npos;) rest.replace(and_at, 5, ", ");
  std::istringstream in(rest);
  for (std::string item; std::getline(in, item, ',');)
    if (!trim(item).empty()) items.push_back(trim(item));
  return items;
}

struct Probe {
  std::string name;                          // for messages
  std::string page;                          // under docs/reference/
  std::vector<std::string> headings;         // where its keys are documented
  std::string section;                       // the case section its keys belong to ("" none)
  std::map<std::string, std::string> files;  // written into the workspace first
  std::vector<std::string> args;             // the command line
  std::string marker;                        // what precedes the list in the message
};

// The list the program gives (empty, with a failure, when it gives none).
std::vector<std::string> ask(const Probe& probe) {
  Workspace ws;
  for (const auto& [name, text] : probe.files) ws.write(name, text);
  const RunResult r = ws.run(probe.args);
  EXPECT_EQ(r.status, 2) << probe.name << ": " << describe(r);
  std::vector<std::string> listed = list_after(r.err, probe.marker);
  EXPECT_FALSE(listed.empty()) << probe.name << ": no list after \"" << probe.marker << "\"\n" << describe(r);
  return listed;
}

// Each probe is asked once, whichever test needs it first (a std::map's elements stay put).
std::mutex answers_mutex;
std::map<std::string, std::vector<std::string>> answered;

// Asks those of `probes` not asked yet, four at a time (each is a short process).
void ask_all(const std::vector<Probe>& probes) {
  std::vector<const Probe*> todo;
  {
    const std::lock_guard<std::mutex> lock(answers_mutex);
    for (const Probe& p : probes)
      if (!answered.count(p.name)) todo.push_back(&p);
  }
  std::atomic<std::size_t> next{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      for (std::size_t i; (i = next++) < todo.size();) {
        std::vector<std::string> listed = ask(*todo[i]);
        const std::lock_guard<std::mutex> lock(answers_mutex);
        answered.emplace(todo[i]->name, std::move(listed));
      }
    });
  for (std::thread& t : threads) t.join();
}

const std::vector<std::string>& answer(const Probe& probe) {
  ask_all({probe});
  const std::lock_guard<std::mutex> lock(answers_mutex);
  return answered.at(probe.name);
}

std::string source(const std::string& relative) { return (docs_test::source_dir() / relative).string(); }

// TOML text of a string.
std::string quoted(const std::string& text) { return "\"" + text + "\""; }

const std::string kUnknownKey = ": unknown key; allowed keys here are ";

// A point-model case: the paper's SDOF (its model file) with `road`.
std::string point_case(const std::string& road) {
  return "[tyre]\nfile = " + quoted(source("models/tyres/larsson2000_sdof.toml")) + "\n[road]\n" + road +
         "\n[rolling]\nspeed = 1.0\nduration = 0.01\ntime_step = 1.0e-4\nstatic_load = 4.0\n";
}

// A tyre case of 1 ms without radiation: the plate file's 205/55 R16 unless `tyre` is given.
std::string tyre_case(const std::string& road, const std::string& tyre = "") {
  const std::string t = tyre.empty() ? "file = " + quoted(source("models/tyres/passenger_205_55R16.toml")) + "\n" : tyre;
  return "[tyre]\n" + t + "\n[road]\n" + road +
         "\n[rolling]\nspeed = 20.0\nduration = 0.001\nstatic_load = 3000.0\n[radiation]\nenabled = false\n";
}

Probe simulate(std::string name, std::vector<std::string> headings, std::string section, std::string case_text,
               std::vector<std::string> extra = {}, std::string where = "") {
  Probe p;
  p.name = std::move(name);
  p.page = "case-files.md";
  p.headings = std::move(headings);
  p.files["case.toml"] = std::move(case_text);
  p.args = {"simulate", "case.toml", "--out", "out"};
  for (auto& a : extra) p.args.push_back(std::move(a));
  if (where.empty()) {
    p.args.push_back("--set");
    p.args.push_back(section + ".zz_probe=1");
    where = "[" + section + "] zz_probe";
  }
  p.section = std::move(section);
  p.marker = where + kUnknownKey;
  return p;
}

// The road types, with the keys each needs before its reader gets to the unknown one.
struct RoadType {
  std::string type;
  std::string keys;
};
const std::vector<RoadType>& road_types() {
  static const std::vector<RoadType> types = {
      {"flat", ""},
      {"sine", "amplitude = 1.0e-3\nwavelength = 0.1\n"},
      {"cleat", "height = 1.0e-3\nlength = 0.01\n"},
      {"random", "std_dev = 1.0e-3\ncorrelation_length = 0.01\n"},
      {"random_surface", "std_dev = 1.0e-3\ncorrelation_length = 0.01\n"},
      {"iso8608", "class = \"A\"\n"},
      {"texture", "wavelengths = [0.01]\nlevels = [40.0]\n"},
      {"aggregate", "max_chip_size = 0.01\n"},
      {"file", "file = \"profile.csv\"\n"},
      {"surface", "file = \"map.csv\"\n"},
      {"profile_surface", "file = \"profile.csv\"\n"},
  };
  return types;
}

std::string road_heading(const std::string& type) {
  if (type == "random" || type == "random_surface") return "type = \"random\" or \"random_surface\"";
  return "type = " + quoted(type);
}

bool point_road(const std::string& type) {
  return type != "random_surface" && type != "surface" && type != "profile_surface";
}

// The type a library surface file gives.
std::string surface_type(const fs::path& file) {
  static const std::regex type_line(R"re(^type\s*=\s*"(\w+)")re");
  std::istringstream in(read_text(file));
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, type_line)) return m[1].str();
  }
  return "";
}

std::vector<fs::path> library_surfaces() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(docs_test::source_dir() / "models" / "surfaces"))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Every configuration of a case file.
const std::vector<Probe>& case_probes() {
  static const std::vector<Probe> probes = [] {
    std::vector<Probe> p;
    const std::string flat = "type = \"flat\"\n";
    p.push_back(simulate("sections", {"Sections"}, "", point_case(flat), {"--set", "zz_probe.x=1"},
                         "zz_probe"));
    p.back().marker = "zz_probe: unknown section; allowed sections are ";
    // [tyre], per model.
    const std::vector<std::string> point_model = {"[tyre]", "model = \"sdof\" or \"coupled_sdof\""};
    p.push_back(simulate("tyre sdof", point_model, "tyre", point_case(flat)));
    p.push_back(simulate("tyre coupled_sdof", point_model, "tyre",
                         "[tyre]\nmodel = \"coupled_sdof\"\nmass = 1.0\ndamping = 50.0\nstiffness = 500.0\n"
                         "contact_stiffness = 1.0e5\ncoupling = 0.4\nspacing = 0.01\n" +
                             point_case(flat).substr(point_case(flat).find("[road]"))));
    p.push_back(simulate("tyre plate", {"[tyre]", "model = \"plate\""}, "tyre", tyre_case(flat)));
    p.push_back(simulate("tyre two_layer", {"[tyre]", "model = \"two_layer\""}, "tyre",
                         tyre_case(flat, "file = " + quoted(source("models/tyres/passenger_205_55R16_two_layer.toml")))));
    p.push_back(simulate("tyre tabulated", {"[tyre]", "model = \"tabulated\""}, "tyre",
                         tyre_case(flat, "file = \"tabulated.toml\"")));
    p.back().files["tabulated.toml"] = "model = \"tabulated\"\nfile = \"table.h5\"\n";
    // [tyre.tread], per type: the case's table replaces the model file's.
    for (const auto& [type, keys] : std::vector<std::pair<std::string, std::string>>{
             {"winkler", "stiffness_per_area = 5.0e8"},
             {"halfspace", "youngs_modulus = 4.0e6"},
             {"nonlinear", "spring_stiffness = 1.0e12"}})
      p.push_back(simulate("tread " + type, {"[tyre.tread]", "type = " + quoted(type)}, "tyre.tread",
                           tyre_case(flat, "file = " + quoted(source("models/tyres/passenger_205_55R16.toml")) +
                                               "\n[tyre.tread]\ntype = " + quoted(type) + "\n" + keys +
                                               "\nzz_probe = 1\n"),
                           {}, "[tyre.tread] zz_probe"));
    // [tyre.pattern] and its rib tables.
    const std::string plate_file = "file = " + quoted(source("models/tyres/passenger_205_55R16.toml")) + "\n";
    p.push_back(simulate("tread pattern", {"[tyre.pattern]"}, "tyre.pattern",
                         tyre_case(flat, plate_file + "[tyre.pattern]\npitches = 8\ngroove_width = 0.005\n"
                                                      "groove_depth = 0.005\nzz_probe = 1\n"),
                         {}, "[tyre.pattern] zz_probe"));
    p.push_back(simulate("rib table", {"Rib tables"}, "tyre.pattern.ribs",
                         tyre_case(flat, plate_file + "[tyre.pattern]\n"
                                                      "ribs = [{position = 0.0, width = 0.005, depth = 0.001, zz_probe = 1}]\n"),
                         {}, "[tyre.pattern.ribs[1]] zz_probe"));
    // [road], per type, under a point model and under a tyre; and each library surface.
    for (const RoadType& road : road_types()) {
      const std::string table = "type = " + quoted(road.type) + "\n" + road.keys;
      if (point_road(road.type))
        p.push_back(simulate("road " + road.type + " (point model)", {"[road]", road_heading(road.type)}, "road",
                             point_case(table)));
      p.push_back(simulate("road " + road.type + " (tyre)", {"[road]", road_heading(road.type)}, "road",
                           tyre_case(table)));
    }
    for (const fs::path& file : library_surfaces())
      p.push_back(simulate("road surface " + file.filename().string(), {"[road]", road_heading(surface_type(file))},
                           "road", tyre_case("surface = " + quoted(file.string()) + "\n")));
    // [road.absorption]: one porous layer of each model (a layer of `layers` takes the same keys).
    const std::string layer = "porosity = 0.2\nflow_resistivity = 8000.0\ntortuosity = 3.5\nthickness = 0.045\n";
    p.push_back(simulate("road absorption hamet_berengier", {"[road.absorption]"}, "road.absorption",
                         point_case(flat + "[road.absorption]\nmodel = \"hamet_berengier\"\n" + layer)));
    p.push_back(simulate("road absorption jca", {"[road.absorption]"}, "road.absorption",
                         point_case(flat + "[road.absorption]\nmodel = \"jca\"\n" + layer +
                                    "viscous_length = 1.0e-4\nthermal_length = 3.0e-4\n")));
    // [rolling], [radiation] and its receiver tables, [output].
    p.push_back(simulate("rolling (point model)", {"Point models"}, "rolling", point_case(flat)));
    p.push_back(simulate("rolling (tyre)", {"Tyre models"}, "rolling", tyre_case(flat)));
    p.push_back(simulate("radiation", {"[radiation]"}, "radiation", tyre_case(flat)));
    p.push_back(simulate("receiver table", {"Receiver tables"}, "radiation.receivers",
                         tyre_case(flat), {"--set", "radiation.receivers=[{name = \"a\", x = 1.0, y = 0.0, z = 0.3, zz_probe = 1}]"},
                         "[radiation.receivers[1]] zz_probe"));
    p.push_back(simulate("output (point model)", {"[output]"}, "output", point_case(flat)));
    p.push_back(simulate("output (tyre)", {"[output]"}, "output", tyre_case(flat)));
    return p;
  }();
  return probes;
}

// What the program lists as the values of a choice that makes a configuration, from an unknown
// value: the tyre models, the tread types, the road types for point models and for tyres.
struct Choice {
  std::string name;
  std::string case_text;
  std::vector<std::string> extra;
  std::string where;
};

std::vector<std::string> choices(const Choice& c) {
  Probe p;
  p.name = c.name;
  p.files["case.toml"] = c.case_text;
  p.args = {"simulate", "case.toml", "--out", "out"};
  p.args.insert(p.args.end(), c.extra.begin(), c.extra.end());
  p.marker = c.where + ": unknown value \"zz_probe\"; allowed values are ";
  return ask(p);
}

// ---------------------------------------------------------------------------------------------
// The comparison

// Where each of `probes` documents its keys on its page: the rows under its headings.
std::map<std::string, std::vector<const Row*>> documented(const std::vector<Heading>& headings,
                                                          const std::vector<std::string>& wanted,
                                                          std::ostringstream& problems, const std::string& page_name) {
  std::map<std::string, std::vector<const Row*>> rows;
  for (const std::string& w : wanted) {
    std::size_t found = 0;
    for (const Heading& h : headings)
      if (h.text == w) {
        ++found;
        for (const Row& r : h.rows) rows[r.key].push_back(&r);
      }
    if (found != 1)
      problems << page_name << ": the heading \"" << w << "\" appears " << found << " times (once expected)\n";
  }
  return rows;
}

// The problems of a page against what the probes listed: a listed key not documented under the
// probe's headings, a documented key that no probe of its heading lists (unless it is a library
// file), and (with `every_table`) a table of keys under a heading no probe covers.
std::string compare(const std::string& page_name, const std::vector<Heading>& headings,
                    const std::vector<std::pair<const Probe*, std::vector<std::string>>>& answers, bool every_table) {
  std::ostringstream problems;
  std::map<std::string, std::set<std::string>> accepted;  // heading -> keys some probe lists
  for (const auto& [probe, listed] : answers) {
    const auto rows = documented(headings, probe->headings, problems, page_name);
    for (const std::string& key : listed) {
      if (!rows.count(key)) {
        problems << page_name << ": `" << key << "` (" << probe->name << ") is not documented under";
        for (const std::string& h : probe->headings) problems << " \"" << h << "\"";
        problems << "\n";
      }
      for (const std::string& h : probe->headings) accepted[h].insert(key);
    }
    for (const std::string& h : probe->headings) accepted[h];
  }
  for (const Heading& h : headings) {
    const auto it = accepted.find(h.text);
    if (it == accepted.end()) {
      if (every_table && !h.rows.empty())
        problems << page_name << ":" << h.line << ": \"" << h.text
                 << "\" documents keys, but no configuration of the test covers it\n";
      continue;
    }
    for (const Row& r : h.rows)
      if (!r.library_file && !it->second.count(r.key))
        problems << page_name << ":" << r.line << ": `" << r.key << "` under \"" << h.text
                 << "\" is accepted by no configuration there (stale, or mark it \"(library file)\")\n";
  }
  return problems.str();
}

std::string check_page(const std::string& page_name, const std::vector<Probe>& probes, bool every_table) {
  ask_all(probes);
  std::vector<std::pair<const Probe*, std::vector<std::string>>> answers;
  for (const Probe& p : probes)
    if (p.page == page_name) answers.emplace_back(&p, answer(p));
  return compare(page_name, page(page_name), answers, every_table);
}

// ---------------------------------------------------------------------------------------------
// Tests

TEST(KeyReference, TheComparisonFindsMissingAndStaleKeys) {
  const auto headings = read_page(
      "# Page\n## [x]\n| key | meaning |\n| --- | --- |\n| `a` | in both |\n| `c` | stale |\n"
      "| `lib` (library file) | exempt |\n```\n| `fenced` | not a row |\n```\n### Other\n| `d` | no probe |\n");
  Probe probe;
  probe.name = "x";
  probe.headings = {"[x]"};
  const std::string problems = compare("page.md", headings, {{&probe, {"a", "b"}}}, true);
  EXPECT_TRUE(contains(problems, "`b` (x) is not documented")) << problems;
  EXPECT_TRUE(contains(problems, "`c` under \"[x]\" is accepted by no configuration")) << problems;
  EXPECT_FALSE(contains(problems, "`a`")) << problems;
  EXPECT_FALSE(contains(problems, "`lib`")) << problems;
  EXPECT_FALSE(contains(problems, "fenced")) << problems;
  EXPECT_TRUE(contains(problems, "\"Other\" documents keys, but no configuration")) << problems;
  EXPECT_EQ(compare("page.md", headings, {{&probe, {"a", "c", "lib"}}}, false), "");
  // The lists of the messages, quoted and plain.
  EXPECT_EQ(list_after("x: allowed keys here are \"a\", \"b\"\nmore", "are "), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(list_after("[study] has name, case and reference_surface", "has "),
            (std::vector<std::string>{"name", "case", "reference_surface"}));
}

// Every key of every configuration of a case file is in docs/reference/case-files.md, under the
// heading of its section and configuration; nothing documented there is a key no reader takes.
TEST(KeyReference, CaseFilesDocumentEveryKeyTheReadersAccept) {
  const std::string problems = check_page("case-files.md", case_probes(), true);
  EXPECT_EQ(problems, "") << "docs/reference/case-files.md and the readers disagree:\n" << problems;
}

// The quoted values in backticks in `text`: `"auto"` gives auto.
std::set<std::string> quoted_values(const std::string& text) {
  static const std::regex value("`\"([^\"`]*)\"`");
  std::set<std::string> values;
  for (auto m = std::sregex_iterator(text.begin(), text.end(), value); m != std::sregex_iterator(); ++m)
    values.insert((*m)[1].str());
  return values;
}

// A key whose value is one of a list: the program lists the values for an unknown one.
struct ValueProbe {
  Probe probe;      // asks for the list
  std::string key;  // whose row documents them
};

ValueProbe values_of(const std::string& section, const std::string& key, std::string heading, std::string case_text,
                     bool by_set = true) {
  ValueProbe v;
  const std::string where = "[" + section + "] " + key;
  v.key = key;
  v.probe.name = "values of " + where + " under " + heading;
  v.probe.page = "case-files.md";
  v.probe.headings = {std::move(heading)};
  v.probe.files["case.toml"] = std::move(case_text);
  v.probe.args = {"simulate", "case.toml", "--out", "out"};
  if (by_set) {
    v.probe.args.push_back("--set");
    v.probe.args.push_back(section + "." + key + "=zz_probe");
  }
  v.probe.marker = where + ": unknown value \"zz_probe\"; allowed values are ";
  return v;
}

// Every value of every key that takes one of a list is in that key's row (as `"value"`), and
// every value its "allowed values" cell names is one the program takes.
TEST(KeyReference, CaseFilesDocumentTheValuesOfEveryChoice) {
  const std::string flat = "type = \"flat\"\n";
  const std::string plate = "file = " + quoted(source("models/tyres/passenger_205_55R16.toml")) + "\n";
  std::vector<ValueProbe> probes = {
      values_of("tyre", "model", "[tyre]", point_case(flat)),
      values_of("tyre", "side_condition", "model = \"two_layer\"",
                tyre_case(flat, "file = " + quoted(source("models/tyres/passenger_205_55R16_two_layer.toml")))),
      values_of("tyre.tread", "type", "[tyre.tread]", tyre_case(flat, plate + "[tyre.tread]\ntype = \"zz_probe\"\n"),
                false),
      values_of("road", "type", "[road]", point_case(flat)),
      values_of("road", "type", "[road]", tyre_case(flat)),
      values_of("road", "class", "type = \"iso8608\"", point_case("type = \"iso8608\"\nclass = \"A\"\n")),
      values_of("road", "texture", "type = \"aggregate\"", point_case("type = \"aggregate\"\nmax_chip_size = 0.01\n")),
      values_of("road", "anisotropy", "type = \"texture\"",
                tyre_case("type = \"texture\"\nwavelengths = [0.01]\nlevels = [40.0]\n")),
      values_of("road", "spikes", "type = \"file\"", point_case("type = \"file\"\nfile = \"profile.csv\"\n")),
      values_of("rolling", "history", "Point models", point_case(flat)),
      values_of("rolling", "discretisation", "Point models", point_case(flat)),
      values_of("rolling", "history", "Tyre models", tyre_case(flat)),
      values_of("rolling", "road_sampling", "Tyre models", tyre_case(flat)),
      values_of("radiation", "geometry", "[radiation]", tyre_case(flat)),
      values_of("output", "fields", "[output]", tyre_case(flat)),
  };
  // The standard receivers, from an unknown name.
  ValueProbe receivers = values_of("radiation", "receivers", "[radiation]", tyre_case(flat));
  receivers.probe.args.back() = "radiation.receivers=[\"zz_probe\"]";
  receivers.probe.marker = "unknown receiver \"zz_probe\"; allowed names are ";
  probes.push_back(receivers);
  std::vector<Probe> asked;
  for (const ValueProbe& v : probes) asked.push_back(v.probe);
  ask_all(asked);
  const auto& headings = page("case-files.md");
  std::ostringstream problems;
  for (const ValueProbe& v : probes) {
    const std::vector<std::string>& listed = answer(v.probe);
    std::vector<const Row*> rows;
    for (const Heading& h : headings)
      if (h.text == v.probe.headings.front())
        for (const Row& r : h.rows)
          if (r.key == v.key) rows.push_back(&r);
    if (rows.size() != 1) {
      problems << "`" << v.key << "` has " << rows.size() << " rows under \"" << v.probe.headings.front() << "\"\n";
      continue;
    }
    std::string text;
    for (const std::string& cell : rows.front()->cells) text += cell + " | ";
    const std::set<std::string> in_row = quoted_values(text);
    for (const std::string& value : listed)
      if (!in_row.count(value))
        problems << "case-files.md:" << rows.front()->line << ": `" << v.key << "` does not name the value \"" << value
                 << "\" (" << v.probe.name << ")\n";
    const std::set<std::string> allowed_cell =
        rows.front()->cells.size() > 3 ? quoted_values(rows.front()->cells[3]) : std::set<std::string>{};
    for (const std::string& value : allowed_cell)
      if (std::find(listed.begin(), listed.end(), value) == listed.end())
        problems << "case-files.md:" << rows.front()->line << ": `" << v.key << "` allows \"" << value
                 << "\", which the program does not take (" << v.probe.name << ")\n";
  }
  EXPECT_EQ(problems.str(), "") << "the allowed values in docs/reference/case-files.md and the readers disagree:\n"
                                << problems.str();
}

// The configurations the probes cover are all there are: a new tyre model, tread type or road
// type makes this fail until it has a probe (and so its documented keys).
TEST(KeyReference, TheProbesCoverEveryModelTreadAndRoadType) {
  const std::string flat = "type = \"flat\"\n";
  std::set<std::string> probed_roads;
  for (const RoadType& r : road_types()) probed_roads.insert(r.type);
  const std::vector<std::string> models =
      choices({"models", point_case(flat), {"--set", "tyre.model=zz_probe"}, "[tyre] model"});
  EXPECT_EQ(std::set<std::string>(models.begin(), models.end()),
            (std::set<std::string>{"sdof", "coupled_sdof", "plate", "two_layer", "tabulated"}));
  const std::vector<std::string> treads = choices(
      {"treads",
       tyre_case(flat, "file = " + quoted(source("models/tyres/passenger_205_55R16.toml")) +
                           "\n[tyre.tread]\ntype = \"zz_probe\"\n"),
       {},
       "[tyre.tread] type"});
  EXPECT_EQ(std::set<std::string>(treads.begin(), treads.end()),
            (std::set<std::string>{"winkler", "halfspace", "nonlinear"}));
  const std::vector<std::string> point_roads =
      choices({"point roads", point_case("type = \"zz_probe\"\n"), {}, "[road] type"});
  const std::vector<std::string> tyre_roads = choices({"tyre roads", tyre_case("type = \"zz_probe\"\n"), {}, "[road] type"});
  EXPECT_FALSE(point_roads.empty());
  EXPECT_FALSE(tyre_roads.empty());
  for (const std::string& type : point_roads) {
    EXPECT_TRUE(probed_roads.count(type)) << "road type \"" << type << "\" has no probe";
    EXPECT_TRUE(point_road(type)) << "road type \"" << type << "\" is probed as a tyre's only";
  }
  for (const std::string& type : tyre_roads) EXPECT_TRUE(probed_roads.count(type)) << "road type \"" << type << "\" has no probe";
  EXPECT_EQ(probed_roads.size(), tyre_roads.size());
  for (const fs::path& file : library_surfaces())
    EXPECT_TRUE(probed_roads.count(surface_type(file))) << file << ": type \"" << surface_type(file) << "\"";
}

// The parameters `rollnoise calibrate` can fit, per model, are in model-files.md.
TEST(KeyReference, ModelFilesDocumentWhatCalibrateFits) {
  std::vector<Probe> probes;
  const std::string coupled =
      "model = \"coupled_sdof\"\nmass = 1.0\ndamping = 50.0\nstiffness = 500.0\ncontact_stiffness = 1.0e5\n"
      "coupling = 0.4\nspacing = 0.01\n";
  for (const auto& [model, file] : std::vector<std::pair<std::string, std::string>>{
           {"sdof", source("models/tyres/larsson2000_sdof.toml")},
           {"coupled_sdof", "coupled.toml"},
           {"plate", source("models/tyres/passenger_205_55R16.toml")},
           {"two_layer", source("models/tyres/passenger_205_55R16_two_layer.toml")}}) {
    Probe p;
    p.name = "calibrate " + model;
    p.page = "model-files.md";
    p.headings = {"Calibrated parameters: " + model};
    p.files["coupled.toml"] = coupled;
    const bool point = model == "sdof" || model == "coupled_sdof";
    p.args = {"calibrate", file, "--data",
              source(point ? "data/mobility/sdof_point_mobility.csv" : "data/mobility/tyre_point_mobility.csv"),
              "--fit", "zz_probe", "--out", "out"};
    p.marker = "is not a parameter of the " + model + " model that calibrate can fit; allowed: ";
    probes.push_back(p);
  }
  const std::string problems = check_page("model-files.md", probes, false);
  EXPECT_EQ(problems, "") << "docs/reference/model-files.md and calibrate disagree:\n" << problems;
}

Probe study_probe(std::string name, std::vector<std::string> headings, std::string body, std::string marker) {
  Probe p;
  p.name = std::move(name);
  p.page = "study-files.md";
  p.headings = std::move(headings);
  p.files["study.toml"] = "[study]\nname = \"s\"\ncase = " + quoted(source("models/cases/larsson2000_sdof_sine.toml")) +
                          "\n" + body;
  p.args = {"study", "study.toml", "--out", "out"};
  p.marker = std::move(marker);
  return p;
}

// A study's [vary] (and [set]) keys of `section`, as the study reader knows them on the
// paper's SDOF sine case.
Probe study_keys(const std::string& section) {
  Probe p = study_probe("study keys of [" + section + "]", {}, "[vary]\n" + section + ".zz_probe = [1]\n",
                        "[vary] " + section + ".zz_probe: unknown key of [" + section + "]; known: ");
  p.section = section;
  return p;
}

// study-files.md documents the sections and the [study] keys the study reader takes.
TEST(KeyReference, StudyFilesDocumentTheStudyReader) {
  const std::vector<Probe> probes = {
      study_probe("study sections", {"Sections"}, "[zz_probe]\n[vary]\nrolling.speed = [1.0]\n",
                  "zz_probe: unknown section; a study file has "),
      study_probe("[study]", {"[study]"}, "zz_probe = 1\n[vary]\nrolling.speed = [1.0]\n",
                  "[study] zz_probe: unknown key; [study] has "),
      study_probe("case sections", {"[set] and [vary]"}, "[vary]\nzz_probe.x = [1]\n",
                  "unknown case section; keys are section.key with section one of "),
  };
  const std::string problems = check_page("study-files.md", probes, false);
  EXPECT_EQ(problems, "") << "docs/reference/study-files.md and the study reader disagree:\n" << problems;
}

// The keys a study knows for each case section are keys a case reader takes (or a library file);
// and every key a case reader takes for [rolling], [radiation] and [output] can be set by a
// study, except those study-files.md lists under "Keys a study cannot set" (and only those).
TEST(KeyReference, StudiesKnowTheKeysTheCaseReadersTake) {
  ask_all(case_probes());
  std::map<std::string, std::set<std::string>> readers;  // section -> keys some case reader lists
  for (const Probe& p : case_probes())
    if (!p.section.empty())
      for (const std::string& k : answer(p)) readers[p.section].insert(k);
  // Library-file keys, documented under the section's own heading in case-files.md.
  for (const Heading& h : page("case-files.md"))
    for (const Row& r : h.rows)
      if (r.library_file && h.text.size() > 2 && h.text.front() == '[') readers[h.text.substr(1, h.text.size() - 2)].insert(r.key);
  std::set<std::string> cannot;  // section.key listed in study-files.md
  for (const Heading& h : page("study-files.md"))
    if (h.text == "Keys a study cannot set")
      for (const Row& r : h.rows) cannot.insert(r.key);
  EXPECT_FALSE(cannot.empty()) << "study-files.md has no table under \"Keys a study cannot set\"";
  for (const std::string section : {"tyre", "road", "rolling", "radiation", "output"}) {
    const std::vector<std::string>& known = answer(study_keys(section));
    const std::set<std::string> study(known.begin(), known.end());
    for (const std::string& k : study)
      EXPECT_TRUE(readers[section].count(k)) << "a study knows " << section << "." << k << ", which no case reader takes";
    if (section == std::string("tyre") || section == std::string("road")) continue;  // from the base case
    for (const std::string& k : readers[section]) {
      const std::string dotted = section + std::string(".") + k;
      EXPECT_EQ(study.count(k) == 0, cannot.count(dotted) == 1)
          << dotted << ": " << (study.count(k) ? "a study can set it, but study-files.md says it cannot"
                                               : "a study cannot set it; list it in study-files.md");
    }
  }
}

// The [about] keys of the library's surface files are described in surface-files.md.
TEST(KeyReference, SurfaceFilesDescribeTheAboutKeysOfTheLibrary) {
  std::set<std::string> described;
  for (const Heading& h : page("surface-files.md"))
    if (h.text == "[about]")
      for (const Row& r : h.rows) described.insert(r.key);
  static const std::regex key_line(R"(^([A-Za-z0-9_]+)\s*=)");
  for (const fs::path& file : library_surfaces()) {
    std::istringstream in(read_text(file));
    bool about = false;
    for (std::string line; std::getline(in, line);) {
      if (!line.empty() && line[0] == '[') about = trim(line) == "[about]";
      std::smatch m;
      if (about && std::regex_search(line, m, key_line)) {
        EXPECT_TRUE(described.count(m[1].str())) << file.filename() << ": [about] " << m[1].str()
                                                 << " is not described under \"[about]\" in surface-files.md";
      }
    }
  }
  EXPECT_FALSE(described.empty());
}

}  // namespace
