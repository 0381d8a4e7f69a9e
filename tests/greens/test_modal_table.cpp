// The modal receptance table (src/greens/modal_receptance_table.hpp) and its HDF5 file
// (modal_table_hdf5.hpp), cache (modal_table_cache.hpp) and model (tabulated_factory.hpp):
//   - the two-layer table is TwoLayerTyre::modal_compliance's H_zz entry by entry, beyond the
//     tyre's own circumferential_modes too, for both side conditions, and does not depend on the
//     number of threads;
//   - a written table reads back bit for bit;
//   - every malformed file (missing or misshaped datasets and attributes, NaN and infinite
//     values, bad frequencies, an unknown layout, garbage and truncated bytes) is an InputError
//     naming the file and the dataset or attribute;
//   - the cache: a hit returns the same table, any change of a parameter (by one ulp) misses, a
//     corrupt cache file is recomputed and overwritten; the key is stable;
//   - the `tabulated` model file, and its centre-line view (`rollnoise greens`): a table written
//     from a two-layer model gives that model's receptance and step means, within the pole fit.
// Small tables (a few modes and frequencies) keep it fast; the passenger tyre's timing is a
// disabled test (run it with --gtest_also_run_disabled_tests).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <variant>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "core/case_file.hpp"
#include "core/error.hpp"
#include "core/hdf5_reader.hpp"
#include "core/hdf5_writer.hpp"
#include "greens/centre_line_response.hpp"
#include "greens/fitted_modal_tyre.hpp"
#include "greens/modal_receptance_table.hpp"
#include "greens/modal_table_cache.hpp"
#include "greens/modal_table_hdf5.hpp"
#include "greens/tabulated_factory.hpp"
#include "greens/two_layer_factory.hpp"
#include "greens/two_layer_tyre.hpp"
#include "road/road_test_support.hpp"
#include "two_layer_test_support.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;
using cd = std::complex<double>;

template <class F>
std::string input_error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

