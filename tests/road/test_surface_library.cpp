// Library surfaces: `[road] surface = "models/surfaces/NAME.toml"` merges a surface file into
// the case's [road] like `[tyre] file`: keys beside `surface` and --set road.key=... override the
// file's, the road factory ignores the file's [about] table, and every message names the file
// that set the key. The example surfaces are tests/surfaces/test_*.toml (copied into a
// temporary project tree as models/surfaces/).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/case_file.hpp"
#include "core/config_table.hpp"
#include "core/error.hpp"
#include "road/file_road.hpp"
#include "road/road_profile.hpp"
#include "road/road_surface.hpp"
#include "road/road_test_support.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;


// A temporary project: models/surfaces/ with the test surfaces, cases/ for the case files.
class SurfaceLibrary : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(root_ / "models/surfaces");
    fs::create_directories(root_ / "cases");
    const fs::path examples = fs::path(ROLLNOISE_SOURCE_DIR) / "tests/surfaces";
    for (const char* name : {"test_sine.toml", "test_measured.toml", "test_measured_profile.csv"}) {
      fs::copy_file(examples / name, root_ / "models/surfaces" / name);
    }
  }
  fs::path write(const std::string& relative, const std::string& text) const { return temp_.write(relative, text); }
  static std::unique_ptr<RoadProfile> profile_of(const CaseFile& file, double x_max = 1.0) {
    return make_road_profile(file.section("road"), 0.0, x_max);
  }
  template <class F>
  static std::string error_of(F f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

  test::TempFolder temp_{"rollnoise_test_surfaces_"};
  const fs::path root_ = temp_.path();
};

TEST_F(SurfaceLibrary, SurfaceKeysMergeAndKeysBesideOverride) {
  // The library surface alone equals the same keys written inline.
  const auto library = CaseFile::load(write("cases/a.toml", "[road]\nsurface = \"models/surfaces/test_sine.toml\"\n"));
  const auto inline_case = CaseFile::load(write("cases/b.toml", "[road]\ntype = \"sine\"\namplitude = 0.001\nwavelength = 0.1\n"));
  const auto a = profile_of(library);
  const auto b = profile_of(inline_case);
  EXPECT_EQ(a->type(), "sine");
  for (int i = 0; i <= 100; ++i) ASSERT_EQ(a->height(0.01 * i), b->height(0.01 * i));
  // A key beside `surface` overrides the file's; the file's other keys stay.
  const auto merged = CaseFile::load(
      write("cases/c.toml", "[road]\nsurface = \"models/surfaces/test_sine.toml\"\namplitude = 0.003\n"));
  const auto c = profile_of(merged);
  const auto expected = CaseFile::load(write("cases/d.toml", "[road]\ntype = \"sine\"\namplitude = 0.003\nwavelength = 0.1\n"));
  const auto d = profile_of(expected);
  for (int i = 0; i <= 100; ++i) ASSERT_EQ(c->height(0.01 * i), d->height(0.01 * i));
  EXPECT_NEAR(c->height(0.025), 0.003, 1e-15);  // a crest at a quarter wavelength
  // Provenance: each key names the file that set it.
  const ConfigTable road = merged.section("road");
  EXPECT_EQ(road.source_of("amplitude"), (root_ / "cases/c.toml").string());
  EXPECT_MENTIONS(road.source_of("wavelength"), "test_sine.toml");
  EXPECT_MENTIONS(road.source_of("about"), "test_sine.toml");
  // The [about] table is there for tools to print.
  ASSERT_TRUE(road.subtable("about").has_value());
  EXPECT_EQ(road.subtable("about")->text("name"), "Test sine");
}

TEST_F(SurfaceLibrary, SetOverridesTheSurfaceAndCanChooseIt) {
  const auto path = write("cases/e.toml", "[road]\nsurface = \"models/surfaces/test_sine.toml\"\n");
  const auto file = CaseFile::load(path, {"road.wavelength=0.2", "road.amplitude=0.002"});
  const auto road = profile_of(file);
  EXPECT_NEAR(road->height(0.05), 0.002, 1e-15);  // crest at a quarter of 0.2 m
  EXPECT_EQ(file.section("road").source_of("wavelength"), "--set road.wavelength");
  // A bad value given by --set is reported against --set.
  const auto bad = CaseFile::load(path, {"road.amplitude=-1"});
  EXPECT_MENTIONS(error_of([&] { (void)profile_of(bad); }), "--set road.amplitude: [road] amplitude");
  // --set road.surface=... chooses the surface (here: replacing an inline flat road's type).
  const auto flat = write("cases/f.toml", "[road]\ntype = \"flat\"\n");
  const auto chosen = CaseFile::load(flat, {"road.surface=models/surfaces/test_sine.toml"});
  EXPECT_EQ(chosen.section("road").text("type"), "flat");  // keys beside `surface` still win ...
  const auto chosen_sine = CaseFile::load(write("cases/g.toml", "[road]\n"), {"road.surface=models/surfaces/test_sine.toml"});
  EXPECT_EQ(profile_of(chosen_sine)->type(), "sine");  // ... and with none beside, the file decides
}

