// Fuzzing parse_numeric_csv: whatever the bytes, it returns a well-formed table or throws
// InputError (naming the source); never another exception, never a crash.
//
// The seed corpus lives in tests/corpus/csv. File names say what each must do: "ok_*" parses,
// "bad_*" is an InputError.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "fuzz_support.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

const fs::path corpus_dir{ROLLNOISE_CSV_CORPUS_DIR};

using fuzz::Outcome;
using fuzz::read_bytes;

// Parses `text` and checks the result: on success the table must be consistent (one column per
// header name, equal lengths, finite values); on failure an InputError naming the source.
// `problem` describes any violation.
Outcome parse_checked(const std::string& text, std::string& problem) {
  const std::string source = "fuzz-source";
  return fuzz::classify(source, [&] {
    const NumericCsv csv = parse_numeric_csv(text, source);
    std::string violation;
    if (csv.header.empty()) violation = "parsed without a header";
    if (csv.columns.size() != csv.header.size()) violation = "columns and header differ in number";
    for (const auto& column : csv.columns) {
      if (column.size() != csv.rows()) violation = "columns of different lengths";
      for (double v : column)
        if (!std::isfinite(v)) violation = "a non-finite value was accepted";
    }
    return violation;
  }, problem);
}

std::vector<fs::path> corpus_files() { return fuzz::sorted_files(corpus_dir); }

TEST(CsvFuzz, CorpusFilesBehaveAsNamed) {
  const auto files = corpus_files();
  ASSERT_GE(files.size(), 5u) << "corpus not found in " << corpus_dir;
  for (const auto& path : files) {
    const std::string name = path.filename().string();
    std::string problem;
    const Outcome outcome = parse_checked(read_bytes(path), problem);
    EXPECT_EQ(problem, "") << name;
    if (name.rfind("ok_", 0) == 0) {
      EXPECT_EQ(outcome, Outcome::accepted) << name;
    } else {
      EXPECT_EQ(outcome, Outcome::input_error) << name;
    }
    // The file reader too: its messages name the file.
    try {
      (void)read_numeric_csv(path);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

TEST(CsvFuzz, CorpusValuesAreReadExactly) {
  const NumericCsv valid = read_numeric_csv(corpus_dir / "ok_valid.csv");
  ASSERT_EQ(valid.rows(), 3u);
  EXPECT_EQ(valid.columns[1][1], 1e-3);
  EXPECT_EQ(valid.columns[1][2], -2.5e-4);
  const NumericCsv bom = read_numeric_csv(corpus_dir / "ok_bom.csv");
  EXPECT_EQ(bom.header.front(), "x");  // the byte-order mark is not part of the name
  const NumericCsv crlf = read_numeric_csv(corpus_dir / "ok_crlf.csv");
  EXPECT_EQ(crlf.header.back(), "z");
  EXPECT_EQ(crlf.columns[1][1], 2.0);
  const NumericCsv huge = read_numeric_csv(corpus_dir / "ok_huge_exponent.csv");
  EXPECT_EQ(huge.columns[0][0], 1e308);
  EXPECT_EQ(huge.columns[1][0], -1.7976931348623157e308);
}

// Bytes a CSV parser has to think about, drawn more often than the rest, and tokens to insert.
const fuzz::Mutations mutations{
    .alphabet = "0123456789.,eE+-\n\r# \txzna",
    .tokens = {"nan", "NaN", "inf", "-inf", "1e999", "-1e999", "1e-400", "4.9e-324", "0x1p3", "\xEF\xBB\xBF",
               ",", ",,", "\r\n", "\n", "#", std::string(1, '\0'), "-", "+", "+-1", "e+", ".", "1.", ".5",
               "  ", "\xff", "99999999999999999999999999999999", "x,z\n", "1,2\n"},
};

std::string mutate(const std::string& text, std::mt19937_64& rng) {
  const int count = 1 + static_cast<int>(rng() % 8);
  return mutations.apply(text, rng, count);
}

TEST(CsvFuzz, RandomAndMutatedInputsReturnOrThrowInputError) {
  std::vector<std::string> seeds = {"x,z\n0,0\n1,1\n", "a,b,c\n1,2,3\n-4.5e-3,+6,7E2\n",
                                    "# c\nx\n1\n2\n", "x,z\r\n0,1\r\n"};
  for (const auto& path : corpus_files()) seeds.push_back(read_bytes(path));

  std::mt19937_64 rng(20240611);  // fixed: the same 20000 inputs on every run
  const int inputs = 20000;
  int parsed = 0, rejected = 0, failures = 0;
  for (int i = 0; i < inputs; ++i) {
    std::string text;
    if (i % 2 == 0) {
      text = fuzz::random_text(rng, mutations.alphabet, 256);
    } else {
      text = mutate(seeds[rng() % seeds.size()], rng);
    }
    std::string problem;
    const Outcome outcome = parse_checked(text, problem);
    (outcome == Outcome::accepted ? parsed : rejected) += 1;
    if (!problem.empty() && ++failures <= 5) {
      ADD_FAILURE() << "input " << i << ": " << problem << "\n  bytes: " << fuzz::hex_dump(text);
    }
  }
  std::printf("  %d inputs: %d parsed, %d rejected with InputError\n", inputs, parsed, rejected);
  EXPECT_EQ(failures, 0);
  // The fuzzer is useful only if it reaches both outcomes in bulk.
  EXPECT_GT(parsed, inputs / 50);
  EXPECT_GT(rejected, inputs / 50);
}

}  // namespace
}  // namespace rollnoise