Eigen::VectorXd small_frequencies() {
  Eigen::VectorXd f(5);
  f << 0.0, 10.0, 100.0, 1000.0, 10000.0;
  return f;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Every field equal, the values bit for bit (source apart).
void expect_same_table(const ModalReceptanceTable& a, const ModalReceptanceTable& b) {
  EXPECT_TRUE(same_bits(a.radius, b.radius));
  EXPECT_TRUE(same_bits(a.width, b.width));
  EXPECT_EQ(a.lateral_shape, b.lateral_shape);
  EXPECT_EQ(a.first_lateral_order, b.first_lateral_order);
  EXPECT_EQ(a.lateral_orders, b.lateral_orders);
  EXPECT_EQ(a.orders, b.orders);
  ASSERT_EQ(a.frequency.size(), b.frequency.size());
  for (Eigen::Index k = 0; k < a.frequency.size(); ++k) EXPECT_TRUE(same_bits(a.frequency(k), b.frequency(k)));
  ASSERT_EQ(a.modes.size(), b.modes.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.modes.size(); ++i) {
    ASSERT_EQ(a.modes[i].size(), b.modes[i].size());
    for (Eigen::Index k = 0; k < a.modes[i].size(); ++k) {
      if (!same_bits(a.modes[i](k).real(), b.modes[i](k).real()) ||
          !same_bits(a.modes[i](k).imag(), b.modes[i](k).imag())) {
        ++differing;
      }
    }
  }
  EXPECT_EQ(differing, 0u);
}

class ModalTableHdf5 : public ::testing::Test {
 protected:
  // A valid little table: the small tyre, simply supported, orders beyond its own M.
  static const ModalReceptanceTable& small_table() {
    static const ModalReceptanceTable table =
        tabulate_two_layer(TwoLayerTyre(test::tyre_like_two_layer(4, 3)), small_frequencies(), 6);
    return table;
  }

  // The pieces of a file in the layout, to be spoilt one at a time.
  struct Dataset {
    std::variant<Eigen::VectorXd, Eigen::MatrixXd, std::vector<std::int64_t>> data;
    std::string units;
  };
  struct RawFile {
    std::map<std::string, std::string> texts;
    std::map<std::string, double> numbers;
    std::map<std::string, std::int64_t> integers;
    std::map<std::string, Dataset> datasets;
  };
  static RawFile raw_of(const ModalReceptanceTable& t) {
    RawFile raw;
    raw.texts = {{"layout", std::string(modal_table_layout)}, {"form", "modal"},
                 {"lateral_shape", t.lateral_shape == LateralShape::sine ? "sine" : "cosine"}, {"source", "test"}};
    raw.numbers = {{"radius_m", t.radius}, {"width_m", t.width}};
    raw.integers = {{"first_lateral_order", t.first_lateral_order}};
    std::vector<std::int64_t> order, lateral;
    for (int m = 0; m <= t.orders; ++m) order.push_back(m);
    for (int n = t.first_lateral_order; n <= t.last_lateral_order(); ++n) lateral.push_back(n);
    Eigen::MatrixXd re(static_cast<Eigen::Index>(t.modes.size()), t.frequency.size());
    Eigen::MatrixXd im(re.rows(), re.cols());
    for (std::size_t i = 0; i < t.modes.size(); ++i) {
      re.row(static_cast<Eigen::Index>(i)) = t.modes[i].real().transpose();
      im.row(static_cast<Eigen::Index>(i)) = t.modes[i].imag().transpose();
    }
    raw.datasets = {{"/frequency", {t.frequency, "Hz"}},
                    {"/order", {order, "1"}},
                    {"/lateral_order", {lateral, "1"}},
                    {"/receptance_re", {re, "m/Pa"}},
                    {"/receptance_im", {im, "m/Pa"}}};
    return raw;
  }
  fs::path write_raw(const std::string& name, const RawFile& raw) const {
    const fs::path path = temp_.path() / name;
    Hdf5Writer h5(path);
    for (const auto& [key, value] : raw.texts) h5.attribute("/", key, value);
    for (const auto& [key, value] : raw.numbers) h5.attribute("/", key, value);
    for (const auto& [key, value] : raw.integers) h5.integer_attribute("/", key, value);
    for (const auto& [key, d] : raw.datasets) {
      if (const auto* v = std::get_if<Eigen::VectorXd>(&d.data)) h5.write(key, *v, d.units, "");
      if (const auto* m = std::get_if<Eigen::MatrixXd>(&d.data)) h5.write(key, *m, d.units, "");
      if (const auto* i = std::get_if<std::vector<std::int64_t>>(&d.data)) h5.write_integers(key, *i, d.units, "");
    }
    return path;
  }
  static std::string bytes_of(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }

  test::TempFolder temp_{"rollnoise_test_modal_table_"};
};

TEST(ModalTableFrequencies, DefaultFitFrequenciesAreZeroAndLogSpacedTo50kHz) {
  const Eigen::VectorXd f = default_fit_frequencies();
  ASSERT_EQ(f.size(), 121);
  EXPECT_EQ(f(0), 0.0);
  EXPECT_EQ(f(1), 1.0);
  EXPECT_EQ(f(120), 5.0e4);
  const double step = std::log(5.0e4) / 119.0;
  for (Eigen::Index k = 2; k < f.size(); ++k) {
    EXPECT_GT(f(k), f(k - 1));
    EXPECT_NEAR(std::log(f(k) / f(k - 1)), step, 1e-12);
  }
}

TEST(TwoLayerModalTable, EqualsTheModalComplianceEntryByEntry) {
  for (const SideCondition side : {SideCondition::simply_supported, SideCondition::sliding}) {
    TwoLayerParameters p = test::tyre_like_two_layer(4, 3);
    p.side_condition = side;
    const TwoLayerTyre tyre(p);
    const Eigen::VectorXd f = small_frequencies();
    const int orders = 7;  // beyond the tyre's own M = 4
    const ModalReceptanceTable table = tabulate_two_layer(tyre, f, orders);
    const bool sine = side == SideCondition::simply_supported;
    EXPECT_EQ(table.lateral_shape, sine ? LateralShape::sine : LateralShape::cosine);
    EXPECT_EQ(table.first_lateral_order, sine ? 1 : 0);
    EXPECT_EQ(table.lateral_orders, 3);
    EXPECT_EQ(table.orders, orders);
    EXPECT_EQ(table.source, "two_layer");
    ASSERT_EQ(table.modes.size(), 3u * 8u);
    for (int n = table.first_lateral_order; n <= table.last_lateral_order(); ++n) {
      EXPECT_EQ(table.modal_norm(n), tyre.modal_norm(n));
      for (const double y : {0.0, 0.031, 0.09, 0.18}) {
        EXPECT_EQ(table.lateral_shape_value(n, y), tyre.lateral_shape(SurfaceDirection::z, n, y));
      }
      for (int m = 0; m <= orders; ++m) {
        EXPECT_EQ(table.mode_index(m, n), static_cast<std::size_t>((n - table.first_lateral_order) * 8 + m));
        for (Eigen::Index k = 0; k < f.size(); ++k) {
          const cd omega(2.0 * std::numbers::pi * f(k), 0.0);
          EXPECT_EQ(table.mode(m, n)(k), tyre.modal_compliance(m, n, omega)(2, 2)) << m << " " << n << " " << k;
        }
      }
    }
    // The same through the one-frequency response (which holds m ≤ M only).
    const TwoLayerResponse response = tyre.response(cd(2.0 * std::numbers::pi * f(3), 0.0));
    for (int n = table.first_lateral_order; n <= table.last_lateral_order(); ++n) {
      for (int m = 0; m <= 4; ++m) EXPECT_EQ(table.mode(m, n)(3), response.modal_compliance(m, n)(2, 2));
    }
    // The static entry is a finite, positive compliance (the sliding uniform mode included).
    EXPECT_GT(table.mode(0, table.first_lateral_order)(0).real(), 0.0);
    EXPECT_THROW((void)table.mode(orders + 1, table.first_lateral_order), std::out_of_range);
    EXPECT_THROW((void)table.mode(0, table.last_lateral_order() + 1), std::out_of_range);
  }
}

TEST(TwoLayerModalTable, DoesNotDependOnTheThreadCount) {
  const TwoLayerTyre tyre(test::tyre_like_two_layer(4, 3));
  const ModalReceptanceTable one = tabulate_two_layer(tyre, small_frequencies(), 5, 1);
  const ModalReceptanceTable three = tabulate_two_layer(tyre, small_frequencies(), 5, 3);
  expect_same_table(one, three);
}

TEST(TwoLayerModalTable, RejectsBadArguments) {
  const TwoLayerTyre tyre(test::tyre_like_two_layer(2, 2));
  Eigen::VectorXd backwards(3);
  backwards << 0.0, 20.0, 10.0;
  EXPECT_THROW(tabulate_two_layer(tyre, backwards, 2), std::invalid_argument);
  EXPECT_THROW(tabulate_two_layer(tyre, Eigen::VectorXd::Constant(1, -1.0), 2), std::invalid_argument);
  EXPECT_THROW(tabulate_two_layer(tyre, Eigen::VectorXd(), 2), std::invalid_argument);
  EXPECT_THROW(tabulate_two_layer(tyre, small_frequencies(), -1), std::invalid_argument);
}

TEST_F(ModalTableHdf5, RoundTripIsBitExact) {
  for (const SideCondition side : {SideCondition::simply_supported, SideCondition::sliding}) {
    TwoLayerParameters p = test::tyre_like_two_layer(3, 2);
    p.side_condition = side;
    const ModalReceptanceTable table = tabulate_two_layer(TwoLayerTyre(p), small_frequencies(), 4);
    const fs::path path = temp_.path() / "table.h5";
    write_modal_table(path, table);
    const ModalReceptanceTable back = read_modal_table(path);
    expect_same_table(table, back);
    EXPECT_EQ(back.source, path.string());
    // The attributes as the layout documents them, for other programs.
    const Hdf5Reader file(path);
    EXPECT_EQ(file.string_attribute("/", "layout"), std::string(modal_table_layout));
    EXPECT_EQ(file.string_attribute("/", "form"), "modal");
    EXPECT_EQ(file.string_attribute("/", "source"), "two_layer");
    EXPECT_EQ(file.number_attribute("/", "first_lateral_order"), side == SideCondition::sliding ? 0.0 : 1.0);
    EXPECT_EQ(file.string_attribute("/receptance_im", "units"), "m/Pa");
    // Atomic: nothing but the table is left in the folder.
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(temp_.path())) files += entry.is_regular_file() ? 1 : 0;
    EXPECT_EQ(files, 1u);
  }
}

