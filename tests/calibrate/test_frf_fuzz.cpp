// Fuzz of the FRF readers: random bytes and mutations of the seed corpus
// (tests/corpus/frf_csv, tests/corpus/uff, FRFs written in every UFF layout, and the small
// real UFF files). Whatever the bytes, a reader returns FRFs that keep their invariants
// (frequencies > 0 and increasing, finite non-zero mobilities, sizes that agree) or throws an
// InputError whose message starts with the source; nothing else, never a crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "calibrate/frf_csv_reader.hpp"
#include "calibrate/frf_uff_reader.hpp"
#include "calibrate/uff_frf_writer.hpp"
#include "core/error.hpp"
#include "fuzz_support.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

using fuzz::Outcome;
using fuzz::read_bytes;

std::vector<std::string> files_in(const fs::path& dir, bool ok_only) {
  std::vector<std::string> out;
  for (const auto& p : fuzz::sorted_files(dir))
    if (!ok_only || p.filename().string().rfind("ok_", 0) == 0) out.push_back(read_bytes(p));
  return out;
}

// Runs a reader and checks what it returns; `problem` describes any violation.
Outcome run_checked(const std::function<FrfFile(const std::string&)>& read, const std::string& bytes,
                    std::string& problem) {
  return fuzz::classify("fuzz-source", [&] {
    const FrfFile file = read(bytes);
    std::string violation;
    if (file.frfs.empty()) violation = "no FRF and no error";
    for (const MeasuredFrf& f : file.frfs) {
      if (f.size() == 0 || f.mobility.size() != f.size()) violation = "sizes disagree";
      for (Eigen::Index k = 0; k < f.size(); ++k) {
        if (!(f.frequency_hz[k] > 0.0) || !std::isfinite(f.frequency_hz[k])) violation = "a frequency <= 0 or not finite";
        if (k > 0 && !(f.frequency_hz[k] > f.frequency_hz[k - 1])) violation = "frequencies do not increase";
        if (!std::isfinite(f.mobility[k].real()) || !std::isfinite(f.mobility[k].imag()) || f.mobility[k] == 0.0)
          violation = "a mobility that is 0 or not finite";
      }
      if (f.response && (!std::isfinite(f.response->x) || !std::isfinite(f.response->y)))
        violation = "a position that is not finite";
    }
    return violation;
  }, problem);
}

std::string mutate(std::string s, std::mt19937_64& rng, const std::vector<std::string>& tokens) {
  const auto pick = [&rng](std::size_t n) { return n == 0 ? std::size_t{0} : static_cast<std::size_t>(rng() % n); };
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits; ++e) {
    switch (rng() % 7) {
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
        s.insert(pick(s.size() + 1), tokens[pick(tokens.size())]);
        break;
      case 5: {  // duplicate a chunk
        const std::size_t at = pick(s.size() + 1);
        const std::string chunk = s.substr(at, pick(120));
        s.insert(pick(s.size() + 1), chunk);
        break;
      }
      default: {  // replace a number by another
        const std::size_t at = s.find_first_of("0123456789", pick(s.size() + 1));
        if (at != std::string::npos) {
          const std::size_t end = s.find_first_not_of("0123456789.", at);
          s.replace(at, (end == std::string::npos ? s.size() : end) - at, tokens[pick(tokens.size())]);
        }
        break;
      }
    }
  }
  if (s.size() > 16384) s.resize(16384);
  return s;
}

struct FuzzCount {
  std::size_t inputs = 0, parsed = 0, rejected = 0, failures = 0;
};

