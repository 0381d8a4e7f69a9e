// Measured FRFs: the CSV reader (both column forms, frequency units, comment settings, every
// kind of bad data) and the FRF selection on top of the UFF 58/58b reader (the real files of
// ../shared/data/uff, the UFF corpus, and records written here in every layout: ASCII and
// binary, single and double precision, even and uneven, each quantity and its units).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "calibrate/frf_csv_reader.hpp"
#include "calibrate/frf_uff_reader.hpp"
#include "calibrate/uff_frf_writer.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;
using testing::UffFrfRecord;
using testing::UffWriteOptions;
using testing::uff58_text;

const fs::path real_dir{ROLLNOISE_SOURCE_DIR "/../shared/data/uff"};
const fs::path uff_corpus{ROLLNOISE_SOURCE_DIR "/tests/corpus/uff"};
const fs::path csv_corpus{ROLLNOISE_SOURCE_DIR "/tests/corpus/frf_csv"};
constexpr double two_pi = 2.0 * std::numbers::pi;

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

FrfFile csv(const std::string& text, FrfReadOptions options = {}) { return parse_frf_csv(text, "test.csv", options); }

// ------------------------------------------------------------------------------------------
// CSV

TEST(FrfCsv, RealAndImaginaryParts) {
  const FrfFile file = csv("# a comment\nfrequency_hz,re,im\n10,1e-4,2e-5\n20,5e-5,-1e-5\n");
  ASSERT_EQ(file.frfs.size(), 1U);
  const MeasuredFrf& f = file.frfs[0];
  EXPECT_EQ(f.quantity, FrfQuantity::mobility);
  ASSERT_EQ(f.size(), 2);
  EXPECT_EQ(f.frequency_hz[1], 20.0);
  EXPECT_EQ(f.mobility[0], std::complex<double>(1e-4, 2e-5));
  EXPECT_FALSE(f.response.has_value());
  EXPECT_EQ(f.name(), "test.csv");
}

TEST(FrfCsv, MagnitudePhaseAccelerancePositionsAndDcLeftOut) {
  const FrfFile file = csv(
      "# data_type = accelerance\n# response_x = 0.1\n# response_y = 0.09\n# excitation_x = 0\n"
      "# excitation_y = 0.09\nfrequency_hz,magnitude,phase_deg\n0,0.5,0\n100,1.5,90\n");
  const MeasuredFrf& f = file.frfs[0];
  EXPECT_EQ(f.quantity, FrfQuantity::accelerance);
  ASSERT_EQ(f.size(), 1) << "the 0 Hz line is left out";
  ASSERT_EQ(file.notes.size(), 1U);
  EXPECT_TRUE(contains(file.notes[0], "0 Hz"));
  // A = 1.5·e^{i90°} = 1.5i at 100 Hz; Y = A/(iω) = 1.5/ω.
  EXPECT_NEAR(f.mobility[0].real(), 1.5 / (two_pi * 100.0), 1e-15);
  EXPECT_NEAR(f.mobility[0].imag(), 0.0, 1e-15);
  ASSERT_TRUE(f.response && f.excitation);
  EXPECT_EQ(f.response->x, 0.1);
  EXPECT_EQ(f.response->y, 0.09);
  EXPECT_EQ(f.excitation->x, 0.0);
}

TEST(FrfCsv, ReceptanceBecomesMobility) {
  const FrfFile file = csv("frequency_hz,re,im\n50,2e-6,-1e-6\n", {FrfQuantity::receptance, true});
  // Y = iω·α.
  const std::complex<double> expected = std::complex<double>(0.0, two_pi * 50.0) * std::complex<double>(2e-6, -1e-6);
  EXPECT_NEAR(std::abs(file.frfs[0].mobility[0] - expected), 0.0, 1e-18);
}

TEST(FrfCsv, FrequencyUnitsGiveTheSameFrf) {
  const FrfFile hz = csv("frequency_hz,re,im\n100,1,2\n1500,3,4\n");
  const FrfFile khz = csv("frequency_khz,re,im\n0.1,1,2\n1.5,3,4\n");
  const FrfFile rad = csv("angular_frequency_rad_s,re,im\n628.3185307179586,1,2\n9424.77796076938,3,4\n");
  for (const FrfFile* other : {&khz, &rad}) {
    ASSERT_EQ(other->frfs[0].size(), 2);
    for (Eigen::Index k = 0; k < 2; ++k) {
      EXPECT_NEAR(other->frfs[0].frequency_hz[k], hz.frfs[0].frequency_hz[k], 1e-12 * hz.frfs[0].frequency_hz[k]);
      EXPECT_EQ(other->frfs[0].mobility[k], hz.frfs[0].mobility[k]);
    }
  }
}

