// The generator of the example measurements in data/mobility: SYNTHETIC mobilities (a model
// with known parameters plus 5 % complex noise, seeded), written as CSV and as UFF 58 (ASCII)
// and 58b (binary) the way measurement systems write them. The test checks that the files in
// data/mobility are what this generator makes (numbers to 1e-9, comment lines exactly), so the
// parameters listed in data/mobility/README.md are the ones that made them.
//
// To write the files anew: ROLLNOISE_WRITE_EXAMPLES=1 ./build/tests/calibrate/test_calibrate
//   --gtest_filter='ExampleData.*'   (from the project folder)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "calibrate/frf_csv_reader.hpp"
#include "calibrate/frf_uff_reader.hpp"
#include "calibrate/plate_calibration.hpp"
#include "calibrate/sdof_calibration.hpp"
#include "calibrate/synthetic_frf.hpp"
#include "calibrate/two_layer_calibration.hpp"
#include "calibrate/uff_frf_writer.hpp"
#include "core/case_file.hpp"
#include "core/csv.hpp"
#include "greens/two_layer_factory.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;
using testing::linear_frequencies;
using testing::NormalSource;
using testing::synthetic_frf;
constexpr double two_pi = 2.0 * std::numbers::pi;
const fs::path data_dir{ROLLNOISE_SOURCE_DIR "/data/mobility"};

// The true parameters (data/mobility/README.md lists them).
SdofParameters sdof_truth() { return {0.8, 40.0, 800.0, 1.5e5}; }

PlateParameters tyre_truth() { return testing::example_tyre_truth(); }

const FrfPoints tyre_point{{0.0, 0.09}, {0.0, 0.09}};
const FrfPoints tyre_transfer{{0.1, 0.09}, {0.0, 0.09}};

std::string synthetic_label() {
  return "# SYNTHETIC DATA, not a measurement: made by tests/calibrate/test_example_data.cpp (see README.md)\n";
}

std::string csv_text(const MeasuredFrf& frf, const std::string& description, bool polar) {
  std::ostringstream out;
  out << synthetic_label() << "# " << description << "\n";
  if (frf.response) {
    out << "# response_x = " << format_number(frf.response->x) << "\n# response_y = " << format_number(frf.response->y)
        << "\n# excitation_x = " << format_number(frf.excitation->x)
        << "\n# excitation_y = " << format_number(frf.excitation->y) << "\n";
  }
  out << "# data_type = mobility\n";
  out << (polar ? "frequency_hz,magnitude,phase_deg\n" : "frequency_hz,re,im\n");
  for (Eigen::Index k = 0; k < frf.size(); ++k) {
    const std::complex<double> y = frf.mobility[k];
    out << format_number(frf.frequency_hz[k]) << ',';
    if (polar)
      out << format_number(std::abs(y)) << ',' << format_number(std::arg(y) * 180.0 / std::numbers::pi) << '\n';
    else
      out << format_number(y.real()) << ',' << format_number(y.imag()) << '\n';
  }
  return out.str();
}

// The tyre's two FRFs as UFF records: node 1 is the driving point, node 2 the transfer point.
std::vector<testing::UffFrfRecord> uff_records(const std::vector<MeasuredFrf>& frfs, bool accelerance) {
  std::vector<testing::UffFrfRecord> records;
  for (std::size_t i = 0; i < frfs.size(); ++i) {
    testing::UffFrfRecord r;
    r.description = i == 0 ? "SYNTHETIC point mobility 1:+Z/1:+Z" : "SYNTHETIC transfer mobility 2:+Z/1:+Z";
    r.response_node = static_cast<std::int64_t>(i + 1);
    r.reference_node = 1;
    r.numerator_type = accelerance ? 12 : 11;
    r.numerator_label = accelerance ? "Acceleration" : "Velocity";
    r.numerator_units = accelerance ? "m/s^2" : "m/s";
    for (Eigen::Index k = 0; k < frfs[i].size(); ++k) {
      const double f = frfs[i].frequency_hz[k];
      r.frequency_hz.push_back(f);
      const std::complex<double> y = frfs[i].mobility[k];
      r.values.push_back(accelerance ? std::complex<double>(0.0, two_pi * f) * y : y);
    }
    records.push_back(r);
  }
  return records;
}

// The two-layer tyre's truth: models/tyres/passenger_205_55R16_two_layer.toml with its nine
// default fitted parameters changed by 15–40 % (data/mobility/README.md).
TwoLayerParameters two_layer_truth() {
  TwoLayerParameters p = read_two_layer_tyre(
      CaseFile::load_model(ROLLNOISE_SOURCE_DIR "/models/tyres/passenger_205_55R16_two_layer.toml").top());
  p.belt.youngs_x = 3.6e9;
  p.belt.youngs_y = 1.1e9;
  p.tension_x = 7.5e4;
  p.tension_y = 1.05e4;
  p.foundation_stiffness = 1.8e6;
  p.tread_youngs_modulus = 5.0e6;
  p.belt_loss_factor = 0.07;
  p.tread_loss_factor = 0.13;
  p.foundation_loss_factor = 0.06;
  return p;
}

