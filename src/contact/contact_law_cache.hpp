#pragma once
// The per-cell contact laws of a run kept between runs in the cache folder (core/cache_folder.hpp),
// under a digest of everything they are made from: the pixel heights of every cell (so any road,
// generated or read, and any change to it gives another entry), the cells' layout, the rubber
// and the table's form. A run rolling the same road at the same grid reads them instead of
// computing them again (the same numbers: a law is set from the stored δ_sub exactly as when it
// was computed). An entry that cannot be read is computed again, with a warning; one is written
// whole or not at all (TemporaryFile).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "contact/cell_contact_law.hpp"

namespace rollnoise {

// "contact-laws-<hex>.h5" for the hex digest of the laws' inputs (texture_law_digest).
std::string contact_law_cache_name(const std::string& digest_hex);

// The laws of entry `path`, or empty when it is missing; `warning` says why an entry that exists
// could not be used (damaged, foreign: another table form or count of cells).
std::shared_ptr<CellContactLaws> read_contact_law_cache(const std::filesystem::path& path, std::size_t cells,
                                                        double force_cap, double minimum_compliance,
                                                        std::string& warning);
void write_contact_law_cache(const std::filesystem::path& path, const CellContactLaws& laws);

}  // namespace rollnoise
