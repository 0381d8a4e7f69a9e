// Fuzzing parse_numeric_csv: whatever the bytes, it returns a well-formed table or throws
// InputError (naming the source); never another exception, never a crash.
//
// The seed corpus lives in tests/corpus/csv. File names say what each must do: "ok_*" parses,
// "bad_*" is an InputError.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

const fs::path corpus_dir{ROLLNOISE_CSV_CORPUS_DIR};

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string hex_dump(const std::string& bytes) {
  std::string out;
  char buffer[4];
  for (std::size_t i = 0; i < std::min<std::size_t>(bytes.size(), 300); ++i) {
    std::snprintf(buffer, sizeof buffer, "%02x ", static_cast<unsigned char>(bytes[i]));
    out += buffer;
  }
  return out;
}

enum class Outcome { parsed, input_error, other };

// Parses `text` and checks the result: on success the table must be consistent (one column per
// header name, equal lengths, finite values); on failure an InputError naming the source.
// `problem` describes any violation.
Outcome parse_checked(const std::string& text, std::string& problem) {
  const std::string source = "fuzz-source";
  try {
    const NumericCsv csv = parse_numeric_csv(text, source);
    if (csv.header.empty()) problem = "parsed without a header";
    if (csv.columns.size() != csv.header.size()) problem = "columns and header differ in number";
    for (const auto& column : csv.columns) {
      if (column.size() != csv.rows()) problem = "columns of different lengths";
      for (double v : column)
        if (!std::isfinite(v)) problem = "a non-finite value was accepted";
    }
    return Outcome::parsed;
  } catch (const InputError& e) {
    if (std::string(e.what()).rfind(source, 0) != 0) problem = std::string("message without the source: ") + e.what();
    return Outcome::input_error;
  } catch (const std::exception& e) {
    problem = std::string("unexpected exception: ") + e.what();
    return Outcome::other;
  } catch (...) {
    problem = "unexpected non-standard exception";
    return Outcome::other;
  }
}

std::vector<fs::path> corpus_files() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(corpus_dir))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());  // directory order is unspecified
  return files;
}

TEST(CsvFuzz, CorpusFilesBehaveAsNamed) {
  const auto files = corpus_files();
  ASSERT_GE(files.size(), 5u) << "corpus not found in " << corpus_dir;
  for (const auto& path : files) {
    const std::string name = path.filename().string();
    std::string problem;
    const Outcome outcome = parse_checked(read_bytes(path), problem);
    EXPECT_EQ(problem, "") << name;
    if (name.rfind("ok_", 0) == 0) {
      EXPECT_EQ(outcome, Outcome::parsed) << name;
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

// Bytes a CSV parser has to think about, drawn more often than the rest.
const std::string alphabet = "0123456789.,eE+-\n\r# \txzna";
const std::vector<std::string> tokens = {
    "nan", "NaN", "inf", "-inf", "1e999", "-1e999", "1e-400", "4.9e-324", "0x1p3", "\xEF\xBB\xBF",
    ",", ",,", "\r\n", "\n", "#", std::string(1, '\0'), "-", "+", "+-1", "e+", ".", "1.", ".5",
    "  ", "\xff", "99999999999999999999999999999999", "x,z\n", "1,2\n"};

char random_byte(std::mt19937_64& rng) {
  if (rng() % 10 < 7) return alphabet[rng() % alphabet.size()];
  return static_cast<char>(static_cast<unsigned char>(rng() % 256));
}

std::string mutate(std::string text, std::mt19937_64& rng) {
  const int count = 1 + static_cast<int>(rng() % 8);
  for (int i = 0; i < count; ++i) {
    const std::size_t at = text.empty() ? 0 : rng() % (text.size() + 1);
    switch (rng() % 6) {
      case 0:  // overwrite a byte
        if (at < text.size()) text[at] = random_byte(rng);
        break;
      case 1:  // insert a byte
        text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), random_byte(rng));
        break;
      case 2:  // delete a run
        if (at < text.size()) text.erase(at, 1 + rng() % 8);
        break;
      case 3: {  // duplicate a chunk
        if (at < text.size()) {
          const std::string chunk = text.substr(at, 1 + rng() % 16);
          text.insert(rng() % (text.size() + 1), chunk);
        }
        break;
      }
      case 4:  // insert a token
        text.insert(at, tokens[rng() % tokens.size()]);
        break;
      default:  // truncate
        text.resize(at);
        break;
    }
  }
  return text;
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
      const std::size_t length = rng() % 257;
      for (std::size_t j = 0; j < length; ++j) text += random_byte(rng);
    } else {
      text = mutate(seeds[rng() % seeds.size()], rng);
    }
    std::string problem;
    const Outcome outcome = parse_checked(text, problem);
    (outcome == Outcome::parsed ? parsed : rejected) += 1;
    if (!problem.empty() && ++failures <= 5) {
      ADD_FAILURE() << "input " << i << ": " << problem << "\n  bytes: " << hex_dump(text);
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
