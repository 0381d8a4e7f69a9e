// The UFF dataset 58/58b reader: the real files in ../shared/data/uff (written by LMS Test.Lab,
// VibControl, catman, pyuff), a corpus of small files for every data layout and for every kind
// of malformed input (tests/corpus/uff: "ok_*" parses, "bad_*" is an InputError), and a fuzz of
// random bytes and mutations: whatever the bytes, the reader returns well-formed records or
// throws InputError naming the source; never anything else, never a crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/uff58.hpp"
#include "fuzz_support.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

const fs::path real_dir{ROLLNOISE_SOURCE_DIR "/../shared/data/uff"};
const fs::path corpus_dir{ROLLNOISE_UFF_CORPUS_DIR};

using fuzz::read_bytes;

fs::path real_file(const char* name) { return real_dir / name; }

#define REQUIRE_REAL_FILE(name)               \
  if (!fs::exists(real_file(name))) {         \
    GTEST_SKIP() << "no " << real_file(name); \
  }                                           \
  static_assert(true)

// ------------------------------------------------------------------------------------------
// The real files

TEST(Uff58Real, AsciiMicrophoneTimeRecord) {
  REQUIRE_REAL_FILE("Sample_UFF58_ascii.uff");
  std::vector<int> skipped;
  const auto records = read_uff58(real_file("Sample_UFF58_ascii.uff"), &skipped);
  ASSERT_EQ(records.size(), 1U);
  EXPECT_TRUE(skipped.empty());
  const Uff58Record& r = records[0];
  EXPECT_FALSE(r.binary);
  EXPECT_EQ(r.position, 1U);
  EXPECT_EQ(r.line, 1U);
  EXPECT_EQ(r.id_lines[0], "Mic 01.0Scalar");
  EXPECT_EQ(r.id_lines[2], "18-Apr-16 13:49:58");
  EXPECT_TRUE(r.is_time_record());
  EXPECT_EQ(r.function_type, uff_function::time_response);
  EXPECT_EQ(r.response_entity, "Mic 01");
  EXPECT_EQ(r.response_node, 0);
  EXPECT_EQ(r.response_direction, 1);
  EXPECT_EQ(r.reference_entity, "NONE");
  EXPECT_EQ(r.ordinate_type, UffOrdinateType::real_single);
  EXPECT_FALSE(r.is_complex());
  EXPECT_EQ(r.points, 79292U);
  EXPECT_TRUE(r.even_spacing);
  EXPECT_EQ(r.abscissa_min, 0.0);
  EXPECT_DOUBLE_EQ(r.abscissa_increment, 1.52588e-05);
  EXPECT_EQ(r.abscissa_axis.specific_data_type, 17);
  EXPECT_EQ(r.abscissa_axis.label, "time");
  EXPECT_EQ(r.abscissa_axis.units, "s");
  EXPECT_EQ(r.numerator_axis.specific_data_type, 21);
  EXPECT_EQ(uff_specific_data_type_name(r.numerator_axis.specific_data_type), "sound pressure");
  EXPECT_EQ(r.numerator_axis.label, "Pressure");
  EXPECT_EQ(r.numerator_axis.units, "Pa");
  EXPECT_EQ(r.denominator_axis.specific_data_type, 0);
  EXPECT_EQ(r.denominator_axis.units, "NONE");
  ASSERT_EQ(r.ordinate.size(), 79292);
  EXPECT_EQ(r.complex_ordinate.size(), 0);
  ASSERT_EQ(r.abscissa.size(), 79292);
  EXPECT_DOUBLE_EQ(r.ordinate[0], -1.47553E-02);
  EXPECT_DOUBLE_EQ(r.ordinate[1], -1.72957E-02);
  EXPECT_DOUBLE_EQ(r.ordinate[79291], -4.31469E-03);
  EXPECT_DOUBLE_EQ(r.abscissa[79291], 79291 * 1.52588e-05);  // about 1.21 s
  EXPECT_NE(describe_uff58(r).find("time response"), std::string::npos);
}

