#pragma once
// What `rollnoise greens` tabulates for any tyre model: the response along the belt's centre
// line to a radial force at the centre of the belt (x = 0), in the frequency domain (receptance
// at any ω, the static compliance at ω = 0) and in the time domain (the Green's function, the
// paper's Fig. 5a). One interface for every model, so that the verb and its outputs are written
// once (the point models, the plate, the two-layer tyre and tabulated tables).
#include <complex>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "greens/modal_receptance_table.hpp"

namespace rollnoise {

class ConfigTable;
class FittedModalTyre;
struct PlateParameters;

class CentreLineResponse {
 public:
  virtual ~CentreLineResponse() = default;

  // The model-file `model` value.
  virtual std::string model() const = 0;
  // What the receptance includes (for the reader of the outputs), such as "belt only: the
  // tread's local compliance is added by the contact stage".
  virtual std::string description() const = 0;
  // Circumference L = 2πR (m) of a tyre model; 0 for a point model.
  virtual double circumference() const = 0;
  // The response points a user most likely wants, m along the circumference (0 = the point).
  virtual std::vector<double> default_distances() const = 0;
  // A frequency range the model describes well, Hz (its modal truncation, or a few times its
  // resonance).
  virtual double default_top_frequency_hz() const = 0;
  // Whether `distance` (m) is a place the model can answer for (a point model: its points).
  virtual bool has_point(double distance) const = 0;

  // Receptance α(ω) = u/F in m/N from the force at x = 0 to the response at `distance`;
  // ω = 0 gives the static compliance.
  virtual std::complex<double> receptance(double distance, double omega) const = 0;
  // The Green's function in m/(N·s) (the displacement per unit impulse, without an
  // instantaneous δ part, which receptance() includes) at t_k = (k + 1)·dt, k = 0 … count − 1,
  // [k][distance]. Models with a closed form give its values at t_k; models transformed from
  // the frequency domain give the mean over the step ending at t_k (what the contact's step
  // kernel uses), which description() says.
  virtual Eigen::MatrixXd green_table(std::span<const double> distances, double dt, int count) const = 0;

  // The model's modal receptance table at these frequencies (Hz), for models computed from
  // parameters that have one to give (two_layer: every mode it sums, m = 0 … M), through the
  // table cache in `cache` (none: computed); std::nullopt for the others. A `tabulated` model
  // file pointed at the table written out gives the same receptance (within the pole fit).
  virtual std::optional<ModalReceptanceTable> modal_table(const Eigen::VectorXd& /*frequency_hz*/,
                                                          const std::optional<std::filesystem::path>& /*cache*/) const {
    return std::nullopt;
  }
  // A model known by a table: its table and the pole fit the responses come from; null for
  // the others.
  virtual const FittedModalTyre* fitted_modes() const { return nullptr; }
};

// Builds the view of a model file (the keys of a [tyre] table at its top level) with the readers
// `simulate` uses: unknown keys and unphysical values are InputErrors naming the file and key;
// a `tabulated` table that cannot be read or fitted is an InputError naming the table's file.
// A `tabulated` model's mode fits go through the cache folder `cache` (fitted_modes_cache.hpp;
// none: not cached); without it, default_cache_directory().
std::unique_ptr<CentreLineResponse> make_centre_line_response(const ConfigTable& model);
std::unique_ptr<CentreLineResponse> make_centre_line_response(const ConfigTable& model,
                                                              const std::optional<std::filesystem::path>& cache);
// The plate's view, for a plate already read (simulate draws its Fig. 5a from it).
std::unique_ptr<CentreLineResponse> make_plate_centre_line(const PlateParameters& plate);

}  // namespace rollnoise