TEST(FrfCsv, DataTypeInTheFileMustAgreeWithAnExplicitOption) {
  const std::string text = "# data_type = receptance\nfrequency_hz,re,im\n10,1,1\n";
  EXPECT_EQ(csv(text).frfs[0].quantity, FrfQuantity::receptance) << "the file says it when the option is a default";
  const std::string m = message_of([&] { csv(text, {FrfQuantity::mobility, true}); });
  EXPECT_TRUE(contains(m, "test.csv: line 1, data_type: the file holds receptance, but --data-type says mobility")) << m;
}

TEST(FrfCsv, BadDataNamesFileLineAndWhatIsAllowed) {
  struct Case {
    const char* text;
    const char* expected;
  };
  const Case cases[] = {
      {"frequency_hz,re,im\n10,1e-4,nan\n", "test.csv: line 2, column \"im\": must be a finite number"},
      {"frequency_hz,re,im\n# c\n-10,1e-4,1e-5\n", "test.csv: line 3: frequency -10 Hz is negative"},
      {"freq,re,im\n10,1,1\n", "test.csv: header: columns \"freq,re,im\" are not an FRF; allowed: frequency_hz,re,im"},
      {"frequency_hz,re,im,coherence\n10,1,1,1\n", "are not an FRF"},
      {"frequency_hz,re,im\n10,0,0\n", "test.csv: line 2: the mobility is 0 at 10 Hz"},
      {"frequency_hz,re,im\n10,1,1\n10,1,1\n", "test.csv: line 3: frequency 10 Hz does not follow 10 Hz"},
      {"# data_type = impedance\nfrequency_hz,re,im\n10,1,1\n",
       "test.csv: line 1, data_type: \"impedance\" is not a quantity calibrate fits; allowed: receptance, mobility or "
       "accelerance"},
      {"# response_x = 0.1\nfrequency_hz,re,im\n10,1,1\n", "'response_x' is given without 'response_y'"},
      {"# response_x = 0.1\n# response_x = 0.2\nfrequency_hz,re,im\n", "test.csv: line 2: 'response_x' is given twice"},
      {"# response_x = left\n# response_y = 0\nfrequency_hz,re,im\n10,1,1\n",
       "line 1, response_x: \"left\" is not a finite number"},
      {"frequency_hz,magnitude,phase_deg\n10,-1,0\n", "magnitude -1 is negative"},
      {"frequency_hz,re,im\n", "holds no data rows"},
      {"", "no header line"},
      {"frequency_hz,re,im\n0,1,1\n", "holds no data above 0 Hz"},
  };
  for (const Case& c : cases) {
    const std::string m = message_of([&] { csv(c.text); });
    EXPECT_TRUE(contains(m, c.expected)) << c.text << "\n  gave: " << m;
  }
}

TEST(FrfCsv, CorpusOkParsesBadIsInputError) {
  std::size_t ok = 0, bad = 0;
  for (const auto& entry : fs::directory_iterator(csv_corpus)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("ok_", 0) == 0) {
      EXPECT_NO_THROW(read_frf_csv(entry.path(), {})) << name;
      ++ok;
    } else if (name.rfind("bad_", 0) == 0) {
      EXPECT_THROW(read_frf_csv(entry.path(), {}), InputError) << name;
      ++bad;
    }
  }
  EXPECT_GE(ok, 5U);
  EXPECT_GE(bad, 10U);
  EXPECT_THROW(read_frf_csv(csv_corpus / "does_not_exist.csv", {}), InputError);
}

// ------------------------------------------------------------------------------------------
// UFF

UffFrfRecord record(int numerator, const char* units, double scale = 1.0) {
  UffFrfRecord r;
  r.numerator_type = numerator;
  r.numerator_units = units;
  for (int k = 1; k <= 5; ++k) {
    r.frequency_hz.push_back(10.0 * k);
    r.values.push_back(scale * std::complex<double>(1e-3 * k, -2e-3 / k));
  }
  return r;
}

FrfFile uff(const std::string& bytes, FrfReadOptions options = {}) { return parse_uff_frfs(bytes, "test.uff", options); }

