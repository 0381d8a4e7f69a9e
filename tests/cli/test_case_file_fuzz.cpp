// Fuzzing the case-file readers: CaseFile::load (and load_model), then make_greens_model and
// read_rolling_settings on what loads. Every input must either load or throw
// rollnoise::InputError (which the program turns into exit status 2); any other exception
// would be an "internal error" (exit status 1) for a mere bad file, and a crash is a crash.
// Deterministic: seeded std::mt19937_64. If the process crashes, the input that did it is the
// file left in the temp folder (rollnoise_fuzz_*/input.toml).
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

#include <gtest/gtest.h>

#include "contact/point_contact.hpp"
#include "contact/rolling_settings.hpp"
#include "contact/tread_pattern_reader.hpp"
#include "core/case_file.hpp"
#include "core/config_table.hpp"
#include "core/error.hpp"
#include "fuzz_support.hpp"
#include "greens/greens_model.hpp"
#include "greens/model_factory.hpp"
#include "greens/plate_factory.hpp"
#include "greens/two_layer_factory.hpp"

namespace {
namespace fs = std::filesystem;

using rollnoise::fuzz::read_bytes;

// Printable preview of an input for failure messages.
std::string escaped(const std::string& bytes, std::size_t limit = 400) {
  std::string out;
  for (std::size_t i = 0; i < bytes.size() && i < limit; ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\\') {
      out += "\\\\";
    } else if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  if (bytes.size() > limit) out += "... (" + std::to_string(bytes.size()) + " bytes)";
  return out;
}

struct Tally {
  int inputs = 0;
  int loaded = 0;     // CaseFile::load succeeded
  int models = 0;     // make_greens_model on [tyre] succeeded
  int settings = 0;   // read_rolling_settings on [rolling] succeeded
  int model_files = 0;  // CaseFile::load_model + make_greens_model(top()) succeeded
  std::vector<std::string> failures;
};

// Runs one input through the readers. An InputError anywhere ends that reader quietly; any
// other exception is recorded as a failure.
void check_one(const fs::path& file, const std::vector<std::string>& overrides,
               const std::string& label, Tally& tally) {
  ++tally.inputs;
  const auto fail = [&](const std::string& stage, const std::string& what) {
    if (tally.failures.size() < 12) {
      std::string overrides_text;
      for (const auto& o : overrides) overrides_text += " --set " + escaped(o, 80);
      tally.failures.push_back(label + ": " + stage + " threw " + what + "\n    input: " +
                               escaped(read_bytes(file)) + (overrides_text.empty() ? "" : "\n    overrides:" + overrides_text));
    }
  };
  const auto guarded = [&](const std::string& stage, auto&& body) {
    try {
      body();
      return true;
    } catch (const rollnoise::InputError& error) {
      if (std::string(error.what()).empty()) fail(stage, "an InputError with an empty message");
      return false;
    } catch (const std::exception& error) {
      fail(stage, std::string(typeid(error).name()) + ": " + error.what());
      return false;
    } catch (...) {
      fail(stage, "a non-standard exception");
      return false;
    }
  };

  std::unique_ptr<rollnoise::CaseFile> loaded;
  if (guarded("CaseFile::load",
              [&] { loaded = std::make_unique<rollnoise::CaseFile>(rollnoise::CaseFile::load(file, overrides)); })) {
    ++tally.loaded;
    const rollnoise::CaseFile& cases = *loaded;
    std::unique_ptr<rollnoise::GreensModel> model;
    // The plate tyre's readers (the tyre and its [rolling] keys) take the same bytes.
    if (guarded("read_plate_tyre", [&] { (void)rollnoise::read_plate_tyre(cases.section("tyre")); })) ++tally.models;
    // The tread pattern's reader, against the 205/55 R16's circumference and tread width.
    guarded("read_tread_pattern", [&] { (void)rollnoise::read_tread_pattern(cases.section("tyre"), 0.316, 0.14); });
    if (guarded("read_tyre_rolling_settings",
                [&] { (void)rollnoise::read_tyre_rolling_settings(cases.section("rolling")); })) {
      ++tally.settings;
    }
    if (guarded("make_greens_model", [&] {
          model = rollnoise::make_greens_model(cases.section("tyre"));
          // Use what was built: a model must answer these for any accepted parameters.
          (void)model->name();
          (void)model->point_count();
          (void)model->contact_point_offsets();
          (void)model->fastest_rate();
        })) {
      ++tally.models;
    }
    rollnoise::RollingSettings settings{};
    if (guarded("read_rolling_settings", [&] {
          settings = rollnoise::read_rolling_settings(cases.section("rolling"));
          (void)settings.steps();
        })) {
      ++tally.settings;
      if (model) guarded("check_time_step", [&] { (void)rollnoise::check_time_step(*model, settings.time_step); });
    }
    guarded("reject_unknown_sections",
            [&] { cases.reject_unknown_sections({"tyre", "road", "rolling", "output"}); });
  }
  // The same bytes as a model file (the keys of [tyre] at the top level).
  if (guarded("CaseFile::load_model", [&] {
        const rollnoise::CaseFile model_file = rollnoise::CaseFile::load_model(file, overrides);
        const rollnoise::ConfigTable top = model_file.top();
        if (top.contains("model") && top.text("model") == "plate") (void)rollnoise::read_plate_tyre(top);
        else (void)rollnoise::make_greens_model(top);
      })) {
    ++tally.model_files;
  }
}

void report(const Tally& tally, const std::string& what) {
  std::printf("[ fuzz     ] %s: %d inputs, %d loaded, %d models, %d rolling settings, %d model files\n",
              what.c_str(), tally.inputs, tally.loaded, tally.models, tally.settings, tally.model_files);
  std::string all;
  for (const auto& f : tally.failures) all += "  " + f + "\n";
  EXPECT_TRUE(tally.failures.empty()) << "inputs that neither loaded nor threw InputError:\n" << all;
}

// A temp folder holding the one input file being tried.
class FuzzFolder {
 public:
  explicit FuzzFolder(const std::string& tag)
      : dir_(fs::temp_directory_path() / ("rollnoise_fuzz_" + tag + "_" + std::to_string(::getpid()))),
        input_(dir_ / "input.toml") {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~FuzzFolder() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  FuzzFolder(const FuzzFolder&) = delete;
  FuzzFolder& operator=(const FuzzFolder&) = delete;

  const fs::path& input(const std::string& bytes) const {
    std::ofstream out(input_, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw std::runtime_error("cannot write " + input_.string());
    return input_;
  }

 private:
  fs::path dir_;
  fs::path input_;
};

// ---------------------------------------------------------------------------------------------
// Generators.

using Rng = std::mt19937_64;

std::size_t pick(Rng& rng, std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); }

const std::vector<std::string>& tokens() {
  static const std::vector<std::string> list = {
      "[", "]", "[[", "]]", "{", "}", "=", ",", ".", "\"", "'", "'''", "\"\"\"", "#", "\n", "\r\n", " ",
      "\t", "\\", "\\u0000", "\\U0010FFFF", "\xef\xbb\xbf", "\xff", "\xc3\x28", "\xed\xa0\x80",
      std::string(1, '\0'), "tyre", "road", "rolling", "output", "model", "file", "mass", "damping",
      "stiffness", "contact_stiffness", "coupling", "spacing", "speed", "duration", "time_step",
      "static_load", "history", "discretisation", "type", "amplitude", "wavelength", "std_dev", "seed",
      "correlation_length", "plots", "directory", "\"sdof\"", "\"coupled_sdof\"", "\"sine\"", "\"file\"",
      "\"modal\"", "\"direct\"", "\"step\"", "nan", "+nan", "-nan", "inf", "+inf", "-inf", "0", "-0",
      "-1", "1", "0.5", "1.5", "1e-300", "1e300", "1e-400", "1e400", "4.9e-324", "1.7976931348623157e308",
      "9223372036854775807", "-9223372036854775808", "99999999999999999999", "0x7fffffffffffffff",
      "0o777", "0b1", "1_000", "true", "false", "1979-05-27T07:32:00Z", "07:32:00", "[]", "{}",
      "[1, 2]", "{a = 1}", "\"x\"", "''", "a.b.c", "\"\\ud800\""};
  return list;
}

// Values that sit on the edges of what the readers accept.
const std::vector<std::string>& values() {
  static const std::vector<std::string> list = {
      "nan", "-nan", "inf", "-inf", "0", "-0.0", "-1", "1e-320", "1e308", "1e-300", "1e300",
      "9223372036854775807", "-9223372036854775808", "0.99999999", "-0.99999999", "1", "2",
      "1e-4", "5e-3", "0.05", "20000000", "1e7", "\"\"", "\"sdof\"", "\"coupled_sdof\"",
      "\"flat\"", "\"sine\"", "\"random\"", "\"file\"", "\"auto\"", "\"direct\"", "\"modal\"",
      "\"fft\"", "\"rectangle\"", "true", "[1.0]", "{x = 1}", "1979-05-27"};
  return list;
}

std::string random_bytes(Rng& rng) {
  std::string s(pick(rng, 600), '\0');
  for (auto& c : s) c = static_cast<char>(pick(rng, 256));
  return s;
}

// Random text over a TOML-ish alphabet.
std::string random_toml_chars(Rng& rng) {
  static const std::string alphabet = "[]{}=.,\"'#\n \t_-+:0123456789eEabcdefinstuxyz\\";
  std::string s(pick(rng, 400), ' ');
  for (auto& c : s) c = alphabet[pick(rng, alphabet.size())];
  return s;
}

// Random sequences of TOML tokens and the readers' keys and values.
std::string token_soup(Rng& rng) {
  std::string s;
  const std::size_t n = pick(rng, 80);
  for (std::size_t i = 0; i < n; ++i) s += tokens()[pick(rng, tokens().size())];
  return s;
}

// Mostly well-formed: section headers, known keys, edge values.
std::string structured(Rng& rng) {
  static const std::vector<std::string> sections = {"tyre", "road", "rolling", "output", "tyre.x", "[tyre]"};
  static const std::vector<std::string> keys = {
      "model", "mass", "damping", "stiffness", "contact_stiffness", "coupling", "spacing", "speed",
      "duration", "time_step", "static_load", "history", "discretisation", "type", "file", "x"};
  std::string s;
  const std::size_t n = 1 + pick(rng, 5);
  for (std::size_t i = 0; i < n; ++i) {
    s += "[" + sections[pick(rng, sections.size())] + "]\n";
    const std::size_t k = pick(rng, 8);
    for (std::size_t j = 0; j < k; ++j) {
      s += keys[pick(rng, keys.size())] + " = " + values()[pick(rng, values().size())] + "\n";
    }
  }
  return s;
}

std::string mutate(std::string s, Rng& rng) {
  const std::size_t count = 1 + pick(rng, 6);
  for (std::size_t m = 0; m < count; ++m) {
    const std::size_t size = s.size();
    switch (pick(rng, 10)) {
      case 0:  // flip a bit
        if (size) s[pick(rng, size)] = static_cast<char>(s[pick(rng, size)] ^ (1 << pick(rng, 8)));
        break;
      case 1:  // set a byte
        if (size) s[pick(rng, size)] = static_cast<char>(pick(rng, 256));
        break;
      case 2:  // insert a byte
        s.insert(s.begin() + static_cast<std::ptrdiff_t>(pick(rng, size + 1)), static_cast<char>(pick(rng, 256)));
        break;
      case 3:  // delete a range
        if (size) {
          const std::size_t at = pick(rng, size);
          s.erase(at, 1 + pick(rng, std::min<std::size_t>(size - at, 16)));
        }
        break;
      case 4:  // insert a token
        s.insert(pick(rng, size + 1), tokens()[pick(rng, tokens().size())]);
        break;
      case 5: {  // replace the value of a line "key = value" with an edge value
        std::vector<std::size_t> eqs;
        for (std::size_t i = 0; i < size; ++i)
          if (s[i] == '=') eqs.push_back(i);
        if (eqs.empty()) break;
        const std::size_t eq = eqs[pick(rng, eqs.size())];
        std::size_t end = s.find_first_of("#\n", eq);
        if (end == std::string::npos) end = size;
        s.replace(eq + 1, end - eq - 1, " " + values()[pick(rng, values().size())] + " ");
        break;
      }
      case 6: {  // duplicate a line somewhere
        if (!size) break;
        const std::size_t start = s.rfind('\n', pick(rng, size));
        const std::size_t from = start == std::string::npos ? 0 : start + 1;
        std::size_t to = s.find('\n', from);
        to = to == std::string::npos ? size : to + 1;
        const std::string line = s.substr(from, to - from);
        s.insert(pick(rng, s.size() + 1), line);
        break;
      }
      case 7: {  // delete a line
        if (!size) break;
        const std::size_t start = s.rfind('\n', pick(rng, size));
        const std::size_t from = start == std::string::npos ? 0 : start + 1;
        std::size_t to = s.find('\n', from);
        to = to == std::string::npos ? size : to + 1;
        s.erase(from, to - from);
        break;
      }
      case 8:  // truncate
        s.resize(pick(rng, size + 1));
        break;
      default: {  // repeat a slice (deep brackets, long strings)
        if (!size) break;
        const std::size_t at = pick(rng, size);
        const std::string slice = s.substr(at, 1 + pick(rng, std::min<std::size_t>(size - at, 8)));
        std::string repeated;
        const std::size_t times = 1 + pick(rng, 300);
        for (std::size_t i = 0; i < times; ++i) repeated += slice;
        s.insert(at, repeated);
        break;
      }
    }
  }
  return s;
}

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".toml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());  // deterministic order
  return files;
}

fs::path project(const std::string& relative) { return fs::path(ROLLNOISE_SOURCE_DIR) / relative; }

// The body of a case's [tyre] table: a model file (keys at the top level).
std::string tyre_table_of(const std::string& text) {
  std::istringstream in(text);
  std::string out;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.front() == '[') {
      inside = line.rfind("[tyre]", 0) == 0;
      continue;
    }
    if (inside) out += line + "\n";
  }
  return out;
}

