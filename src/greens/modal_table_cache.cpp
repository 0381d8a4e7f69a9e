#include "greens/modal_table_cache.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/cache_limit.hpp"
#include "core/cache_folder.hpp"
#include "core/fnv_digest.hpp"
#include "greens/modal_table_hdf5.hpp"
#include "greens/two_layer_tyre.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

// Raise when a change of the two-layer code changes its results: old cache entries then miss.
// (The sampled entries in the key catch most such changes anyway; this makes it certain.)
constexpr int two_layer_revision = 1;

// A new parameter must be weighed for the digest below: this fails to compile until it is
// counted. (25 doubles; three ints and the padding after them.)
static_assert(sizeof(OrthotropicConstants) == 9 * sizeof(double));
static_assert(sizeof(TwoLayerParameters) == 25 * sizeof(double) + 4 * sizeof(int),
              "TwoLayerParameters changed: add the new member to the digest of two_layer_table_key");

struct Sample {
  int m, n;
  Eigen::Index k;
};

// The entries of the table that the key samples: first, middle and last mode and frequency.
std::array<Sample, 3> samples(const TwoLayerTyre& tyre, int orders, const Eigen::VectorXd& frequency_hz) {
  const int first = tyre.first_lateral_order();
  const int last = tyre.last_lateral_order();
  const Eigen::Index frequencies = frequency_hz.size();
  return {Sample{0, first, 0}, Sample{orders / 2, (first + last) / 2, frequencies / 2},
          Sample{orders, last, frequencies - 1}};
}

std::string key_of(const TwoLayerTyre& tyre, int orders, const Eigen::VectorXd& frequency_hz) {
  if (orders < 0) throw std::invalid_argument("two_layer_table_key: orders must be >= 0");
  if (frequency_hz.size() == 0) throw std::invalid_argument("two_layer_table_key: no frequencies");
  const TwoLayerParameters& p = tyre.parameters();
  FnvDigest d;
  d.text(modal_table_layout);
  d.text("two_layer");
  d.integer(two_layer_revision);
  for (const double v : {p.radius, p.width, p.belt.youngs_x, p.belt.youngs_y, p.belt.youngs_z, p.belt.shear_xy,
                         p.belt.shear_xz, p.belt.shear_yz, p.belt.poisson_xy, p.belt.poisson_xz, p.belt.poisson_yz,
                         p.belt_thickness, p.belt_density, p.belt_loss_factor, p.tread_thickness, p.tread_density,
                         p.tread_youngs_modulus, p.tread_poisson_ratio, p.tread_loss_factor, p.tension_x,
                         p.tension_y, p.foundation_stiffness, p.foundation_loss_factor}) {
    d.real(v);
  }
  d.integer(p.circumferential_modes);
  d.integer(p.lateral_modes);
  d.integer(p.side_condition == SideCondition::simply_supported ? 0 : 1);
  // Not crown_radius and tread_width: they shape the contact grid, not the layers, and the
  // table does not depend on them (a change of them reuses the table).
  d.integer(orders);
  d.integer(frequency_hz.size());
  for (Eigen::Index k = 0; k < frequency_hz.size(); ++k) d.real(frequency_hz(k));
  for (const Sample& s : samples(tyre, orders, frequency_hz)) {
    const std::complex<double> h = two_layer_entry(tyre, s.m, s.n, frequency_hz(s.k));
    d.real(h.real());
    d.real(h.imag());
  }
  return "two_layer-" + d.hex();
}

fs::path cache_file(const fs::path& directory, const std::string& key) {
  if (!is_cache_key(key)) {
    throw std::invalid_argument("modal table cache: the key \"" + key +
                                "\" is not a plain file name (letters, digits, '-', '_', '.')");
  }
  return directory / (key + ".h5");
}

// Whether a table from the cache is the one asked for: the same axes, and the sampled entries
// the key was made from reproduced bit for bit.
bool matches(const ModalReceptanceTable& table, const TwoLayerTyre& tyre, int orders,
             const Eigen::VectorXd& frequency_hz) {
  const TwoLayerParameters& p = tyre.parameters();
  const LateralShape shape =
      p.side_condition == SideCondition::simply_supported ? LateralShape::sine : LateralShape::cosine;
  if (table.radius != p.radius || table.width != p.width || table.lateral_shape != shape ||
      table.first_lateral_order != tyre.first_lateral_order() || table.lateral_orders != p.lateral_modes ||
      table.orders != orders || table.frequency.size() != frequency_hz.size()) {
    return false;
  }
  for (Eigen::Index k = 0; k < frequency_hz.size(); ++k) {
    if (std::bit_cast<std::uint64_t>(table.frequency(k)) != std::bit_cast<std::uint64_t>(frequency_hz(k))) return false;
  }
  for (const Sample& s : samples(tyre, orders, frequency_hz)) {
    if (table.mode(s.m, s.n)(s.k) != two_layer_entry(tyre, s.m, s.n, frequency_hz(s.k))) return false;
  }
  return true;
}

}  // namespace

std::string two_layer_table_key(const TwoLayerParameters& parameters, int orders, const Eigen::VectorXd& frequency_hz) {
  return key_of(TwoLayerTyre(parameters), orders, frequency_hz);
}

std::optional<ModalReceptanceTable> load_cached_table(const fs::path& directory, const std::string& key) {
  const fs::path file = cache_file(directory, key);
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return std::nullopt;
  try {
    ModalReceptanceTable table = read_modal_table(file);
    mark_cache_entry_used(file);  // recency for the folder's limit (core/cache_limit.hpp)
    return table;
  } catch (const std::exception&) {
    // Corrupt, truncated or from another layout: a miss; the caller recomputes and overwrites.
    return std::nullopt;
  }
}

void store_cached_table(const fs::path& directory, const std::string& key, const ModalReceptanceTable& table) {
  const fs::path file = cache_file(directory, key);
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) throw std::runtime_error("cannot create the cache folder " + directory.string() + ": " + ec.message());
  write_modal_table(file, table);
}

ModalReceptanceTable cached_two_layer_table(const TwoLayerTyre& tyre, const Eigen::VectorXd& frequency_hz, int orders,
                                            const std::optional<fs::path>& directory, unsigned threads) {
  if (!directory) return tabulate_two_layer(tyre, frequency_hz, orders, threads);
  const std::string key = key_of(tyre, orders, frequency_hz);
  if (std::optional<ModalReceptanceTable> cached = load_cached_table(*directory, key)) {
    if (matches(*cached, tyre, orders, frequency_hz)) return std::move(*cached);
  }
  ModalReceptanceTable table = tabulate_two_layer(tyre, frequency_hz, orders, threads);
  try {
    store_cached_table(*directory, key, table);
  } catch (const std::exception&) {
    // A read-only or full disk: the table is still right, only the next run recomputes it.
  }
  return table;
}

}  // namespace rollnoise
