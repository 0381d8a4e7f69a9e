#include "contact/contact_law_cache.hpp"

#include <cmath>
#include <exception>
#include <vector>

#include <Eigen/Core>

#include "core/cache_folder.hpp"
#include "core/error.hpp"
#include "core/hdf5_reader.hpp"
#include "core/hdf5_writer.hpp"

namespace rollnoise {
namespace {

// The form of an entry: bump when what is stored or how a law is made from it changes.
constexpr double kFormat = 1.0;

}  // namespace

std::string contact_law_cache_name(const std::string& digest_hex) { return "contact-laws-" + digest_hex + ".h5"; }

std::shared_ptr<CellContactLaws> read_contact_law_cache(const std::filesystem::path& path, std::size_t cells,
                                                        double force_cap, double minimum_compliance,
                                                        std::string& warning) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return nullptr;
  try {
    const Hdf5Reader file(path);
    if (file.number_attribute("/", "format") != kFormat || file.number_attribute("/", "force_cap_N") != force_cap ||
        file.number_attribute("/", "minimum_compliance_m_per_N") != minimum_compliance)
      throw std::runtime_error("another table form");
    const std::size_t levels = static_cast<std::size_t>(CellContactLaws::levels);
    const Hdf5Array top = file.read_numbers("top_m", 1, cells);
    const Hdf5Array sub = file.read_numbers("sub_cell_approach_m", 2, cells * levels);
    if (top.values.size() != cells || sub.dims.size() != 2 || sub.dims[0] != cells || sub.dims[1] != levels)
      throw std::runtime_error("another count of cells");
    auto laws = std::make_shared<CellContactLaws>(cells, force_cap, minimum_compliance);
    for (std::size_t c = 0; c < cells; ++c)
      laws->set(c, top.values[c], std::span<const double>(sub.values.data() + c * levels, levels));
    return laws;
  } catch (const std::exception& e) {
    warning = "the contact-law cache entry " + path.string() + " could not be used (" + e.what() +
              "): computing the laws again";
    return nullptr;
  }
}

void write_contact_law_cache(const std::filesystem::path& path, const CellContactLaws& laws) {
  TemporaryFile temporary(path);
  {
    Hdf5Writer h5(temporary.path());
    h5.attribute("/", "format", kFormat);
    h5.attribute("/", "force_cap_N", laws.force_cap());
    h5.attribute("/", "minimum_compliance_m_per_N", laws.minimum_compliance());
    h5.write("top_m", laws.tops(), "m", "each cell's first-touch height");
    h5.write("sub_cell_approach_m", laws.approach_table(), "m",
             "each cell's approach below the cell at the table's force levels");
    h5.close();
  }
  temporary.rename_to(path);
}

}  // namespace rollnoise