// The project's cases, their [tyre] tables as model files, and the seed corpus.
std::vector<std::string> seed_texts() {
  std::vector<std::string> texts;
  for (const auto& file : files_in(project("models/cases"))) {
    texts.push_back(read_bytes(file));
    texts.push_back(tyre_table_of(texts.back()));
  }
  // Model files (the plate tyre's keys at the top level).
  for (const auto& file : files_in(project("models/tyres"))) texts.push_back(read_bytes(file));
  for (const auto& file : files_in(project("tests/corpus/toml"))) texts.push_back(read_bytes(file));
  return texts;
}

// ---------------------------------------------------------------------------------------------
// Tests.

TEST(CaseFileFuzz, SeedCorpusLoadsOrThrowsInputError) {
  const auto files = files_in(project("tests/corpus/toml"));
  ASSERT_GE(files.size(), 5u) << "the seed corpus is missing";
  Tally tally;
  for (const auto& file : files) check_one(file, {}, file.filename().string(), tally);
  report(tally, "corpus");
}

TEST(CaseFileFuzz, ProjectCasesLoadAndRead) {
  // The sanity base of the mutations: every real case loads and reads.
  const auto files = files_in(project("models/cases"));
  ASSERT_FALSE(files.empty());
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const rollnoise::CaseFile cases = rollnoise::CaseFile::load(file);
    const std::string model = cases.section("tyre").text("model");
    if (model == "plate") {
      EXPECT_NO_THROW((void)rollnoise::read_plate_tyre(cases.section("tyre")));
      EXPECT_NO_THROW((void)rollnoise::read_tyre_rolling_settings(cases.section("rolling")));
    } else if (model == "two_layer") {
      EXPECT_NO_THROW((void)rollnoise::read_two_layer_tyre(cases.section("tyre")));
      EXPECT_NO_THROW((void)rollnoise::read_tyre_rolling_settings(cases.section("rolling")));
    } else {
      EXPECT_NO_THROW((void)rollnoise::make_greens_model(cases.section("tyre")));
      EXPECT_NO_THROW((void)rollnoise::read_rolling_settings(cases.section("rolling")));
    }
  }
}

