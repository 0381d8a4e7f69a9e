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

std::string contact_law_cache_name(std::uint64_t digest) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string hex(16, '0');
  for (int i = 0; i < 16; ++i) hex[static_cast<std::size_t>(15 - i)] = digits[(digest >> (4 * i)) & 0xf];
  return "contact-laws-" + hex + ".h5";
}

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
    const auto cells = static_cast<Eigen::Index>(laws.cells());
    Eigen::VectorXd top(cells);
    Eigen::MatrixXd sub(cells, CellContactLaws::levels);
    for (Eigen::Index c = 0; c < cells; ++c) {
      top(c) = laws.top(static_cast<std::size_t>(c));
      const auto approaches = laws.approaches(static_cast<std::size_t>(c));
      for (int k = 0; k < CellContactLaws::levels; ++k) sub(c, k) = static_cast<double>(approaches[static_cast<std::size_t>(k)]);
    }
    h5.write("top_m", top, "m", "each cell's first-touch height");
    h5.write("sub_cell_approach_m", sub, "m", "each cell's approach below the cell at the table's force levels");
    h5.close();
  }
  temporary.rename_to(path);
}

}  // namespace rollnoise
