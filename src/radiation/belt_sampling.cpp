#include "radiation/belt_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rollnoise {
namespace {

// Overlaps of cells of two partitions of [0, 1) into n and m equal cells centred at i/n and
// k/m (periodic) or (i + ½)/n and (k + ½)/m (not periodic): the fraction of coarse cell k
// covered by fine cell i, for every pair that overlaps.
struct Overlap {
  int fine = 0;
  int coarse = 0;
  double fraction = 0.0;
};

std::vector<Overlap> overlaps(int fine, int coarse, bool periodic) {
  std::vector<Overlap> out;
  const double shift = periodic ? -0.5 : 0.0;  // cells centred on i/n start half a cell early
  for (int k = 0; k < coarse; ++k) {
    const double c0 = (k + shift) / coarse;
    const double c1 = (k + 1 + shift) / coarse;
    // Fine cells that can reach [c0, c1), with their periodic images.
    const int first = static_cast<int>(std::floor(c0 * fine)) - 1;
    const int last = static_cast<int>(std::ceil(c1 * fine)) + 1;
    for (int i = first; i <= last; ++i) {
      const double f0 = (i + shift) / fine;
      const double f1 = (i + 1 + shift) / fine;
      const double common = std::min(c1, f1) - std::max(c0, f0);
      if (common <= 1e-15) continue;
      int index = i;
      if (periodic) {
        index = ((i % fine) + fine) % fine;
      } else if (i < 0 || i >= fine) {
        continue;
      }
      out.push_back({index, k, common * coarse});
    }
  }
  return out;
}

}  // namespace

Eigen::SparseMatrix<double> belt_to_tread_matrix(int belt_around, int belt_across, int mesh_around, int mesh_across) {
  if (belt_around < 1 || belt_across < 1 || mesh_around < 1 || mesh_across < 1)
    throw std::invalid_argument("belt sampling: point counts must be at least 1");
  const std::vector<Overlap> around = overlaps(belt_around, mesh_around, true);
  const std::vector<Overlap> across = overlaps(belt_across, mesh_across, false);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(around.size() * across.size() / std::max(1, std::min(mesh_around, mesh_across)));
  for (const Overlap& a : around)
    for (const Overlap& c : across)
      entries.emplace_back(a.coarse + mesh_around * c.coarse, c.fine + belt_across * a.fine, a.fraction * c.fraction);
  Eigen::SparseMatrix<double> m(mesh_around * mesh_across, belt_around * belt_across);
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

}  // namespace rollnoise