TEST(Uff58Real, BinarySinglePrecisionMatchesTheAsciiFile) {
  REQUIRE_REAL_FILE("Sample_UFF58b_bin.uff");
  REQUIRE_REAL_FILE("Sample_UFF58_ascii.uff");
  const auto binary = read_uff58(real_file("Sample_UFF58b_bin.uff"));
  const auto ascii = read_uff58(real_file("Sample_UFF58_ascii.uff"));
  ASSERT_EQ(binary.size(), 1U);
  const Uff58Record& b = binary[0];
  const Uff58Record& a = ascii.at(0);
  EXPECT_TRUE(b.binary);
  EXPECT_TRUE(b.is_time_record());
  EXPECT_EQ(b.ordinate_type, UffOrdinateType::real_single);
  EXPECT_EQ(b.points, 79292U);
  EXPECT_EQ(b.abscissa_increment, a.abscissa_increment);
  EXPECT_EQ(b.numerator_axis.units, "Pa");
  EXPECT_EQ(b.response_entity, a.response_entity);
  ASSERT_EQ(b.ordinate.size(), a.ordinate.size());
  // The ASCII file holds the same single-precision values rounded to 6 significant digits.
  double worst = 0.0;
  for (Eigen::Index i = 0; i < a.ordinate.size(); ++i) {
    const double tolerance = 5.0e-6 * std::abs(b.ordinate[i]) + 1e-12;
    worst = std::max(worst, std::abs(a.ordinate[i] - b.ordinate[i]) / tolerance);
  }
  EXPECT_LE(worst, 1.0) << "largest difference, in units of half the last ASCII digit";
  EXPECT_NEAR(b.ordinate[0], -1.47553E-02, 5e-8);
  EXPECT_NEAR(b.ordinate[79291], -4.31469E-03, 5e-9);
}

TEST(Uff58Real, BinaryDoublePrecisionSine) {
  REQUIRE_REAL_FILE("binary8byte.uff");
  const auto records = read_uff58(real_file("binary8byte.uff"));
  ASSERT_EQ(records.size(), 1U);
  const Uff58Record& r = records[0];
  EXPECT_TRUE(r.binary);
  EXPECT_TRUE(r.is_time_record());
  EXPECT_EQ(r.ordinate_type, UffOrdinateType::real_double);
  EXPECT_EQ(r.points, 250U);
  EXPECT_DOUBLE_EQ(r.abscissa_increment, 0.01);
  EXPECT_EQ(r.response_entity, "sine 5 Hz");
  EXPECT_EQ(r.response_node, 1);
  EXPECT_EQ(r.numerator_axis.specific_data_type, 12);
  EXPECT_EQ(r.numerator_axis.label, "acc (g)");
  EXPECT_EQ(r.numerator_axis.units, "g");
  EXPECT_EQ(r.abscissa_axis.units, "s");
  ASSERT_EQ(r.ordinate.size(), 250);
  EXPECT_DOUBLE_EQ(r.abscissa[249], 2.49);
  // A unit 5 Hz sine, computed in single precision (deviations up to 7.4e-6) and stored as
  // doubles.
  for (Eigen::Index i = 0; i < r.ordinate.size(); ++i)
    ASSERT_NEAR(r.ordinate[i], std::sin(2.0 * std::numbers::pi * 5.0 * r.abscissa[i]), 1e-5)
        << "sample " << i;
}

TEST(Uff58Real, NonAsciiHeaderFrf) {
  REQUIRE_REAL_FILE("non_ascii_header.uff");
  const auto records = read_uff58(real_file("non_ascii_header.uff"));
  ASSERT_EQ(records.size(), 1U);
  const Uff58Record& r = records[0];
  EXPECT_TRUE(r.is_frf());
  EXPECT_FALSE(r.is_time_record());
  EXPECT_EQ(uff_function_type_name(r.function_type), "frequency response function");
  EXPECT_EQ(r.id_lines[0], "ref6_23_Mar");
  EXPECT_EQ(r.id_lines[4], "H1 : #  2 / #  1");
  EXPECT_EQ(r.ordinate_type, UffOrdinateType::complex_single);
  EXPECT_EQ(r.points, 6U);
  EXPECT_TRUE(r.even_spacing);
  EXPECT_DOUBLE_EQ(r.abscissa_increment, 1.95313e-01);
  EXPECT_EQ(r.abscissa_axis.specific_data_type, 18);
  EXPECT_EQ(r.abscissa_axis.units, "Hz");
  EXPECT_EQ(r.numerator_axis.label, "Frequency Function");
  // The Latin-1 byte 0xB2 comes back as UTF-8 '²'.
  EXPECT_EQ(r.numerator_axis.units, "(1/N)*(m/s\xC2\xB2)");
  ASSERT_EQ(r.complex_ordinate.size(), 6);
  EXPECT_EQ(r.ordinate.size(), 0);
  EXPECT_EQ(r.complex_ordinate[0], std::complex<double>(4.07994e-01, 0.0));
  EXPECT_EQ(r.complex_ordinate[1], std::complex<double>(-5.99924e-02, -5.53260e-02));
  EXPECT_EQ(r.complex_ordinate[5], std::complex<double>(3.75037e+00, 2.93363e+00));
  EXPECT_DOUBLE_EQ(r.abscissa[5], 5 * 1.95313e-01);
}