// Its four FRFs on 10 mm cells of the tread: node 1 (0, 0.09) m, node 2 (0.1, 0.09) m, node 3
// (0, 0.045) m; point 1/1, transfer 2/1, point 3/3, transfer 3/1.
struct TwoLayerFrf {
  std::int64_t response;
  std::int64_t reference;
  FrfPoints points;
  const char* what;
};
const TwoLayerFrf two_layer_frfs[] = {
    {1, 1, {{0.0, 0.09}, {0.0, 0.09}}, "point mobility at the belt centre"},
    {2, 1, {{0.1, 0.09}, {0.0, 0.09}}, "transfer mobility 0.1 m around"},
    {3, 3, {{0.0, 0.045}, {0.0, 0.045}}, "point mobility at a quarter of the width"},
    {3, 1, {{0.0, 0.045}, {0.0, 0.09}}, "transfer mobility 0.045 m across"},
};

struct ExampleFile {
  std::string name;
  std::string text;
};

std::vector<ExampleFile> example_files() {
  std::vector<ExampleFile> files;
  {
    const SdofCalibration model(sdof_truth(), false, 0.0, 0.0);
    NormalSource noise(1);
    MeasuredFrf frf = synthetic_frf(model, model.file_values(), {}, linear_frequencies(0.5, 500.0, 0.5), 0.05, noise);
    frf.response.reset();
    frf.excitation.reset();
    files.push_back({"sdof_point_mobility.csv",
                     csv_text(frf,
                              "point mobility of an sdof tyre model: mass = 0.8 kg, damping = 40 N*s/m, stiffness = "
                              "800 N/m, contact_stiffness = 1.5e5 N/m, 5 % complex noise (seed 1)",
                              false)});
  }
  const PlateCalibration tyre(tyre_truth());
  NormalSource noise(2);
  const auto f = linear_frequencies(20.0, 3000.0, 5.0);
  const std::vector<MeasuredFrf> frfs = {synthetic_frf(tyre, tyre.file_values(), tyre_point, f, 0.05, noise),
                                         synthetic_frf(tyre, tyre.file_values(), tyre_transfer, f, 0.05, noise)};
  const std::string truth =
      "passenger 205/55 R16 plate (models/tyres/passenger_205_55R16.toml) with tension_x = 5.2e4 N/m, bending_x = 5.5 "
      "N*m, foundation_stiffness = 2.7e6 N/m^3, loss_factor = 0.08; 5 % complex noise (seed 2)";
  files.push_back({"tyre_point_mobility.csv", csv_text(frfs[0], "driving-point mobility at the belt centre: " + truth, true)});
  files.push_back({"tyre_transfer_mobility.csv",
                   csv_text(frfs[1], "transfer mobility 0.1 m along the belt centre line: " + truth, false)});
  files.push_back({"tyre_frfs.uff", testing::uff58_text(uff_records(frfs, true), {false, true, true})});
  files.push_back({"tyre_frfs_58b.uff", testing::uff58_text(uff_records(frfs, false), {true, true, true})});
  {
    const TwoLayerCalibration two_layer(two_layer_truth(), 400.0);
    NormalSource two_layer_noise(3);
    std::vector<testing::UffFrfRecord> records;
    for (const TwoLayerFrf& t : two_layer_frfs) {
      const MeasuredFrf frf = synthetic_frf(two_layer, two_layer.file_values(), t.points,
                                            linear_frequencies(20.0, 400.0, 5.0),
                                            0.05, two_layer_noise);
      if (t.response == 1 && t.reference == 1)
        files.push_back({"two_layer_point_mobility.csv",
                         csv_text(frf,
                                  std::string(t.what) +
                                      " of the two-layer passenger tyre (10 mm cells), see README.md; 5 % complex "
                                      "noise (seed 3)",
                                  false)});
      testing::UffFrfRecord r;
      r.description = "SYNTHETIC two-layer " + std::string(t.what) + " " + std::to_string(t.response) + ":+Z/" +
                      std::to_string(t.reference) + ":+Z";
      r.response_node = t.response;
      r.reference_node = t.reference;
      for (Eigen::Index k = 0; k < frf.size(); ++k) {
        r.frequency_hz.push_back(frf.frequency_hz[k]);
        r.values.push_back(frf.mobility[k]);
      }
      records.push_back(r);
    }
    files.push_back({"two_layer_frfs.uff", testing::uff58_text(records, {false, true, true})});
  }
  return files;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ExampleData, FilesInDataMobilityAreWhatTheGeneratorMakes) {
  const std::vector<ExampleFile> files = example_files();
  const char* write = std::getenv("ROLLNOISE_WRITE_EXAMPLES");
  if (write != nullptr && std::string(write) == "1") {
    fs::create_directories(data_dir);
    for (const ExampleFile& f : files) {
      std::ofstream out(data_dir / f.name, std::ios::binary);
      out << f.text;
    }
    std::printf("  wrote %zu files to %s\n", files.size(), data_dir.string().c_str());
  }
  for (const ExampleFile& f : files) {
    const fs::path path = data_dir / f.name;
    ASSERT_TRUE(fs::exists(path)) << path << " is missing: run the generator (see the top of this file)";
    const std::string stored = read_bytes(path);
    if (stored == f.text) continue;
    // Not byte for byte (another libm may round a last digit differently): the same numbers.
    const bool uff = path.extension() == ".uff";
    const FrfFile a = uff ? parse_uff_frfs(stored, f.name, {}) : parse_frf_csv(stored, f.name, {});
    const FrfFile b = uff ? parse_uff_frfs(f.text, f.name, {}) : parse_frf_csv(f.text, f.name, {});
    ASSERT_EQ(a.frfs.size(), b.frfs.size()) << f.name;
    for (std::size_t i = 0; i < a.frfs.size(); ++i) {
      ASSERT_EQ(a.frfs[i].size(), b.frfs[i].size()) << f.name;
      for (Eigen::Index k = 0; k < a.frfs[i].size(); ++k) {
        ASSERT_NEAR(a.frfs[i].frequency_hz[k], b.frfs[i].frequency_hz[k], 1e-9 * b.frfs[i].frequency_hz[k]);
        ASSERT_NEAR(std::abs(a.frfs[i].mobility[k] - b.frfs[i].mobility[k]), 0.0, 1e-9 * std::abs(b.frfs[i].mobility[k]))
            << f.name << " line " << k;
      }
    }
  }
  // The README names the generating parameters.
  const std::string readme = read_bytes(data_dir / "README.md");
  for (const char* value : {"SYNTHETIC", "0.8 kg", "40 N·s/m", "800 N/m", "1.5e5 N/m", "5.2e4", "5.5", "2.7e6", "0.08",
                            "5 %", "seed 1", "seed 2", "seed 3", "3.6e9", "1.1e9", "7.5e4", "1.05e4", "1.8e6",
                            "5.0e6", "0.07", "0.13", "0.06"})
    EXPECT_NE(readme.find(value), std::string::npos) << "README.md does not mention " << value;
}

