#include "radiation/radiation_cache.hpp"

#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string_view>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "core/cache_folder.hpp"
#include "core/error.hpp"
#include "core/fnv_digest.hpp"
#include "core/hdf5_reader.hpp"
#include "core/hdf5_writer.hpp"
#include "core/mapped_file.hpp"
#include "core/run_estimate.hpp"
#include "radiation/quantised_power_operator.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

// At most this many rows of power operator: the power matrix's rank is at most the source
// count, and a damaged dimension must not make the reader allocate wildly.
constexpr std::size_t kMaxPowerRows = std::size_t{1} << 16;

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Deflate's level for the datasets: on one radiating body's power blocks, level 4 gave 36.7 MB in
// 1.7 s of compression, 9 gave 35.4 MB in 49 s and 1 gave 39.1 MB in 1.2 s (zlib, 2 cores).
constexpr int kDeflateLevel = 4;

void digest_matrix(FnvDigest& d, const Eigen::MatrixXcd& m) {
  d.integer(m.rows());
  d.integer(m.cols());
  // Column by column, real and imaginary parts interleaved: the matrix's own memory.
  d.words(reinterpret_cast<const char*>(m.data()), sizeof(std::complex<double>) * static_cast<std::size_t>(m.size()));
}

// One complex matrix of doubles from its two datasets, C order [rows][cols].
Eigen::MatrixXcd read_complex(const Hdf5Reader& file, const std::string& name, std::size_t rows, std::size_t columns) {
  const Hdf5Array re = file.read_numbers("/" + name + "_re", 2, rows * columns);
  const Hdf5Array im = file.read_numbers("/" + name + "_im", 2, rows * columns);
  if (re.dims.size() != 2 || re.dims != im.dims || re.dims[0] != rows || re.dims[1] != columns)
    throw InputError(file.source(), "/" + name, "has dimensions other than the entry's key asks for");
  const auto r = static_cast<Eigen::Index>(rows);
  const auto c = static_cast<Eigen::Index>(columns);
  Eigen::MatrixXcd out(r, c);
  out.real() = Eigen::Map<const RowMajor>(re.values.data(), r, c);
  out.imag() = Eigen::Map<const RowMajor>(im.values.data(), r, c);
  return out;
}

// A quantised block from its two datasets of integers (quantised_power_operator.hpp): the same
// doubles the stage applied when it solved the anchor (integer × quantum).
Eigen::MatrixXcd read_quantised(const Hdf5Reader& file, const std::string& name, std::size_t rows, std::size_t columns,
                                double quantum) {
  const auto part = [&](const std::string& suffix) {
    const Hdf5Array a = file.read_numbers("/" + name + suffix, 2, rows * columns);
    if (a.dims.size() != 2 || a.dims[0] != rows || a.dims[1] != columns)
      throw InputError(file.source(), "/" + name + suffix, "has dimensions other than the entry says");
    Int16Matrix integers(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(columns));
    for (std::size_t i = 0; i < a.values.size(); ++i) {
      const double v = a.values[i];
      if (!(std::abs(v) <= 32767.0) || v != std::nearbyint(v))
        throw InputError(file.source(), "/" + name + suffix, "holds a value that is not a 16-bit integer");
      integers.data()[i] = static_cast<std::int16_t>(v);
    }
    return values_of(integers, quantum);
  };
  Eigen::MatrixXcd out(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(columns));
  out.real() = part("_re");
  out.imag() = part("_im");
  return out;
}