TEST(Uff58Real, PsdIsNotATimeRecord) {
  REQUIRE_REAL_FILE("sample_dataset58_psd.uff");
  const auto records = read_uff58(real_file("sample_dataset58_psd.uff"));
  ASSERT_EQ(records.size(), 1U);
  const Uff58Record& r = records[0];
  EXPECT_EQ(r.function_type, uff_function::power_spectral_density);
  EXPECT_FALSE(r.is_time_record());
  EXPECT_NE(describe_uff58(r).find("power spectral density"), std::string::npos);
  EXPECT_EQ(r.id_lines[0], "Power Spectral Density (PSD)");
  EXPECT_EQ(r.response_entity, "Pilot 1");
  EXPECT_EQ(r.ordinate_type, UffOrdinateType::complex_single);
  EXPECT_EQ(r.points, 3201U);
  EXPECT_FALSE(r.even_spacing);  // uneven: (x, re, im) triples
  EXPECT_EQ(r.numerator_axis.units, "g\xC2\xB2/Hz");
  ASSERT_EQ(r.abscissa.size(), 3201);
  ASSERT_EQ(r.complex_ordinate.size(), 3201);
  for (Eigen::Index k = 0; k < r.abscissa.size(); ++k) {
    ASSERT_EQ(r.abscissa[k], static_cast<double>(k)) << "abscissa is 0, 1, ..., 3200 Hz";
    ASSERT_EQ(r.complex_ordinate[k].imag(), 0.0);
    ASSERT_GE(r.complex_ordinate[k].real(), 0.0) << "a PSD is not negative";
  }
  EXPECT_EQ(r.complex_ordinate[1].real(), 1.255863E-06);
  EXPECT_EQ(r.complex_ordinate[3200].real(), 2.634827E-10);
}

TEST(Uff58Real, TimeHistoryWithShortLastLine) {
  REQUIRE_REAL_FILE("time-history-not-all-columns-filled.uff");
  const auto records = read_uff58(real_file("time-history-not-all-columns-filled.uff"));
  ASSERT_EQ(records.size(), 1U);
  const Uff58Record& r = records[0];
  EXPECT_TRUE(r.is_time_record());
  EXPECT_EQ(r.points, 13U);
  ASSERT_EQ(r.ordinate.size(), 13);
  EXPECT_DOUBLE_EQ(r.abscissa_increment, 5.0e-5);
  EXPECT_DOUBLE_EQ(r.abscissa[12], 12 * 5.0e-5);
  EXPECT_EQ(r.ordinate[0], -3.81956);
  EXPECT_EQ(r.ordinate[6], -3.90210);
  EXPECT_EQ(r.ordinate[12], -5.84096);
  EXPECT_EQ(r.id_lines[0], "1x : m/s\xC2\xB2");  // already UTF-8: kept
  EXPECT_EQ(r.id_lines[1], "UFF58 file created by HBM catman");
  EXPECT_EQ(r.abscissa_axis.label, "Time");
  EXPECT_EQ(r.numerator_axis.units, "m/s\xC2\xB2");
}