TEST(FrfUff, QuantityFromTheTypeCodesInEveryLayout) {
  const std::vector<UffWriteOptions> layouts = {
      {false, true, true}, {false, false, true}, {true, true, true}, {true, false, false}, {true, true, false}};
  for (const UffWriteOptions& layout : layouts) {
    for (bool even : {true, false}) {
      std::vector<UffFrfRecord> records = {record(8, "m"), record(11, "m/s"), record(12, "m/s^2")};
      for (auto& r : records) r.even = even;
      const FrfFile file = uff(uff58_text(records, layout));
      ASSERT_EQ(file.frfs.size(), 3U);
      EXPECT_EQ(file.frfs[0].quantity, FrfQuantity::receptance);
      EXPECT_EQ(file.frfs[1].quantity, FrfQuantity::mobility);
      EXPECT_EQ(file.frfs[2].quantity, FrfQuantity::accelerance);
      const double tolerance = layout.double_precision ? 1e-12 : 1e-6;
      for (std::size_t i = 0; i < 3; ++i) {
        const MeasuredFrf& f = file.frfs[i];
        ASSERT_EQ(f.size(), 5);
        const std::string label = "dataset " + std::to_string(i + 1) + (layout.binary ? " (58b, line " : " (58, line ");
        EXPECT_EQ(f.label.substr(0, label.size()), label);
        for (Eigen::Index k = 0; k < 5; ++k) {
          const double omega = two_pi * f.frequency_hz[k];
          const std::complex<double> raw = records[i].values[static_cast<std::size_t>(k)];
          const std::complex<double> expected = i == 0   ? std::complex<double>(0.0, omega) * raw
                                                : i == 1 ? raw
                                                         : raw / std::complex<double>(0.0, omega);
          EXPECT_NEAR(std::abs(f.mobility[k] - expected), 0.0, tolerance * std::abs(expected))
              << "binary " << layout.binary << " double " << layout.double_precision << " even " << even;
        }
        ASSERT_TRUE(f.response_dof && f.reference_dof);
        EXPECT_EQ(f.response_dof->node, 1);
        EXPECT_EQ(f.response_dof->direction, 3);
      }
    }
  }
}

TEST(FrfUff, UnitsLabelsScaleToSi) {
  struct Case {
    int code;
    const char* units;
    double to_si;
    FrfQuantity quantity;
  };
  const Case cases[] = {{12, "g", 9.80665, FrfQuantity::accelerance},
                        {11, "mm/s", 1e-3, FrfQuantity::mobility},
                        {8, "mm", 1e-3, FrfQuantity::receptance},
                        {1, "(1/N)*(m/s\xC2\xB2)", 1.0, FrfQuantity::accelerance},
                        {0, "m/s/N", 1.0, FrfQuantity::mobility},
                        {0, "(m/s^2)/kN", 1e-3, FrfQuantity::accelerance},
                        {1, "g/N", 9.80665, FrfQuantity::accelerance}};
  for (const Case& c : cases) {
    UffFrfRecord scaled = record(c.code, c.units);
    if (c.code <= 1) scaled.denominator_type = 0;
    const FrfFile file = uff(uff58_text({scaled}, {}));
    ASSERT_EQ(file.frfs.size(), 1U) << c.units;
    EXPECT_EQ(file.frfs[0].quantity, c.quantity) << c.units;
    const double omega = two_pi * 10.0;
    const std::complex<double> raw = scaled.values[0] * c.to_si;
    const std::complex<double> expected = to_mobility(raw, c.quantity, omega);
    EXPECT_NEAR(std::abs(file.frfs[0].mobility[0] - expected), 0.0, 1e-12 * std::abs(expected)) << c.units;
  }
  // Unknown units with a clear code: SI assumed, with a note.
  const FrfFile odd = uff(uff58_text({record(11, "furlong/fortnight")}, {}));
  ASSERT_EQ(odd.notes.size(), 1U);
  EXPECT_TRUE(contains(odd.notes[0], "'furlong/fortnight' over 'N' are not recognised; SI units")) << odd.notes[0];
}

TEST(FrfUff, OppositeDirectionsNegateTheData) {
  UffFrfRecord r = record(11, "m/s");
  r.reference_direction = -3;
  const FrfFile file = uff(uff58_text({r}, {}));
  EXPECT_NEAR(std::abs(file.frfs[0].mobility[0] + r.values[0]), 0.0, 1e-15);
  r.reference_direction = 1;
  EXPECT_TRUE(contains(message_of([&] { uff(uff58_text({r}, {})); }),
                       "test.uff: dataset 1 (58, line 1), record 6: response direction 3 and reference direction 1 "
                       "are not translations along one axis"));
}