AnchorOperators read_entry(const fs::path& path, const std::string& key, Eigen::Index receivers, Eigen::Index columns,
                           const std::vector<Eigen::Index>& power_columns) {
  const Hdf5Reader file(path);
  const std::optional<std::string> layout = file.string_attribute("/", "layout");
  if (!layout || *layout != kRadiationCacheLayout)
    throw InputError(path.string(), "/ attribute layout", "is not \"" + std::string(kRadiationCacheLayout) + "\"");
  const std::optional<std::string> stored_key = file.string_attribute("/", "key");
  if (!stored_key || *stored_key != key)
    throw InputError(path.string(), "/ attribute key", "is not the entry's own key (a foreign file)");
  AnchorOperators out;
  out.transfer = read_complex(file, "transfer", static_cast<std::size_t>(receivers), static_cast<std::size_t>(columns));
  const std::optional<double> blocks = file.number_attribute("/", "power_blocks");
  if (!blocks || *blocks != static_cast<double>(power_columns.size()))
    throw InputError(path.string(), "/ attribute power_blocks", "is not the number of the mesh's symmetry blocks");
  const std::optional<double> quantum = file.number_attribute("/", "power_quantum");
  if (!quantum || !(*quantum >= 0.0) || !std::isfinite(*quantum))
    throw InputError(path.string(), "/ attribute power_quantum", "is missing, negative or not finite");
  out.power_quantum = *quantum;
  for (std::size_t c = 0; c < power_columns.size(); ++c) {
    const std::string name = "power_" + std::to_string(c);
    const std::optional<double> rows = file.number_attribute("/", name + "_rows");
    if (!rows || !(*rows >= 0.0) || *rows > static_cast<double>(kMaxPowerRows) || *rows != std::floor(*rows) ||
        (*rows > 0.0 && !(*quantum > 0.0)))
      throw InputError(path.string(), "/ attribute " + name + "_rows", "is missing or out of range");
    const auto k = static_cast<std::size_t>(*rows);
    const auto t = static_cast<std::size_t>(power_columns[c]);
    out.power.push_back(k == 0 ? Eigen::MatrixXcd(0, power_columns[c]) : read_quantised(file, name, k, t, *quantum));
  }
  // The checksum attribute of the values is not computed again: the trailer's, checked before,
  // covers every byte of the file, the values' among them.
  return out;
}

// The trailer after the HDF5 bytes: a magic and a checksum of every byte before it, so that a
// damaged or truncated file is told before the HDF5 library reads any of it (that library can
// crash on damaged metadata; reading in a child process instead, as modal_table_hdf5 does, can
// hang when another thread holds the library's lock at the fork, as a study's other cases
// writing contact.h5 do). HDF5 ignores bytes past the end address its superblock records.
constexpr char kTrailerMagic[8] = {'R', 'N', 'C', 'A', 'C', 'H', 'E', '1'};
constexpr std::size_t kTrailerSize = 16;

std::uint64_t file_checksum(std::string_view bytes) {
  FnvDigest d;
  d.words(bytes.data(), bytes.size());
  return d.value();
}

// The file mapped, not read into a buffer: a warm run checked 520 MB of entries before they were
// rounded (45 MB since), and the copy (and the buffer's first touch) cost more than the checksum
// (issue 12). The
// entries are replaced by rename, never rewritten in place, so the mapped bytes stay those checked.
void check_file_trailer(const fs::path& path) {
  const MappedFile file(path);
  const std::string_view bytes = file.bytes();
  if (bytes.size() < kTrailerSize || bytes.compare(bytes.size() - kTrailerSize, 8, std::string_view(kTrailerMagic, 8)) != 0)
    throw std::runtime_error("no checksum trailer: truncated, or not a cache entry");
  std::uint64_t stored = 0;
  for (int i = 0; i < 8; ++i)
    stored |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[bytes.size() - 8 + static_cast<std::size_t>(i)])) << (8 * i);
  if (stored != file_checksum(bytes.substr(0, bytes.size() - kTrailerSize)))
    throw std::runtime_error("the file's checksum does not match its bytes: damaged");
}

void append_file_trailer(const fs::path& path) {
  std::uint64_t sum = 0;
  {
    const MappedFile file(path);
    sum = file_checksum(file.bytes());
  }
  std::string trailer(kTrailerMagic, 8);
  for (int i = 0; i < 8; ++i) trailer += static_cast<char>((sum >> (8 * i)) & 0xff);
  std::ofstream out(path, std::ios::binary | std::ios::app);
  out.write(trailer.data(), static_cast<std::streamsize>(trailer.size()));
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

// A file as the file system knows it (device and inode): a rename onto the path or a removal
// changes it, a write in place does not.
using FileIdentity = std::pair<std::uint64_t, std::uint64_t>;
std::optional<FileIdentity> identity_of(const fs::path& path) {
  struct stat s {};
  if (::stat(path.c_str(), &s) != 0) return std::nullopt;
  return FileIdentity{static_cast<std::uint64_t>(s.st_dev), static_cast<std::uint64_t>(s.st_ino)};
}

}  // namespace

