#pragma once
// Plots: every PNG is drawn by a gnuplot script that is kept beside it, so users can restyle
// and redraw it (`gnuplot NAME.gp`).
#include <filesystem>
#include <string>

namespace rollnoise {

// Writes `script` to dir/NAME.gp and, when gnuplot is installed, runs it in `dir` (the script
// sets its own output NAME.png). Returns false (with a warning on stderr) when no PNG was made.
bool write_plot(const std::filesystem::path& dir, const std::string& name, const std::string& script);

bool gnuplot_available();

}  // namespace rollnoise