TEST(FrfUff, AbscissaInKilohertzOrRadiansPerSecond) {
  UffFrfRecord hz = record(11, "m/s");
  UffFrfRecord khz = hz, rad = hz;
  khz.abscissa_units = "kHz";
  rad.abscissa_units = "rad/s";
  for (std::size_t k = 0; k < hz.frequency_hz.size(); ++k) {
    khz.frequency_hz[k] = hz.frequency_hz[k] / 1000.0;
    rad.frequency_hz[k] = hz.frequency_hz[k] * two_pi;
  }
  khz.even = rad.even = false;
  const FrfFile file = uff(uff58_text({khz, rad}, {}));
  for (const MeasuredFrf& f : file.frfs)
    for (Eigen::Index k = 0; k < f.size(); ++k) EXPECT_NEAR(f.frequency_hz[k], 10.0 * static_cast<double>(k + 1), 1e-9);
  UffFrfRecord time = hz;
  time.abscissa_type = 17;
  time.abscissa_units = "s";
  EXPECT_TRUE(contains(message_of([&] { uff(uff58_text({time}, {})); }),
                       "record 8: the abscissa is time (specific data type 17, units 's'); an FRF's abscissa is "
                       "frequency"));
  UffFrfRecord rpm = hz;
  rpm.abscissa_units = "rpm";
  EXPECT_TRUE(contains(message_of([&] { uff(uff58_text({rpm}, {})); }), "allowed: Hz, kHz, rad/s"));
}

TEST(FrfUff, WrongQuantitiesAreRefused) {
  struct Case {
    UffFrfRecord record;
    const char* expected;
  };
  UffFrfRecord impedance = record(13, "N");
  impedance.denominator_type = 11;
  impedance.denominator_units = "m/s";
  UffFrfRecord stiffness = record(13, "N");
  stiffness.denominator_type = 8;
  UffFrfRecord pressure = record(15, "Pa");
  UffFrfRecord transmissibility = record(12, "m/s^2");
  transmissibility.denominator_type = 12;
  UffFrfRecord unknown = record(1, "V/V");
  unknown.denominator_type = 0;
  UffFrfRecord disagreeing = record(12, "m/s/N");
  const Case cases[] = {
      {impedance, "force over motion (an impedance, dynamic stiffness or apparent mass); calibrate fits motion over force"},
      {stiffness, "force over motion"},
      {pressure, "the FRF is pressure (specific data type 15, units 'Pa') over excitation force"},
      {transmissibility, "force over motion"},
      {unknown, "the record does not say what it holds"},
      {disagreeing, "but its units say mobility; the codes and units labels disagree"},
  };
  for (const Case& c : cases) {
    const std::string m = message_of([&] { uff(uff58_text({c.record}, {})); });
    EXPECT_TRUE(contains(m, "test.uff: dataset 1 (58, line 1), records 9-10: ")) << m;
    EXPECT_TRUE(contains(m, c.expected)) << m;
  }
  // Unknown codes and units read as the explicitly given --data-type, with a note.
  const FrfFile given = uff(uff58_text({unknown}, {}), {FrfQuantity::receptance, true});
  EXPECT_EQ(given.frfs[0].quantity, FrfQuantity::receptance);
  EXPECT_EQ(given.notes.size(), 1U);
  // An explicit --data-type that disagrees with the record.
  EXPECT_TRUE(contains(message_of([&] { uff(uff58_text({record(12, "m/s^2")}, {}), {FrfQuantity::mobility, true}); }),
                       "the record holds accelerance (acceleration (specific data type 12, units 'm/s^2')), but "
                       "--data-type says mobility"));
}

TEST(FrfUff, RealDataIsRefused) {
  UffFrfRecord r = record(11, "m/s");
  r.complex_data = false;
  EXPECT_TRUE(contains(message_of([&] { uff(uff58_text({r}, {})); }),
                       "record 7: the FRF is real double precision; the fit needs magnitude and phase"));
}