TEST_F(SurfaceLibrary, FileNamedInASurfaceIsFoundBesideIt) {
  const auto file = CaseFile::load(write("cases/deep/er/h.toml", "[road]\nsurface = \"models/surfaces/test_measured.toml\"\n"));
  const auto road = profile_of(file, 0.06);
  EXPECT_EQ(road->type(), "file");
  EXPECT_NEAR(road->height(0.03), 0.06e-3, 1e-18);  // the dropout, filled on the ramp
  EXPECT_NEAR(road->height(0.055), 0.11e-3, 1e-18);
  const auto* file_road = dynamic_cast<const FileRoad*>(road.get());
  ASSERT_NE(file_road, nullptr);
  EXPECT_EQ(file_road->dropouts(), 1u);
  // As a surface for a tyre too.
  const auto surface = make_road_surface(file.section("road"), 0.0, 0.06, 0.1);
  EXPECT_NEAR(surface->height(0.02, 0.05), 0.04e-3, 1e-18);
  // A run longer than the profile: an error naming the profile file, not a wrap.
  const std::string message = error_of([&] { (void)profile_of(file, 1.0); });
  EXPECT_MENTIONS(message, "test_measured_profile.csv");
  EXPECT_MENTIONS(message, "needs x from 0 to 1 m");
}

TEST_F(SurfaceLibrary, ErrorsNameTheSurfaceFile) {
  write("models/surfaces/odd.toml", "type = \"sine\"\namplitude = 0.001\nwavelength = 0.1\ncolour = \"grey\"\n");
  const auto odd = CaseFile::load(write("cases/i.toml", "[road]\nsurface = \"models/surfaces/odd.toml\"\n"));
  std::string message = error_of([&] { (void)profile_of(odd); });
  EXPECT_MENTIONS(message, "odd.toml: [road] colour: unknown key");
  write("models/surfaces/negative.toml", "type = \"sine\"\namplitude = -0.001\nwavelength = 0.1\n");
  const auto negative = CaseFile::load(write("cases/j.toml", "[road]\nsurface = \"models/surfaces/negative.toml\"\n"));
  message = error_of([&] { (void)profile_of(negative); });
  EXPECT_MENTIONS(message, "negative.toml: [road] amplitude");
  // [about] must be a table.
  write("models/surfaces/about.toml", "type = \"flat\"\nabout = \"a flat road\"\n");
  const auto about = CaseFile::load(write("cases/k.toml", "[road]\nsurface = \"models/surfaces/about.toml\"\n"));
  EXPECT_MENTIONS(error_of([&] { (void)profile_of(about); }), "about.toml: [road] about: must be a table");
  // Malformed TOML in the surface file.
  write("models/surfaces/broken.toml", "type = \n");
  message = error_of([&] { (void)CaseFile::load(write("cases/l.toml", "[road]\nsurface = \"models/surfaces/broken.toml\"\n")); });
  EXPECT_MENTIONS(message, "broken.toml: line 1");
}

TEST_F(SurfaceLibrary, UnknownSurfaceNamesKeyPathAndListsTheLibrary) {
  const auto path = write("cases/m.toml", "[road]\nsurface = \"models/surfaces/no_such.toml\"\n");
  std::string message = error_of([&] { (void)CaseFile::load(path); });
  EXPECT_MENTIONS(message, path.string() + ": [road] surface: no surface file \"models/surfaces/no_such.toml\"");
  EXPECT_MENTIONS(message, "tried ");
  EXPECT_MENTIONS(message, "no_such.toml");
  EXPECT_MENTIONS(message, "test_measured, test_sine");
  // A bare name (no folder) is tried beside the case; the library is still listed.
  message = error_of([&] { (void)CaseFile::load(write("cases/n.toml", "[road]\nsurface = \"test_sine\"\n")); });
  EXPECT_MENTIONS(message, "test_measured, test_sine");
  // Named by --set: the message says so.
  message = error_of([&] { (void)CaseFile::load(write("cases/o.toml", "[road]\n"), {"road.surface=models/surfaces/nope.toml"}); });
  EXPECT_MENTIONS(message, "--set road.surface: [road] surface");
  // Not a string.
  message = error_of([&] { (void)CaseFile::load(write("cases/p.toml", "[road]\nsurface = 3\n")); });
  EXPECT_MENTIONS(message, "[road] surface: must be a string");
}

}  // namespace
}  // namespace rollnoise