TEST_F(ModalTableHdf5, ReadsAFileWrittenByAnotherProgram) {
  // Integer and double types swapped relative to this writer, no source attribute.
  RawFile raw = raw_of(small_table());
  raw.texts.erase("source");
  raw.numbers["first_lateral_order"] = 1.0;
  raw.integers.erase("first_lateral_order");
  Eigen::VectorXd order = Eigen::VectorXd::LinSpaced(small_table().orders + 1, 0.0, small_table().orders);
  raw.datasets["/order"] = {order, ""};
  const fs::path path = write_raw("other.h5", raw);
  const ModalReceptanceTable back = read_modal_table(path);
  expect_same_table(small_table(), back);
}

TEST_F(ModalTableHdf5, EveryMalformedFileNamesTheFileAndThePlace) {
  struct Case {
    std::string name;
    std::function<void(RawFile&)> spoil;
    std::string place;    // the dataset or attribute named
    std::string problem;  // a part of what is said
  };
  const auto nan = std::numeric_limits<double>::quiet_NaN();
  const auto inf = std::numeric_limits<double>::infinity();
  const auto matrix_of = [](RawFile& r, const std::string& key) -> Eigen::MatrixXd& {
    return std::get<Eigen::MatrixXd>(r.datasets.at(key).data);
  };
  const auto vector_of = [](RawFile& r, const std::string& key) -> Eigen::VectorXd& {
    return std::get<Eigen::VectorXd>(r.datasets.at(key).data);
  };
  const std::vector<Case> cases = {
      {"no_layout", [](RawFile& r) { r.texts.erase("layout"); }, "/ attribute layout", "is missing"},
      {"layout_v2", [](RawFile& r) { r.texts["layout"] = "rollnoise modal receptance v2"; }, "/ attribute layout",
       "this reader knows"},
      {"form", [](RawFile& r) { r.texts["form"] = "spatial"; }, "/ attribute form", "\"modal\" only"},
      {"no_form", [](RawFile& r) { r.texts.erase("form"); }, "/ attribute form", "is missing"},
      {"radius_zero", [](RawFile& r) { r.numbers["radius_m"] = 0.0; }, "/ attribute radius_m", "> 0"},
      {"radius_nan", [nan](RawFile& r) { r.numbers["radius_m"] = nan; }, "/ attribute radius_m", "finite"},
      {"no_radius", [](RawFile& r) { r.numbers.erase("radius_m"); }, "/ attribute radius_m", "is missing"},
      {"radius_text", [](RawFile& r) { r.numbers.erase("radius_m"); r.texts["radius_m"] = "0.3"; },
       "/ attribute radius_m", "must be a number"},
      {"width_negative", [](RawFile& r) { r.numbers["width_m"] = -0.18; }, "/ attribute width_m", "> 0"},
      {"shape", [](RawFile& r) { r.texts["lateral_shape"] = "square"; }, "/ attribute lateral_shape",
       "\"sine\" and \"cosine\""},
      {"sine_from_zero",
       [](RawFile& r) {
         r.integers["first_lateral_order"] = 0;
         r.datasets["/lateral_order"] = {std::vector<std::int64_t>{0, 1, 2}, "1"};
       },
       "/ attribute first_lateral_order", ">= 1"},
      {"first_half", [](RawFile& r) { r.integers.erase("first_lateral_order"); r.numbers["first_lateral_order"] = 1.5; },
       "/ attribute first_lateral_order", "integer"},
      {"no_frequency", [](RawFile& r) { r.datasets.erase("/frequency"); }, "/frequency", "no such dataset"},
      {"frequency_2d", [](RawFile& r) { r.datasets["/frequency"] = {Eigen::MatrixXd(Eigen::MatrixXd::Ones(2, 3)), "Hz"}; }, "/frequency",
       "dimensions"},
      {"frequency_nan", [&](RawFile& r) { vector_of(r, "/frequency")(2) = nan; }, "/frequency[2]", "finite"},
      {"frequency_negative", [&](RawFile& r) { vector_of(r, "/frequency")(0) = -1.0; }, "/frequency[0]", ">= 0"},
      {"frequency_backwards", [&](RawFile& r) { vector_of(r, "/frequency")(3) = 50.0; }, "/frequency[3]",
       "strictly increasing"},
      {"frequency_repeated", [&](RawFile& r) { vector_of(r, "/frequency")(2) = 10.0; }, "/frequency[2]",
       "strictly increasing"},
      {"frequency_rad_s", [](RawFile& r) { r.datasets["/frequency"].units = "rad/s"; }, "/frequency attribute units",
       "\"Hz\""},
      {"no_order", [](RawFile& r) { r.datasets.erase("/order"); }, "/order", "no such dataset"},
      {"order_gap", [](RawFile& r) { r.datasets["/order"] = {std::vector<std::int64_t>{0, 2, 3, 4, 5, 6, 7}, "1"}; },
       "/order[1]", "steps of 1"},
      {"lateral_shifted", [](RawFile& r) { r.datasets["/lateral_order"] = {std::vector<std::int64_t>{2, 3, 4}, "1"}; },
       "/lateral_order[0]", "first_lateral_order"},
      {"no_re", [](RawFile& r) { r.datasets.erase("/receptance_re"); }, "/receptance_re", "no such dataset"},
      {"no_im", [](RawFile& r) { r.datasets.erase("/receptance_im"); }, "/receptance_im", "no such dataset"},
      {"re_transposed",
       [&](RawFile& r) { matrix_of(r, "/receptance_re") = Eigen::MatrixXd(matrix_of(r, "/receptance_re").transpose()); },
       "/receptance_re", "transposed"},
      {"im_short_rows", [&](RawFile& r) { matrix_of(r, "/receptance_im") = Eigen::MatrixXd::Zero(20, 5); },
       "/receptance_im", "[mode][frequency], 21 x 5"},
      {"re_1d", [](RawFile& r) { r.datasets["/receptance_re"] = {Eigen::VectorXd(Eigen::VectorXd::Zero(105)), "m/Pa"}; },
       "/receptance_re", "has shape 105"},
      {"re_inf", [&](RawFile& r) { matrix_of(r, "/receptance_re")(1, 2) = inf; }, "/receptance_re[1][2]", "finite"},
      {"im_nan", [&](RawFile& r) { matrix_of(r, "/receptance_im")(20, 4) = nan; }, "/receptance_im[20][4]", "finite"},
      {"re_units", [](RawFile& r) { r.datasets["/receptance_re"].units = "m/N"; }, "/receptance_re attribute units",
       "\"m/Pa\""},
      {"source_number", [](RawFile& r) { r.texts.erase("source"); r.numbers["source"] = 1.0; }, "/ attribute source",
       "must be a string"},
  };
  for (const Case& c : cases) {
    RawFile raw = raw_of(small_table());
    c.spoil(raw);
    const fs::path path = write_raw("bad_" + c.name + ".h5", raw);
    const std::string message = input_error_of([&] { (void)read_modal_table(path); });
    EXPECT_MENTIONS(message, path.string() + ": " + c.place + ": ") << c.name;
    EXPECT_MENTIONS(message, c.problem) << c.name;
  }
}

