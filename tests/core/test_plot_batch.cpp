// Plots drawn together (core/gnuplot.hpp, PlotBatch): the same PNGs byte for byte as one gnuplot
// process per plot (the reference, write_plot), settings of one script not leaking into the
// next, and a failing script reported by name while the others are still drawn.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "core/gnuplot.hpp"

namespace {
namespace fs = std::filesystem;
using namespace rollnoise;

class Folder {
 public:
  explicit Folder(const std::string& name) {
    path_ = fs::temp_directory_path() / ("rollnoise_plot_batch_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~Folder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Two plots, the first changing settings (log scale, a title, a key) the second does not set.
std::string first_script() {
  return "set terminal pngcairo size 400,300 noenhanced\nset output 'first.png'\nset logscale x\nset title 'one'\n"
         "set key top left\nplot [1:100] log(x) title 'log'\n";
}
std::string second_script() {
  return "set terminal pngcairo size 400,300 noenhanced\nset output 'second.png'\nplot [-2:2] x*x notitle\n";
}

TEST(PlotBatch, DrawsTheSamePngsAsOneProcessPerPlot) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const Folder alone("alone"), together("together");
  ASSERT_TRUE(write_plot(alone.path(), "first", first_script()));
  ASSERT_TRUE(write_plot(alone.path(), "second", second_script()));
  PlotBatch batch(together.path());
  ASSERT_TRUE(write_plot(together.path(), "first", first_script(), &batch));
  ASSERT_TRUE(write_plot(together.path(), "second", second_script(), &batch));
  EXPECT_TRUE(fs::exists(together.path() / "first.gp"));  // the scripts at once,
  EXPECT_FALSE(fs::exists(together.path() / "first.png"));  // the PNGs at draw()
  ASSERT_TRUE(batch.draw());
  for (const char* name : {"first.png", "second.png", "first.gp", "second.gp"}) {
    const std::string reference = bytes_of(alone.path() / name);
    EXPECT_FALSE(reference.empty()) << name;
    EXPECT_EQ(bytes_of(together.path() / name), reference) << name;
  }
}

TEST(PlotBatch, AFailingScriptIsNamedAndTheOthersAreDrawn) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const Folder folder("failing");
  PlotBatch batch(folder.path());
  batch.add("first", first_script());
  batch.add("broken", "set terminal pngcairo\nset output 'broken.png'\nplot no_such_function(x)\n");
  batch.add("second", second_script());
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  EXPECT_FALSE(batch.draw());
  const std::string errors = testing::internal::GetCapturedStderr();
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_NE(errors.find("gnuplot failed on broken.gp"), std::string::npos) << errors;
  // gnuplot's own reason beside ours, on stderr (not on the command's stdout).
  EXPECT_NE(errors.find("undefined function: no_such_function"), std::string::npos) << errors;
  EXPECT_EQ(errors.find("first.gp"), std::string::npos) << errors;
  EXPECT_EQ(errors.find("second.gp"), std::string::npos) << errors;
  EXPECT_TRUE(fs::exists(folder.path() / "first.png"));
  EXPECT_TRUE(fs::exists(folder.path() / "second.png"));
  EXPECT_TRUE(batch.draw());  // nothing left to draw
}

}  // namespace
