#pragma once
// The radiation cache (issues 12 and 30: solved once per tyre, in a bounded folder): what the radiation stage
// (tyre_radiation.hpp) solves at one anchor frequency that does not depend on the velocities,
// kept on disk so that the next run of the same radiating body (another road, another speed,
// another study case) loads it instead of solving the equivalent-source problem again.
//
// What an entry holds (AnchorOperators), for one anchor and one mesh level:
//  - transfer: R × C, the receivers' pressures per unit normal velocity of the level mesh's
//    first C collocation points (the tread; all points when one mesh serves every anchor and
//    the velocities cover it all), T = P_rec·V⁺ (equivalent_sources.hpp), in doubles;
//  - power: the power operator in blocks, one per character of the mesh's mirror symmetries,
//    W = ½ Σ_c ‖B_c x_c‖², x_c the symmetry-adapted coordinates of the velocities of the same C
//    points, each block rotated to its singular basis and rounded to 16-bit multiples of one
//    quantum (quantised_power_operator.hpp): 1.9 MB at 5.6 kHz on the runs' default mesh where
//    the blocks in doubles took 27 MB.
// Both are in the level mesh's own points, before the stage carries them to its input mesh, so
// that an entry does not depend on which finer mesh the run's velocities come in on (the finest
// level depends on the sample rate, the anchors below it do not).
//
// One HDF5 file per anchor and level, KEY.h5 with KEY = "radiation-" and an FNV-1a 64 digest
// of everything the operators depend on (TyreRadiation::anchor_key): the level mesh's geometry
// to the bit (points, normals, sources, source normals: the mesh spec, the deformation, the
// band's split and rings and the sample-rate-dependent choices all act through it), the
// medium, the receivers, the anchor frequency, the regularisation, the source type and its
// coupling, the power factor's tolerance and a revision of this code. Why one file per anchor:
// the anchors are solved on parallel threads and each stores its own file as soon as it is
// solved, so no thread waits for the others and a run cut off keeps what it finished; a damaged
// file costs one anchor's solve, not the whole tyre's; and runs of one body at other sample
// rates share the anchors below their tops (the top anchor and the finest level's sidewall rings
// follow the sample rate). The body is deformed by the run's mean contact patch
// (tyre_simulation.cpp), so cases on other roads or at other speeds have their own entries:
// docs/radiation_cache.md.
//
// Layout ("rollnoise radiation anchor 3"): datasets /transfer_re, /transfer_im (R × C, doubles),
// /power_K_re, /power_K_im (k_K × t_K, 16-bit integers in units of the quantum; absent when
// k_K = 0), all in chunks through HDF5's shuffle and deflate filters; root attributes layout,
// key, power_blocks, power_K_rows (k_K), power_quantum (the quantum, a double), checksum (16 hex
// digits: FNV-1a 64 of the layout, the key, the dimensions and every value's bits as the stage
// applies them), and a description for `rollnoise cache list` (anchor_hz, sources,
// collocation_points, tread_split, sidewall_rings, receivers, power_rank, source_type,
// software). After the HDF5 bytes a 16-byte trailer: "RNCACHE1" and a checksum of every byte
// before it (FnvDigest::words), which HDF5 ignores (it reads up to the end address in its
// superblock; h5dump and h5py read the file as usual). Reading checks the trailer first, so a
// truncated or damaged file never reaches the HDF5 library (which can crash on damaged
// metadata), then the layout, the key (a foreign file renamed into place), the dimensions and
// that the quantum and the integers are in range. Anything wrong: one warning ("rollnoise:
// warning: the radiation cache entry ... is damaged or foreign (...): solving it again") and the
// anchor is solved and stored again. An entry removed by another run's trim while this one read
// it is a miss, silently. Writes go to a temporary file beside the entry, renamed into place
// (core/cache_folder.hpp): two runs storing one entry at once both leave a whole file (the same
// one: the operators are deterministic), and a reader sees the old file or the new one. A hit
// marks the entry used and a store trims the folder to its limit (core/cache_limit.hpp).
//
// The cache never changes a result: the stage applies the operators in the same way whether
// they were solved or loaded, the quantised power operator included, and HDF5 keeps doubles and
// integers bit for bit.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/cache_limit.hpp"