TEST_F(ModalTableHdf5, GarbageAndTruncatedFilesAreInputErrors) {
  const fs::path good = temp_.path() / "good.h5";
  write_modal_table(good, small_table());
  const std::string bytes = bytes_of(good);
  std::string scrambled = bytes;
  for (std::size_t i = 64; i < scrambled.size(); i += 7) scrambled[i] = static_cast<char>(scrambled[i] ^ 0x5a);
  std::string noise(bytes.size(), '\0');
  for (std::size_t i = 0; i < noise.size(); ++i) noise[i] = static_cast<char>((i * 2654435761u) >> 13);
  const std::vector<std::pair<std::string, std::string>> files = {
      {"cut_half.h5", bytes.substr(0, bytes.size() / 2)},
      {"cut_end.h5", bytes.substr(0, bytes.size() - 100)},
      {"cut_signature.h5", bytes.substr(0, 8)},
      {"scrambled.h5", scrambled},
      {"signature_then_noise.h5", bytes.substr(0, 8) + noise},
      {"noise.h5", noise},
      {"text.h5", "frequency,re,im\n0,1,0\n"},
      {"empty.h5", ""},
  };
  for (const auto& [name, content] : files) {
    const fs::path path = temp_.write(name, content);
    const std::string message = input_error_of([&] { (void)read_modal_table(path); });
    EXPECT_MENTIONS(message, path.string()) << name;
  }
  EXPECT_MENTIONS(input_error_of([&] { (void)read_modal_table(temp_.path() / "absent.h5"); }), "absent.h5");

  // Random bytes spoilt anywhere, metadata or data: an InputError naming the file, or (values
  // hit that still look like numbers) a valid table, never a crash or another exception.
  std::mt19937 random(20240611u);
  std::size_t errors = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::string spoilt = bytes;
    std::uniform_int_distribution<std::size_t> where(8, spoilt.size() - 1);
    for (int k = 0; k < 8; ++k) spoilt[where(random)] = static_cast<char>(random());
    const fs::path path = temp_.write("fuzz.h5", spoilt);
    try {
      read_modal_table(path).validate();
    } catch (const InputError& e) {
      ++errors;
      EXPECT_EQ(e.source(), path.string()) << e.what();
    }
  }
  EXPECT_GT(errors, 0u);
}

