#pragma once
// An independent estimate of the contact force from the texture (issue 10 §1): one contact
// point, the tread a spring k_c (the tread springs over the contact area, in series) on the
// belt's point receptance α(ω) at (x = 0, y0). Holding the tyre's surface on the road,
// r = (1/k_c + α)·F, so
//   |F/r|² = 1/|1/k_c + α(ω)|².
// It knows nothing of loss of contact, of the pressure's distribution over the patch or of the
// belt's response to a distributed load; it is a scale for the rolling solution, not a
// replacement for it.
#include "greens/kropp_plate.hpp"

namespace rollnoise {

// |F/r|² in (N/m)². contact_stiffness k_c > 0 (N/m; infinity: a rigid tread), y0 in [0, b].
double single_point_force_transfer(const KroppPlate& plate, double contact_stiffness, double y0, double omega);

}  // namespace rollnoise
