#pragma once
// The normal modal compliances of a translation-invariant tyre, sampled at frequencies (issue 11,
// "tabulated Green's functions"): the form in which a layered model (two_layer_tyre.hpp), or a
// file (modal_table_hdf5.hpp), hands its modes to the rolling code, which fits poles to each
// mode (pole_residue_response.hpp).
//
// The tyre is periodic along the circumference x (L = 2πR) and has width b. Its modes are
// e^{i k_m x}·φ_n(y), k_m = 2πm/L, with the lateral shapes
//   sine:   φ_n = sin(nπy/b)  (simply supported edges, n ≥ 1),
//   cosine: φ_n = cos(nπy/b)  (sliding edges, n ≥ 0),
// and the modal norm L·N_n, N_n = ∫₀ᵇ φ_n² dy = b/2 (b for the cosine n = 0). Per mode the table
// holds H_mn(ω) = H_zz(m, n, ω), m/Pa: the normal displacement amplitude of the shape per normal
// traction amplitude of the same shape, for m = 0 … M (H(−m) = H(m) for the normal component)
// and n = first … first + N − 1. The normal receptance between two surface points follows as
//   α_zz = Σ_n Σ_m H_mn e^{ik_m(x_r − x_s)} φ_n(y_r) φ_n(y_s) / (L·N_n).
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

class TwoLayerTyre;

enum class LateralShape { sine, cosine };

struct ModalReceptanceTable {
  double radius = 0.0;  // R, m (L = 2πR)
  double width = 0.0;   // b, m
  LateralShape lateral_shape = LateralShape::sine;
  int first_lateral_order = 1;  // n of the first row: ≥ 1 for sine, ≥ 0 for cosine
  int lateral_orders = 0;       // N: n = first … first + N − 1
  int orders = 0;               // M: m = 0 … M
  Eigen::VectorXd frequency;    // Hz, strictly increasing, ≥ 0 (0: the static compliance)
  // H_mn at each frequency, m/Pa; index mode_index(m, n) = (n − first)·(M + 1) + m.
  std::vector<Eigen::VectorXcd> modes;
  // Where the values came from, for messages: "two_layer" when computed, the file's path when
  // read (modal_table_hdf5.hpp).
  std::string source;

  double circumference() const noexcept;          // L = 2πR, m
  int last_lateral_order() const noexcept { return first_lateral_order + lateral_orders - 1; }
  double wavenumber_x(int m) const noexcept;      // k_m = 2πm/L, rad/m
  double wavenumber_y(int n) const noexcept;      // nπ/b, rad/m
  double modal_norm(int n) const noexcept;        // L·N_n, m²
  double lateral_shape_value(int n, double y) const noexcept;  // φ_n(y)
  std::size_t mode_index(int m, int n) const;     // std::out_of_range outside the table
  const Eigen::VectorXcd& mode(int m, int n) const { return modes[mode_index(m, n)]; }

  // Throws InputError(source, what, problem) unless the table is whole and physical: R, b > 0,
  // orders ≥ 0, N ≥ 1, a lateral order range its shape allows, frequencies finite, ≥ 0 and
  // strictly increasing, every mode sized like `frequency` with finite values. The places are
  // named as in the HDF5 layout (modal_table_hdf5.hpp): "/frequency[3]", "/ attribute radius_m".
  void validate() const;
};

// Evaluates H_zz(m, n, 2πf) of the tyre for m = 0 … orders, every lateral order of the tyre and
// every frequency (Hz, ≥ 0, strictly increasing). `orders` may exceed the tyre's own
// circumferential_modes: each mode is an exact layer solution for any m. Frequencies are
// spread over `threads` threads (0: the hardware's count); each value is computed alone, so the
// result does not depend on the thread count. std::invalid_argument for bad arguments.
ModalReceptanceTable tabulate_two_layer(const TwoLayerTyre& tyre, const Eigen::VectorXd& frequency_hz, int orders,
                                        unsigned threads = 0);

// One entry of that table, H_zz(m, n, 2πf), m/Pa, computed exactly as tabulate_two_layer does.
std::complex<double> two_layer_entry(const TwoLayerTyre& tyre, int m, int n, double frequency_hz);

// The frequencies a pole fit of a mode needs for a contact step of about 88 µs: 0 Hz (the static
// compliance) and `count` values log-spaced from `lowest` to `highest` Hz, both included. The
// default band runs well past the 5.7 kHz Nyquist frequency of that step, to where each mode's
// response has become the dashpot-like tail 1/(iωZ). 121 values.
Eigen::VectorXd default_fit_frequencies(int count = 120, double lowest = 1.0, double highest = 5.0e4);

}  // namespace rollnoise