TEST_F(ModalTableHdf5, WritingRejectsAnInvalidTable) {
  ModalReceptanceTable table = small_table();
  table.frequency(2) = table.frequency(1);
  EXPECT_THROW(write_modal_table(temp_.path() / "x.h5", table), InputError);
  EXPECT_FALSE(fs::exists(temp_.path() / "x.h5"));
  table = small_table();
  table.modes.pop_back();
  EXPECT_THROW(write_modal_table(temp_.path() / "x.h5", table), InputError);
  EXPECT_THROW(write_modal_table(temp_.path() / "no_folder" / "x.h5", small_table()), std::runtime_error);
}

// Sets an environment variable for the life of the object, then restores it.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) {
      ::setenv(name, value, 1);
    } else {
      ::unsetenv(name);
    }
  }
  ~ScopedVariable() {
    if (old_) {
      ::setenv(name_.c_str(), old_->c_str(), 1);
    } else {
      ::unsetenv(name_.c_str());
    }
  }
  ScopedVariable(const ScopedVariable&) = delete;
  ScopedVariable& operator=(const ScopedVariable&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

TEST(ModalTableCache, CacheDirectoryFollowsTheEnvironment) {
  {
    const ScopedVariable own("ROLLNOISE_CACHE", "/tmp/own_cache");
    const ScopedVariable xdg("XDG_CACHE_HOME", "/tmp/xdg");
    const ScopedVariable home("HOME", "/home/someone");
    EXPECT_EQ(default_cache_directory(), fs::path("/tmp/own_cache"));
  }
  {
    const ScopedVariable own("ROLLNOISE_CACHE", nullptr);
    const ScopedVariable xdg("XDG_CACHE_HOME", "/tmp/xdg");
    const ScopedVariable home("HOME", "/home/someone");
    EXPECT_EQ(default_cache_directory(), fs::path("/tmp/xdg/rollnoise"));
  }
  {
    const ScopedVariable own("ROLLNOISE_CACHE", "");
    const ScopedVariable xdg("XDG_CACHE_HOME", "relative/is/ignored");
    const ScopedVariable home("HOME", "/home/someone");
    EXPECT_EQ(default_cache_directory(), fs::path("/home/someone/.cache/rollnoise"));
  }
  {
    const ScopedVariable own("ROLLNOISE_CACHE", nullptr);
    const ScopedVariable xdg("XDG_CACHE_HOME", nullptr);
    const ScopedVariable home("HOME", nullptr);
    EXPECT_EQ(default_cache_directory(), std::nullopt);
  }
}

TEST(ModalTableCache, KeyIsStableAndChangesWithEveryParameter) {
  const TwoLayerParameters base = test::tyre_like_two_layer(3, 2);
  const Eigen::VectorXd f = small_frequencies();
  const std::string key = two_layer_table_key(base, 4, f);
  EXPECT_EQ(two_layer_table_key(base, 4, f), key);
  EXPECT_EQ(two_layer_table_key(TwoLayerParameters(base), 4, Eigen::VectorXd(f)), key);
  EXPECT_EQ(key.rfind("two_layer-", 0), 0u);
  EXPECT_EQ(key.size(), 26u);
  // Every double by one unit in the last place.
  const auto up = [](double& v) { v = std::nextafter(v, std::numeric_limits<double>::infinity()); };
  const std::vector<std::function<void(TwoLayerParameters&)>> changes = {
      [&](TwoLayerParameters& p) { up(p.radius); }, [&](TwoLayerParameters& p) { up(p.width); },
      [&](TwoLayerParameters& p) { up(p.belt.youngs_x); }, [&](TwoLayerParameters& p) { up(p.belt.youngs_y); },
      [&](TwoLayerParameters& p) { up(p.belt.youngs_z); }, [&](TwoLayerParameters& p) { up(p.belt.shear_xy); },
      [&](TwoLayerParameters& p) { up(p.belt.shear_xz); }, [&](TwoLayerParameters& p) { up(p.belt.shear_yz); },
      [&](TwoLayerParameters& p) { up(p.belt.poisson_xy); }, [&](TwoLayerParameters& p) { up(p.belt.poisson_xz); },
      [&](TwoLayerParameters& p) { up(p.belt.poisson_yz); }, [&](TwoLayerParameters& p) { up(p.belt_thickness); },
      [&](TwoLayerParameters& p) { up(p.belt_density); }, [&](TwoLayerParameters& p) { up(p.belt_loss_factor); },
      [&](TwoLayerParameters& p) { up(p.tread_thickness); }, [&](TwoLayerParameters& p) { up(p.tread_density); },
      [&](TwoLayerParameters& p) { up(p.tread_youngs_modulus); },
      [&](TwoLayerParameters& p) { up(p.tread_poisson_ratio); },
      [&](TwoLayerParameters& p) { up(p.tread_loss_factor); }, [&](TwoLayerParameters& p) { up(p.tension_x); },
      [&](TwoLayerParameters& p) { up(p.tension_y); }, [&](TwoLayerParameters& p) { up(p.foundation_stiffness); },
      [&](TwoLayerParameters& p) { up(p.foundation_loss_factor); },
      [](TwoLayerParameters& p) { p.circumferential_modes += 1; },
      [](TwoLayerParameters& p) { p.lateral_modes += 1; },
      [](TwoLayerParameters& p) { p.side_condition = SideCondition::sliding; },
  };
  for (std::size_t i = 0; i < changes.size(); ++i) {
    TwoLayerParameters p = base;
    changes[i](p);
    EXPECT_NE(two_layer_table_key(p, 4, f), key) << "change " << i;
  }
  // The contact geometry does not shape the table: the same key.
  TwoLayerParameters contact = base;
  contact.crown_radius = 0.5;
  contact.tread_width = 0.15;
  EXPECT_EQ(two_layer_table_key(contact, 4, f), key);
  EXPECT_NE(two_layer_table_key(base, 5, f), key);
  Eigen::VectorXd g = f;
  up(g(2));
  EXPECT_NE(two_layer_table_key(base, 4, g), key);
  EXPECT_NE(two_layer_table_key(base, 4, f.head(4)), key);
}

TEST(ModalTableCache, HitMissAndCorruptFile) {
  const test::TempFolder temp("rollnoise_test_modal_cache_");
  const fs::path directory = temp.path() / "cache" / "rollnoise";  // created on the first store
  const TwoLayerTyre tyre(test::tyre_like_two_layer(3, 2));
  const Eigen::VectorXd f = small_frequencies();
  const std::string key = two_layer_table_key(tyre.parameters(), 4, f);
  const fs::path file = directory / (key + ".h5");
  EXPECT_EQ(load_cached_table(directory, key), std::nullopt);

  const ModalReceptanceTable computed = cached_two_layer_table(tyre, f, 4, directory);
  EXPECT_EQ(computed.source, "two_layer");
  ASSERT_TRUE(fs::exists(file));
  const ModalReceptanceTable hit = cached_two_layer_table(tyre, f, 4, directory);
  EXPECT_EQ(hit.source, file.string());
  expect_same_table(computed, hit);
  ASSERT_TRUE(load_cached_table(directory, key).has_value());

  // A changed parameter misses and adds its own file.
  TwoLayerParameters changed = tyre.parameters();
  changed.tread_loss_factor = 0.11;
  const ModalReceptanceTable other = cached_two_layer_table(TwoLayerTyre(changed), f, 4, directory);
  EXPECT_EQ(other.source, "two_layer");
  EXPECT_NE(other.mode(1, 1)(3), computed.mode(1, 1)(3));
  EXPECT_TRUE(fs::exists(directory / (two_layer_table_key(changed, 4, f) + ".h5")));

  // A corrupt file is a miss: recomputed, overwritten, then a hit again.
  for (const std::string& corrupt : {std::string("garbage"), std::string("\x89HDF\r\n\x1a\n", 8) + "garbage"}) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << corrupt;
    EXPECT_EQ(load_cached_table(directory, key), std::nullopt);
    const ModalReceptanceTable again = cached_two_layer_table(tyre, f, 4, directory);
    EXPECT_EQ(again.source, "two_layer");
    expect_same_table(computed, again);
    EXPECT_EQ(cached_two_layer_table(tyre, f, 4, directory).source, file.string());
  }
  // A valid table under the wrong key (another tyre's) is not taken.
  fs::copy_file(directory / (two_layer_table_key(changed, 4, f) + ".h5"), file, fs::copy_options::overwrite_existing);
  EXPECT_EQ(cached_two_layer_table(tyre, f, 4, directory).source, "two_layer");
  // No cache folder: computed.
  EXPECT_EQ(cached_two_layer_table(tyre, f, 4, std::nullopt).source, "two_layer");
  // A cache that cannot be written is no error.
  const fs::path blocked = temp.write("blocked", "a file, not a folder");
  EXPECT_EQ(cached_two_layer_table(tyre, f, 4, blocked / "sub").source, "two_layer");
  EXPECT_THROW(store_cached_table(blocked / "sub", key, computed), std::runtime_error);
  // Keys are plain file names.
  EXPECT_THROW((void)load_cached_table(directory, "../escape"), std::invalid_argument);
  EXPECT_THROW((void)load_cached_table(directory, ""), std::invalid_argument);
}

