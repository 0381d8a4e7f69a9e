#pragma once
// A tyre model's Green's functions and mobilities, tabulated (what `rollnoise greens` and the
// Python module's rollnoise.greens call): the receptance and mobility between a force at the
// belt's centre and responses on the centre line, the Green's function in time (around the
// whole circumference for a tyre, at the model's points for a point model), and for a two_layer
// model its modal table. The result is in memory; write_greens_outputs writes receptance.csv,
// mobility.csv, greens.h5, the modal table, summary.json and the plots into a folder, atomically.
#include <complex>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "greens/centre_line_response.hpp"
#include "greens/modal_receptance_table.hpp"

namespace rollnoise {

// At most this many frequencies and distances (--frequencies, --distances).
inline constexpr long long kMaxGreensFrequencies = 100000;
inline constexpr std::size_t kMaxGreensDistances = 10000;

// n values evenly spaced from a to b inclusive (a alone when n = 1).
std::vector<double> evenly_spaced(double a, double b, long long n);

struct GreensRunOptions {
  std::string model;                  // the model file, named in messages and summary.json
  std::optional<toml::table> toml;    // the model's keys given in memory instead of the file
  std::vector<double> frequencies;    // Hz; empty: 501 from 0 Hz to the model's top frequency
  std::vector<double> distances;      // m along the circumference; empty: the model's default
  std::optional<std::filesystem::path> cache;  // the cache folder (two-layer tables, mode fits)
  std::optional<std::uint64_t> cache_limit;    // its size limit (--cache-limit; none: the default)
  bool force = false;                 // run even when the estimate exceeds the machine
};

struct GreensRun {
  std::unique_ptr<CentreLineResponse> response;
  std::vector<double> frequencies;  // Hz (rows)
  std::vector<double> distances;    // m (columns)
  Eigen::MatrixXcd receptance;      // m/N, [frequency][distance]
  Eigen::MatrixXcd mobility;        // m/(N·s)
  Eigen::VectorXd time;             // s after the impulse
  std::vector<double> around;       // m, the Green's function's points (one revolution, or the model's)
  Eigen::MatrixXd green;            // m/(N·s), [time][point], without the delta part
  std::optional<ModalReceptanceTable> modal_table;  // two_layer
  nlohmann::json summary;           // what summary.json holds
};

// Tabulates the model. Bad input is an InputError (naming the file, or --frequencies and
// --distances for those). `out`: where the outputs will go, for the size estimate (empty: the
// current folder).
GreensRun run_greens(const GreensRunOptions& options, const std::filesystem::path& out = {});

// Writes the outputs of `run` into `out`, atomically (core/output_directory.hpp).
void write_greens_outputs(const std::filesystem::path& out, const GreensRun& run);

}  // namespace rollnoise
