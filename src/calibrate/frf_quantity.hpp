#pragma once
// What a measured frequency response function is: motion over force, as displacement
// (receptance α, m/N), velocity (mobility Y, m/(N·s)) or acceleration (accelerance A,
// m/(N·s²)). With the Fourier convention of MODEL.md §1 (α = ∫ g e^{−iωt} dt), Y = iω·α and
// A = iω·Y = −ω²·α; calibration compares mobilities.
#include <complex>
#include <optional>
#include <string>
#include <string_view>

namespace rollnoise {

enum class FrfQuantity { receptance, mobility, accelerance };

// "receptance", "mobility", "accelerance".
std::string frf_quantity_name(FrfQuantity quantity);
// The quantity with that name; std::nullopt for anything else.
std::optional<FrfQuantity> parse_frf_quantity(std::string_view name);
// "receptance, mobility or accelerance", for messages.
std::string frf_quantity_choices();

// The mobility Y = iω·α = A/(iω) for a value of `quantity` at angular frequency ω > 0 (rad/s).
std::complex<double> to_mobility(std::complex<double> value, FrfQuantity quantity, double omega);

}  // namespace rollnoise