TEST(ExampleData, TheFormatsHoldTheSameMeasurement) {
  // CSV, UFF 58 (accelerance) and UFF 58b (mobility): one measurement.
  const FrfFile point = read_frf_csv(data_dir / "tyre_point_mobility.csv", {});
  const FrfFile transfer = read_frf_csv(data_dir / "tyre_transfer_mobility.csv", {});
  const FrfFile ascii = read_uff_frfs(data_dir / "tyre_frfs.uff", {});
  const FrfFile binary = read_uff_frfs(data_dir / "tyre_frfs_58b.uff", {});
  ASSERT_EQ(ascii.frfs.size(), 2U);
  ASSERT_EQ(binary.frfs.size(), 2U);
  EXPECT_EQ(ascii.frfs[0].quantity, FrfQuantity::accelerance);
  EXPECT_EQ(binary.frfs[0].quantity, FrfQuantity::mobility);
  const MeasuredFrf* csv[] = {&point.frfs[0], &transfer.frfs[0]};
  for (std::size_t i = 0; i < 2; ++i) {
    ASSERT_EQ(csv[i]->size(), 597);
    for (const FrfFile* uff : {&ascii, &binary}) {
      ASSERT_EQ(uff->frfs[i].size(), 597);
      for (Eigen::Index k = 0; k < 597; ++k) {
        // E13.5 abscissa increments and E20.12 values in the ASCII file.
        ASSERT_NEAR(uff->frfs[i].frequency_hz[k], csv[i]->frequency_hz[k], 1e-9);
        ASSERT_NEAR(std::abs(uff->frfs[i].mobility[k] - csv[i]->mobility[k]), 0.0, 1e-11 * std::abs(csv[i]->mobility[k]));
      }
    }
  }
  EXPECT_EQ(ascii.frfs[1].response_dof->node, 2);
  EXPECT_EQ(ascii.frfs[1].reference_dof->node, 1);
}

}  // namespace
}  // namespace rollnoise
