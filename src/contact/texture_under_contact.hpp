#pragma once
// The road texture as a rolling tyre samples it: time series of road height that the energy
// budget turns into texture spectra over frequency, f = v/λ. At step n the window column i sits
// over the road at x_i + v·nΔt, so each column's series is the road profile along its line read
// at speed v.
#include <vector>

#include <Eigen/Core>

#include "contact/rolling_tyre.hpp"
#include "contact/tyre_grid.hpp"

namespace rollnoise {

// Gathers, step by step, what the budget needs of the road under the window: the centre
// column's lines and each column's mean over the tread's rows (Nw values a step, not Nw·Ny, so a
// streamed run keeps a small fraction of its fields).
class TextureUnderContact {
 public:
  explicit TextureUnderContact(const TyreGrid& grid);
  // One step's road under the window, p = i + Nw·j (m).
  void push(const Eigen::Ref<const Eigen::VectorXd>& road);

  // The road under the window column at x = 0 (i = Nw/2), on the lateral centre line(s) of the
  // tread: one series for an odd Ny (row (Ny − 1)/2), two for an even Ny (rows Ny/2 − 1,
  // Ny/2). m.
  const std::vector<std::vector<double>>& centre_lines() const noexcept { return centre_; }

  // The mean road height over the patch: the window columns with |x_i| ≤ patch_length/2 (at
  // least the centre column), all Ny rows of the tread, per step (m). This is what a rigid flat
  // patch of that size would follow; it filters wavelengths shorter than the patch.
  std::vector<double> patch_mean(double patch_length) const;

 private:
  TyreGrid grid_;
  std::vector<int> centre_rows_;
  std::vector<std::vector<double>> centre_;
  std::vector<double> column_means_;  // step-major: Nw per step
};

// The same from a trace that kept its road field (TyreRunSettings::keep_fields).
std::vector<std::vector<double>> centre_line_road(const TyreContactTrace& trace, const TyreGrid& grid);
std::vector<double> patch_mean_road(const TyreContactTrace& trace, const TyreGrid& grid, double patch_length);

}  // namespace rollnoise
