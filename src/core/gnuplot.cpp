#include "core/gnuplot.hpp"

#include <cstdio>
#include <cstdlib>

#include "core/output_directory.hpp"

namespace rollnoise {

bool gnuplot_available() {
  return std::system("command -v gnuplot >/dev/null 2>&1") == 0;
}

namespace {

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

bool write_plot(const std::filesystem::path& dir, const std::string& name, const std::string& script) {
  write_text_file(dir / (name + ".gp"), script);
  if (!gnuplot_available()) {
    std::fprintf(stderr, "rollnoise: warning: gnuplot is not installed; wrote %s.gp but no PNG\n", name.c_str());
    return false;
  }
  const std::string command =
      "cd " + shell_quote(dir.string()) + " && gnuplot " + shell_quote(name + ".gp") + " 2>&1";
  if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "rollnoise: warning: gnuplot failed on %s.gp; no PNG written\n", name.c_str());
    return false;
  }
  return true;
}

}  // namespace rollnoise