std::string radiation_entry_checksum(const std::string& key, const AnchorOperators& operators) {
  FnvDigest d;
  d.text(kRadiationCacheLayout);
  d.text(key);
  digest_matrix(d, operators.transfer);
  d.integer(static_cast<std::int64_t>(operators.power.size()));
  for (const Eigen::MatrixXcd& block : operators.power) digest_matrix(d, block);
  d.real(operators.power_quantum);
  return d.hex();
}

RadiationCache::RadiationCache(fs::path folder, std::uint64_t limit) : folder_(std::move(folder)), limit_(limit) {}

fs::path RadiationCache::file_of(const std::string& key) const {
  if (!is_cache_key(key)) throw std::invalid_argument("radiation cache: the key \"" + key + "\" is not a plain file name");
  return folder_ / (key + ".h5");
}

Eigen::Index AnchorOperators::power_rank() const {
  Eigen::Index rank = 0;
  for (const Eigen::MatrixXcd& block : power) rank += block.rows();
  return rank;
}

std::optional<AnchorOperators> RadiationCache::load(const std::string& key, Eigen::Index receivers, Eigen::Index columns,
                                                    const std::vector<Eigen::Index>& power_columns) const {
  const fs::path path = file_of(key);
  // Loaded, or about to be solved: another store's trim may take it from here on.
  release(key);
  const std::optional<FileIdentity> before = identity_of(path);
  if (!before) return std::nullopt;
  try {
    check_file_trailer(path);
    // The bytes are those this code wrote: the HDF5 library reads them in this process.
    AnchorOperators operators = read_entry(path, key, receivers, columns, power_columns);
    mark_cache_entry_used(path);
    return operators;
  } catch (const std::exception& error) {
    // Removed by another run's trim, or replaced by another run's store, while this one read it:
    // a miss, not damage.
    if (identity_of(path) != before) return std::nullopt;
    // Each entry is loaded once per run, so this is the one warning for it.
    std::fprintf(stderr, "rollnoise: warning: the radiation cache entry %s is damaged or foreign (%s): solving it again\n",
                 path.string().c_str(), error.what());
    return std::nullopt;
  }
}

void RadiationCache::hold(const std::vector<std::string>& keys) const {
  const std::lock_guard lock(held_mutex_);
  held_.insert(keys.begin(), keys.end());
}

void RadiationCache::release(const std::string& key) const {
  const std::lock_guard lock(held_mutex_);
  held_.erase(key);
}

bool RadiationCache::held(const fs::path& entry) const {
  const std::lock_guard lock(held_mutex_);
  return held_.count(entry.stem().string()) > 0;
}

void RadiationCache::release_and_trim() const {
  {
    const std::lock_guard lock(held_mutex_);
    held_.clear();
  }
  try {
    keep_cache_within(folder_, limit_);
  } catch (const std::exception&) {
    // A folder that cannot be scanned holds nothing this run stored: the store warned already.
  }
}

std::string describe_radiation_entry(const fs::path& file) {
  try {
    check_file_trailer(file);
    const Hdf5Reader h5(file);
    const auto text = [&](const char* name) {
      const std::optional<std::string> value = h5.string_attribute("/", name);
      if (!value) throw InputError(file.string(), std::string("/ attribute ") + name, "is missing");
      return *value;
    };
    const auto number = [&](const char* name) {
      const std::optional<double> value = h5.number_attribute("/", name);
      if (!value) throw InputError(file.string(), std::string("/ attribute ") + name, "is missing");
      return *value;
    };
    if (text("layout") != kRadiationCacheLayout) throw InputError(file.string(), "/ attribute layout", "is another layout");
    if (file.stem().string() != text("key")) throw InputError(file.string(), "/ attribute key", "is not the file's name");
    // The attributes only: load() checks the content against its checksum.
    char line[400];
    std::snprintf(line, sizeof line,
                  "radiation operators at %.6g Hz: %.0f receivers, power rank %.0f, mesh of %.0f points and %.0f sources "
                  "(tread split %.0f, %.0f sidewall rings), %s",
                  number("anchor_hz"), number("receivers"), number("power_rank"), number("collocation_points"),
                  number("sources"), number("tread_split"), number("sidewall_rings"), text("source_type").c_str());
    return line;
  } catch (const std::exception& error) {
    return std::string("damaged or foreign: ") + error.what();
  }
}

