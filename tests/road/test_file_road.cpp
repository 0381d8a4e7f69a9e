// FileRoad: exact linear interpolation, and every bad file an InputError naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>

#include "core/error.hpp"
#include "road/file_road.hpp"
#include "road/profile_cleaning.hpp"
#include "road/road_test_support.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

class FileRoadTest : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& text) const { return temp_.write(name, text); }
  // The InputError message of building a FileRoad from `path`, or "" if none was thrown.
  static std::string error_of(const fs::path& path, double x_min, double x_max) {
    try {
      FileRoad road(path, x_min, x_max);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

  test::TempFolder temp_{"rollnoise_test_file_road_"};
  const fs::path dir_ = temp_.path();
};

TEST_F(FileRoadTest, LinearDataIsInterpolatedExactly) {
  // z = 0.003 x - 0.001 on irregular rows; linear interpolation reproduces a straight line up
  // to rounding: the decimal data, the interpolation and the reference each carry a few ulp of
  // |z| <= 0.0065 (ulp ~ 1e-18), so 1e-16 is a safe bound that still catches any wrong weight.
  const auto path = write("line.csv",
                          "# a straight ramp\nx,z\n0,-0.001\n0.1,-0.0007\n0.35,0.00005\n"
                          "1,0.002\n2.5,0.0065\n");
  const FileRoad road(path, 0.0, 2.5);
  EXPECT_EQ(road.type(), "file");
  for (int i = 0; i <= 2500; ++i) {
    const double x = 0.001 * i;
    ASSERT_NEAR(road.height(x), 0.003 * x - 0.001, 1e-16) << "x = " << x;
  }
  EXPECT_EQ(road.height(0.35), 0.00005);  // a data point is returned exactly
  EXPECT_EQ(road.height(2.5), 0.0065);
}

TEST_F(FileRoadTest, PiecewiseLinearBetweenRowsAndZeroBeforeStart) {
  const auto path = write("tent.csv", "x,z\n-1,5\n0,0\n1,1\n2,0\n");
  // Steps of 1 to 5 m per metre, spikes to ISO 13473-1 if α (spike_slope_threshold) is at most
  // their slope: kept here whatever α is, as the test is about the interpolation.
  const FileRoad road(path, -1.0, 2.0, SpikeHandling::keep);
  EXPECT_EQ(road.height(-0.5), 0.0);  // data at x < 0 is replaced by the flat lead-in
  EXPECT_EQ(road.height(0.5), 0.5);
  EXPECT_EQ(road.height(1.0), 1.0);
  EXPECT_EQ(road.height(1.75), 0.25);
  EXPECT_THROW((void)road.height(2.5), std::logic_error);
}

TEST_F(FileRoadTest, SpikesAreRemovedUnlessKept) {
  // A spike twice the threshold (2 α mm over 1 mm) on a flat 1 mm-spaced profile: the sample
  // and both next to it (the ends of each step) are spikes.
  const double spike_mm = 2 * spike_slope_threshold;
  const auto path = write("spike.csv", "x_mm,z_mm\n0,0\n1,0\n2,0\n3," + std::to_string(spike_mm) +
                                           "\n4,0\n5,0\n6,0\n");
  const FileRoad cleaned(path, 0.0, 0.006);
  EXPECT_EQ(cleaned.spikes(), 3u);
  for (int i = 0; i <= 6; ++i) EXPECT_EQ(cleaned.height(1e-3 * i), 0.0) << i;
  const FileRoad kept(path, 0.0, 0.006, SpikeHandling::keep);
  EXPECT_EQ(kept.spikes(), 0u);
  EXPECT_NEAR(kept.height(3e-3), spike_mm * 1e-3, 1e-17);
}

TEST_F(FileRoadTest, CrlfAndExtraColumnsAreAccepted) {
  const auto path = write("crlf.csv", "t,x,z\r\n0,0,1\r\n9,2,3\r\n");
  const FileRoad road(path, 0.0, 2.0);
  EXPECT_EQ(road.height(1.0), 2.0);
}

TEST_F(FileRoadTest, NonIncreasingXNamesFileAndRow) {
  const auto path = write("repeat_x.csv", "x,z\n0,0\n1,0\n1,0.5\n2,0\n");
  const std::string message = error_of(path, 0.0, 2.0);
  EXPECT_NE(message.find("repeat_x.csv"), std::string::npos) << message;
  EXPECT_NE(message.find("row 3"), std::string::npos) << message;
  const auto back = write("backwards.csv", "x,z\n0,0\n2,0\n1,0\n");
  EXPECT_NE(error_of(back, 0.0, 1.0).find("backwards.csv"), std::string::npos);
}

TEST_F(FileRoadTest, TooFewRowsNamesFile) {
  const auto one = write("one_row.csv", "x,z\n0,0\n");
  EXPECT_NE(error_of(one, 0.0, 0.0).find("one_row.csv"), std::string::npos);
  const auto none = write("header_only.csv", "x,z\n");
  EXPECT_NE(error_of(none, 0.0, 0.0).find("header_only.csv"), std::string::npos);
}

TEST_F(FileRoadTest, NonFiniteValueNamesFile) {
  for (const char* bad : {"nan", "NaN", "inf", "1e999"}) {
    const auto path = write("bad_value.csv", std::string("x,z\n0,0\n1,") + bad + "\n2,0\n");
    const std::string message = error_of(path, 0.0, 2.0);
    EXPECT_NE(message.find("bad_value.csv"), std::string::npos) << bad << ": " << message;
  }
}

TEST_F(FileRoadTest, MissingFileOrColumnNamesFile) {
  EXPECT_NE(error_of(dir_ / "no_such_road.csv", 0.0, 1.0).find("no_such_road.csv"), std::string::npos);
  const auto path = write("no_z.csv", "x,height\n0,0\n1,0\n");
  const std::string message = error_of(path, 0.0, 1.0);
  EXPECT_NE(message.find("no_z.csv"), std::string::npos) << message;
  EXPECT_NE(message.find("\"z\""), std::string::npos) << message;
}

TEST_F(FileRoadTest, RangeNotCoveredNamesFileAndBothRanges) {
  const auto path = write("short_road.csv", "x,z\n0,0\n1.5,0\n");
  const std::string message = error_of(path, -2.0, 3.0);
  EXPECT_NE(message.find("short_road.csv"), std::string::npos) << message;
  EXPECT_NE(message.find("from 0 to 1.5"), std::string::npos) << message;  // what it covers
  EXPECT_NE(message.find("from 0 to 3"), std::string::npos) << message;    // what the run needs
  // Starting after 0 is too late when the run reaches x = 0 ...
  const auto late = write("late_start.csv", "x,z\n0.5,0\n4,0\n");
  EXPECT_NE(error_of(late, -1.0, 3.0).find("late_start.csv"), std::string::npos);
  // ... but fine when the run itself starts later.
  EXPECT_EQ(error_of(late, 0.5, 3.0), "");
  EXPECT_EQ(error_of(path, -2.0, 1.5), "");
}

}  // namespace
}  // namespace rollnoise
