#pragma once
// The manual's pages as the docs tests see them: README.md, CHANGELOG.md and every Markdown file
// under docs/, with the text outside code (fenced blocks and inline code spans blanked, so that a
// command or a TOML example never counts as a link or as prose).
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_workspace.hpp"

namespace docs_test {
namespace fs = std::filesystem;

inline fs::path source_dir() { return fs::path(ROLLNOISE_SOURCE_DIR); }

// Every page of the manual, relative to the source folder, sorted (a stable order for messages).
inline std::vector<fs::path> manual_pages() {
  std::vector<fs::path> pages{"README.md", "CHANGELOG.md"};
  for (const auto& entry : fs::recursive_directory_iterator(source_dir() / "docs"))
    if (entry.is_regular_file() && entry.path().extension() == ".md")
      pages.push_back(fs::relative(entry.path(), source_dir()));
  std::sort(pages.begin(), pages.end());
  pages.erase(std::remove_if(pages.begin(), pages.end(),
                             [](const fs::path& p) { return !fs::exists(source_dir() / p); }),
              pages.end());
  return pages;
}

// The page's lines with fenced code blocks and inline code spans replaced by spaces (line
// numbers and columns stay those of the file).
inline std::vector<std::string> prose_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  bool fenced = false;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    line = text.substr(start, end - start);
    start = end + 1;
    const auto first = line.find_first_not_of(' ');
    const bool fence = first != std::string::npos &&
                       (line.compare(first, 3, "```") == 0 || line.compare(first, 3, "~~~") == 0);
    if (fence || fenced) {
      if (fence) fenced = !fenced;
      lines.emplace_back(line.size(), ' ');
      continue;
    }
    // Inline code: blank from each run of backticks to the next run of the same length.
    for (std::size_t i = 0; i < line.size();) {
      if (line[i] != '`') { ++i; continue; }
      std::size_t run = 0;
      while (i + run < line.size() && line[i + run] == '`') ++run;
      const std::string ticks(run, '`');
      const std::size_t close = line.find(ticks, i + run);
      if (close == std::string::npos) break;
      std::fill(line.begin() + static_cast<std::ptrdiff_t>(i),
                line.begin() + static_cast<std::ptrdiff_t>(close + run), ' ');
      i = close + run;
    }
    lines.push_back(line);
    if (end == text.size()) break;
  }
  return lines;
}

// GitHub's anchor for a heading: lower case, spaces to '-', punctuation and symbols dropped
// (letters outside ASCII are dropped too, which no heading of this manual relies on).
inline std::string heading_anchor(const std::string& heading) {
  std::string anchor;
  for (unsigned char c : heading) {
    if (std::isalnum(c) || c == '-' || c == '_')
      anchor += static_cast<char>(std::tolower(c));
    else if (c == ' ')
      anchor += '-';
  }
  return anchor;
}

// The anchors of a page's headings (# to ######, outside fenced code; the text of inline code
// counts, its backticks do not), with GitHub's -1, -2 suffixes for repeats.
inline std::vector<std::string> page_anchors(const std::string& text) {
  std::vector<std::string> anchors;
  const std::vector<std::string> prose = prose_lines(text);
  std::size_t start = 0;
  for (std::size_t n = 0; n < prose.size(); ++n) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    std::size_t level = 0;
    while (level < line.size() && line[level] == '#') ++level;
    // A heading in the file whose prose line is blank lies in a fenced block.
    if (level == 0 || level > 6 || level >= line.size() || line[level] != ' ' || prose[n][0] != '#')
      continue;
    std::string heading = line.substr(level + 1);
    while (!heading.empty() && (heading.back() == ' ' || heading.back() == '#')) heading.pop_back();
    const std::string base = heading_anchor(heading);
    std::string anchor = base;
    for (int k = 1; std::find(anchors.begin(), anchors.end(), anchor) != anchors.end(); ++k)
      anchor = base + "-" + std::to_string(k);
    anchors.push_back(anchor);
  }
  return anchors;
}

}  // namespace docs_test