TEST(CaseFileFuzz, RandomBytesLoadOrThrowInputError) {
  FuzzFolder folder("bytes");
  Rng rng(0x726f6c6cULL);
  Tally tally;
  for (int i = 0; i < 1000; ++i) {
    std::string input;
    switch (i % 4) {
      case 0: input = random_bytes(rng); break;
      case 1: input = random_toml_chars(rng); break;
      case 2: input = token_soup(rng); break;
      default: input = structured(rng); break;
    }
    check_one(folder.input(input), {}, "random input " + std::to_string(i), tally);
  }
  report(tally, "random");
  EXPECT_GT(tally.loaded, 50) << "the generators should reach past the parser";
}

TEST(CaseFileFuzz, MutatedCaseFilesLoadOrThrowInputError) {
  FuzzFolder folder("mutations");
  const std::vector<std::string> seeds = seed_texts();
  ASSERT_FALSE(seeds.empty());
  Rng rng(0x6e6f697365ULL);
  Tally tally;
  for (int i = 0; i < 2000; ++i) {
    const std::string input = mutate(seeds[pick(rng, seeds.size())], rng);
    check_one(folder.input(input), {}, "mutation " + std::to_string(i), tally);
  }
  report(tally, "mutations");
  // Small mutations of good cases must often still load, and sometimes still read: otherwise
  // the fuzz never reaches the model and rolling readers.
  EXPECT_GT(tally.loaded, 200);
  EXPECT_GT(tally.models, 20);
  EXPECT_GT(tally.settings, 20);
  EXPECT_GT(tally.model_files, 20);
}