namespace rollnoise {

struct AnchorOperators {
  Eigen::MatrixXcd transfer;            // R × C
  std::vector<Eigen::MatrixXcd> power;  // per character: k_c × t_c, quantised (quantised_power_operator.hpp)
  double power_quantum = 0.0;           // their values' quantum (0: every block empty)
  Eigen::Index power_rank() const;      // Σ k_c
};

// What an entry says of itself (attributes), for `rollnoise cache list`.
struct AnchorDescription {
  double anchor_hz = 0.0;
  std::int64_t collocation_points = 0;
  std::int64_t sources = 0;
  std::int64_t tread_split = 1;
  std::int64_t sidewall_rings = 0;
  std::string source_type;  // "monopoles" or "combined"
};

inline constexpr char kRadiationCacheLayout[] = "rollnoise radiation anchor 3";
inline constexpr char kRadiationCachePrefix[] = "radiation-";

class RadiationCache {
 public:
  // `folder`: the cache folder (core/cache_folder.hpp), created when the first entry is stored;
  // `limit`: the folder's size limit in bytes, kept after each store (core/cache_limit.hpp).
  explicit RadiationCache(std::filesystem::path folder, std::uint64_t limit = kDefaultCacheLimitBytes);

  const std::filesystem::path& folder() const noexcept { return folder_; }
  std::uint64_t limit() const noexcept { return limit_; }
  std::filesystem::path file_of(const std::string& key) const;

  // The entry under `key` with `receivers` rows of transfer and `columns` columns, and power
  // blocks of `power_columns` columns each: std::nullopt
  // when there is none (silently) or when it is damaged, truncated or foreign (with one warning
  // naming the file and what is wrong). Safe to call from several threads.
  std::optional<AnchorOperators> load(const std::string& key, Eigen::Index receivers, Eigen::Index columns,
                                      const std::vector<Eigen::Index>& power_columns) const;
  // Stores the entry atomically, then trims the folder to the limit. An entry larger than the
  // limit by itself is not stored. A failure (a full disk, a folder made read-only mid-run) is
  // warned about once per RadiationCache and then stores are skipped: the run's results do not
  // depend on the cache. Safe to call from several threads.
  void store(const std::string& key, const AnchorOperators& operators, const AnchorDescription& description) const;

  // A run's own entries, `keys`, spared by the trims of its stores until it has loaded (or solved)
  // each: under a tight limit a store on one thread would otherwise remove an entry another thread
  // is about to read, a miss the run made for itself. release_and_trim() ends that and trims the
  // folder to the limit. Safe to call from several threads.
  void hold(const std::vector<std::string>& keys) const;
  void release_and_trim() const;

 private:
  void release(const std::string& key) const;
  bool held(const std::filesystem::path& entry) const;

  std::filesystem::path folder_;
  std::uint64_t limit_;
  mutable std::mutex held_mutex_;
  mutable std::set<std::string> held_;
  mutable std::atomic<bool> store_failed_{false};
  mutable std::atomic<bool> oversize_warned_{false};
};

// One line on an entry file for `rollnoise cache list`: its anchor, receivers, power rank,
// mesh and source type from its attributes; "damaged or foreign: WHY" when they cannot be read
// (in a child process, as load()). The content is not read: load() checks it.
std::string describe_radiation_entry(const std::filesystem::path& file);

// The FNV-1a 64 checksum of an entry's content as it is stored (the key, the dimensions, the
// values' bits), 16 hex digits.
std::string radiation_entry_checksum(const std::string& key, const AnchorOperators& operators);

}  // namespace rollnoise