TEST(TabulatedTyre, ModelFileReadsTheTableBesideIt) {
  const test::TempFolder temp("rollnoise_test_tabulated_");
  const ModalReceptanceTable table =
      tabulate_two_layer(TwoLayerTyre(test::tyre_like_two_layer(2, 2)), small_frequencies(), 3);
  fs::create_directories(temp.path() / "tables");
  write_modal_table(temp.path() / "tables" / "tyre.h5", table);
  // Relative to the model file's folder, not the working folder (the source tree in ctest).
  const fs::path model = temp.write("models/tabulated.toml", "model = \"tabulated\"\nfile = \"../tables/tyre.h5\"\n");
  const ModalReceptanceTable read = read_tabulated_tyre(CaseFile::load_model(model).top());
  expect_same_table(table, read);
  EXPECT_MENTIONS(read.source, "tyre.h5");

  const fs::path misspelt = temp.write("models/misspelt.toml", "model = \"tabulated\"\nflie = \"x.h5\"\n");
  std::string message = input_error_of([&] { (void)read_tabulated_tyre(CaseFile::load_model(misspelt).top()); });
  EXPECT_MENTIONS(message, "misspelt.toml");
  EXPECT_MENTIONS(message, "flie");
  const fs::path missing = temp.write("models/missing.toml", "model = \"tabulated\"\nfile = \"absent.h5\"\n");
  message = input_error_of([&] { (void)read_tabulated_tyre(CaseFile::load_model(missing).top()); });
  EXPECT_MENTIONS(message, "missing.toml");
  EXPECT_MENTIONS(message, "file");
  EXPECT_MENTIONS(message, "absent.h5");
  const fs::path no_file = temp.write("models/no_file.toml", "model = \"tabulated\"\n");
  EXPECT_MENTIONS(input_error_of([&] { (void)read_tabulated_tyre(CaseFile::load_model(no_file).top()); }),
                  "is required");
  const fs::path other = temp.write("models/other.toml", "model = \"two_layer\"\nfile = \"x.h5\"\n");
  EXPECT_MENTIONS(input_error_of([&] { (void)read_tabulated_tyre(CaseFile::load_model(other).top()); }), "model");
  // A bad table: the table's file and dataset are named.
  write_modal_table(temp.path() / "tables" / "tyre.h5", table);
  std::ofstream(temp.path() / "tables" / "tyre.h5", std::ios::binary | std::ios::trunc) << "not a table";
  EXPECT_MENTIONS(input_error_of([&] { (void)read_tabulated_tyre(CaseFile::load_model(model).top()); }), "tyre.h5");
}

