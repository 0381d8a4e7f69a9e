#pragma once
// Plots: every PNG is drawn by a gnuplot script that is kept beside it, so users can restyle
// and redraw it (`gnuplot NAME.gp`).
#include <filesystem>
#include <string>
#include <vector>

namespace rollnoise {

// Writes `script` to dir/NAME.gp and, when gnuplot is installed, runs it in `dir` (the script
// sets its own output NAME.png). Returns false (with a warning on stderr) when no PNG was made.
bool write_plot(const std::filesystem::path& dir, const std::string& name, const std::string& script);

// Plots of one folder drawn together: each script is written at once, and draw() runs them all
// in one gnuplot process (`reset session` between them), which makes the same PNGs byte for
// byte as one process each and spares a process start per plot (a tyre case draws seven:
// issue 12). If that process fails, each plot is drawn alone again, so that the warnings name
// the failing ones as write_plot's do.
class PlotBatch {
 public:
  explicit PlotBatch(std::filesystem::path dir) : dir_(std::move(dir)) {}
  const std::filesystem::path& dir() const noexcept { return dir_; }
  // Writes dir/NAME.gp; its PNG is drawn by draw().
  void add(const std::string& name, const std::string& script);
  // Draws what was added since the last draw(). Returns false when some PNG was not made.
  bool draw();

 private:
  std::filesystem::path dir_;
  std::vector<std::string> names_;
};

// write_plot's, or deferred to `batch` (its folder is `dir`) when there is one.
bool write_plot(const std::filesystem::path& dir, const std::string& name, const std::string& script, PlotBatch* batch);

bool gnuplot_available();

}  // namespace rollnoise
