#pragma once
// A cache of computed modal receptance tables (modal_receptance_table.hpp): tabulating the
// passenger two-layer tyre for a pole fit takes tens of seconds, loading it a fraction of one.
// Each table is an HDF5 file in the layout of modal_table_hdf5.hpp, named by a digest of
// everything it depends on, KEY.h5 in the cache folder; it is written atomically, so that runs
// sharing the folder never read half a file.
//
// The key of a two-layer table digests (FNV-1a, 64 bits) the layout version, a revision number
// of the two-layer code, every parameter of the layers and modes (doubles as their exact bits;
// not the contact geometry crown_radius and tread_width, on which the table does not depend),
// the orders, the frequencies (exact bits), and a few entries of the table itself computed
// afresh (H_zz at the first, a middle and the last mode and frequency). Those entries catch most changes of the
// model's code that were not marked by a new revision: a table is reused only if the code
// reproduces it bit for bit at those samples.
//
// A cache file that is missing, unreadable or corrupt is a miss (recomputed and overwritten),
// never an error.
#include <filesystem>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "core/cache_folder.hpp"  // default_cache_directory(), the folder shared by every cache
#include "greens/modal_receptance_table.hpp"

namespace rollnoise {

class TwoLayerTyre;
struct TwoLayerParameters;

// "two_layer-" and 16 hex digits. std::invalid_argument for non-physical parameters (as
// TwoLayerTyre), orders < 0 or no frequencies.
std::string two_layer_table_key(const TwoLayerParameters& parameters, int orders, const Eigen::VectorXd& frequency_hz);

// The table stored under `key` (a file name: letters, digits, '-', '_', '.'), or std::nullopt
// when there is none or it cannot be read. Its `source` is the cache file's path.
std::optional<ModalReceptanceTable> load_cached_table(const std::filesystem::path& directory, const std::string& key);
// Stores `table` under `key`, creating the folder; std::runtime_error when it cannot.
void store_cached_table(const std::filesystem::path& directory, const std::string& key,
                        const ModalReceptanceTable& table);

// tabulate_two_layer through the cache in `directory` (none: no cache): a table found under the
// key, whose axes and sampled entries match, is returned (its `source` the cache file);
// otherwise the table is computed (`source` "two_layer") and stored. A cache that cannot be
// written only costs the time of the next computation, so that failure is ignored.
ModalReceptanceTable cached_two_layer_table(const TwoLayerTyre& tyre, const Eigen::VectorXd& frequency_hz, int orders,
                                            const std::optional<std::filesystem::path>& directory,
                                            unsigned threads = 0);

}  // namespace rollnoise