TEST(Uff58Real, EveryFileParses) {
  if (!fs::exists(real_dir)) GTEST_SKIP() << "no " << real_dir;
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(real_dir)) {
    if (entry.path().extension() != ".uff") continue;
    ++files;
    std::vector<int> skipped;
    const auto records = read_uff58(entry.path(), &skipped);
    EXPECT_EQ(records.size(), 1U) << entry.path();
    EXPECT_TRUE(skipped.empty()) << entry.path();
    for (const auto& r : records)
      std::printf("  %-40s %s\n", entry.path().filename().string().c_str(),
                  describe_uff58(r).c_str());
  }
  EXPECT_EQ(files, 6U);
}

// ------------------------------------------------------------------------------------------
// Layouts and header fields, from the corpus

Uff58Record only_record(const char* name) {
  const auto records = read_uff58(corpus_dir / name);
  if (records.size() != 1) throw std::runtime_error(std::string(name) + ": not one record");
  return records.front();
}

TEST(Uff58Layouts, RealDoubleEven) {
  const Uff58Record r = only_record("ok_ascii_real_double_even.uff");
  EXPECT_EQ(r.ordinate_type, UffOrdinateType::real_double);
  ASSERT_EQ(r.ordinate.size(), 7);
  for (Eigen::Index k = 0; k < 7; ++k) {
    EXPECT_EQ(r.ordinate[k], static_cast<double>(k) + 0.5);
    EXPECT_DOUBLE_EQ(r.abscissa[k], 0.001 * static_cast<double>(k));
  }
}

TEST(Uff58Layouts, RealDoubleUneven) {
  const Uff58Record r = only_record("ok_ascii_real_double_uneven.uff");
  EXPECT_EQ(r.function_type, uff_function::spectrum);
  EXPECT_FALSE(r.even_spacing);
  ASSERT_EQ(r.points, 5U);
  const double x[] = {1, 2, 4, 8, 16};
  for (Eigen::Index k = 0; k < 5; ++k) {
    EXPECT_EQ(r.abscissa[k], x[k]);
    EXPECT_EQ(r.ordinate[k], -x[k]);
  }
}

TEST(Uff58Layouts, FrfComplexDoubleUnevenWithDofAndUnits) {
  const Uff58Record r = only_record("ok_ascii_frf_complex_double_uneven.uff");
  EXPECT_TRUE(r.is_frf());
  EXPECT_EQ(r.ordinate_type, UffOrdinateType::complex_double);
  EXPECT_EQ(r.response_entity, "TYRE");
  EXPECT_EQ(r.response_node, 2);
  EXPECT_EQ(r.response_direction, 3);
  EXPECT_EQ(r.reference_entity, "HAMMER");
  EXPECT_EQ(r.reference_node, 1);
  EXPECT_EQ(r.reference_direction, -3);
  EXPECT_EQ(r.numerator_axis.specific_data_type, 12);
  EXPECT_EQ(r.numerator_axis.units, "m/s^2");
  EXPECT_EQ(r.denominator_axis.specific_data_type, 13);
  EXPECT_EQ(r.denominator_axis.units, "N");
  ASSERT_EQ(r.points, 3U);
  EXPECT_EQ(r.abscissa[2], 40.0);
  EXPECT_EQ(r.complex_ordinate[0], std::complex<double>(1.0, -1.0));
  EXPECT_EQ(r.complex_ordinate[2], std::complex<double>(-2.0, 3.0));
}

TEST(Uff58Layouts, ComplexSingleEvenShortLastLine) {
  const Uff58Record r = only_record("ok_ascii_complex_single_even_short_line.uff");
  ASSERT_EQ(r.complex_ordinate.size(), 4);
  EXPECT_EQ(r.complex_ordinate[1], std::complex<double>(0.0, 1.0));
  EXPECT_EQ(r.complex_ordinate[3], std::complex<double>(0.0, -1.0));
  EXPECT_EQ(r.abscissa[3], 107.5);
}

TEST(Uff58Layouts, BinaryBigEndianComplexSingle) {
  const Uff58Record r = only_record("ok_binary_big_endian_complex_single.uff");
  EXPECT_TRUE(r.binary);
  ASSERT_EQ(r.complex_ordinate.size(), 3);
  EXPECT_EQ(r.complex_ordinate[0], std::complex<double>(1.5, -0.5));
  EXPECT_EQ(r.complex_ordinate[2], std::complex<double>(-3.25, 4.0));
  EXPECT_EQ(r.response_node, 5);
  EXPECT_EQ(r.reference_node, 6);
}

