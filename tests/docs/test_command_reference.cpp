// docs/reference/commands.md against the program: every verb `rollnoise --help` lists (and every
// verb under a verb, such as `cache list`) has a section, every option and argument that
// `rollnoise VERB --help` lists is described in that verb's section, and no section describes an
// option its verb does not have. The program is the reference: a new option without its
// documentation fails here. Cost: 2-3.5 s (the help of every verb, run once per test; 2026-11-27, 2 shared cores).
#include <initializer_list>
#include <regex>
#include <string_view>
#include <string>
#include <vector>

#include "cli_workspace.hpp"

namespace {
using namespace cli_test;

const fs::path kCommands = fs::path(ROLLNOISE_SOURCE_DIR) / "docs" / "reference" / "commands.md";

// What CLI11's help lists: option names (--out; -h,--help gives --help), positional arguments
// and verbs. Entries sit on lines indented by two spaces; their descriptions continue on lines
// indented further, which are skipped.
struct Help {
  std::vector<std::string> options;
  std::vector<std::string> positionals;
  std::vector<std::string> verbs;
};

Help parse_help(const std::string& text) {
  Help help;
  enum class Part { none, options, positionals, verbs } part = Part::none;
  static const std::regex option_line(R"(^  (?:-[A-Za-z],)?(--[A-Za-z0-9][A-Za-z0-9-]*))");
  static const std::regex name_line(R"(^  ([a-z][a-z_]*)(?: |$))");
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line == "Options:") part = Part::options;
    else if (line == "Positionals:") part = Part::positionals;
    else if (line == "Subcommands:") part = Part::verbs;
    else if (!line.empty() && line[0] != ' ') part = Part::none;  // "Usage:", "Example:", ...
    std::smatch m;
    if (part == Part::options && std::regex_search(line, m, option_line)) help.options.push_back(m[1]);
    if (part == Part::positionals && std::regex_search(line, m, name_line)) help.positionals.push_back(m[1]);
    if (part == Part::verbs && std::regex_search(line, m, name_line)) help.verbs.push_back(m[1]);
  }
  return help;
}

Help help_of(const std::vector<std::string>& verb) {
  Workspace ws;
  std::vector<std::string> args = verb;
  args.push_back("--help");
  const RunResult r = ws.run(args);
  EXPECT_EQ(r.status, 0) << describe(r);
  return parse_help(r.out);
}

// Pieces joined by appending (GCC 12 warns falsely, -Wrestrict, on "text" + std::string).
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) out += p;
  return out;
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) {
    if (!out.empty()) out += ' ';
    out += w;
  }
  return out;
}

// The text under the heading "## `rollnoise VERB`" (or ### for a verb under a verb), up to the
// next heading of the same or a higher level; empty when there is no such heading.
std::string section(const std::string& doc, const std::string& title, int level) {
  const std::string hashes(static_cast<std::size_t>(level), '#');
  const std::string heading = cat({hashes, " ", title, "\n"});
  std::size_t at = 0;
  if (doc.compare(0, heading.size(), heading) != 0) {
    const std::size_t found = doc.find(cat({"\n", heading}));
    if (found == std::string::npos) return {};
    at = found + 1;
  }
  std::size_t end = doc.size();
  for (int l = 1; l <= level; ++l) {
    const std::size_t next = doc.find(cat({"\n", std::string(static_cast<std::size_t>(l), '#'), " "}), at + heading.size() - 1);
    if (next != std::string::npos) end = std::min(end, next);
  }
  return doc.substr(at, end - at);
}

std::string verb_title(const std::vector<std::string>& verb) { return cat({"`rollnoise ", joined(verb), "`"}); }

// `name` written as code: a backtick, the name, and no further letter of a longer name.
bool mentions(const std::string& text, const std::string& name) {
  const std::string code = cat({"`", name});
  for (std::size_t at = text.find(code); at != std::string::npos; at = text.find(code, at + 1)) {
    const std::size_t after = at + 1 + name.size();
    if (after >= text.size() || !(std::isalnum(static_cast<unsigned char>(text[after])) || text[after] == '-' || text[after] == '_'))
      return true;
  }
  return false;
}

