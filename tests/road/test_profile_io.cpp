// Profile and height-map files: the profile CSV reader (one and several lines, units, dropouts),
// the HDF5 height-map reader, format detection, load_profile_file (uniform grid, linear
// resampling) and FileRoad / HeightMapSurface reading through them. Round trips are exact to
// round-off; every bad file is an InputError naming the file, the place and what is allowed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/hdf5_writer.hpp"
#include "road/file_road.hpp"
#include "road/height_map_hdf5.hpp"
#include "road/height_map_surface.hpp"
#include "road/profile_csv.hpp"
#include "road/profile_file.hpp"
#include "road/profile_format.hpp"
#include "road/road_test_support.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;


class ProfileIo : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& text) const { return temp_.write(name, text); }
  // An HDF5 height map with z = f(x, y); units per dataset, values written in those units.
  fs::path write_h5(const std::string& name, const std::vector<double>& x, const std::vector<double>& y,
                    double (*f)(double, double), const std::string& xy_units = "m",
                    const std::string& z_units = "m") const {
    const double sxy = unit_to_metres(xy_units);
    const double sz = unit_to_metres(z_units);
    const fs::path path = dir_ / name;
    Hdf5Writer h5(path);
    Eigen::VectorXd xv(static_cast<Eigen::Index>(x.size()));
    Eigen::VectorXd yv(static_cast<Eigen::Index>(y.size()));
    Eigen::MatrixXd z(static_cast<Eigen::Index>(x.size()), static_cast<Eigen::Index>(y.size()));
    for (std::size_t i = 0; i < x.size(); ++i) xv(static_cast<Eigen::Index>(i)) = x[i] / sxy;
    for (std::size_t j = 0; j < y.size(); ++j) yv(static_cast<Eigen::Index>(j)) = y[j] / sxy;
    for (std::size_t i = 0; i < x.size(); ++i)
      for (std::size_t j = 0; j < y.size(); ++j)
        z(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = f(x[i], y[j]) / sz;
    h5.write("/x", xv, xy_units, "along the road");
    h5.write("/y", yv, xy_units, "across the road");
    h5.write("/z", z, z_units, "height");
    return path;
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

  test::TempFolder temp_{"rollnoise_test_profile_io_"};
  const fs::path dir_ = temp_.path();
};

// A known profile: z(x) = 1e-3 sin(40 x) + 2e-4 x on x = 0 .. 0.999 step 1 mm.
std::vector<double> grid(double x0, double step, std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = x0 + static_cast<double>(i) * step;
  return x;
}
double known(double x) { return 1e-3 * std::sin(40.0 * x) + 2e-4 * x; }
double plane(double x, double y) { return 0.002 * x - 0.003 * y + 0.0001; }

std::string csv_of(const std::vector<double>& x, const std::vector<std::vector<double>>& z, const std::string& header,
                   double scale, const std::string& preamble = "") {
  std::ostringstream out;
  out << preamble << header << "\n";
  for (std::size_t i = 0; i < x.size(); ++i) {
    out << format_number(x[i] / scale);
    for (const auto& line : z) out << "," << (std::isnan(line[i]) ? "" : format_number(line[i] / scale));
    out << "\n";
  }
  return out.str();
}

TEST_F(ProfileIo, CsvRoundTripInMetresAndMillimetres) {
  const auto x = grid(0.0, 1e-3, 1000);
  std::vector<double> z(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) z[i] = known(x[i]);
  for (const std::string header : {"x,z", "x_m,z_m", "x [m],z [m]"}) {
    const ProfileTable t = read_profile_csv(write("m.csv", csv_of(x, {z}, header, 1.0)));
    ASSERT_EQ(t.z_lines.size(), 1u);
    EXPECT_EQ(t.x, x) << header;  // shortest round-trip text: exact
    EXPECT_EQ(t.z_lines[0], z) << header;
    EXPECT_EQ(t.y, std::vector<double>{0.0});
    EXPECT_EQ(t.dropouts, 0u);
  }
  for (const std::string header : {"x_mm,z_mm", "x [mm], z [mm]", "x [mm],z_mm"}) {
    const ProfileTable t = read_profile_csv(write("mm.csv", csv_of(x, {z}, header, 1e-3)));
    ASSERT_EQ(t.x.size(), x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      ASSERT_NEAR(t.x[i], x[i], 2e-16 * (1.0 + x[i])) << header;  // one rounding in x/1e-3, one in *1e-3
      ASSERT_NEAR(t.z_lines[0][i], z[i], 1e-18) << header;
    }
  }
  // Micrometres, and other columns ignored.
  const ProfileTable um = parse_profile_csv("t,x [mm],z [um]\n9,0,1500\n9,2,-250\n", "um.csv");
  EXPECT_EQ(um.x[1], 2e-3);
  EXPECT_NEAR(um.z_lines[0][0], 1.5e-3, 1e-18);
  EXPECT_NEAR(um.z_lines[0][1], -2.5e-4, 1e-18);
}

TEST_F(ProfileIo, MultiLineCsvRoundTripWithYLine) {
  const auto x = grid(0.5, 2e-3, 300);
  const std::vector<double> y = {-0.05, 0.0, 0.05};
  std::vector<std::vector<double>> z(3, std::vector<double>(x.size()));
  for (std::size_t l = 0; l < 3; ++l)
    for (std::size_t i = 0; i < x.size(); ++i) z[l][i] = plane(x[i], y[l]);
  const ProfileTable m = read_profile_csv(write("lines.csv", csv_of(x, z, "x,z_1,z_2,z_3", 1.0, "# y = -0.05, 0, 0.05\n")));
  EXPECT_EQ(m.x, x);
  EXPECT_EQ(m.y, y);
  EXPECT_EQ(m.z_lines, z);
  // Millimetres everywhere, columns in another order, the y line after a free comment.
  std::string text = "# measured 2024\n# y [mm] = -50, 0, 50\nx_mm,z_3_mm,z_1_mm,z_2_mm\n0,3,1,2\n1,6,4,5\n";
  const ProfileTable mm = parse_profile_csv(text, "lines_mm.csv");
  ASSERT_EQ(mm.z_lines.size(), 3u);
  EXPECT_NEAR(mm.y[0], -0.05, 1e-17);
  EXPECT_EQ(mm.y[1], 0.0);
  EXPECT_NEAR(mm.z_lines[0][1], 4e-3, 1e-18);  // z_1 is the second column
  EXPECT_NEAR(mm.z_lines[2][0], 3e-3, 1e-18);
  const ProfileTable ymm = parse_profile_csv("# y_mm = 10\nx,z_1\n0,0\n1,1\n", "s.csv");
  EXPECT_NEAR(ymm.y[0], 0.01, 1e-18);
}

TEST_F(ProfileIo, EmptyCellsAreDropoutsAndCounted) {
  const ProfileTable t = parse_profile_csv("# y = 0, 0.1\nx,z_1,z_2\n0,1,\n1,,2\n2,3,4\n3,,\n", "drop.csv");
  EXPECT_EQ(t.dropouts, 4u);
  EXPECT_TRUE(std::isnan(t.z_lines[0][1]));
  EXPECT_TRUE(std::isnan(t.z_lines[1][0]));
  // load_profile_file fills them (linear between neighbours; the end value at the ends).
  const LoadedProfile p = load_profile_file(write("drop.csv", "x,z\n0,1\n1,\n2,3\n3,\n"));
  EXPECT_EQ(p.dropouts, 2u);
  EXPECT_EQ(p.z_lines[0], (std::vector<double>{1, 2, 3, 3}));
  // FileRoad too (x uniform: cleaned); uneven x: the row is left out and bridged.
  const FileRoad even(write("even.csv", "x,z\n0,0\n1,\n2,2\n"), 0.0, 2.0);
  EXPECT_EQ(even.dropouts(), 1u);
  EXPECT_EQ(even.height(1.0), 1.0);
  const FileRoad uneven(write("uneven.csv", "x,z\n0,0\n1,\n3,3\n"), 0.0, 3.0);
  EXPECT_EQ(uneven.dropouts(), 1u);
  EXPECT_EQ(uneven.height(1.0), 1.0);
}

TEST_F(ProfileIo, BadCsvNamesFileLineAndWhatIsAllowed) {
  struct Case {
    std::string text, expect1, expect2;
  };
  const std::vector<Case> cases = {
      {"x,z\n0,0\n1,0\n1,0.5\n", "line 4", "strictly increasing"},           // repeated x
      {"x,z\n0,0\n2,0\n1,0\n", "line 4", "strictly increasing"},             // x backwards
      {"x,z\n0,0\n1,nan\n", "line 3", "leave the cell empty"},               // NaN written out
      {"x,z\n0,0\nNaN,1\n", "line 3, column \"x\"", "finite number"},
      {"x,z\n0,0\n1,inf\n", "line 3", "finite number"},
      {"x,z\n0,0\n,1\n", "line 3", "position x"},                            // x missing
      {"x,z\n0,0\n1,0,3\n", "line 3", "the header has 2"},                  // unequal row lengths
      {"x,z\n0,0\n1\n", "line 3", "the header has 2"},
      {"x,z\n0,\n1,\n", "column \"z\"", "no value at all"},                 // all dropouts
      {"x,z_1,z_2\n0,0,0\n1,0,0\n", "y line", "# y [mm] = -50, 0, 50"},     // no y line
      {"# y = 0, 1, 2\nx,z_1,z_2\n0,0,0\n1,0,0\n", "the y line", "one per column"},
      {"# y = 1, 0\nx,z_1,z_2\n0,0,0\n1,0,0\n", "y line", "strictly increasing"},
      {"# y = 0, zero\nx,z_1,z_2\n0,0,0\n1,0,0\n", "y line", "not a finite number"},
      {"x,z_1,z_3\n0,0,0\n1,0,0\n", "header", "z_2 is missing"},
      {"x,z,z_1\n0,0,0\n1,0,0\n", "header", "both a z column"},
      {"x [cm],z\n0,0\n1,0\n", "x [cm]", "m, mm or um"},
      {"x,z [inch]\n0,0\n1,0\n", "z [inch]", "m, mm or um"},
      {"pos,z\n0,0\n1,0\n", "header", "no column \"x\""},
      {"x,height\n0,0\n1,0\n", "header", "z_1"},
      {"x,z\n0,0\n", "", "at least 2 data rows"},
      {"", "", "no header"},
  };
  for (const auto& c : cases) {
    const fs::path path = write("bad_profile.csv", c.text);
    const std::string message = error_of([&] { (void)read_profile_csv(path); });
    EXPECT_MENTIONS(message, "bad_profile.csv");
    EXPECT_MENTIONS(message, c.expect1);
    EXPECT_MENTIONS(message, c.expect2);
    // The same error through the loader (an empty file is no CSV to it: another message).
    if (!c.text.empty()) {
      EXPECT_EQ(error_of([&] { (void)load_profile_file(path); }), message);
    }
  }
}

TEST_F(ProfileIo, LoadProfileFileResamplesUnevenXLinearly) {
  // Uneven rows of a straight line: resampled at the median interval, exact to round-off.
  const auto path = write("ramp.csv", "x,z\n0,-0.001\n0.1,-0.0007\n0.2,-0.0004\n0.35,0.00005\n0.45,0.00035\n1,0.002\n");
  const LoadedProfile p = load_profile_file(path);
  EXPECT_EQ(p.spacing_m, p.x[1] - p.x[0]);
  EXPECT_NEAR(p.spacing_m, 0.1, 1e-15);
  ASSERT_EQ(p.x.size(), 11u);
  for (std::size_t i = 0; i < p.x.size(); ++i) EXPECT_NEAR(p.z_lines[0][i], 0.003 * p.x[i] - 0.001, 1e-17) << i;
  EXPECT_EQ(p.source, path.string());
  // Uniform rows are kept as they are.
  const auto x = grid(0.0, 1e-3, 200);
  std::vector<double> z(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) z[i] = known(x[i]);
  const LoadedProfile u = load_profile_file(write("u.csv", csv_of(x, {z}, "x,z", 1.0)));
  EXPECT_EQ(u.z_lines[0], z);
  EXPECT_NEAR(u.spacing_m, 1e-3, 1e-15);
  EXPECT_EQ(u.dropouts + u.spikes, 0u);
  EXPECT_EQ(u.y, std::vector<double>{0.0});
}

TEST_F(ProfileIo, SteepStoneEdgesSurviveACsvRoundTrip) {
  // Stone edges sampled at the laser's 0.0375 mm, written in mm and read back as a file road:
  // each rises 1.2 mm over 4 samples (slope 8) and falls over 36. The spike criterion is judged
  // at 0.5 mm (profile_cleaning.hpp), where these steps are texture: nothing is replaced. A
  // single reading 4 mm too high is still a spike (it and both neighbours).
  const double dx = 0.0375e-3;
  const auto x = grid(0.0, dx, 8000);  // 300 mm
  std::vector<double> z(x.size());
  for (std::size_t i = 0; i < z.size(); ++i) {
    const std::size_t k = i % 40;
    z[i] = k < 4 ? 0.3e-3 * static_cast<double>(k) : 1.2e-3 * (1.0 - static_cast<double>(k - 4) / 36.0);
  }
  const FileRoad road(write("edges_mm.csv", csv_of(x, {z}, "x_mm,z_mm", 1e-3)), 0.0, x.back());
  EXPECT_EQ(road.spikes(), 0u);
  EXPECT_EQ(road.dropouts(), 0u);
  for (std::size_t i = 0; i < x.size(); i += 7) EXPECT_NEAR(road.height(x[i]), z[i], 1e-12) << i;
  z[4010] += 4e-3;
  const FileRoad spiked(write("spiked_mm.csv", csv_of(x, {z}, "x_mm,z_mm", 1e-3)), 0.0, x.back());
  EXPECT_EQ(spiked.spikes(), 3u);
}

TEST_F(ProfileIo, FileRoadInterpolatesLinearlyAndRejectsAShortProfile) {
  const auto x = grid(0.0, 1e-3, 1001);  // 0 .. 1 m, in mm
  std::vector<double> z(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) z[i] = 0.004 * x[i] - 0.001;
  const FileRoad road(write("ramp_mm.csv", csv_of(x, {z}, "x [mm],z [mm]", 1e-3)), 0.0, 1.0);
  for (int i = 0; i <= 3000; ++i) {
    const double xi = i / 3000.0;
    ASSERT_NEAR(road.height(xi), 0.004 * xi - 0.001, 1e-17) << xi;
  }
  // Shorter than the run needs: an error naming the file and both ranges, never a wrap.
  const std::string message = error_of([&] { FileRoad r(write("short.csv", csv_of(x, {z}, "x_mm,z_mm", 1e-3)), -0.1, 1.5); });
  EXPECT_MENTIONS(message, "short.csv");
  EXPECT_MENTIONS(message, "covers x from 0 to 1 m");
  EXPECT_MENTIONS(message, "needs x from 0 to 1.5 m");
  // Several lines are not a 1-D profile.
  const auto lines = write("lines.csv", "# y = 0, 1\nx,z_1,z_2\n0,0,0\n1,0,0\n");
  EXPECT_MENTIONS(error_of([&] { FileRoad r(lines, 0.0, 1.0); }), "takes one column z");
}

TEST_F(ProfileIo, Hdf5HeightMapRoundTripInMetresAndMillimetres) {
  const auto x = grid(0.0, 0.01, 21);
  const auto y = grid(-0.1, 0.05, 5);
  for (const std::string units : {"m", "mm"}) {
    const auto path = write_h5("map_" + units + ".h5", x, y, plane, units, units);
    EXPECT_EQ(detect_profile_format(path), ProfileFormat::hdf5);
    const HeightMapGrid g = read_height_map_hdf5(path);
    ASSERT_EQ(g.x.size(), x.size());
    ASSERT_EQ(g.y.size(), y.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      EXPECT_NEAR(g.x[i], x[i], 1e-16);
      for (std::size_t j = 0; j < y.size(); ++j) EXPECT_NEAR(g.z[i * y.size() + j], plane(x[i], y[j]), 1e-18);
    }
    // As a surface: bilinear interpolation of a plane is exact.
    const HeightMapSurface surface(path, 0.0, 0.2, 0.1);
    EXPECT_EQ(surface.type(), "surface");
    for (double xi = 0.0; xi <= 0.2; xi += 0.0037)
      for (double yj = -0.1; yj <= 0.1; yj += 0.013) ASSERT_NEAR(surface.height(xi, yj), plane(xi, yj), 1e-17);
    // As a profile: one line per y.
    const LoadedProfile p = load_profile_file(path);
    ASSERT_EQ(p.z_lines.size(), y.size());
    for (std::size_t j = 0; j < y.size(); ++j) {
      EXPECT_NEAR(p.y[j], y[j], 1e-16);
      for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(p.z_lines[j][i], plane(x[i], y[j]), 1e-18);
    }
  }
  // Shorter than the run needs.
  const auto path = write_h5("small.h5", x, y, plane);
  const std::string message = error_of([&] { HeightMapSurface s(path, 0.0, 0.5, 0.1); });
  EXPECT_MENTIONS(message, "small.h5");
  EXPECT_MENTIONS(message, "the run needs x from 0 to 0.5 m");
}

TEST_F(ProfileIo, Hdf5NanIsADropoutAndFilled) {
  const auto x = grid(0.0, 0.01, 5);
  const auto y = grid(0.0, 0.1, 2);
  const auto path = write_h5("nan.h5", x, y, [](double xi, double yj) {
    return (xi > 0.015 && xi < 0.025 && yj < 0.05) ? std::numeric_limits<double>::quiet_NaN() : xi;
  });
  const HeightMapGrid g = read_height_map_hdf5(path);
  EXPECT_EQ(g.dropouts, 1u);
  const HeightMapSurface s(path, 0.0, 0.04, 0.0);
  EXPECT_EQ(s.dropouts(), 1u);
  EXPECT_NEAR(s.height(0.02, 0.0), 0.02, 1e-17);
  const LoadedProfile p = load_profile_file(path);
  EXPECT_EQ(p.dropouts, 1u);
}

TEST_F(ProfileIo, BadHdf5NamesFileAndDataset) {
  const auto x = grid(0.0, 0.01, 4);
  const auto y = grid(0.0, 0.1, 3);
  const auto good = write_h5("good.h5", x, y, plane);
  std::ifstream in(good, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Corrupted: the signature kept, the rest cut or overwritten.
  std::string cut = bytes.substr(0, bytes.size() / 2);
  std::string scrambled = bytes;
  for (std::size_t i = 64; i < scrambled.size(); i += 7) scrambled[i] = static_cast<char>(scrambled[i] ^ 0x5a);
  for (const auto& [name, text] : {std::pair{"cut.h5", cut}, std::pair{"scrambled.h5", scrambled}}) {
    const auto path = write(name, text);
    const std::string message = error_of([&] { (void)read_height_map_hdf5(path); });
    EXPECT_MENTIONS(message, name);
    EXPECT_EQ(error_of([&] { (void)load_profile_file(path); }).empty(), false);
  }
  // Units missing or unknown, a transposed z, a missing dataset.
  {
    Hdf5Writer h5(dir_ / "no_units.h5");
    h5.write("/x", Eigen::VectorXd(Eigen::VectorXd::LinSpaced(4, 0.0, 0.03)), "m", "");
    h5.write("/y", Eigen::VectorXd(Eigen::VectorXd::LinSpaced(3, 0.0, 0.2)), "furlong", "");
    h5.write("/z", Eigen::MatrixXd(Eigen::MatrixXd::Zero(3, 4)), "m", "");
  }
  std::string message = error_of([&] { (void)read_height_map_hdf5(dir_ / "no_units.h5"); });
  EXPECT_MENTIONS(message, "no_units.h5");
  EXPECT_MENTIONS(message, "/y attribute units");
  EXPECT_MENTIONS(message, "\"mm\"");
  {
    Hdf5Writer h5(dir_ / "transposed.h5");
    h5.write("/x", Eigen::VectorXd(Eigen::VectorXd::LinSpaced(4, 0.0, 0.03)), "m", "");
    h5.write("/y", Eigen::VectorXd(Eigen::VectorXd::LinSpaced(3, 0.0, 0.2)), "m", "");
    h5.write("/z", Eigen::MatrixXd(Eigen::MatrixXd::Zero(3, 4)), "m", "");
  }
  message = error_of([&] { (void)read_height_map_hdf5(dir_ / "transposed.h5"); });
  EXPECT_MENTIONS(message, "/z");
  EXPECT_MENTIONS(message, "[y][x]");
  {
    Hdf5Writer h5(dir_ / "no_z.h5");
    h5.write("/x", Eigen::VectorXd(Eigen::VectorXd::LinSpaced(4, 0.0, 0.03)), "m", "");
    h5.write("/y", Eigen::VectorXd(Eigen::VectorXd::LinSpaced(3, 0.0, 0.2)), "m", "");
  }
  message = error_of([&] { (void)read_height_map_hdf5(dir_ / "no_z.h5"); });
  EXPECT_MENTIONS(message, "no_z.h5: /z: no such dataset");
  {
    Hdf5Writer h5(dir_ / "backwards.h5");
    Eigen::VectorXd xb(3);
    xb << 0.0, 0.02, 0.01;
    h5.write("/x", Eigen::VectorXd(xb), "m", "");
    h5.write("/y", Eigen::VectorXd(Eigen::VectorXd::LinSpaced(2, 0.0, 0.2)), "m", "");
    h5.write("/z", Eigen::MatrixXd(Eigen::MatrixXd::Zero(3, 2)), "m", "");
  }
  message = error_of([&] { (void)read_height_map_hdf5(dir_ / "backwards.h5"); });
  EXPECT_MENTIONS(message, "/x[2]");
  EXPECT_MENTIONS(message, "strictly increasing");
  // Not HDF5 at all.
  message = error_of([&] { (void)read_height_map_hdf5(write("text.h5", "x,z\n0,0\n")); });
  EXPECT_MENTIONS(message, "not an HDF5 file");
}

TEST_F(ProfileIo, FormatIsToldByContent) {
  EXPECT_EQ(detect_profile_format(write("a.dat", "x,z\n0,0\n1,0\n")), ProfileFormat::csv);
  EXPECT_EQ(detect_profile_format(write("b.csv", std::string("\x89HDF\r\n\x1a\n", 8) + "junk")), ProfileFormat::hdf5);
  EXPECT_EQ(detect_profile_format(write("c.csv", std::string("PK\x03\x04\x00\x01", 6))), ProfileFormat::unknown);
  EXPECT_EQ(detect_profile_format(write("d.csv", "")), ProfileFormat::unknown);
  // An HDF5 file with a 512-byte user block.
  std::string block(512, ' ');
  block += std::string("\x89HDF\r\n\x1a\n", 8);
  EXPECT_EQ(detect_profile_format(write("e.bin", block)), ProfileFormat::hdf5);
  EXPECT_MENTIONS(error_of([&] { (void)detect_profile_format(dir_ / "missing.csv"); }), "missing.csv");
  EXPECT_MENTIONS(error_of([&] { (void)load_profile_file(write("f.bin", std::string("\x01\x02\x03", 3))); }),
                  "is not a profile file");
  EXPECT_EQ(to_string(ProfileFormat::hdf5), "hdf5");
}

}  // namespace
}  // namespace rollnoise

namespace rollnoise {
namespace {

TEST(ProfileFormatLaser, CaptifRecordIsDetectedAndLoaded) {
  const std::filesystem::path record =
      std::filesystem::path(ROLLNOISE_SOURCE_DIR) / "data/surfaces/captif/20211011_aylesbury_dec_station_0.dat";
  ASSERT_TRUE(std::filesystem::exists(record)) << record;
  EXPECT_EQ(detect_profile_format(record), ProfileFormat::laser);
  const LoadedProfile p = load_profile_file(record);
  ASSERT_EQ(p.z_lines.size(), 1u);
  EXPECT_GT(p.spacing_m, 0.0);
  EXPECT_EQ(p.x.size(), p.z_lines[0].size());
  EXPECT_GT(p.x.size(), 1000u);
  for (double z : p.z_lines[0]) ASSERT_TRUE(std::isfinite(z));
  std::printf("  CAPTIF record: %zu samples at %.4g mm, %zu dropouts, %zu spikes\n", p.x.size(),
              p.spacing_m * 1e3, p.dropouts, p.spikes);
}

}  // namespace
}  // namespace rollnoise
