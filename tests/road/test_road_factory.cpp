// make_road_profile: type selection, key validation with messages naming "[road] key", and
// the profiles it builds equal those built directly.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <string>

#include <toml++/toml.h>

#include "core/config_table.hpp"
#include "core/error.hpp"
#include "road/random_road.hpp"
#include "road/road_profile.hpp"
#include "road/sine_road.hpp"
#include "road/road_test_support.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

// Builds a road from the [road] table of `text`, as if read from `source`.
std::unique_ptr<RoadProfile> build(const std::string& text, double x_min = -1.0, double x_max = 10.0,
                                   const std::string& source = "case.toml") {
  toml::table t = toml::parse(text);
  ConfigTable road(*t["road"].as_table(), source, "road");
  return make_road_profile(road, x_min, x_max);
}

// what() of the InputError that building throws, or "" if it builds.
std::string error_of(const std::string& text, double x_max = 10.0) {
  try {
    build(text, -1.0, x_max);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}


TEST(RoadFactory, UnknownTypeListsAllowedValues) {
  const std::string message = error_of("[road]\ntype = \"cobbles\"\n");
  EXPECT_MENTIONS(message, "case.toml");
  EXPECT_MENTIONS(message, "[road] type");
  EXPECT_MENTIONS(message, "cobbles");
  for (const char* allowed : {"\"flat\"", "\"sine\"", "\"random\"", "\"file\""}) EXPECT_MENTIONS(message, allowed);
  EXPECT_MENTIONS(error_of("[road]\namplitude = 1.0\n"), "[road] type");
}

TEST(RoadFactory, UnknownKeyIsNamed) {
  EXPECT_MENTIONS(error_of("[road]\ntype = \"sine\"\namplitude = 1e-3\nwavelength = 0.1\namplitdue = 2\n"),
                  "[road] amplitdue");
  EXPECT_MENTIONS(error_of("[road]\ntype = \"flat\"\namplitude = 1e-3\n"), "[road] amplitude");
  EXPECT_MENTIONS(error_of("[road]\ntype = \"random\"\nstd_dev = 1e-3\ncorrelation_length = 0.1\n"
                           "wavelength = 0.1\n"),
                  "[road] wavelength");
  EXPECT_MENTIONS(error_of("[road]\ntype = \"file\"\nfile = \"x.csv\"\nseed = 3\n"), "[road] seed");
}

TEST(RoadFactory, SineKeysValidated) {
  EXPECT_MENTIONS(error_of("[road]\ntype = \"sine\"\namplitude = -1e-3\nwavelength = 0.1\n"),
                  "[road] amplitude");
  EXPECT_MENTIONS(error_of("[road]\ntype = \"sine\"\namplitude = 1e-3\nwavelength = 0\n"),
                  "[road] wavelength");
  EXPECT_MENTIONS(error_of("[road]\ntype = \"sine\"\nwavelength = 0.1\n"), "[road] amplitude");
  EXPECT_MENTIONS(error_of("[road]\ntype = \"sine\"\namplitude = \"big\"\nwavelength = 0.1\n"),
                  "[road] amplitude");
}

TEST(RoadFactory, RandomSpectrumFormsAreExclusive) {
  const std::string head = "[road]\ntype = \"random\"\nstd_dev = 1e-3\n";
  EXPECT_MENTIONS(error_of(head + "correlation_length = 0.1\nmin_wavelength = 0.01\nmax_wavelength = 0.5\n"),
                  "[road] correlation_length");
  EXPECT_MENTIONS(error_of(head + "correlation_length = 0.1\nmax_wavelength = 0.5\n"),
                  "[road] correlation_length");
  EXPECT_MENTIONS(error_of(head), "[road] correlation_length");
  EXPECT_MENTIONS(error_of(head + "min_wavelength = 0.01\n"), "[road] max_wavelength");
  EXPECT_MENTIONS(error_of(head + "max_wavelength = 0.01\n"), "[road] min_wavelength");
  EXPECT_MENTIONS(error_of(head + "min_wavelength = 0.5\nmax_wavelength = 0.1\n"), "[road] min_wavelength");
  EXPECT_MENTIONS(error_of("[road]\ntype = \"random\"\ncorrelation_length = 0.1\n"), "[road] std_dev");
}

TEST(RoadFactory, RandomNumericKeysValidated) {
  const std::string head = "[road]\ntype = \"random\"\nstd_dev = 1e-3\ncorrelation_length = 0.1\n";
  EXPECT_MENTIONS(error_of(head + "seed = -1\n"), "[road] seed");
  EXPECT_MENTIONS(error_of(head + "seed = 1.5\n"), "[road] seed");
  EXPECT_MENTIONS(error_of(head + "lead_in = -0.1\n"), "[road] lead_in");
  EXPECT_MENTIONS(error_of(head + "sample_spacing = 0\n"), "[road] sample_spacing");
  // Checks made by RandomRoad itself come back named by key and case file too.
  const std::string coarse = error_of(head + "sample_spacing = 0.2\n");
  EXPECT_MENTIONS(coarse, "case.toml: [road] sample_spacing");
  const std::string huge = error_of(head + "sample_spacing = 1e-6\n", 1e3);  // 1e9 samples
  EXPECT_MENTIONS(huge, "case.toml: [road] sample_spacing");
  EXPECT_MENTIONS(huge, "2^26");
  EXPECT_EQ(error_of(head + "seed = 0\nlead_in = 0\nsample_spacing = 0.01\n"), "");
}

TEST(RoadFactory, BuildsTheProfilesItDescribes) {
  const auto flat = build("[road]\ntype = \"flat\"\n");
  EXPECT_EQ(flat->type(), "flat");
  EXPECT_EQ(flat->height(1.0), 0.0);

  const auto sine = build("[road]\ntype = \"sine\"\namplitude = 2e-3\nwavelength = 0.3\n");
  const SineRoad direct_sine(2e-3, 0.3);
  for (double x : {-0.1, 0.0, 0.05, 0.2, 7.3}) EXPECT_EQ(sine->height(x), direct_sine.height(x));

  // Defaults: seed 1, spacing lc/16, lead-in 2 lc, 100 m of road (more than the run's 10 m).
  const auto random = build("[road]\ntype = \"random\"\nstd_dev = 1e-3\ncorrelation_length = 0.1\n", -1.0, 10.0);
  RandomRoadSpec spec;
  spec.std_dev = 1e-3;
  spec.correlation_length = 0.1;
  spec.sample_spacing = 0.1 / 16.0;
  spec.lead_in = 0.2;
  spec.seed = 1;
  spec.x_max = 100.0;
  const RandomRoad direct_random(spec);
  EXPECT_EQ(random->type(), "random");
  for (double x : {-0.1, 0.0, 0.05, 0.2, 7.3, 10.0}) EXPECT_EQ(random->height(x), direct_random.height(x));
  // A shorter run sees the same road.
  const auto shorter = build("[road]\ntype = \"random\"\nstd_dev = 1e-3\ncorrelation_length = 0.1\n", -1.0, 3.0);
  for (double x : {0.05, 0.2, 2.9}) EXPECT_EQ(shorter->height(x), random->height(x));

  const auto band = build("[road]\ntype = \"random\"\nstd_dev = 1e-3\nmin_wavelength = 0.02\n"
                          "max_wavelength = 0.4\nseed = 4\n");
  EXPECT_EQ(band->type(), "random");
  EXPECT_EQ(dynamic_cast<const RandomRoad&>(*band).lead_in(), 0.8);  // 2 max_wavelength
}

TEST(RoadFactory, FileIsResolvedBesideTheCaseFile) {
  std::random_device device;
  const fs::path dir = fs::temp_directory_path() /
                       ("rollnoise_test_road_factory_" + std::to_string(device()) + std::to_string(device()));
  fs::create_directories(dir / "profiles");
  std::ofstream(dir / "profiles" / "ramp.csv") << "x,z\n0,0\n20,0.02\n";
  const std::string case_file = (dir / "case.toml").string();

  const auto road = build("[road]\ntype = \"file\"\nfile = \"profiles/ramp.csv\"\n", -1.0, 10.0, case_file);
  EXPECT_EQ(road->type(), "file");
  EXPECT_NEAR(road->height(5.0), 0.005, 1e-18);

  // Errors about the data name the data file.
  try {
    build("[road]\ntype = \"file\"\nfile = \"profiles/ramp.csv\"\n", -1.0, 30.0, case_file);
    ADD_FAILURE() << "a range beyond the data was accepted";
  } catch (const InputError& e) {
    EXPECT_MENTIONS(e.what(), "ramp.csv");
  }
  try {
    build("[road]\ntype = \"file\"\nfile = \"profiles/nope.csv\"\n", -1.0, 10.0, case_file);
    ADD_FAILURE() << "a missing file was accepted";
  } catch (const InputError& e) {
    EXPECT_MENTIONS(e.what(), "nope.csv");
  }
  EXPECT_MENTIONS(error_of("[road]\ntype = \"file\"\n"), "[road] file");
  EXPECT_MENTIONS(error_of("[road]\ntype = \"file\"\nfile = 3\n"), "[road] file");

  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
}  // namespace rollnoise
