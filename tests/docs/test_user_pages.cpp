// The user pages read as a manual, not as a lab notebook: a README that fits on a screen, no
// development history (sessions, helpers, issue numbers) outside CHANGELOG.md and
// docs/development.md, and every figure shown with the date it was made.
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "markdown_pages.hpp"

namespace {
using docs_test::fs::path;

bool is_user_page(const path& page) {
  return page != "CHANGELOG.md" && page != path("docs/development.md");
}

// Words that belong to how the code was written, not to what it does.
std::string development_talk(const std::string& line) {
  static const std::regex talk(
      R"re(\b(sessions?|helpers?|yesterday|issues? ?#?[0-9]+|tasks? #?[0-9]+)\b|#[0-9]{1,3}\b)re",
      std::regex::icase);
  std::smatch match;
  return std::regex_search(line, match, talk) ? match[0].str() : "";
}

TEST(UserPages, ReadmeFitsOnAFewScreens) {
  const std::string readme = cli_test::read_text(docs_test::source_dir() / "README.md");
  EXPECT_LE(cli_test::count_lines(readme), 250u);
  EXPECT_GE(cli_test::count_lines(readme), 40u) << "README.md looks empty";
}

TEST(UserPages, NoDevelopmentHistory) {
  std::ostringstream found;
  std::size_t pages = 0;
  for (const path& page : docs_test::manual_pages()) {
    if (!is_user_page(page)) continue;
    ++pages;
    std::istringstream text(cli_test::read_text(docs_test::source_dir() / page));
    std::string line;
    for (std::size_t n = 1; std::getline(text, line); ++n)
      if (const std::string word = development_talk(line); !word.empty())
        found << page.string() << ":" << n << ": \"" << word << "\": " << line.substr(0, 120) << "\n";
  }
  EXPECT_GE(pages, 10u);
  EXPECT_EQ(found.str(), "") << "development history on user pages (it belongs in CHANGELOG.md):\n"
                             << found.str();
}

TEST(UserPages, TheCheckRecognisesHistory) {
  EXPECT_EQ(development_talk("measured this session"), "session");
  EXPECT_EQ(development_talk("see issue 13"), "issue 13");
  EXPECT_EQ(development_talk("(a helper wrote it)"), "helper");
  EXPECT_EQ(development_talk("blocked (#10)"), "#10");
  EXPECT_EQ(development_talk("the plate's 205/55 R16 tyre at 80 km/h, ISO 13473-1"), "");
  EXPECT_EQ(development_talk("the third octaves of IEC 61260-1"), "");
}

// A figure is shown with its date (YYYY-MM-DD) within a few lines of the image, where the caption
// says when, on what machine and by which command it was made.
TEST(UserPages, EveryFigureCarriesItsDate) {
  static const std::regex image(R"re(!\[[^\]]*\]\(([^)\s]+))re");
  static const std::regex date(R"re(\b20[0-9]{2}-[01][0-9]-[0-3][0-9]\b)re");
  std::ostringstream undated;
  std::size_t figures = 0;
  for (const path& page : docs_test::manual_pages()) {
    if (!is_user_page(page)) continue;
    const std::string text = cli_test::read_text(docs_test::source_dir() / page);
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    const auto prose = docs_test::prose_lines(text);
    for (std::size_t n = 0; n < prose.size() && n < lines.size(); ++n) {
      std::smatch match;
      if (!std::regex_search(prose[n], match, image)) continue;
      ++figures;
      bool dated = false;
      for (std::size_t k = n >= 6 ? n - 6 : 0; k < std::min(lines.size(), n + 7) && !dated; ++k)
        dated = std::regex_search(lines[k], date);
      if (!dated) undated << page.string() << ":" << n + 1 << ": " << match[1].str() << "\n";
    }
  }
  EXPECT_GE(figures, 5u);
  EXPECT_EQ(undated.str(), "") << "figures without a date within 6 lines:\n" << undated.str();
}

}  // namespace
