// A model file named by [tyre] file, with keys beside it (in the case or by --set): the keys
// override the file's key by key, inside tables such as [tyre.tread] too, unless they name
// another tread type, which replaces the file's table. Every key keeps the file it came from.
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "core/case_file.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {
namespace fs = std::filesystem;

class CaseFileMerge : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rollnoise_merge_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    write("model.toml",
          "model = \"plate\"\nradius = 0.3\n[tread]\ntype = \"winkler\"\nstiffness_per_area = 5e8\n");
    write("case.toml", "[tyre]\nfile = \"model.toml\"\n");
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
  fs::path case_path() const { return dir_ / "case.toml"; }
  fs::path dir_;
};

TEST_F(CaseFileMerge, AKeyInsideTheTreadKeepsTheFilesType) {
  const CaseFile file = CaseFile::load(case_path(), {"tyre.tread.stiffness_per_area=2e8"});
  const ConfigTable tread = *file.section("tyre").subtable("tread");
  EXPECT_EQ(tread.text("type"), "winkler");
  EXPECT_DOUBLE_EQ(tread.number("stiffness_per_area"), 2e8);
  EXPECT_EQ(tread.source_of("stiffness_per_area"), "--set tyre.tread.stiffness_per_area");
  EXPECT_EQ(tread.source_of("type"), (dir_ / "model.toml").string());
  EXPECT_DOUBLE_EQ(file.section("tyre").number("radius"), 0.3);
}

TEST_F(CaseFileMerge, AnotherTreadTypeReplacesTheFilesTread) {
  const CaseFile file =
      CaseFile::load(case_path(), {"tyre.tread.type=\"halfspace\"", "tyre.tread.youngs_modulus=4e6"});
  const ConfigTable tread = *file.section("tyre").subtable("tread");
  EXPECT_EQ(tread.text("type"), "halfspace");
  EXPECT_FALSE(tread.contains("stiffness_per_area")) << "the winkler key would be unknown to a half-space";
}

TEST_F(CaseFileMerge, TheCasesOwnTableOverridesKeyByKey) {
  write("case.toml", "[tyre]\nfile = \"model.toml\"\nradius = 0.31\n[tyre.tread]\nstiffness_per_area = 3e8\n");
  const CaseFile file = CaseFile::load(case_path());
  const ConfigTable tyre = file.section("tyre");
  EXPECT_DOUBLE_EQ(tyre.number("radius"), 0.31);
  EXPECT_EQ(tyre.text("model"), "plate");
  EXPECT_FALSE(tyre.contains("file"));
  const ConfigTable tread = *tyre.subtable("tread");
  EXPECT_EQ(tread.text("type"), "winkler");
  EXPECT_DOUBLE_EQ(tread.number("stiffness_per_area"), 3e8);
}

}  // namespace
}  // namespace rollnoise
