// Fuzzing the profile readers added for measured roads: the profile CSV reader (one and several
// lines) and the HDF5 height-map reader. Whatever the bytes, each returns a well-formed result
// or throws InputError naming the source; never another exception, never a crash, never an
// unbounded allocation.
//
// Seed corpora: tests/corpus/profile_csv and tests/corpus/height_map_hdf5. File names say what
// each must do: "ok_*" reads, "bad_*" is an InputError.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "fuzz_support.hpp"
#include "road/height_map_hdf5.hpp"
#include "road/profile_csv.hpp"
#include "road/profile_file.hpp"
#include "road/road_test_support.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;

const fs::path csv_corpus{ROLLNOISE_PROFILE_CSV_CORPUS_DIR};
const fs::path hdf5_corpus{ROLLNOISE_HEIGHT_MAP_HDF5_CORPUS_DIR};

using fuzz::Outcome;
using fuzz::read_bytes;

bool increasing(const std::vector<double>& v) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) return false;
    if (i > 0 && !(v[i] > v[i - 1])) return false;
  }
  return true;
}

// The invariants of a profile table; "" when they hold.
std::string check_table(const ProfileTable& t) {
  if (t.x.size() < 2) return "fewer than 2 rows";
  if (!increasing(t.x)) return "x not finite and strictly increasing";
  if (t.z_lines.empty() || t.y.size() != t.z_lines.size()) return "lines and y positions differ in number";
  if (!increasing(t.y)) return "y not finite and strictly increasing";
  std::size_t dropouts = 0;
  for (const auto& line : t.z_lines) {
    if (line.size() != t.x.size()) return "a line of another length than x";
    bool valid = false;
    for (double z : line) {
      if (std::isnan(z)) {
        ++dropouts;
      } else if (!std::isfinite(z)) {
        return "an infinite height";
      } else {
        valid = true;
      }
    }
    if (!valid) return "a line with no valid value";
  }
  if (dropouts != t.dropouts) return "dropouts miscounted";
  return "";
}

std::string check_grid(const HeightMapGrid& g) {
  if (g.x.size() < 2 || g.y.empty()) return "too few grid lines";
  if (!increasing(g.x) || !increasing(g.y)) return "grid lines not finite and increasing";
  if (g.z.size() != g.x.size() * g.y.size()) return "z of the wrong size";
  std::size_t dropouts = 0;
  for (double z : g.z) {
    if (std::isnan(z)) ++dropouts;
    else if (!std::isfinite(z)) return "an infinite height";
  }
  if (dropouts != g.dropouts || dropouts == g.z.size()) return "dropouts miscounted, or all";
  return "";
}

// Flip one bit (binary formats: lengths, offsets, flags).
void flip_a_bit(std::string& text, std::size_t at, std::mt19937_64& rng) {
  if (at < text.size()) text[at] = static_cast<char>(text[at] ^ (1 << (rng() % 8)));
}

std::string mutate(const std::string& text, std::mt19937_64& rng, const fuzz::Mutations& mutations) {
  const int count = 1 + static_cast<int>(rng() % 8);
  return mutations.apply(text, rng, count);
}

// ---- profile CSV ----

Outcome parse_profile_checked(const std::string& text, std::string& problem) {
  const std::string source = "fuzz-profile";
  return fuzz::classify(source, [&] { return check_table(parse_profile_csv(text, source)); }, problem);
}