void RadiationCache::store(const std::string& key, const AnchorOperators& operators,
                           const AnchorDescription& description) const {
  if (store_failed_) return;
  const fs::path path = file_of(key);
  try {
    std::error_code ec;
    fs::create_directories(folder_, ec);
    if (ec) throw std::runtime_error("cannot create the folder: " + ec.message());
    TemporaryFile temporary(path);
    {
      Hdf5Writer h5(temporary.path());
      h5.attribute("/", "layout", std::string(kRadiationCacheLayout));
      h5.attribute("/", "key", key);
      h5.attribute("/", "checksum", radiation_entry_checksum(key, operators));
      h5.attribute("/", "software", std::string("rollnoise ") + ROLLNOISE_VERSION);
      h5.attribute("/", "anchor_hz", description.anchor_hz);
      h5.integer_attribute("/", "collocation_points", description.collocation_points);
      h5.integer_attribute("/", "sources", description.sources);
      h5.integer_attribute("/", "tread_split", description.tread_split);
      h5.integer_attribute("/", "sidewall_rings", description.sidewall_rings);
      h5.integer_attribute("/", "receivers", operators.transfer.rows());
      h5.integer_attribute("/", "power_rank", operators.power_rank());
      h5.integer_attribute("/", "power_blocks", static_cast<std::int64_t>(operators.power.size()));
      h5.attribute("/", "power_quantum", operators.power_quantum);
      h5.attribute("/", "source_type", description.source_type);
      const std::string columns = "; column: collocation point of the level mesh (the tread first)";
      h5.write_compressed("/transfer_re", Eigen::MatrixXd(operators.transfer.real()), kDeflateLevel, "Pa/(m/s)",
                          "real part of the transfer from normal velocity to receiver pressure; row: receiver" + columns);
      h5.write_compressed("/transfer_im", Eigen::MatrixXd(operators.transfer.imag()), kDeflateLevel, "Pa/(m/s)",
                          "imaginary part of the transfer to the receivers" + columns);
      for (std::size_t c = 0; c < operators.power.size(); ++c) {
        const std::string name = "power_" + std::to_string(c);
        const Eigen::MatrixXcd& block = operators.power[c];
        h5.integer_attribute("/", name + "_rows", block.rows());
        if (block.rows() == 0) continue;
        const std::string what = "part of the power operator's block B_" + std::to_string(c) +
                                 " in units of power_quantum (W = 0.5*sum_c |B_c x_c|^2, x_c the velocities' "
                                 "coordinates in the mesh's symmetry character c); row: radiating pattern, strongest "
                                 "first; column: coordinate";
        h5.write_compressed("/" + name + "_re", integers_of(block.real(), operators.power_quantum), kDeflateLevel,
                            "power_quantum", "real " + what);
        h5.write_compressed("/" + name + "_im", integers_of(block.imag(), operators.power_quantum), kDeflateLevel,
                            "power_quantum", "imaginary " + what);
      }
      h5.close();
    }
    append_file_trailer(temporary.path());
    // An entry that alone exceeds the limit would only be trimmed again: not stored.
    if (const std::uint64_t bytes = fs::file_size(temporary.path()); bytes > limit_) {
      if (!oversize_warned_.exchange(true))
        std::fprintf(stderr,
                     "rollnoise: warning: a radiation cache entry (%s) is larger than the cache's limit (%s): not stored\n",
                     format_bytes(bytes).c_str(), format_bytes(limit_).c_str());
      return;
    }
    temporary.rename_to(path);
    keep_cache_within(folder_, limit_, [this](const fs::path& entry) { return held(entry); });
  } catch (const std::exception& error) {
    if (!store_failed_.exchange(true))
      std::fprintf(stderr, "rollnoise: warning: cannot store in the radiation cache %s (%s): going on without storing\n",
                   folder_.string().c_str(), error.what());
  }
}

}  // namespace rollnoise
