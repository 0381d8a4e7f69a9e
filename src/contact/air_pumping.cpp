#include "contact/air_pumping.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rollnoise {

AirPumping::AirPumping(const AirPumpingGeometry& geometry) : geometry_(geometry) {
  const AirPumpingGeometry& g = geometry_;
  if (g.window < 2 || g.lateral < 1 || !(g.dx > 0.0) || !(g.dy > 0.0) || g.substeps < 1 || !(g.dt > 0.0) ||
      !(g.sealing_gap >= 0.0))
    throw std::invalid_argument("air pumping: the grid needs at least 2 × 1 cells, dx, dy, dt > 0, p >= 1 and a "
                                "sealing gap >= 0 (got " + std::to_string(g.window) + " × " + std::to_string(g.lateral) +
                                " cells, p = " + std::to_string(g.substeps) + ")");
  const auto points = static_cast<std::size_t>(g.window) * static_cast<std::size_t>(g.lateral);
  ring_.resize(static_cast<std::size_t>(g.substeps));
  for (Slot& s : ring_) {
    s.gap.assign(points, 0.0);
    s.destination.assign(points, none);
    s.closed.assign(points, 0);
    s.thin.assign(points, 0);
  }
  first_.assign(static_cast<std::size_t>(g.lateral), 0);
  last_.assign(static_cast<std::size_t>(g.lateral), 0);
  label_.assign(points, -1);
  stack_.assign(points, 0);
  gap_.assign(points, 0.0);
  destination_.assign(points, none);
  closed_.assign(points, 0);
  thin_.assign(points, 0);
  opens_front_.assign(points, 0);
  opens_rear_.assign(points, 0);
}

