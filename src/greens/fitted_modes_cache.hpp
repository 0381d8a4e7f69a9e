#pragma once
// A cache of the pole–residue fits of a tyre's modes (fitted_modal_tyre.hpp), beside the cache
// of the tables they were fitted to (modal_table_cache.hpp): fitting every mode of the passenger
// two-layer tyre takes about 10 s, reading them back a fraction of a second.
//
// The file is a plain binary record written by this code, not HDF5, so that reading it needs
// no library that could crash on a damaged file: the magic "RNFITS01", the key, the number of
// modes, per mode its direct term, pole count, poles and residues (doubles, this machine's byte
// order), and an FNV-1a 64 digest of all that. Anything that does not check out — a short or
// long file, wrong magic, key or count, a bad digest, an invalid response — is a miss; the
// caller fits again and overwrites.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "greens/fitted_modal_tyre.hpp"
#include "greens/modal_receptance_table.hpp"
#include "greens/pole_residue_response.hpp"
#include "greens/vector_fitting.hpp"

namespace rollnoise {

// The key of the fits of the table under `table_key` made with `options`.
std::string fitted_modes_key(const std::string& table_key, const VectorFittingOptions& options);

// The `modes` fits stored under `key` in `directory`, or std::nullopt.
std::optional<std::vector<PoleResidueResponse>> load_cached_fits(const std::filesystem::path& directory,
                                                                 const std::string& key, std::size_t modes);
// Stores them (atomically: a temporary file renamed); std::runtime_error when it cannot.
void store_cached_fits(const std::filesystem::path& directory, const std::string& key,
                       const std::vector<PoleResidueResponse>& fits);

// A digest of a table's content (its axes, shape and every value): the key of the fits of a
// table that has no other (a tabulated model's file), "table-" and 16 hex digits.
std::string modal_table_content_key(const ModalReceptanceTable& table);

// `table` made into a fitted tyre with tyre_mode_fit_options(): its fits from the cache under
// `fit_key` in `directory` when there (their errors measured again against the table), otherwise
// fitted and stored there (a cache that cannot be written is skipped). `from_cache` reports which.
FittedModalTyre fit_with_cache(ModalReceptanceTable table, std::string name,
                               const std::optional<std::filesystem::path>& directory, const std::string& fit_key,
                               bool& from_cache);

}  // namespace rollnoise