// The round trip of `rollnoise greens`: a two-layer model's own table (its modes, m = 0 … M, at
// the fit's frequencies) written out and read back as a `tabulated` model file gives the
// two-layer view's cell receptance (each within the pole fit: 3e-3 RMS, 3e-2 at worst per mode)
// and its step means (by FFT there, closed form here). A reduced passenger file (M = 16, N = 4)
// keeps it quick; both side conditions, so both lateral shapes.
TEST(TabulatedCentreLine, TableWrittenFromTwoLayerGivesItsReceptance) {
  const test::TempFolder temp("rollnoise_test_tabulated_view_");
  const std::string passenger = [] {
    std::ifstream in(fs::path(ROLLNOISE_SOURCE_DIR) / "models/tyres/passenger_205_55R16_two_layer.toml");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  for (const std::string side : {"simply_supported", "sliding"}) {
    SCOPED_TRACE(side);
    std::string text = passenger;
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
             {"circumferential_modes = 256", "circumferential_modes = 16"},
             {"lateral_modes = 25", "lateral_modes = 4"},
             {"side_condition = \"simply_supported\"", "side_condition = \"" + side + "\""}}) {
      const auto at = text.find(from);
      ASSERT_NE(at, std::string::npos) << from;
      text.replace(at, from.size(), to);
    }
    const fs::path layered_file = temp.write(side + "/two_layer.toml", text);
    const auto layered = make_centre_line_response(CaseFile::load_model(layered_file).top());
    std::optional<ModalReceptanceTable> table = layered->modal_table(tyre_mode_fit_frequencies(), std::nullopt);
    ASSERT_TRUE(table.has_value());
    EXPECT_EQ(table->orders, 16);
    EXPECT_EQ(table->lateral_orders, 4);
    write_modal_table(temp.path() / side / "modal_receptance.h5", *table);
    const fs::path tabulated_file =
        temp.write(side + "/tabulated.toml", "model = \"tabulated\"\nfile = \"modal_receptance.h5\"\n");
    const auto tabulated = make_centre_line_response(CaseFile::load_model(tabulated_file).top());
    EXPECT_EQ(tabulated->model(), "tabulated");
    EXPECT_MENTIONS(tabulated->description(), "cell");
    EXPECT_MENTIONS(tabulated->description(), "modal_receptance.h5");
    ASSERT_NE(tabulated->fitted_modes(), nullptr);
    EXPECT_EQ(tabulated->fitted_modes()->fit_report().unconverged, 0u);
    EXPECT_EQ(layered->fitted_modes(), nullptr);
    EXPECT_FALSE(tabulated->modal_table(tyre_mode_fit_frequencies(), std::nullopt).has_value());
    EXPECT_NEAR(tabulated->circumference(), layered->circumference(), 1e-15);

    // Each difference against the larger of the value and the point receptance at that
    // frequency: near a node a transfer receptance is small, and the fit's error is a share of
    // the modes' sum rather than of the value (700 Hz, 0.05 m, sliding: 8.8e-3 of the value).
    double worst = 0.0, worst_own = 0.0;
    for (const double f : {0.0, 30.0, 89.0, 250.0, 700.0, 1500.0, 3000.0, 5000.0}) {
      const double omega = 2.0 * std::numbers::pi * f;
      const double point = std::abs(layered->receptance(0.0, omega));
      for (const double d : {0.0, 0.02, 0.05, 0.1, 0.2}) {
        const cd exact = layered->receptance(d, omega);
        const cd fitted = tabulated->receptance(d, omega);
        const double error = std::abs(fitted - exact) / std::max(std::abs(exact), point);
        worst = std::max(worst, error);
        worst_own = std::max(worst_own, std::abs(fitted - exact) / std::abs(exact));
        EXPECT_LT(error, 0.01) << f << " Hz, " << d << " m: " << fitted << " against " << exact;
      }
    }
    std::printf("[ %s ] tabulated against two_layer receptance: worst difference %.2e of max(|value|, |point|), "
                "%.2e of the value itself\n",
                side.c_str(), worst, worst_own);

    // Step means at 0.125 ms (the greens plot's), along the circumference: the two-layer view's
    // by FFT against the fit's closed form, relative to the peak.
    const std::vector<double> along{0.0, 0.01, 0.03, 0.1, 0.3};
    const Eigen::MatrixXd g_exact = layered->green_table(along, 0.125e-3, 40);
    const Eigen::MatrixXd g_fitted = tabulated->green_table(along, 0.125e-3, 40);
    const double peak = g_exact.cwiseAbs().maxCoeff();
    const double step_error = (g_fitted - g_exact).cwiseAbs().maxCoeff() / peak;
    std::printf("[ %s ] step means: worst difference %.2e of the peak\n", side.c_str(), step_error);
    EXPECT_LT(step_error, 0.01);
  }
}

