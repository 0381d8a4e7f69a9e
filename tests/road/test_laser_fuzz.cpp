// Fuzzing parse_laser_profile: whatever the bytes, it returns a well-formed profile or throws
// InputError naming the source; never another exception, never a crash or a hang.
//
// Seeds: the corpus in tests/corpus/laser ("ok_*" parse, "bad_*" are InputErrors, checked in
// test_laser_profile.cpp), the two real CAPTIF records, and short pieces of them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "fuzz_support.hpp"
#include "road/laser_profile.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

using fuzz::Outcome;
using fuzz::read_bytes;

// Parses `text`; a parsed profile must be consistent (finite heights, at least 2 of them, a
// finite spacing > 0, counts within the points, no more rows than the text has lines).
Outcome parse_checked(const std::string& text, std::string& problem) {
  const std::string source = "fuzz-source";
  return fuzz::classify(source, [&] {
    const MeasuredProfile p = parse_laser_profile(text, source);
    const auto lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
    std::string violation;
    if (p.z_m.size() < 2) violation = "fewer than 2 points";
    if (!(std::isfinite(p.spacing_m) && p.spacing_m > 0)) violation = "bad spacing";
    if (!std::isfinite(p.x0_m)) violation = "non-finite x0";
    for (double v : p.z_m)
      if (!std::isfinite(v)) violation = "a non-finite height";
    if (p.dropouts + p.spikes > p.z_m.size()) violation = "more dropouts and spikes than points";
    if (p.z_m.size() + p.trimmed_points > lines) violation = "more rows than lines";
    if (p.source != source) violation = "wrong source";
    return violation;
  }, problem);
}

const fuzz::Mutations mutations{
    .alphabet = "0123456789.\t\n\r -+eENa",
    .tokens = {"NaN", "nan", "inf", "-inf", "1e999", "1e-400", "47.5", "-3.0", "\t", "\t\t", "\r\n", "\n",
               "*****DATA*****", "*****DATA*****\t\t\r\n", "Data Point No:\tDistance (mm)\tDepth (mm)\r\n",
               "Distance (mm)", "Depth (mm)", std::string(1, '\0'), "\xEF\xBB\xBF", "\xff", "0x1p3",
               "99999999999999999999999999", "1.000\t0.000\t1.0\r\n", "2.000\t0.037\t47.0\r\n"},
    .max_erase = 16,
    .max_chunk = 64,
    .truncate_one_in = 4,
    // Overwrite a line's depth with a plate or a wild value.
    .extra =
        [](std::string& text, std::size_t at, std::mt19937_64& rng) {
          const auto tab = text.rfind('\t', at);
          if (tab != std::string::npos) text.replace(tab + 1, std::min<std::size_t>(5, text.size() - tab - 1), rng() % 2 ? "47.00" : "-9e9");
        },
};

std::string mutate(const std::string& text, std::mt19937_64& rng) {
  // One mutation half of the time (the format is strict: most damage is an error, and the
  // fuzzer must also reach the parsed outcome in bulk), else up to 8.
  const int count = rng() % 2 ? 1 : 1 + static_cast<int>(rng() % 8);
  return mutations.apply(text, rng, count);
}

// The first and last `rows` data rows of a real record, with its header: a short real seed.
std::string head_and_tail(const std::string& text, std::size_t rows) {
  std::size_t start = text.find("Depth (mm)");
  start = text.find('\n', start) + 1;
  std::size_t head_end = start;
  for (std::size_t i = 0; i < rows && head_end != std::string::npos; ++i) head_end = text.find('\n', head_end) + 1;
  std::size_t tail_start = text.size();
  for (std::size_t i = 0; i <= rows && tail_start > 0; ++i) tail_start = text.rfind('\n', tail_start - 1);
  return text.substr(0, head_end) + text.substr(tail_start + 1);
}

TEST(LaserFuzz, RandomAndMutatedInputsReturnOrThrowInputError) {
  std::vector<std::string> seeds;
  for (const auto& entry : fs::directory_iterator(fs::path{ROLLNOISE_LASER_CORPUS_DIR})) seeds.push_back(read_bytes(entry.path()));
  std::sort(seeds.begin(), seeds.end());  // directory order is unspecified
  ASSERT_GE(seeds.size(), 10u);
  std::vector<std::string> real;
  for (const char* name : {"20211011_aylesbury_dec_station_0.dat", "20211011_aylesbury_dec_station_1.dat"}) {
    real.push_back(read_bytes(fs::path{ROLLNOISE_SOURCE_DIR "/data/surfaces/captif"} / name));
    ASSERT_GT(real.back().size(), 1000000u);
    seeds.push_back(head_and_tail(real.back(), 400));
  }

  std::mt19937_64 rng(20240612);  // fixed: the same inputs on every run
  const int inputs = 20000;
  const int real_inputs = 400;  // mutations of the whole 1.3 MB records (slower: ~1 ms each)
  int parsed = 0, rejected = 0, failures = 0;
  for (int i = 0; i < inputs + real_inputs; ++i) {
    std::string text;
    if (i >= inputs) {
      text = mutate(real[rng() % real.size()], rng);
    } else if (i % 3 == 0) {
      text = fuzz::random_text(rng, mutations.alphabet, 512);
      if (rng() % 2) text = "*****DATA*****\nDistance (mm)\tDepth (mm)\n" + text;
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
  std::printf("  %d inputs: %d parsed, %d rejected with InputError\n", inputs + real_inputs, parsed, rejected);
  EXPECT_EQ(failures, 0);
  // The fuzzer is useful only if it reaches both outcomes in bulk.
  EXPECT_GT(parsed, inputs / 50);
  EXPECT_GT(rejected, inputs / 50);
}

TEST(LaserFuzz, OversizedInputIsRefusedBeforeParsing) {
  const std::string huge(laser_max_bytes + 1, '\n');
  try {
    parse_laser_profile(huge, "huge");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "huge");
  }
}

}  // namespace
}  // namespace rollnoise