TEST(Uff58Layouts, BinaryUnevenDoubleWithSingleAbscissa) {
  const Uff58Record r = only_record("ok_binary_uneven_double_single_abscissa.uff");
  ASSERT_EQ(r.points, 3U);
  EXPECT_EQ(r.abscissa[1], 0.25);
  EXPECT_EQ(r.ordinate[2], 30.125);
}

TEST(Uff58Layouts, OtherDatasetsAreSkippedAndReported) {
  std::vector<int> skipped;
  const auto records = read_uff58(corpus_dir / "ok_datasets_151_164_mixed_in.uff", &skipped);
  ASSERT_EQ(records.size(), 1U);
  EXPECT_EQ(records[0].position, 3U);
  EXPECT_EQ(records[0].line, 17U);
  EXPECT_EQ(skipped, (std::vector<int>{151, 164, 151}));
  EXPECT_EQ(records[0].ordinate[2], 3.0);

  const auto none = read_uff58(corpus_dir / "ok_only_dataset_151.uff", &skipped);
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(skipped, std::vector<int>{151});
}

TEST(Uff58Layouts, TouchingValuesDExponentsCrlfBom) {
  const Uff58Record r = only_record("ok_touching_values_d_exponents_crlf_bom.uff");
  ASSERT_EQ(r.ordinate.size(), 5);
  const double expected[] = {-1.0, -2.0, 3.0, 4.0, 0.5};
  for (Eigen::Index k = 0; k < 5; ++k) EXPECT_EQ(r.ordinate[k], expected[k]);
}

TEST(Uff58Layouts, Record6WithoutColumns) {
  const Uff58Record r = only_record("ok_record6_free_format.uff");
  EXPECT_EQ(r.response_entity, "MIC");
  EXPECT_EQ(r.response_node, 7);
}

TEST(Uff58Layouts, MessagesNameFileDatasetAndLine) {
  const fs::path file = corpus_dir / "bad_truncated_data.uff";
  try {
    read_uff58(file);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.source(), file.string());
    EXPECT_NE(message.find("dataset 1 (58, line 1)"), std::string::npos) << message;
    EXPECT_NE(message.find("line 15"), std::string::npos) << message;
    EXPECT_NE(message.find("2 of the 3 data values"), std::string::npos) << message;
  }
  try {
    read_uff58(corpus_dir / "bad_ordinate_type_3.uff");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("record 7, line 9"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("ordinate data type 3"), std::string::npos) << e.what();
  }
  try {
    read_uff58(corpus_dir / "bad_binary_vax_float.uff");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("DEC VMS"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_uff58(corpus_dir / "does_not_exist.uff"), InputError);
}

// ------------------------------------------------------------------------------------------
// Fuzz

using fuzz::Outcome;

// Parses and checks the result's invariants; `problem` describes any violation.
Outcome parse_checked(const std::string& bytes, std::string& problem) {
  const std::string source = "fuzz-source";
  return fuzz::classify(source, [&] {
    std::vector<int> skipped;
    const auto records = parse_uff58(bytes, source, &skipped);
    std::string violation;
    for (const auto& r : records) {
      const auto n = static_cast<Eigen::Index>(r.points);
      if (r.points == 0) violation = "a record without points";
      if (r.abscissa.size() != n) violation = "abscissa length differs from the point count";
      if (r.is_complex() != (r.complex_ordinate.size() == n)) violation = "complex ordinate size";
      if (r.is_complex() == (r.ordinate.size() == n)) violation = "real ordinate size";
      if (!r.abscissa.allFinite() || !r.ordinate.allFinite() ||
          !r.complex_ordinate.real().allFinite() || !r.complex_ordinate.imag().allFinite())
        violation = "a non-finite value was accepted";
      if (r.points > bytes.size()) violation = "more points than bytes";
    }
    return violation;
  }, problem);
}

std::vector<fs::path> corpus_files() { return fuzz::sorted_files(corpus_dir); }