TEST(CaseFileFuzz, RandomOverridesLoadOrThrowInputError) {
  FuzzFolder folder("overrides");
  const std::string base = read_bytes(project("models/cases/larsson2000_coupled_sine.toml"));
  static const std::vector<std::string> paths = {
      "tyre.mass", "tyre.coupling", "tyre.model", "tyre.file", "tyre", "rolling.time_step",
      "rolling.duration", "rolling.history", "rolling", "road.type", "x.y.z", "tyre.mass.x", ".",
      "a..b", "rolling.", ".rolling", "", "tyre.\xff", "output.directory", "tyre.spacing"};
  static const std::vector<std::string> override_values = {
      "1", "nan", "-inf", "\"s\"", "bare words", "[1,2]", "{a=1}", "{}", "", "=", "\xff\xfe",
      "1e999", "0", "-1", "0.999999", "sdof", "coupled_sdof", "modal", ".", "/",
      "no_such_model.toml", "\"\"", "[", "\"unterminated", "1 # comment", "\n[evil]\nx=1"};
  Rng rng(0x736574ULL);
  Tally tally;
  const fs::path& file = folder.input(base);
  for (int i = 0; i < 600; ++i) {
    std::vector<std::string> overrides;
    const std::size_t n = 1 + pick(rng, 3);
    for (std::size_t j = 0; j < n; ++j) {
      const std::string& path = paths[pick(rng, paths.size())];
      const std::string& value = override_values[pick(rng, override_values.size())];
      switch (pick(rng, 8)) {
        case 0: overrides.push_back(path); break;  // no '='
        case 1: overrides.push_back("=" + value); break;
        default: overrides.push_back(path + "=" + value); break;
      }
    }
    check_one(file, overrides, "overrides " + std::to_string(i), tally);
  }
  report(tally, "overrides");
  EXPECT_GT(tally.loaded, 50);
}

}  // namespace
