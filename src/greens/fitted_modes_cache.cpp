#include "greens/fitted_modes_cache.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <system_error>

#include "core/cache_limit.hpp"
#include "core/cache_folder.hpp"
#include "core/fnv_digest.hpp"

namespace rollnoise {

namespace fs = std::filesystem;

namespace {

constexpr char magic[] = "RNFITS01";
constexpr std::size_t magic_size = 8;
// At most this many poles per mode: a damaged count must not make the reader allocate wildly.
constexpr std::uint64_t max_poles = 4096;

std::uint64_t fnv1a(const char* data, std::size_t n) {
  FnvDigest d;
  d.bytes(data, n);
  return d.value();
}

void put(std::string& out, const void* data, std::size_t n) { out.append(static_cast<const char*>(data), n); }
void put_u64(std::string& out, std::uint64_t v) { put(out, &v, sizeof v); }
void put_double(std::string& out, double v) { put(out, &v, sizeof v); }

class Cursor {
 public:
  explicit Cursor(std::string_view bytes) : bytes_(bytes) {}
  bool take(void* out, std::size_t n) {
    if (n > bytes_.size() - pos_) return false;
    std::memcpy(out, bytes_.data() + pos_, n);
    pos_ += n;
    return true;
  }
  bool u64(std::uint64_t& v) { return take(&v, sizeof v); }
  bool real(double& v) { return take(&v, sizeof v); }
  std::size_t position() const noexcept { return pos_; }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
};

fs::path file_of(const fs::path& directory, const std::string& key) {
  if (!is_cache_key(key))
    throw std::invalid_argument("fitted modes cache: the key \"" + key + "\" is not a plain file name");
  return directory / (key + ".fits");
}

}  // namespace

std::string fitted_modes_key(const std::string& table_key, const VectorFittingOptions& o) {
  FnvDigest d;
  for (const double v : {static_cast<double>(o.starting_pole_pairs), static_cast<double>(o.real_poles),
                         static_cast<double>(o.maximum_pole_pairs), static_cast<double>(o.iterations),
                         o.target_rms_error, o.target_max_error, static_cast<double>(o.weighting == FitWeighting::relative),
                         static_cast<double>(o.spacing == StartingPoleSpacing::logarithmic),
                         static_cast<double>(o.fit_direct)})
    d.real(v);
  return table_key + "-fit-" + d.hex();
}

std::optional<std::vector<PoleResidueResponse>> load_cached_fits(const fs::path& directory, const std::string& key,
                                                                 std::size_t modes) {
  const fs::path file = file_of(directory, key);
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) return std::nullopt;
  if (bytes.size() < magic_size + 3 * sizeof(std::uint64_t)) return std::nullopt;
  const std::size_t body = bytes.size() - sizeof(std::uint64_t);
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + body, sizeof stored);
  if (stored != fnv1a(bytes.data(), body)) return std::nullopt;
  Cursor c(std::string_view(bytes.data(), body));
  char head[magic_size];
  std::uint64_t key_size = 0, count = 0;
  if (!c.take(head, magic_size) || std::memcmp(head, magic, magic_size) != 0) return std::nullopt;
  if (!c.u64(key_size) || key_size != key.size()) return std::nullopt;
  std::string stored_key(key_size, '\0');
  if (!c.take(stored_key.data(), key_size) || stored_key != key) return std::nullopt;
  if (!c.u64(count) || count != modes) return std::nullopt;
  std::vector<PoleResidueResponse> fits(modes);
  for (auto& fit : fits) {
    std::uint64_t poles = 0;
    if (!c.real(fit.direct) || !c.u64(poles) || poles > max_poles) return std::nullopt;
    fit.poles.resize(poles);
    fit.residues.resize(poles);
    for (std::uint64_t s = 0; s < poles; ++s) {
      double v[4];
      for (double& x : v)
        if (!c.real(x)) return std::nullopt;
      fit.poles[s] = {v[0], v[1]};
      fit.residues[s] = {v[2], v[3]};
    }
    try {
      fit.validate();
    } catch (const std::invalid_argument&) {
      return std::nullopt;
    }
  }
  if (c.position() != body) return std::nullopt;
  mark_cache_entry_used(file);  // recency for the folder's limit (core/cache_limit.hpp)
  return fits;
}

void store_cached_fits(const fs::path& directory, const std::string& key, const std::vector<PoleResidueResponse>& fits) {
  const fs::path file = file_of(directory, key);
  std::string out;
  put(out, magic, magic_size);
  put_u64(out, key.size());
  out += key;
  put_u64(out, fits.size());
  for (const auto& fit : fits) {
    put_double(out, fit.direct);
    put_u64(out, fit.poles.size());
    for (std::size_t s = 0; s < fit.poles.size(); ++s) {
      put_double(out, fit.poles[s].real());
      put_double(out, fit.poles[s].imag());
      put_double(out, fit.residues[s].real());
      put_double(out, fit.residues[s].imag());
    }
  }
  put_u64(out, fnv1a(out.data(), out.size()));
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) throw std::runtime_error("cannot create the cache folder " + directory.string() + ": " + ec.message());
  // A name of this writer alone (not only of this process: a study's threads store the same
  // fits at once), renamed into place.
  TemporaryFile temporary(file);
  {
    std::ofstream o(temporary.path(), std::ios::binary | std::ios::trunc);
    o.write(out.data(), static_cast<std::streamsize>(out.size()));
    o.close();
    if (!o) throw std::runtime_error("cannot write " + temporary.path().string());
  }
  temporary.rename_to(file);
}

std::string modal_table_content_key(const ModalReceptanceTable& t) {
  FnvDigest d;
  for (const double v : {t.radius, t.width, t.lateral_shape == LateralShape::sine ? 0.0 : 1.0,
                         static_cast<double>(t.first_lateral_order), static_cast<double>(t.lateral_orders),
                         static_cast<double>(t.orders), static_cast<double>(t.frequency.size())})
    d.real(v);
  for (Eigen::Index k = 0; k < t.frequency.size(); ++k) d.real(t.frequency(k));
  for (const auto& mode : t.modes)
    for (Eigen::Index k = 0; k < mode.size(); ++k) {
      d.real(mode(k).real());
      d.real(mode(k).imag());
    }
  return "table-" + d.hex();
}

FittedModalTyre fit_with_cache(ModalReceptanceTable table, std::string name,
                               const std::optional<fs::path>& directory, const std::string& fit_key, bool& from_cache) {
  const VectorFittingOptions options = tyre_mode_fit_options();
  const auto modes = static_cast<std::size_t>((table.orders + 1) * table.lateral_orders);
  from_cache = false;
  if (directory && !fit_key.empty()) {
    if (auto fits = load_cached_fits(*directory, fit_key, modes)) {
      from_cache = true;
      return FittedModalTyre(std::move(table), std::move(name), true, std::move(*fits), options);
    }
  }
  FittedModalTyre fitted(std::move(table), std::move(name), true, options);
  if (directory && !fit_key.empty()) {
    try {
      store_cached_fits(*directory, fit_key, fitted.fits());
    } catch (const std::exception&) {
      // A cache that cannot be written costs only the next run's fitting time.
    }
  }
  return fitted;
}

}  // namespace rollnoise
