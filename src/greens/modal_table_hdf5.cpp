#include "greens/modal_table_hdf5.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "core/cache_folder.hpp"
#include "core/child_process.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/hdf5_reader.hpp"
#include "core/hdf5_writer.hpp"

namespace rollnoise {
namespace fs = std::filesystem;
namespace {

// Bounds on the axes, checked before anything is allocated for them.
constexpr std::size_t max_frequencies = std::size_t{1} << 20;
constexpr std::size_t max_orders = std::size_t{1} << 20;
constexpr std::size_t max_lateral_orders = std::size_t{1} << 16;

const char* shape_name(LateralShape shape) { return shape == LateralShape::sine ? "sine" : "cosine"; }

// --- Reading -------------------------------------------------------------------------------

std::string required_string(const Hdf5Reader& file, const std::string& name, const std::string& allowed) {
  const auto value = file.string_attribute("/", name);
  if (!value) throw InputError(file.source(), "/ attribute " + name, "is missing; it must be " + allowed);
  return *value;
}

double required_number(const Hdf5Reader& file, const std::string& name, const std::string& allowed) {
  const auto value = file.number_attribute("/", name);
  if (!value) throw InputError(file.source(), "/ attribute " + name, "is missing; it must be " + allowed);
  return *value;
}

void require_units(const Hdf5Reader& file, const std::string& dataset, const std::string& units) {
  const auto value = file.string_attribute(dataset, "units");
  if (!value) {
    throw InputError(file.source(), dataset, "has no attribute \"units\"; add units = \"" + units + "\"");
  }
  if (*value != units) {
    throw InputError(file.source(), dataset + " attribute units",
                     "is \"" + printable_excerpt(*value) + "\"; the layout needs \"" + units + "\"");
  }
}

std::string shape_text(const std::vector<std::size_t>& dims) {
  std::string text;
  for (const std::size_t d : dims) text += (text.empty() ? "" : " x ") + std::to_string(d);
  return text;
}

// The values of a 1-D index dataset, which must be first, first + 1, … exactly.
void require_consecutive(const Hdf5Reader& file, const std::string& dataset, const Hdf5Array& array, double first,
                         const std::string& meaning) {
  for (std::size_t j = 0; j < array.values.size(); ++j) {
    const double expected = first + static_cast<double>(j);
    if (array.values[j] != expected) {
      throw InputError(file.source(), dataset + "[" + std::to_string(j) + "]",
                       "is " + format_number(array.values[j]) + "; " + meaning + " must run " + format_number(first) +
                           ", " + format_number(first + 1.0) + ", … in steps of 1 (expected " +
                           format_number(expected) + ")");
    }
  }
}

ModalReceptanceTable read_in_this_process(const fs::path& path) {
  const Hdf5Reader file(path);
  const std::string& source = file.source();
  const std::string layout = required_string(
      file, "layout", "\"" + std::string(modal_table_layout) + "\" (docs/greens/tabulated_layout.md)");
  if (layout != modal_table_layout) {
    throw InputError(source, "/ attribute layout",
                     "is \"" + printable_excerpt(layout) + "\"; this reader knows \"" + std::string(modal_table_layout) +
                         "\" only (docs/greens/tabulated_layout.md)");
  }
  const std::string form = required_string(file, "form", "\"modal\"");
  if (form != "modal") {
    throw InputError(source, "/ attribute form",
                     "is \"" + printable_excerpt(form) + "\"; layout v1 has the form \"modal\" only");
  }
  ModalReceptanceTable table;
  table.source = source;
  table.radius = required_number(file, "radius_m", "the tyre's radius in m, > 0");
  table.width = required_number(file, "width_m", "the belt's width in m, > 0");
  const std::string shape = required_string(file, "lateral_shape", "\"sine\" or \"cosine\"");
  if (shape != "sine" && shape != "cosine") {
    throw InputError(source, "/ attribute lateral_shape",
                     "is \"" + printable_excerpt(shape) + "\"; allowed are \"sine\" and \"cosine\"");
  }
  table.lateral_shape = shape == "sine" ? LateralShape::sine : LateralShape::cosine;
  const double first = required_number(file, "first_lateral_order", "an integer (>= 1 for sine, >= 0 for cosine)");
  if (!(first >= 0.0 && first <= static_cast<double>(max_lateral_orders) && first == std::floor(first))) {
    throw InputError(source, "/ attribute first_lateral_order",
                     "is " + format_number(first) + "; it must be an integer from 0 to " +
                         std::to_string(max_lateral_orders));
  }
  table.first_lateral_order = static_cast<int>(first);
  (void)file.string_attribute("/", "source");  // optional, but a string when present

  Hdf5Array frequency = file.read_numbers("/frequency", 1, max_frequencies);
  require_units(file, "/frequency", "Hz");
  const Hdf5Array order = file.read_numbers("/order", 1, max_orders);
  require_consecutive(file, "/order", order, 0.0, "the orders m");
  const Hdf5Array lateral = file.read_numbers("/lateral_order", 1, max_lateral_orders);
  require_consecutive(file, "/lateral_order", lateral, first, "the lateral orders n (from first_lateral_order)");
  const std::size_t frequencies = frequency.values.size();
  const std::size_t rows = order.values.size() * lateral.values.size();
  table.orders = static_cast<int>(order.values.size()) - 1;
  table.lateral_orders = static_cast<int>(lateral.values.size());
  if (rows > max_modal_table_values / frequencies) {
    throw InputError(source, "/receptance_re",
                     "would hold " + std::to_string(rows) + " modes x " + std::to_string(frequencies) +
                         " frequencies: more than the " + std::to_string(max_modal_table_values) + " values allowed");
  }
  table.frequency = Eigen::Map<const Eigen::VectorXd>(frequency.values.data(), static_cast<Eigen::Index>(frequencies));
  table.modes.assign(rows, Eigen::VectorXcd(static_cast<Eigen::Index>(frequencies)));
  for (const bool imaginary : {false, true}) {
    const std::string dataset = imaginary ? "/receptance_im" : "/receptance_re";
    const Hdf5Array part = file.read_numbers(dataset, 2, max_modal_table_values);
    if (part.dims.size() != 2 || part.dims[0] != rows || part.dims[1] != frequencies) {
      const bool transposed = part.dims.size() == 2 && part.dims[0] == frequencies && part.dims[1] == rows;
      throw InputError(source, dataset,
                       "has shape " + shape_text(part.dims) + "; it must be [mode][frequency], " +
                           std::to_string(rows) + " x " + std::to_string(frequencies) + " (" +
                           std::to_string(table.lateral_orders) + " lateral orders x " +
                           std::to_string(table.orders + 1) + " orders, by " + std::to_string(frequencies) +
                           " frequencies)" + (transposed ? "; it looks transposed ([frequency][mode])" : ""));
    }
    require_units(file, dataset, "m/Pa");
    for (std::size_t i = 0; i < rows; ++i) {
      Eigen::VectorXcd& mode = table.modes[i];
      for (std::size_t k = 0; k < frequencies; ++k) {
        const double v = part.values[i * frequencies + k];
        const Eigen::Index column = static_cast<Eigen::Index>(k);
        mode(column) = imaginary ? std::complex<double>(mode(column).real(), v) : std::complex<double>(v, 0.0);
      }
    }
  }
  table.validate();  // names the file: its source is the path
  return table;
}

}  // namespace

void write_modal_table(const fs::path& path, const ModalReceptanceTable& table) {
  table.validate();
  const std::size_t rows = table.modes.size();
  const Eigen::Index frequencies = table.frequency.size();
  Eigen::MatrixXd re(static_cast<Eigen::Index>(rows), frequencies);
  Eigen::MatrixXd im(static_cast<Eigen::Index>(rows), frequencies);
  for (std::size_t i = 0; i < rows; ++i) {
    re.row(static_cast<Eigen::Index>(i)) = table.modes[i].real().transpose();
    im.row(static_cast<Eigen::Index>(i)) = table.modes[i].imag().transpose();
  }
  std::vector<std::int64_t> order(static_cast<std::size_t>(table.orders + 1));
  for (std::size_t m = 0; m < order.size(); ++m) order[m] = static_cast<std::int64_t>(m);
  std::vector<std::int64_t> lateral(static_cast<std::size_t>(table.lateral_orders));
  for (std::size_t j = 0; j < lateral.size(); ++j) lateral[j] = table.first_lateral_order + static_cast<std::int64_t>(j);

  TemporaryFile temporary(path);
  try {
    Hdf5Writer h5(temporary.path());
    h5.attribute("/", "layout", std::string(modal_table_layout));
    h5.attribute("/", "form", std::string("modal"));
    h5.attribute("/", "radius_m", table.radius);
    h5.attribute("/", "width_m", table.width);
    h5.attribute("/", "lateral_shape", std::string(shape_name(table.lateral_shape)));
    h5.integer_attribute("/", "first_lateral_order", table.first_lateral_order);
    h5.attribute("/", "source", table.source);
    h5.write("/frequency", table.frequency, "Hz", "frequencies of the samples");
    h5.write_integers("/order", order, "1", "circumferential orders m (k_m = 2*pi*m/L, L = 2*pi*radius_m)");
    h5.write_integers("/lateral_order", lateral, "1",
                      std::string("lateral orders n (") + shape_name(table.lateral_shape) + "(n*pi*y/width_m))");
    const std::string rows_are = "row (n - first_lateral_order)*(M + 1) + m: mode (m, n); column: frequency";
    h5.write("/receptance_re", re, "m/Pa", "real part of the normal modal compliance H_zz(m, n, f); " + rows_are);
    h5.write("/receptance_im", im, "m/Pa", "imaginary part of the normal modal compliance H_zz(m, n, f); " + rows_are);
    h5.close();
  } catch (const std::runtime_error& error) {
    throw std::runtime_error("writing the modal table " + path.string() + ": " + error.what());
  }
  temporary.rename_to(path);
}

ModalReceptanceTable read_modal_table(const fs::path& path) {
  const std::string source = path.string();
  const std::size_t max_bytes =
      16 * sizeof(std::uint64_t) + sizeof(double) * (max_frequencies + 2 * max_modal_table_values);
  // The HDF5 library can crash or hang on a corrupted file: it reads in a child process.
  const std::string bytes = run_in_child_process(
      [&] {
        const ModalReceptanceTable table = read_in_this_process(path);
        ChildResultWriter out;
        out.doubles(&table.radius, 1);
        out.doubles(&table.width, 1);
        out.count(table.lateral_shape == LateralShape::sine ? 0 : 1);
        out.count(static_cast<std::uint64_t>(table.first_lateral_order));
        out.count(static_cast<std::uint64_t>(table.lateral_orders));
        out.count(static_cast<std::uint64_t>(table.orders));
        out.count(static_cast<std::uint64_t>(table.frequency.size()));
        out.doubles(table.frequency.data(), static_cast<std::size_t>(table.frequency.size()));
        // A VectorXcd is (re, im) pairs of doubles in memory.
        for (const Eigen::VectorXcd& mode : table.modes) {
          out.doubles(reinterpret_cast<const double*>(mode.data()), 2 * static_cast<std::size_t>(mode.size()));
        }
        return std::move(out.bytes());
      },
      source, "the HDF5 library", max_bytes, time_to_read(path));

  ChildResultReader in(bytes, "modal table " + source);
  ModalReceptanceTable table;
  table.source = source;
  in.doubles(&table.radius, 1);
  in.doubles(&table.width, 1);
  table.lateral_shape = in.count() == 0 ? LateralShape::sine : LateralShape::cosine;
  const std::uint64_t first = in.count();
  const std::uint64_t lateral = in.count();
  const std::uint64_t orders = in.count();
  const std::uint64_t frequencies = in.count();
  if (first > max_lateral_orders || lateral > max_lateral_orders || orders >= max_orders ||
      frequencies > max_frequencies || lateral * (orders + 1) * frequencies > max_modal_table_values) {
    throw std::runtime_error("modal table " + source + ": malformed result from the reading process");
  }
  table.first_lateral_order = static_cast<int>(first);
  table.lateral_orders = static_cast<int>(lateral);
  table.orders = static_cast<int>(orders);
  table.frequency.resize(static_cast<Eigen::Index>(frequencies));
  in.doubles(table.frequency.data(), static_cast<std::size_t>(frequencies));
  table.modes.assign(static_cast<std::size_t>(lateral * (orders + 1)), Eigen::VectorXcd(table.frequency.size()));
  for (Eigen::VectorXcd& mode : table.modes) {
    in.doubles(reinterpret_cast<double*>(mode.data()), 2 * static_cast<std::size_t>(frequencies));
  }
  table.validate();
  return table;
}

}  // namespace rollnoise