TEST(Uff58Fuzz, CorpusOkParsesBadIsInputError) {
  const auto files = corpus_files();
  ASSERT_GE(files.size(), 20U);
  for (const auto& file : files) {
    const std::string name = file.filename().string();
    std::string problem;
    const Outcome outcome = parse_checked(read_bytes(file), problem);
    EXPECT_TRUE(problem.empty()) << name << ": " << problem;
    if (name.rfind("ok_", 0) == 0) {
      EXPECT_EQ(outcome, Outcome::accepted) << name << ": " << problem;
    }
    if (name.rfind("bad_", 0) == 0) {
      EXPECT_EQ(outcome, Outcome::input_error) << name;
      try {
        read_uff58(file);
      } catch (const InputError& e) {
        std::printf("  %-45s %s\n", name.c_str(), e.what() + file.string().size() + 2);
      }
    }
  }
}

// Small real-world seeds: the small real files whole, the big ones cut down to a few points
// (header with a matching count, the first data).
std::vector<std::string> seeds() {
  std::vector<std::string> out;
  for (const auto& file : corpus_files())
    if (file.filename().string().rfind("ok_", 0) == 0) out.push_back(read_bytes(file));
  for (const char* name :
       {"binary8byte.uff", "non_ascii_header.uff", "time-history-not-all-columns-filled.uff"})
    if (fs::exists(real_file(name))) out.push_back(read_bytes(real_file(name)));
  if (fs::exists(real_file("Sample_UFF58_ascii.uff"))) {
    std::string text = read_bytes(real_file("Sample_UFF58_ascii.uff")).substr(0, 2000);
    const std::size_t count = text.find("79292");
    const std::size_t last = text.rfind('\n', 1800);
    if (count != std::string::npos && last != std::string::npos) {
      // Count the complete data lines kept (6 values each) after the 13 header lines.
      text = text.substr(0, last + 1);
      std::size_t lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
      const std::string kept = std::to_string((lines - 13) * 6);
      text.replace(count, 5, std::string(5 - kept.size(), ' ') + kept);
      out.push_back(text + "    -1\n");
    }
  }
  if (fs::exists(real_file("Sample_UFF58b_bin.uff"))) {
    std::string bytes = read_bytes(real_file("Sample_UFF58b_bin.uff"));
    const std::size_t header_end = [&] {
      std::size_t pos = 0;
      for (int k = 0; k < 13 && pos != std::string::npos; ++k) pos = bytes.find('\n', pos) + 1;
      return pos;
    }();
    std::string header = bytes.substr(0, header_end);
    const std::size_t byte_count = header.find("317168");
    const std::size_t points = header.find("79292");
    if (byte_count != std::string::npos && points != std::string::npos) {
      header.replace(byte_count, 6, "   256");
      header.replace(points, 5, "   64");
      out.push_back(header + bytes.substr(header_end, 256) + "    -1\r\n");
    }
  }
  return out;
}

std::string mutate(std::string s, std::mt19937_64& rng) {
  const auto pick = [&rng](std::size_t n) {
    return n == 0 ? std::size_t{0} : static_cast<std::size_t>(rng() % n);
  };
  static const char* const tokens[] = {"-1",
                                       "    -1\n",
                                       "58",
                                       "58b",
                                       "\n",
                                       "\r\n",
                                       "999999999",
                                       "-999999999",
                                       "2147483648",
                                       "NaN",
                                       "1e999",
                                       "inf",
                                       "1.0E-01-2.0E-01",
                                       "D+00",
                                       "\xB2",
                                       "\xFF\xFE",
                                       " ",
                                       "0",
                                       "    58b     2     2          11        9999",
                                       "         6         3         0"};
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits; ++e) {
    switch (rng() % 8) {
      case 0:  // flip a bit
        if (!s.empty()) s[pick(s.size())] ^= static_cast<char>(1U << (rng() % 8));
        break;
      case 1:  // random byte
        if (!s.empty()) s[pick(s.size())] = static_cast<char>(rng() & 0xFFU);
        break;
      case 2:  // truncate
        s.resize(pick(s.size() + 1));
        break;
      case 3: {  // delete a chunk
        const std::size_t at = pick(s.size() + 1);
        s.erase(at, pick(64));
        break;
      }
      case 4:  // insert a token
        s.insert(pick(s.size() + 1), tokens[pick(std::size(tokens))]);
        break;
      case 5: {  // duplicate a chunk
        const std::size_t at = pick(s.size() + 1);
        const std::string chunk = s.substr(at, pick(200));
        s.insert(pick(s.size() + 1), chunk);
        break;
      }
      case 6: {  // replace a digit run with another number
        const std::size_t at = s.find_first_of("0123456789", pick(s.size() + 1));
        if (at != std::string::npos) {
          const std::size_t end = s.find_first_not_of("0123456789", at);
          s.replace(at, (end == std::string::npos ? s.size() : end) - at, tokens[6 + pick(4)]);
        }
        break;
      }
      default: {  // move a line elsewhere
        const std::size_t a = s.find('\n', pick(s.size() + 1));
        if (a == std::string::npos) break;
        const std::size_t end = s.find('\n', a + 1);
        if (end == std::string::npos) break;
        const std::string line = s.substr(a + 1, end - a);
        s.erase(a + 1, end - a);
        s.insert(pick(s.size() + 1), line);
        break;
      }
    }
  }
  if (s.size() > 16384) s.resize(16384);
  return s;
}