// A table that is whole but too thin for the pole fit (two frequencies) is the file's fault: an
// InputError naming it.
TEST(TabulatedCentreLine, TableTooThinToFitIsAnInputErrorNamingIt) {
  const test::TempFolder temp("rollnoise_test_tabulated_thin_");
  Eigen::VectorXd f(2);
  f << 0.0, 100.0;
  write_modal_table(temp.path() / "thin.h5", tabulate_two_layer(TwoLayerTyre(test::tyre_like_two_layer(2, 2)), f, 3));
  const fs::path model = temp.write("tabulated.toml", "model = \"tabulated\"\nfile = \"thin.h5\"\n");
  const std::string message = input_error_of([&] { (void)make_centre_line_response(CaseFile::load_model(model).top()); });
  EXPECT_MENTIONS(message, "thin.h5");
  EXPECT_MENTIONS(message, "fitted");
}

// The cost of the passenger tyre's table for a pole fit (orders 508, 25 lateral orders, 121
// frequencies) and of loading it from the cache. Minutes on 2 cores: disabled by default.
TEST(TwoLayerModalTable, DISABLED_PassengerTiming) {
  const TwoLayerTyre tyre(read_two_layer_tyre(
      CaseFile::load_model(fs::path(ROLLNOISE_SOURCE_DIR) / "models/tyres/passenger_205_55R16_two_layer.toml").top()));
  const Eigen::VectorXd f = default_fit_frequencies();
  const test::TempFolder temp("rollnoise_test_modal_timing_");
  using clock = std::chrono::steady_clock;
  const auto seconds = [](clock::duration d) { return std::chrono::duration<double>(d).count(); };
  auto t0 = clock::now();
  const ModalReceptanceTable table = cached_two_layer_table(tyre, f, 508, temp.path());
  const double compute = seconds(clock::now() - t0);
  t0 = clock::now();
  const ModalReceptanceTable hit = cached_two_layer_table(tyre, f, 508, temp.path());
  const double load = seconds(clock::now() - t0);
  EXPECT_EQ(hit.source, (temp.path() / (two_layer_table_key(tyre.parameters(), 508, f) + ".h5")).string());
  expect_same_table(table, hit);
  std::uintmax_t bytes = 0;
  for (const auto& entry : fs::directory_iterator(temp.path())) bytes += entry.file_size();
  std::printf("passenger table %zu modes x %td frequencies: computed and stored in %.1f s (%u hardware threads), "
              "loaded from the cache in %.3f s; file %.1f MB\n",
              table.modes.size(), f.size(), compute, std::thread::hardware_concurrency(), load,
              static_cast<double>(bytes) / 1e6);
}

}  // namespace
}  // namespace rollnoise