// Every verb, verbs under verbs included ({"cache", "list"}), from the program's own help.
std::vector<std::vector<std::string>> all_verbs() {
  std::vector<std::vector<std::string>> out;
  for (const std::string& verb : help_of({}).verbs) {
    const Help help = help_of({verb});
    if (help.verbs.empty()) {
      out.push_back({verb});
    } else {
      for (const std::string& sub : help.verbs) out.push_back({verb, sub});
    }
  }
  return out;
}

int level_of(const std::vector<std::string>& verb) { return verb.size() == 1 ? 2 : 3; }

TEST(CommandReference, EveryVerbOfTheProgramHasItsSection) {
  const std::string doc = read_text(kCommands);
  ASSERT_FALSE(doc.empty()) << kCommands;
  const auto verbs = all_verbs();
  // The help is what the test reads: if its format changed so that nothing is found, say so.
  ASSERT_GE(verbs.size(), 8u) << "rollnoise --help lists too few verbs; has CLI11's help format changed?";
  for (const auto& verb : verbs) {
    EXPECT_FALSE(section(doc, verb_title(verb), level_of(verb)).empty())
        << "docs/reference/commands.md has no heading '" << std::string(static_cast<std::size_t>(level_of(verb)), '#') << ' '
        << verb_title(verb) << "'";
    // A verb with verbs under it ("cache") has its own heading too.
    if (verb.size() > 1) {
      EXPECT_FALSE(section(doc, verb_title({verb[0]}), 2).empty()) << verb[0];
    }
  }
}

TEST(CommandReference, EveryOptionAndArgumentIsDescribedUnderItsVerb) {
  const std::string doc = read_text(kCommands);
  std::size_t checked = 0;
  for (const auto& verb : all_verbs()) {
    const Help help = help_of(verb);
    const std::string text = section(doc, verb_title(verb), level_of(verb));
    ASSERT_FALSE(text.empty()) << verb_title(verb);
    for (const std::string& option : help.options) {
      if (option == "--help") continue;  // described once, under "Global options"
      ++checked;
      EXPECT_TRUE(mentions(text, option)) << "rollnoise " << joined(verb) << " " << option
                                          << " is not described under " << verb_title(verb) << " in docs/reference/commands.md";
    }
    for (const std::string& argument : help.positionals) {
      ++checked;
      EXPECT_TRUE(mentions(text, argument)) << "the argument '" << argument << "' of rollnoise " << joined(verb)
                                            << " is not described under " << verb_title(verb);
    }
  }
  EXPECT_GE(checked, 40u) << "too few options found in the help texts; has CLI11's help format changed?";
}

TEST(CommandReference, NoSectionDescribesAnOptionItsVerbLacks) {
  const std::string doc = read_text(kCommands);
  static const std::regex option(R"(`(--[a-z][a-z-]*))");
  for (const auto& verb : all_verbs()) {
    const Help help = help_of(verb);
    std::string text = section(doc, verb_title(verb), level_of(verb));
    // A verb's own table rows: "| `--out DIR` | ..." (its first cell).
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      if (!starts_with(line, "| `")) continue;
      const std::string first_cell = line.substr(0, line.find(" |", 2));
      for (std::sregex_iterator it(first_cell.begin(), first_cell.end(), option), end; it != end; ++it) {
        const std::string name = (*it)[1];
        const bool listed = std::find(help.options.begin(), help.options.end(), name) != help.options.end();
        EXPECT_TRUE(listed)
            << verb_title(verb) << " describes " << name << ", which `rollnoise " << joined(verb) << " --help` does not list";
      }
    }
  }
}

TEST(CommandReference, GlobalOptionsAreDescribed) {
  const std::string doc = read_text(kCommands);
  const std::string text = section(doc, "Global options", 2);
  ASSERT_FALSE(text.empty()) << "no '## Global options' in docs/reference/commands.md";
  const Help help = help_of({});
  ASSERT_FALSE(help.options.empty());
  for (const std::string& option : help.options) EXPECT_TRUE(mentions(text, option)) << option;
}

}  // namespace
