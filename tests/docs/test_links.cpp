// Every relative link and image of README.md, CHANGELOG.md and docs/ resolves in a clone of the
// repository: the file exists inside the repository (not in build/ or out/, which a fresh clone
// lacks), and an anchor names a heading of the page it points into.
#include <regex>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "markdown_pages.hpp"

namespace {
using docs_test::fs::path;

struct Link {
  std::size_t line;
  std::string target;
};

// Inline links and images [text](target "title"), reference definitions [id]: target, and
// <img src="target">, outside code.
std::vector<Link> links_of(const std::string& text) {
  static const std::regex inline_link(R"re(\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\))re");
  static const std::regex reference(R"re(^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+.*)?$)re");
  static const std::regex image_tag(R"re(<img[^>]*\bsrc\s*=\s*"([^"]+)")re");
  std::vector<Link> links;
  const auto lines = docs_test::prose_lines(text);
  for (std::size_t n = 0; n < lines.size(); ++n) {
    for (const std::regex* pattern : {&inline_link, &image_tag})
      for (auto it = std::sregex_iterator(lines[n].begin(), lines[n].end(), *pattern);
           it != std::sregex_iterator(); ++it)
        links.push_back({n + 1, (*it)[1].str()});
    std::smatch match;
    if (std::regex_match(lines[n], match, reference)) links.push_back({n + 1, match[1].str()});
  }
  return links;
}

bool is_external(const std::string& target) {
  return target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0 ||
         target.rfind("mailto:", 0) == 0;
}

// What is wrong with one link of `page`, or "" when it resolves.
std::string check_link(const path& page, const std::string& target) {
  const auto hash = target.find('#');
  const std::string file_part = target.substr(0, hash);
  const std::string anchor = hash == std::string::npos ? "" : target.substr(hash + 1);
  const path root = docs_test::source_dir();
  path file = page;
  if (!file_part.empty()) {
    file = (page.parent_path() / file_part).lexically_normal();
    const std::string first = file.begin() == file.end() ? "" : file.begin()->string();
    if (first == ".." || file.is_absolute()) return "points outside the repository";
    if (first == "build" || first == "out") return "points into " + first + "/, which a fresh clone does not have";
    if (!docs_test::fs::exists(root / file)) return "no such file";
  }
  if (!anchor.empty()) {
    if (file.extension() != ".md") return "an anchor into a file that is not a page";
    const auto anchors = docs_test::page_anchors(cli_test::read_text(root / file));
    if (std::find(anchors.begin(), anchors.end(), anchor) == anchors.end())
      return "no heading of " + file.string() + " has the anchor #" + anchor;
  }
  return "";
}

TEST(ManualLinks, EveryRelativeLinkAndImageResolves) {
  const auto pages = docs_test::manual_pages();
  ASSERT_GE(pages.size(), 10u) << "the manual's pages were not found";
  std::size_t checked = 0;
  std::ostringstream broken;
  for (const path& page : pages) {
    for (const Link& link : links_of(cli_test::read_text(docs_test::source_dir() / page))) {
      if (is_external(link.target)) continue;
      ++checked;
      const std::string problem = check_link(page, link.target);
      if (!problem.empty())
        broken << page.string() << ":" << link.line << ": " << link.target << ": " << problem << "\n";
    }
  }
  EXPECT_GT(checked, 50u) << "too few links found: is the link pattern still right?";
  EXPECT_EQ(broken.str(), "") << "broken links:\n" << broken.str();
}

// The checker itself: a link that cannot resolve is reported, one that does is not.
TEST(ManualLinks, CheckerTellsBrokenFromSound) {
  const path readme = "README.md";
  EXPECT_EQ(check_link(readme, "docs/README.md"), "");
  EXPECT_EQ(check_link(readme, "docs/no-such-page.md"), "no such file");
  EXPECT_EQ(check_link(readme, "../shared/seed"), "points outside the repository");
  EXPECT_EQ(check_link(readme, "out/demo/spectrum.png"), "points into out/, which a fresh clone does not have");
  EXPECT_NE(check_link(readme, "docs/README.md#no-such-heading"), "");
  EXPECT_EQ(check_link(readme, "docs/README.md#reference"), "");
  const auto links = links_of("see [a](x.md) and ![b](y.png \"t\")\n`[c](z.md)`\n```\n[d](w.md)\n```\n[e]: v.md\n");
  ASSERT_EQ(links.size(), 3u);
  EXPECT_EQ(links[0].target, "x.md");
  EXPECT_EQ(links[1].target, "y.png");
  EXPECT_EQ(links[2].target, "v.md");
  EXPECT_EQ(links[2].line, 6u);
}

TEST(ManualLinks, AnchorsFollowGitHub) {
  EXPECT_EQ(docs_test::heading_anchor("The paper's §4, reproduced"), "the-papers-4-reproduced");
  EXPECT_EQ(docs_test::heading_anchor("Studies: tyres × surfaces × speeds"), "studies-tyres--surfaces--speeds");
  const auto anchors = docs_test::page_anchors("# A\n## `rollnoise greens`\n```\n# not a heading\n```\n## A\n");
  ASSERT_EQ(anchors.size(), 3u);
  EXPECT_EQ(anchors[1], "rollnoise-greens");
  EXPECT_EQ(anchors[2], "a-1");
}

}  // namespace
