// CHANGELOG.md against the program: it keeps the Keep a Changelog form (an [Unreleased] section
// first, then releases "## [MAJOR.MINOR.PATCH] - YYYY-MM-DD", newest first, each with its
// Added/Changed/... sections), and `rollnoise --version` prints the newest release.
#include <gtest/gtest.h>

#include <chrono>
#include <regex>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "cli_workspace.hpp"

namespace {

namespace fs = std::filesystem;

struct Release {
  std::string version;  // "0.10.0"
  std::tuple<int, int, int> number;
  std::chrono::year_month_day date;
  std::string date_text;
  int line = 0;
  std::vector<std::string> sections;  // the "### ..." headings under it
};

struct Changelog {
  std::vector<std::string> level2;  // every "## " heading, in order
  std::vector<Release> releases;
  std::vector<std::string> problems;  // "## " headings that are neither [Unreleased] nor a release
};

Changelog read_changelog() {
  Changelog log;
  const std::string text = cli_test::read_text(fs::path(ROLLNOISE_SOURCE_DIR) / "CHANGELOG.md");
  EXPECT_FALSE(text.empty()) << "CHANGELOG.md is missing or empty";
  static const std::regex release(R"(^## \[(\d+)\.(\d+)\.(\d+)\] - (\d{4})-(\d{2})-(\d{2})$)");
  std::istringstream in(text);
  std::string line;
  int number = 0;
  bool fenced = false;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("```", 0) == 0) fenced = !fenced;
    if (fenced) continue;
    if (line.rfind("## ", 0) == 0) {
      log.level2.push_back(line);
      std::smatch m;
      if (std::regex_match(line, m, release)) {
        Release r;
        r.version = m[1].str() + "." + m[2].str() + "." + m[3].str();
        r.number = {std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3])};
        r.date = std::chrono::year_month_day{std::chrono::year{std::stoi(m[4])},
                                             std::chrono::month{static_cast<unsigned>(std::stoi(m[5]))},
                                             std::chrono::day{static_cast<unsigned>(std::stoi(m[6]))}};
        r.date_text = m[4].str() + "-" + m[5].str() + "-" + m[6].str();
        r.line = number;
        log.releases.push_back(r);
      } else if (line != "## [Unreleased]") {
        log.problems.push_back("line " + std::to_string(number) + ": " + line);
      }
    } else if (line.rfind("### ", 0) == 0 && !log.releases.empty()) {
      log.releases.back().sections.push_back(line.substr(4));
    }
  }
  return log;
}

TEST(Changelog, OpensWithUnreleasedThenReleasesInDescendingOrderWithIsoDates) {
  const Changelog log = read_changelog();
  ASSERT_FALSE(log.level2.empty()) << "CHANGELOG.md has no '## ' sections";
  EXPECT_EQ(log.level2.front(), "## [Unreleased]") << "Keep a Changelog puts the unreleased changes first";
  for (const auto& problem : log.problems)
    ADD_FAILURE() << "CHANGELOG.md: a section that is neither '## [Unreleased]' nor '## [X.Y.Z] - YYYY-MM-DD': "
                  << problem;
  ASSERT_GE(log.releases.size(), 2u) << "CHANGELOG.md lists fewer than two releases";
  for (const Release& r : log.releases) {
    EXPECT_TRUE(r.date.ok()) << "CHANGELOG.md line " << r.line << ": " << r.date_text << " is not a calendar date";
    EXPECT_FALSE(r.sections.empty()) << "CHANGELOG.md line " << r.line << ": release " << r.version
                                     << " has no '### Added', '### Changed', ... section";
  }
  for (std::size_t i = 1; i < log.releases.size(); ++i) {
    const Release& newer = log.releases[i - 1];
    const Release& older = log.releases[i];
    EXPECT_GT(newer.number, older.number) << "CHANGELOG.md line " << older.line << ": " << older.version
                                          << " comes after " << newer.version << " but is not older";
    EXPECT_GE(std::chrono::sys_days{newer.date}, std::chrono::sys_days{older.date})
        << "CHANGELOG.md line " << older.line << ": " << older.version << " (" << older.date_text
        << ") is dated after " << newer.version << " (" << newer.date_text << ")";
  }
}

TEST(Changelog, VersionOptionPrintsTheNewestRelease) {
  const Changelog log = read_changelog();
  ASSERT_FALSE(log.releases.empty()) << "CHANGELOG.md lists no release";
  const cli_test::Workspace ws;
  const cli_test::RunResult r = ws.run({"--version"});
  ASSERT_EQ(r.status, 0) << cli_test::describe(r);
  std::string printed = r.out;
  while (!printed.empty() && (printed.back() == '\n' || printed.back() == ' ')) printed.pop_back();
  EXPECT_EQ(printed, log.releases.front().version)
      << "rollnoise --version must print the newest release of CHANGELOG.md (set project(rollnoise VERSION ...) in "
         "CMakeLists.txt to it)";
}

}  // namespace
