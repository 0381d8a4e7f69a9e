#pragma once
// A tyre known by a table of its modal compliances (modal_receptance_table.hpp: the two-layer
// tyre's exact layer solutions, or a tabulated model's file), made into a ModalTyre for rolling
// (modal_tyre.hpp) by fitting poles and residues to every mode (vector_fitting.hpp). The fit is
// what makes a model without a closed-form time response roll with the same exact one-state
// recursions as the plate (issue 11, "a pole–residue fit per order"); its accuracy per mode is
// measured against the table and reported (fit_report()).
//
// The table's H_mn(ω) is per traction amplitude of the shape (m/Pa). For the contact's cells of
// length ℓ and width w the rolling code's modal form (modal_tyre.hpp) needs
//   h_ml ↔ H_mn·c_m²·c_n²/(L·N_n),   c_m = sinc(k_m ℓ/2),  c_n = sinc(k_n w/2),
// (the force spread over a cell and the displacement averaged over it: the cell's mean of
// e^{ik_m x} and of sin or cos(k_n y)), as in two_layer_tyre.hpp's receptance.
#include <string>
#include <vector>

#include "greens/modal_receptance_table.hpp"
#include "greens/modal_tyre.hpp"
#include "greens/vector_fitting.hpp"

namespace rollnoise {

// How well the poles reproduce the table, over all modes (relative errors as vector_fitting.hpp
// defines them).
struct ModalFitReport {
  std::size_t modes = 0;
  std::size_t poles = 0;          // total over all modes
  std::size_t unconverged = 0;    // modes that missed the options' targets
  double worst_rms_error = 0.0;
  double mean_rms_error = 0.0;
  double worst_max_error = 0.0;
  int worst_order = 0;            // m of the worst mode (by RMS error)
  int worst_lateral_order = 0;    // n of the worst mode
  double seconds = 0.0;           // wall time of the fits
};

class FittedModalTyre final : public ModalTyre {
 public:
  // Fits every mode of `table` (validated first); modes are spread over `threads` threads (0: the
  // hardware's count), each fitted alone, so the result does not depend on the thread count.
  // `includes_tread`: whether the table is of the tread surface (a layered model, or a table of
  // the tread surface from elsewhere).
  FittedModalTyre(ModalReceptanceTable table, std::string name, bool includes_tread,
                  const VectorFittingOptions& options, unsigned threads = 0);
  // With fits made before (fitted_modes_cache.hpp), one per mode in mode order (l·(M + 1) + m):
  // their errors against `table` are measured again for the report, and `options`' targets say
  // which count as converged. std::invalid_argument when their number or a fit is wrong.
  FittedModalTyre(ModalReceptanceTable table, std::string name, bool includes_tread,
                  std::vector<PoleResidueResponse> fits, const VectorFittingOptions& options);

  std::string name() const override { return name_; }
  double circumference() const override { return table_.circumference(); }
  double width() const override { return table_.width; }
  int orders() const override { return table_.orders; }
  int lateral_modes() const override { return table_.lateral_orders; }
  double lateral_shape(int l, double y) const override {
    return table_.lateral_shape_value(table_.first_lateral_order + l, y);
  }
  PoleResidueResponse mode_response(int m, int l, double cell_length, double cell_width) const override;
  bool includes_tread() const override { return includes_tread_; }

  // The fitted H_mn (m/Pa) of order m and lateral index l (n = first + l).
  const PoleResidueResponse& fitted(int m, int l) const;
  const ModalFitReport& fit_report() const noexcept { return report_; }
  const ModalReceptanceTable& table() const noexcept { return table_; }
  const std::vector<PoleResidueResponse>& fits() const noexcept { return fits_; }

 private:
  ModalReceptanceTable table_;
  std::string name_;
  bool includes_tread_;
  // Fills report_ from each mode's errors (in mode order) and pole counts.
  void summarise(const std::vector<double>& rms, const std::vector<double>& max, const std::vector<char>& converged);

  std::vector<PoleResidueResponse> fits_;  // index l·(M + 1) + m
  ModalFitReport report_;
};

// The fit rollnoise uses for tyre modes, and the frequencies it samples: 0 Hz and 160 values
// log-spaced from 1 Hz to 20 kHz (4.2 % apart), relative weighting, 2 real starting poles, no
// direct term, until a relative RMS error of 3e-3 (largest 3e-2). Chosen on the passenger
// two-layer tyre's modes (0,1), (10,3), (60,5), (150,10), (250,13), (256,25), (3,20) against
// their Green's functions by FFT (two_layer_greens_functions.hpp) at the 80 km/h step of 88 µs:
// 20–30 poles and 2–4 ms per mode, step means within 4.4e-3 of the peak over 90 ms, static
// compliance within 0.25 %. Sampling to 50 kHz at 1e-3 (the tread's 7–11 thickness resonances
// below 50 kHz each fitted) needed 30–66 poles and 3–11 ms for errors of 0.6e-4–0.9e-3, a
// contact step does not see; uniform weighting did no better (docs/greens/rolling_fit.md).
VectorFittingOptions tyre_mode_fit_options();
Eigen::VectorXd tyre_mode_fit_frequencies();

}  // namespace rollnoise