TEST(FrfUff, OtherRecordsAndDatasetsAreLeftOutWithANote) {
  UffFrfRecord coherence = record(0, "NONE");
  coherence.function_type = 6;
  const std::string frf = uff58_text({record(11, "m/s"), coherence}, {});
  const std::string dataset151 = "    -1\n   151\nmodel\nNONE\n    -1\n";
  const FrfFile file = uff(dataset151 + frf);
  ASSERT_EQ(file.frfs.size(), 1U);
  ASSERT_EQ(file.notes.size(), 2U);
  EXPECT_TRUE(contains(file.notes[0], "dataset 3 (58, line ")) << file.notes[0];
  EXPECT_TRUE(contains(file.notes[0], "is a coherence (function type 6), not an FRF: left out")) << file.notes[0];
  EXPECT_TRUE(contains(file.notes[1], "datasets 151 are left out")) << file.notes[1];
  // Only other datasets: the file has no dataset 58.
  EXPECT_TRUE(contains(message_of([&] { uff(dataset151); }),
                       "test.uff: holds no dataset 58 (function at nodal DOF); calibrate reads FRFs from datasets 58 "
                       "and 58b (the file holds datasets 151)"));
  // Only time data: no FRF, with what was found.
  UffFrfRecord time = record(0, "Pa");
  time.function_type = 1;
  time.abscissa_type = 17;
  time.complex_data = false;
  EXPECT_TRUE(contains(message_of([&] { uff(uff58_text({time}, {})); }),
                       "holds no frequency response function (dataset 58, function type 4); found: dataset 1 (58, "
                       "line 1): time response (function type 1)"));
}

TEST(FrfUff, RealFilesReadOrSayWhatTheyHold) {
  if (!fs::exists(real_dir)) GTEST_SKIP() << "no " << real_dir;
  // The H1 FRF written by a measurement system: numerator "general", units (1/N)*(m/s²).
  const FrfFile h1 = read_uff_frfs(real_dir / "non_ascii_header.uff", {});
  ASSERT_EQ(h1.frfs.size(), 1U);
  const MeasuredFrf& f = h1.frfs[0];
  EXPECT_EQ(f.quantity, FrfQuantity::accelerance);
  ASSERT_EQ(f.size(), 5) << "6 lines, the one at 0 Hz left out";
  EXPECT_DOUBLE_EQ(f.frequency_hz[0], 1.95313e-01);
  // Y = A/(iω) with A = −5.99924e-02 − 5.53260e-02i (single precision in the file).
  const std::complex<double> a(-5.99924e-02, -5.53260e-02);
  const std::complex<double> expected = a / std::complex<double>(0.0, two_pi * 1.95313e-01);
  EXPECT_NEAR(std::abs(f.mobility[0] - expected), 0.0, 1e-6 * std::abs(expected));
  // Time records and a PSD: a message naming what they are.
  struct Case {
    const char* file;
    const char* expected;
  };
  const Case cases[] = {{"Sample_UFF58_ascii.uff", "time response (function type 1)"},
                        {"Sample_UFF58b_bin.uff", "time response (function type 1)"},
                        {"binary8byte.uff", "time response (function type 1)"},
                        {"time-history-not-all-columns-filled.uff", "time response (function type 1)"},
                        {"sample_dataset58_psd.uff", "power spectral density (PSD) (function type 9)"}};
  for (const Case& c : cases) {
    const std::string m = message_of([&] { read_uff_frfs(real_dir / c.file, {}); });
    EXPECT_TRUE(contains(m, "holds no frequency response function (dataset 58, function type 4); found:")) << m;
    EXPECT_TRUE(contains(m, c.expected)) << m;
  }
}

TEST(FrfUff, CorpusFilesReadOrGiveInputError) {
  // The FRFs of the corpus read; everything else is an InputError (never another exception).
  const FrfFile frf = read_uff_frfs(uff_corpus / "ok_ascii_frf_complex_double_uneven.uff", {});
  ASSERT_EQ(frf.frfs.size(), 1U);
  EXPECT_EQ(frf.frfs[0].quantity, FrfQuantity::accelerance);
  // Response +Z, reference −Z: negated into the model's convention.
  const std::complex<double> a(1.0, -1.0);
  EXPECT_NEAR(std::abs(frf.frfs[0].mobility[0] + a / std::complex<double>(0.0, two_pi * 10.0)), 0.0, 1e-15);
  const FrfFile binary = read_uff_frfs(uff_corpus / "ok_binary_big_endian_complex_single.uff", {});
  EXPECT_EQ(binary.frfs[0].quantity, FrfQuantity::mobility);
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(uff_corpus)) {
    ++files;
    try {
      read_uff_frfs(entry.path(), {});
    } catch (const InputError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << entry.path() << ": " << e.what();
    }
  }
  EXPECT_GE(files, 20U);
  EXPECT_TRUE(contains(message_of([&] { read_uff_frfs(uff_corpus / "ok_only_dataset_151.uff", {}); }),
                       "holds no dataset 58"));
}

}  // namespace
}  // namespace rollnoise
