// Files named by case files (core/referenced_file.hpp): where each is found, and which leave
// the folder they were looked up in through ".." or a symlink (listed in the run's summary).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/case_file.hpp"
#include "core/referenced_file.hpp"

namespace {
namespace fs = std::filesystem;
using namespace rollnoise;

// A fresh folder, removed at the end.
class Folder {
 public:
  Folder() {
    path_ = fs::temp_directory_path() /
            ("rollnoise_referenced_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
    path_ = fs::canonical(path_);
  }
  ~Folder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  void write(const std::string& name, const std::string& text) const {
    fs::create_directories((path_ / name).parent_path());
    std::ofstream(path_ / name) << text;
  }

 private:
  fs::path path_;
};

TEST(CaseFilePaths, AFileBesideTheCaseIsInside) {
  Folder f;
  f.write("cases/a.toml", "");
  f.write("cases/road.csv", "x,z\n");
  const ReferencedFile found = find_referenced_file("road.csv", f.path() / "cases/a.toml");
  EXPECT_EQ(found.path, f.path() / "cases/road.csv");
  EXPECT_EQ(found.base, f.path() / "cases");
  EXPECT_TRUE(outside_base(found).empty());
  // A ".." that comes back inside is inside.
  EXPECT_TRUE(outside_base(find_referenced_file("../cases/road.csv", f.path() / "cases/a.toml")).empty());
}

TEST(CaseFilePaths, DotDotOutOfTheFolderIsOutside) {
  Folder f;
  f.write("cases/a.toml", "");
  f.write("shared/road.csv", "x,z\n");
  const ReferencedFile found = find_referenced_file("../shared/road.csv", f.path() / "cases/a.toml");
  EXPECT_EQ(outside_base(found), f.path() / "shared/road.csv");
  // A folder whose name only starts like the base's is not inside it.
  f.write("cases2/road.csv", "x,z\n");
  EXPECT_EQ(outside_base(find_referenced_file("../cases2/road.csv", f.path() / "cases/a.toml")),
            f.path() / "cases2/road.csv");
}

TEST(CaseFilePaths, ASymlinkOutOfTheFolderIsOutside) {
  Folder f;
  f.write("cases/a.toml", "");
  f.write("elsewhere/road.csv", "x,z\n");
  fs::create_symlink(f.path() / "elsewhere/road.csv", f.path() / "cases/road.csv");
  fs::create_directory_symlink(f.path() / "elsewhere", f.path() / "cases/data");
  EXPECT_EQ(outside_base(find_referenced_file("road.csv", f.path() / "cases/a.toml")), f.path() / "elsewhere/road.csv");
  EXPECT_EQ(outside_base(find_referenced_file("data/road.csv", f.path() / "cases/a.toml")),
            f.path() / "elsewhere/road.csv");
  // A case reached through a symlinked folder is inside its own folder.
  fs::create_directory_symlink(f.path() / "cases", f.path() / "linked");
  f.write("cases/inside.csv", "x,z\n");
  EXPECT_TRUE(outside_base(find_referenced_file("inside.csv", f.path() / "linked/a.toml")).empty());
}

TEST(CaseFilePaths, AbsoluteMissingAndLibrarySearchPathsAreNotListed) {
  Folder f;
  f.write("cases/a.toml", "");
  f.write("elsewhere/road.csv", "x,z\n");
  // Absolute: it says where it points.
  EXPECT_TRUE(outside_base(find_referenced_file(f.path() / "elsewhere/road.csv", f.path() / "cases/a.toml")).empty());
  // Missing: its reader reports it.
  EXPECT_TRUE(outside_base(find_referenced_file("../nowhere.csv", f.path() / "cases/a.toml")).empty());
  // The project's cases name "models/tyres/..." found in a folder above them: inside that folder.
  const fs::path source = ROLLNOISE_SOURCE_DIR;
  const ReferencedFile library =
      find_referenced_file("models/tyres/passenger_205_55R16.toml", source / "models/cases/plate_smooth_80kmh.toml");
  EXPECT_TRUE(fs::exists(library.path));
  EXPECT_TRUE(outside_base(library).empty());
}

TEST(CaseFilePaths, ACaseFileListsItsLibraryFilesOutsideItsFolderOnce) {
  Folder f;
  f.write("surfaces/flat.toml", "type = \"flat\"\n");
  f.write("cases/a.toml", "[road]\nsurface = \"../surfaces/flat.toml\"\n");
  const CaseFile file = CaseFile::load(f.path() / "cases/a.toml");
  ASSERT_EQ(file.paths_outside_folder().size(), 1u);
  const PathOutsideCaseFolder listed = file.paths_outside_folder().front();
  EXPECT_EQ(listed.key, "[road] surface");
  EXPECT_EQ(listed.file, (f.path() / "cases/a.toml").string());
  EXPECT_EQ(listed.written, "../surfaces/flat.toml");
  EXPECT_EQ(listed.resolved, (f.path() / "surfaces/flat.toml").string());
  // A reader noting the same key of the same file again (a road built twice) adds nothing.
  f.write("shared/road.csv", "x,z\n");
  f.write("cases/b.toml", "[road]\ntype = \"file\"\nfile = \"../shared/road.csv\"\n");
  const CaseFile b = CaseFile::load(f.path() / "cases/b.toml");
  EXPECT_TRUE(b.paths_outside_folder().empty()) << "noted by the reader that resolves it, not by the loader";
  for (int twice = 0; twice < 2; ++twice)
    b.section("road").note_referenced_file("file", find_referenced_file("../shared/road.csv", b.path()));
  ASSERT_EQ(b.paths_outside_folder().size(), 1u);
  EXPECT_EQ(b.paths_outside_folder().front().key, "[road] file");
  EXPECT_EQ(b.paths_outside_folder().front().written, "../shared/road.csv");
  // --set names its files from the case file's folder too; the list says who named it.
  const CaseFile set = CaseFile::load(f.path() / "cases/a.toml", {"road.surface=\"../surfaces/flat.toml\""});
  ASSERT_EQ(set.paths_outside_folder().size(), 1u);
  EXPECT_EQ(set.paths_outside_folder().front().file, "--set road.surface");
}

}  // namespace