TEST(ProfileCsvFuzz, CorpusFilesBehaveAsNamed) {
  const auto files = fuzz::sorted_files(csv_corpus);
  ASSERT_GE(files.size(), 10u) << "corpus not found in " << csv_corpus;
  for (const auto& path : files) {
    const std::string name = path.filename().string();
    std::string problem;
    const Outcome outcome = parse_profile_checked(read_bytes(path), problem);
    EXPECT_EQ(problem, "") << name;
    EXPECT_EQ(outcome, name.rfind("ok_", 0) == 0 ? Outcome::accepted : Outcome::input_error) << name;
    // Through the file loader: messages name the file; what reads is cleaned and uniform.
    try {
      const LoadedProfile p = load_profile_file(path);
      for (const auto& line : p.z_lines)
        for (double z : line) EXPECT_TRUE(std::isfinite(z)) << name;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

TEST(ProfileCsvFuzz, RandomAndMutatedInputsReturnOrThrowInputError) {
  const fuzz::Mutations mutations{
      .alphabet = "0123456789.,eE+-\n\r# \txyz_[]m=u",
      .tokens = {"nan", "NaN", "inf", "1e999", "-1e999", "4.9e-324", ",", ",,", "\n", "\r\n", "#", std::string(1, '\0'),
                 "x", "z", "z_1", "z_2", "z_0", "z_99999999999999999999", "_mm", "_m", "_um", " [mm]", " [m]", "[", "]",
                 "# y = 0, 1\n", "# y [mm] = -50, 0, 50\n", "# y =\n", "# y_mm = 1e308, 1e309\n", "x,z\n", "x,z_1,z_2\n",
                 "0,0\n", "1,\n", "\xC2\xB5m", "\xEF\xBB\xBF"},
      .truncate_one_in = 4,
      .extra = flip_a_bit,
  };
  std::vector<std::string> seeds = {"x,z\n0,0\n1,1\n", "# y = 0, 0.1\nx,z_1,z_2\n0,0,\n1,,1\n2,2,2\n",
                                    "x [mm],z [um]\n0,1\n1,2\n"};
  for (const auto& path : fuzz::sorted_files(csv_corpus)) seeds.push_back(read_bytes(path));

  std::mt19937_64 rng(20241124);  // fixed: the same inputs on every run
  const int inputs = 20000;
  int read = 0, rejected = 0, failures = 0;
  for (int i = 0; i < inputs; ++i) {
    std::string text;
    if (i % 4 == 0) {
      text = fuzz::random_text(rng, mutations.alphabet, 256);
    } else {
      text = mutate(seeds[rng() % seeds.size()], rng, mutations);
    }
    std::string problem;
    const Outcome outcome = parse_profile_checked(text, problem);
    (outcome == Outcome::accepted ? read : rejected) += 1;
    if (!problem.empty() && ++failures <= 5) ADD_FAILURE() << "input " << i << ": " << problem;
  }
  std::printf("  profile CSV: %d inputs: %d read, %d rejected with InputError\n", inputs, read, rejected);
  EXPECT_EQ(failures, 0);
  EXPECT_GT(read, inputs / 50);
  EXPECT_GT(rejected, inputs / 50);
}

// ---- HDF5 height maps ----

class HeightMapHdf5Fuzz : public ::testing::Test {
 protected:
  Outcome read_checked(const std::string& bytes, std::string& problem) const {
    const fs::path path = dir_ / "fuzz.h5";
    {
      std::ofstream out(path, std::ios::binary | std::ios::trunc);
      out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    return fuzz::classify(path.string(), [&] { return check_grid(read_height_map_hdf5(path)); }, problem);
  }
  test::TempFolder temp_{"rollnoise_test_hdf5_fuzz_"};
  const fs::path dir_ = temp_.path();
};

TEST_F(HeightMapHdf5Fuzz, CorpusFilesBehaveAsNamed) {
  const auto files = fuzz::sorted_files(hdf5_corpus);
  ASSERT_GE(files.size(), 8u) << "corpus not found in " << hdf5_corpus;
  for (const auto& path : files) {
    const std::string name = path.filename().string();
    std::string problem;
    const Outcome outcome = fuzz::classify(path.string(), [&] { return check_grid(read_height_map_hdf5(path)); }, problem);
    EXPECT_EQ(problem, "") << name;
    EXPECT_EQ(outcome, name.rfind("ok_", 0) == 0 ? Outcome::accepted : Outcome::input_error) << name;
  }
  // The values of one file in every encoding: float32 z in mm, variable-length unit strings.
  const HeightMapGrid g = read_height_map_hdf5(hdf5_corpus / "ok_float32_z_in_mm.h5");
  EXPECT_EQ(g.x.size(), 10u);
  EXPECT_EQ(g.y.size(), 2u);
  // Written as 1e3 * (1e-3 sin(300 x)) + 1e-5 * j mm: the 1e-5 is in mm.
  EXPECT_NEAR(g.z[2 * 2 + 1], 1e-3 * std::sin(300.0 * 0.004) + 1e-8, 1e-10);  // float32 in mm: ~1e-10 m
  const HeightMapGrid mm = read_height_map_hdf5(hdf5_corpus / "ok_millimetres_variable_strings.h5");
  EXPECT_NEAR(mm.x[1], 0.002, 1e-17);
  EXPECT_NEAR(mm.y[0], -0.01, 1e-17);
}

TEST_F(HeightMapHdf5Fuzz, RandomAndMutatedFilesReturnOrThrowInputError) {
  std::vector<std::string> seeds;
  for (const auto& path : fuzz::sorted_files(hdf5_corpus))
    if (path.filename().string().rfind("ok_", 0) == 0) seeds.push_back(read_bytes(path));
  ASSERT_FALSE(seeds.empty());
  const std::string signature("\x89HDF\r\n\x1a\n", 8);
  // Any byte (no alphabet: the format is binary).
  const fuzz::Mutations mutations{
      .tokens = {std::string(8, '\xff'), std::string(8, '\0'), signature, std::string("\x01\x00\x00\x00", 4),
                 std::string("\xff\xff\xff\x7f", 4), "TREE", "HEAP", "SNOD", "OHDR", "units", "mm"},
      .truncate_one_in = 4,
      .extra = flip_a_bit,
  };
  std::mt19937_64 rng(20241125);
  const int inputs = 3000;
  int read = 0, rejected = 0, failures = 0;
  for (int i = 0; i < inputs; ++i) {
    std::string bytes;
    if (i % 10 == 0) {  // random bytes behind the signature
      bytes = signature + fuzz::random_text(rng, "", 4095);
    } else {
      bytes = mutate(seeds[rng() % seeds.size()], rng, mutations);
    }
    std::string problem;
    const Outcome outcome = read_checked(bytes, problem);
    (outcome == Outcome::accepted ? read : rejected) += 1;
    if (!problem.empty() && ++failures <= 5) ADD_FAILURE() << "input " << i << ": " << problem;
  }
  std::printf("  HDF5 height map: %d inputs: %d read, %d rejected with InputError\n", inputs, read, rejected);
  EXPECT_EQ(failures, 0);
  EXPECT_GT(read, inputs / 50);
  EXPECT_GT(rejected, inputs / 50);
}

}  // namespace
}  // namespace rollnoise