AirPumpingStep AirPumping::step(const Eigen::Ref<const Eigen::VectorXd>& gap, const Eigen::Ref<const Eigen::VectorXd>& force) {
  const int w = geometry_.window, ny = geometry_.lateral;
  const auto points = static_cast<std::size_t>(w) * static_cast<std::size_t>(ny);
  if (static_cast<std::size_t>(gap.size()) != points || static_cast<std::size_t>(force.size()) != points)
    throw std::invalid_argument("air pumping: a step needs " + std::to_string(points) + " gaps and forces (got " +
                                std::to_string(gap.size()) + " and " + std::to_string(force.size()) + ")");
  const double seal = geometry_.sealing_gap;
  const double cell_area = geometry_.dx * geometry_.dy;
  Slot& slot = ring_[steps_ % ring_.size()];  // holds step n − p until it is overwritten below
  const auto at = [w](int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(w) * static_cast<std::size_t>(j); };
  const auto in_contact = [&](std::size_t p) { return force(static_cast<Eigen::Index>(p)) > 0.0; };
  const auto air = [&](std::size_t p) { return in_contact(p) ? 0.0 : std::max(0.0, gap(static_cast<Eigen::Index>(p))); };

  // Each line's span of contact; the patch's centre along x (its columns' extent).
  int i_min = w, i_max = -1;
  for (int j = 0; j < ny; ++j) {
    int a = w, b = -1;
    for (int i = 0; i < w; ++i)
      if (in_contact(at(i, j))) {
        a = std::min(a, i);
        b = i;
      }
    first_[static_cast<std::size_t>(j)] = a;
    last_[static_cast<std::size_t>(j)] = b;
    i_min = std::min(i_min, a);
    i_max = std::max(i_max, b);
  }
  const double centre = 0.5 * (i_min + i_max);
  const auto inside = [&](int i, int j) {
    return i > first_[static_cast<std::size_t>(j)] && i < last_[static_cast<std::size_t>(j)] && !in_contact(at(i, j));
  };
  const auto conducting = [&](int i, int j) { return inside(i, j) && air(at(i, j)) >= seal; };
  const auto nearer_edge = [&](int i) { return i > centre ? front : rear; };

  // Regions of conducting inside cells, and where each opens.
  std::fill(label_.begin(), label_.end(), -1);
  int regions = 0;
  AirPumpingStep out;
  for (int j0 = 0; j0 < ny; ++j0)
    for (int i0 = 0; i0 < w; ++i0) {
      if (label_[at(i0, j0)] >= 0 || !conducting(i0, j0)) continue;
      const int region = regions++;
      opens_front_[static_cast<std::size_t>(region)] = 0;
      opens_rear_[static_cast<std::size_t>(region)] = 0;
      std::size_t top = 0;
      stack_[top++] = static_cast<int>(at(i0, j0));
      label_[at(i0, j0)] = region;
      while (top > 0) {
        const int p = stack_[--top];
        const int i = p % w, j = p / w;
        const auto visit = [&](int ii, int jj) {
          if (label_[at(ii, jj)] < 0 && conducting(ii, jj)) {
            label_[at(ii, jj)] = region;
            stack_[top++] = static_cast<int>(at(ii, jj));
          }
        };
        if (i > 0) visit(i - 1, j);
        if (i + 1 < w) visit(i + 1, j);
        // Across: the next line, or beyond the tread (the shoulder's open air).
        for (const int jj : {j - 1, j + 1}) {
          if (jj < 0 || jj >= ny) {
            (nearer_edge(i) == front ? opens_front_ : opens_rear_)[static_cast<std::size_t>(region)] = 1;
            continue;
          }
          if (inside(i, jj) || in_contact(at(i, jj))) {
            visit(i, jj);
            continue;
          }
          if (air(at(i, jj)) < seal) continue;  // open air, but through a gap too thin to flow
          const int b = last_[static_cast<std::size_t>(jj)];
          // Ahead of that line's contact, behind it, or a line with none (a circumferential
          // groove: a tunnel whose nearer end takes the air).
          const Destination edge = b < 0 ? nearer_edge(i) : i > b ? front : rear;
          (edge == front ? opens_front_ : opens_rear_)[static_cast<std::size_t>(region)] = 1;
        }
      }
      const bool closed = !opens_front_[static_cast<std::size_t>(region)] && !opens_rear_[static_cast<std::size_t>(region)];
      ++(closed ? out.closed_regions : out.open_regions);
    }

  // This step's destination of every inside cell.
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < w; ++i) {
      const std::size_t p = at(i, j);
      const double g = air(p);
      gap_[p] = g;
      destination_[p] = none;
      closed_[p] = 0;
      thin_[p] = 0;
      if (!inside(i, j)) continue;
      const int region = label_[p];
      if (region < 0) {
        destination_[p] = nearer_edge(i);  // a thin cell: its air seeps out through the texture
        thin_[p] = 1;
      } else {
        const bool f = opens_front_[static_cast<std::size_t>(region)], r = opens_rear_[static_cast<std::size_t>(region)];
        closed_[p] = !f && !r;
        destination_[p] = f && !r ? front : r && !f ? rear : nearer_edge(i);
      }
      out.enclosed_volume += g * cell_area;
      if (closed_[p]) out.closed_volume += g * cell_area;
    }
  // The flows against step n − p: the material at (i, j) now was at (i + 1, j) then. A cell
  // counts where its air goes now or, if it is no longer inside, where it went then.
  const bool ready = steps_ >= ring_.size();
  const double per_second = cell_area / (static_cast<double>(geometry_.substeps) * geometry_.dt);
  if (ready)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i + 1 < w; ++i) {
        const std::size_t p = at(i, j), before = at(i + 1, j);
        const bool now = destination_[p] != none;
        const auto d = now ? destination_[p] : slot.destination[before];
        if (d == none) continue;
        const double flow = -(gap_[p] - slot.gap[before]) * per_second;
        (d == front ? out.front_flow : out.rear_flow) += flow;
        if (now ? closed_[p] : slot.closed[before]) out.closed_flow += flow;
        if (now ? thin_[p] : slot.thin[before]) out.thin_flow += flow;
      }
  // Step n's state takes the place of step n − p's, which has been read.
  std::swap(slot.gap, gap_);
  std::swap(slot.destination, destination_);
  std::swap(slot.closed, closed_);
  std::swap(slot.thin, thin_);
  out.ready = ready;
  ++steps_;
  return out;
}

}  // namespace rollnoise