void fuzz(const char* name, const std::function<FrfFile(const std::string&)>& read, const std::vector<std::string>& seeds,
          const std::vector<std::string>& tokens, const std::string& random_prefix, int mutations, FuzzCount& count) {
  const auto start = std::chrono::steady_clock::now();
  std::mt19937_64 rng(20250101);
  const auto check = [&](const std::string& bytes) {
    ++count.inputs;
    std::string problem;
    const Outcome outcome = run_checked(read, bytes, problem);
    (outcome == Outcome::accepted ? count.parsed : count.rejected) += 1;
    if (!problem.empty() && count.failures++ < 10) {
      std::string shown;
      for (char c : bytes.substr(0, 300)) shown += (c >= 32 && c < 127) || c == '\n' ? c : '?';
      ADD_FAILURE() << name << ": " << problem << "\n  input:\n" << shown;
    }
  };
  for (const std::string& seed : seeds) check(seed);
  for (int i = 0; i < 1000; ++i) {
    std::string bytes = fuzz::random_text(rng, "", 399);
    if (i % 2 == 1) bytes = random_prefix + bytes;
    check(bytes);
  }
  // Mutations of the last `mutated` seeds (the valid ones come last).
  const std::size_t mutated = std::min<std::size_t>(seeds.size(), 16);
  for (int i = 0; i < mutations; ++i)
    check(mutate(seeds[seeds.size() - mutated + static_cast<std::size_t>(i) % mutated], rng, tokens));
  std::printf("  %s fuzz: %zu inputs so far (%zu seeds): %zu read, %zu InputError, %.2f s\n", name, count.inputs,
              seeds.size(), count.parsed, count.rejected,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

TEST(FrfFuzz, CsvReaderReturnsValidFrfsOrInputError) {
  // Every corpus file as it is; mutations of the valid ones.
  std::vector<std::string> seeds = files_in(ROLLNOISE_SOURCE_DIR "/tests/corpus/frf_csv", true);
  ASSERT_GE(seeds.size(), 5U);
  for (const std::string& bad : files_in(ROLLNOISE_SOURCE_DIR "/tests/corpus/frf_csv", false))
    if (std::find(seeds.begin(), seeds.end(), bad) == seeds.end()) seeds.insert(seeds.begin(), bad);
  const std::vector<std::string> tokens = {
      ",",      "\n",           "\r\n",         "#",           "# response_x = ", "# data_type = receptance",
      "=",      "nan",          "inf",          "-1",          "0",               "1e308",
      "1e-320", "frequency_hz", "magnitude",    "phase_deg",   "re,im",           "\xEF\xBB\xBF",
      "\xFF",   " ",            "# excitation_y = 1e999",      "-0",              "1e400"};
  FuzzCount count;
  for (bool given : {false, true}) {
    const FrfReadOptions options{FrfQuantity::accelerance, given};
    fuzz("FRF CSV", [&](const std::string& b) { return parse_frf_csv(b, "fuzz-source", options); }, seeds, tokens,
         "frequency_hz,re,im\n", 10000, count);
  }
  EXPECT_EQ(count.failures, 0U);
  EXPECT_GT(count.parsed, 500U) << "mutations should often keep a file valid";
  EXPECT_GT(count.rejected, 2000U);
}

TEST(FrfFuzz, UffFrfSelectionReturnsValidFrfsOrInputError) {
  using testing::UffFrfRecord;
  std::vector<std::string> seeds = files_in(ROLLNOISE_SOURCE_DIR "/tests/corpus/uff", true);
  const fs::path real_dir{ROLLNOISE_SOURCE_DIR "/../shared/data/uff"};
  for (const char* name : {"non_ascii_header.uff", "time-history-not-all-columns-filled.uff", "binary8byte.uff"})
    if (fs::exists(real_dir / name)) seeds.push_back(read_bytes(real_dir / name));
  // FRFs in every layout and quantity, as measurement systems write them.
  UffFrfRecord r;
  for (int k = 1; k <= 6; ++k) {
    r.frequency_hz.push_back(5.0 * k);
    r.values.push_back({1e-3 * k, -1e-3});
  }
  for (const auto& [code, units] : std::vector<std::pair<int, std::string>>{{8, "m"}, {11, "mm/s"}, {12, "g"}, {1, "(1/N)*(m/s^2)"}}) {
    r.numerator_type = code;
    r.numerator_units = units;
    for (bool binary : {false, true})
      for (bool even : {false, true}) {
        r.even = even;
        seeds.push_back(testing::uff58_text({r, r}, {binary, !even, binary && even}));
      }
  }
  const std::vector<std::string> tokens = {"-1",  "    -1\n", "58",  "58b", "\n",   "\r\n",  "4",  "13", "12", "11",
                                           "8",   "18",      "17",  "-3",  "NaN",  "1e999", "Hz", "kHz", "g", "mm/s",
                                           "1",   "0",       "999999999",  "\xB2", " ",     "9"};
  FuzzCount count;
  for (bool given : {false, true}) {
    const FrfReadOptions options{FrfQuantity::mobility, given};
    fuzz("FRF UFF", [&](const std::string& b) { return parse_uff_frfs(b, "fuzz-source", options); }, seeds, tokens,
         "    -1\n    58\n", 10000, count);
  }
  EXPECT_EQ(count.failures, 0U);
  EXPECT_GT(count.parsed, 300U);
  EXPECT_GT(count.rejected, 2000U);
}

}  // namespace
}  // namespace rollnoise
