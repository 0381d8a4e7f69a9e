#pragma once
// The road texture as a rolling tyre samples it (TyreContactTrace::road): time series of road
// height that the energy budget turns into texture spectra over frequency, f = v/λ. At step n
// the window column i sits over the road at x_i + v·nΔt, so each column's series is the road
// profile along its line read at speed v.
#include <vector>

#include "contact/rolling_tyre.hpp"
#include "contact/tyre_grid.hpp"

namespace rollnoise {

// The road under the window column at x = 0 (i = Nw/2), on the lateral centre line(s) of the
// tread: one series for an odd Ny (row (Ny − 1)/2), two for an even Ny (rows Ny/2 − 1, Ny/2). m.
std::vector<std::vector<double>> centre_line_road(const TyreContactTrace& trace, const TyreGrid& grid);

// The mean road height over the patch: the window columns with |x_i| ≤ patch_length/2 (at least
// the centre column), all Ny rows of the tread, per step (m). This is what a rigid flat patch
// of that size would follow; it filters wavelengths shorter than the patch.
std::vector<double> patch_mean_road(const TyreContactTrace& trace, const TyreGrid& grid, double patch_length);

}  // namespace rollnoise
