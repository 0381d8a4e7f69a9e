#include "radiation/belt_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rollnoise {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The overlaps of two partitions of an interval, fine cells [f_i, f_{i+1}) and coarse cells
// [c_k, c_{k+1}), with the fine one extended periodically by `period` (0: not periodic): the
// fraction of coarse cell k covered by fine cell i, for every pair that overlaps. The fine
// partition is uniform: fine_edge(i) = start + i·step.
struct Overlap {
  int fine = 0;
  int coarse = 0;
  double fraction = 0.0;
};

std::vector<Overlap> overlaps(int fine, double start, double step, const std::vector<double>& coarse_edges, bool periodic) {
  std::vector<Overlap> out;
  for (std::size_t k = 0; k + 1 < coarse_edges.size(); ++k) {
    const double c0 = coarse_edges[k];
    const double c1 = coarse_edges[k + 1];
    // Fine cells that can reach [c0, c1), with their periodic images.
    const int first = static_cast<int>(std::floor((c0 - start) / step)) - 1;
    const int last = static_cast<int>(std::ceil((c1 - start) / step)) + 1;
    for (int i = first; i <= last; ++i) {
      const double f0 = start + i * step;
      const double f1 = start + (i + 1) * step;
      const double common = std::min(c1, f1) - std::max(c0, f0);
      if (common <= 1e-15 * (c1 - c0)) continue;
      int index = i;
      if (periodic) {
        index = ((i % fine) + fine) % fine;
      } else if (i < 0 || i >= fine) {
        continue;
      }
      out.push_back({index, static_cast<int>(k), common / (c1 - c0)});
    }
  }
  return out;
}

}  // namespace

Eigen::SparseMatrix<double> belt_to_tread_matrix(int belt_around, int belt_across, const TyreSurfaceMesh& mesh) {
  const int mesh_around = mesh.tread_around;
  const int mesh_across = mesh.tread_across;
  if (belt_around < 1 || belt_across < 1 || mesh_around < 1 || mesh_across < 1)
    throw std::invalid_argument("belt sampling: point counts must be at least 1");
  const std::vector<double>& edges = mesh.tread_angle_edges;
  if (edges.size() != static_cast<std::size_t>(mesh_around) + 1 || mesh.tread_points != mesh_around * mesh_across ||
      !(std::abs(edges.back() - edges.front() - kTwoPi) < 1e-9) || !std::is_sorted(edges.begin(), edges.end()))
    throw std::invalid_argument("belt sampling: the mesh's tread cells must cover one turn in Na + 1 rising edges");
  // Around: belt cells centred on 2πg/Nθ start half a cell early.
  const double belt_step = kTwoPi / belt_around;
  const std::vector<Overlap> around = overlaps(belt_around, -0.5 * belt_step, belt_step, edges, true);
  // Across: the mesh's row edges as fractions of the width (uniform, or with the contact
  // patch's sides as row edges on a deformed mesh).
  const std::vector<double>& rows = mesh.tread_row_edges;
  if (rows.size() != static_cast<std::size_t>(mesh_across) + 1 || !std::is_sorted(rows.begin(), rows.end()) ||
      !(rows.back() > rows.front()))
    throw std::invalid_argument("belt sampling: the mesh's tread rows must span the width in Nb + 1 rising edges");
  std::vector<double> across_edges(rows.size());
  for (std::size_t c = 0; c < rows.size(); ++c) across_edges[c] = (rows[c] - rows.front()) / (rows.back() - rows.front());
  const std::vector<Overlap> across = overlaps(belt_across, 0.0, 1.0 / belt_across, across_edges, false);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(around.size() * across.size() / std::max(1, std::min(mesh_around, mesh_across)));
  for (const Overlap& a : around)
    for (const Overlap& c : across)
      entries.emplace_back(a.coarse + mesh_around * c.coarse, c.fine + belt_across * a.fine, a.fraction * c.fraction);
  Eigen::SparseMatrix<double> m(mesh_around * mesh_across, belt_around * belt_across);
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

Eigen::SparseMatrix<double> tread_to_tread_matrix(const TyreSurfaceMesh& from, const TyreSurfaceMesh& to) {
  const int across = to.tread_across;
  if (from.tread_across != across || from.tread_row_edges.size() != to.tread_row_edges.size())
    throw std::invalid_argument("tread resampling: the meshes must have the same rows across");
  for (std::size_t c = 0; c < to.tread_row_edges.size(); ++c)
    if (!(std::abs(from.tread_row_edges[c] - to.tread_row_edges[c]) <= 1e-12))
      throw std::invalid_argument("tread resampling: the meshes must have the same rows across");
  const std::vector<double>& f = from.tread_angle_edges;
  const std::vector<double>& t = to.tread_angle_edges;
  // The overlaps in angle, each row normalised to sum 1 (the meshes' edges, accumulated cell by
  // cell, agree only to rounding; slivers of that size are left out).
  std::vector<Eigen::Triplet<double>> entries;
  for (int a = 0; a < to.tread_around; ++a) {
    const double t0 = t[static_cast<std::size_t>(a)], t1 = t[static_cast<std::size_t>(a) + 1];
    std::vector<std::pair<int, double>> row;
    double total = 0.0;
    for (int b = 0; b < from.tread_around; ++b)
      for (int turn = -1; turn <= 1; ++turn) {
        const double f0 = f[static_cast<std::size_t>(b)] + turn * kTwoPi, f1 = f[static_cast<std::size_t>(b) + 1] + turn * kTwoPi;
        const double common = std::min(t1, f1) - std::max(t0, f0);
        if (common <= 1e-9 * (t1 - t0)) continue;
        row.emplace_back(b, common);
        total += common;
      }
    for (const auto& [b, common] : row)
      for (int c = 0; c < across; ++c) entries.emplace_back(a + to.tread_around * c, b + from.tread_around * c, common / total);
  }
  Eigen::SparseMatrix<double> m(to.tread_points, from.tread_points);
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

}  // namespace rollnoise