TEST(Uff58Fuzz, RandomBytesAndMutationsReturnOrThrowInputError) {
  const auto start = std::chrono::steady_clock::now();
  std::mt19937_64 rng(20240611);
  const auto base = seeds();
  ASSERT_GE(base.size(), 10U);
  std::size_t inputs = 0, parsed = 0, rejected = 0, failures = 0;
  const auto check = [&](const std::string& bytes) {
    ++inputs;
    std::string problem;
    const Outcome outcome = parse_checked(bytes, problem);
    (outcome == Outcome::accepted ? parsed : rejected) += 1;
    if (!problem.empty() && failures++ < 10) ADD_FAILURE() << problem << "\n  input: " << fuzz::hex_dump(bytes, 200);
  };
  // Random bytes, plain and UFF-flavoured.
  for (int i = 0; i < 2000; ++i) {
    std::string bytes = fuzz::random_text(rng, "", 599);
    if (i % 2 == 1) bytes = "    -1\n    58" + std::string(i % 4 == 1 ? "b" : "") + "\n" + bytes;
    check(bytes);
  }
  // Mutations of the seeds.
  for (int i = 0; i < 10000; ++i)
    check(mutate(base[static_cast<std::size_t>(i) % base.size()], rng));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("  fuzz: %zu inputs (%zu seeds): %zu parsed, %zu InputError, %.2f s\n", inputs,
              base.size(), parsed, rejected, seconds);
  EXPECT_EQ(failures, 0U);
  EXPECT_GT(parsed, 100U) << "mutations should often keep a file valid";
  EXPECT_GT(rejected, 5000U);
}

TEST(Uff58Fuzz, CorruptCountsInTheRealFilesAreCaught) {
  REQUIRE_REAL_FILE("Sample_UFF58b_bin.uff");
  REQUIRE_REAL_FILE("Sample_UFF58_ascii.uff");
  struct Case {
    const char* file;
    const char* from;
    const char* to;
  };
  const Case cases[] = {
      {"Sample_UFF58b_bin.uff", "317168", "999999999"},  // bytes beyond the file
      {"Sample_UFF58b_bin.uff", "79292", "79293"},       // points and bytes disagree
      {"Sample_UFF58b_bin.uff", "     79292", " 2000000000"},
      {"Sample_UFF58_ascii.uff", "     79292", " 9999999999"},  // points beyond the file
      {"Sample_UFF58_ascii.uff", "79292", "79291"},             // one value too many
      {"Sample_UFF58_ascii.uff", "79292", "79293"},             // one value missing
  };
  for (const Case& c : cases) {
    std::string bytes = read_bytes(real_file(c.file));
    const std::size_t at = bytes.find(c.from);
    ASSERT_NE(at, std::string::npos);
    bytes.replace(at, std::strlen(c.from), c.to);
    std::string problem;
    EXPECT_EQ(parse_checked(bytes, problem), Outcome::input_error) << c.file << " " << c.to;
    EXPECT_TRUE(problem.empty()) << problem;
    try {
      parse_uff58(bytes, c.file);
    } catch (const InputError& e) {
      std::printf("  %s\n", e.what());
    }
  }
}

}  // namespace
}  // namespace rollnoise
