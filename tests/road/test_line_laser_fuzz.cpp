// Fuzzing parse_line_laser_csv in every test run (the libFuzzer target is fuzz/line_laser.cpp):
// whatever the bytes, it returns well-formed profiles or throws InputError naming the source;
// never another exception, never a crash or a hang.
//
// Seeds: the corpus in tests/corpus/line_laser ("ok_*" parse, "bad_*" are InputErrors, checked in
// test_line_laser_csv.cpp) and the shipped CAPTIF file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "fuzz_support.hpp"
#include "road/line_laser_csv.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

using fuzz::Outcome;
using fuzz::read_bytes;

// Parses `text`; what it returns must be consistent: at least one line, as many lines as time
// stamps, every line as long as the positions (at least 2, finite, increasing), heights finite or
// NaN (not all NaN), the dropouts counted, no more lines than the text has line pairs.
Outcome parse_checked(const std::string& text, std::string& problem) {
  const std::string source = "fuzz-source";
  return fuzz::classify(source, [&] {
    const LineLaserProfiles p = parse_line_laser_csv(text, source);
    const auto newlines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
    std::string violation;
    if (p.z_lines.empty() || p.z_lines.size() != p.time_stamps.size()) violation = "lines and stamps differ";
    if (p.x_m.size() < 2) violation = "fewer than 2 positions";
    for (std::size_t i = 0; i < p.x_m.size(); ++i) {
      if (!std::isfinite(p.x_m[i])) violation = "a non-finite position";
      if (i > 0 && !(p.x_m[i] > p.x_m[i - 1])) violation = "positions not increasing";
    }
    std::size_t nan = 0;
    for (const auto& z : p.z_lines) {
      if (z.size() != p.x_m.size()) violation = "a line of another length";
      std::size_t line_nan = 0;
      for (double v : z) {
        if (std::isnan(v)) ++line_nan;
        else if (!std::isfinite(v)) violation = "an infinite height";
      }
      if (line_nan == z.size()) violation = "a line of dropouts only";
      nan += line_nan;
    }
    if (nan != p.dropouts) violation = "dropouts miscounted";
    if (2 * p.z_lines.size() > newlines + 1) violation = "more lines than the text has";
    if (p.source != source) violation = "wrong source";
    return violation;
  }, problem);
}

const fuzz::Mutations mutations{
    .alphabet = "0123456789.,-+eENa \r\n",
    .tokens = {"NaN", "nan", "inf", "-inf", "1e999", "1e-400", ",", ",,", "\r\n", "\n", "145327.039720,",
               "-93.1", "-100.04", std::string(1, '\0'), "\xEF\xBB\xBF", "\xff", "0x1p3", "99999999999999999999999"},
    .max_erase = 16,
    .max_chunk = 64,
    .truncate_one_in = 4,
    // Swap two lines: pairs out of order.
    .extra =
        [](std::string& text, std::size_t at, std::mt19937_64& rng) {
          const auto a = text.rfind('\n', at);
          const auto b = text.find('\n', at);
          if (a != std::string::npos && b != std::string::npos && rng() % 2) text.erase(a, b - a);
        },
};

TEST(LineLaserFuzz, RandomAndMutatedInputsReturnOrThrowInputError) {
  std::vector<std::string> seeds;
  for (const auto& entry : fs::directory_iterator(fs::path{ROLLNOISE_LINE_LASER_CORPUS_DIR}))
    seeds.push_back(read_bytes(entry.path()));
  std::sort(seeds.begin(), seeds.end());  // directory order is unspecified
  ASSERT_GE(seeds.size(), 15u);
  const std::string real =
      read_bytes(fs::path{ROLLNOISE_SOURCE_DIR "/data/surfaces/captif-transverse/20231114_cpx_demo.csv"});
  ASSERT_GT(real.size(), 100000u);

  std::mt19937_64 rng(20261127);  // fixed: the same inputs on every run
  const int inputs = 20000;
  const int real_inputs = 200;  // mutations of the whole 150 kB file
  int parsed = 0, rejected = 0, failures = 0;
  for (int i = 0; i < inputs + real_inputs; ++i) {
    std::string text;
    if (i >= inputs) {
      text = mutations.apply(real, rng, 1 + static_cast<int>(rng() % 4));
    } else if (i % 3 == 0) {
      text = fuzz::random_text(rng, mutations.alphabet, 512);
    } else {
      // One mutation half of the time (the format is strict: most damage is an error, and the
      // fuzzer must also reach the parsed outcome in bulk), else up to 8.
      text = mutations.apply(seeds[rng() % seeds.size()], rng, rng() % 2 ? 1 : 1 + static_cast<int>(rng() % 8));
    }
    std::string problem;
    const Outcome outcome = parse_checked(text, problem);
    (outcome == Outcome::accepted ? parsed : rejected) += 1;
    if (!problem.empty() && ++failures <= 5) {
      ADD_FAILURE() << "input " << i << ": " << problem << "\n  bytes: " << fuzz::hex_dump(text);
    }
  }
  std::printf("  %d inputs: %d parsed, %d rejected with InputError\n", inputs + real_inputs, parsed, rejected);
  EXPECT_EQ(failures, 0);
  EXPECT_GT(parsed, inputs / 50);
  EXPECT_GT(rejected, inputs / 50);
}

TEST(LineLaserFuzz, OversizedInputIsRefusedBeforeParsing) {
  const std::string huge(line_laser_max_bytes + 1, '\n');
  try {
    parse_line_laser_csv(huge, "huge");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "huge");
  }
}

}  // namespace
}  // namespace rollnoise
