#pragma once
// Air pumping from the contact solution (docs/physics/air-pumping.md): each step, the air
// between tread, road and the grooves or road cavities inside the contact patch, the rate at
// which the rolling squeezes or opens it, and where that air leaves the patch.
//
// Hayden (1971) took the volume of the tread's cavities as the tyre rolls and radiated its rate of
// change as a monopole, p = ρ·q̇(t − r/c)/(4πr); Gagen (1999) and Kim et al. (JASA 119, 2006)
// followed the air inside the grooves; Bou Leba Bassil et al. (JSV 469, 2020) did the same for the
// road's cavities. Here the volumes come from the solved contact: a window cell's air gap g is the
// gap the contact problem has (road, pattern, tyre displacement; zero in contact), and
//  - a cell is inside the patch when its lateral line has cells in contact ahead of and behind
//    it; the others are open air beside, ahead of or behind the patch;
//  - the inside cells whose gap is at least `sealing_gap` conduct air; thinner gaps (the road's
//    connected texture under a cell, a cell just off the road) do not. The conducting cells form
//    regions (4-connectivity). A region is closed when none of its cells has a lateral neighbour
//    in the open air with a conducting gap (the tyre's shoulder, a line without contact such as a
//    circumferential groove, the air ahead or behind a line's contact); open at the front, the
//    rear or both otherwise;
//  - the air a cell gives up is the change of its gap following the material, which passes the
//    window one cell per p sub-steps (no slip): q_cell = −(g(i, j, n) − g(i + 1, j, n − p))·ΔxΔy/(p·Δt),
//    a volume flow out (m³/s) over the last p steps. A cell counts while it is inside the patch now
//    or was p steps ago (a cavity closing to zero, a groove opening at the rear), so regions that
//    merge, split, are caught or let go give no jumps of volume, only their flows;
//  - the air leaves at the patch's front edge or its rear edge: an open region's through its
//    openings (each cell to the nearer edge when it opens at both), a closed region's (which can
//    only leak through the road's texture, Hayden's assumption that it is squeezed out) and a thin
//    cell's to the nearer edge along x.
// A slick on a smooth road gives the same flows every step (the steady shape's wedges), which
// radiate nothing: only what changes with time is heard.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

// The gap below which a cell's air does not flow: twice the viscous boundary layer at 1 kHz,
// 2·√(2ν/ω) = 0.14 mm for ν = 1.5e-5 m²/s, where a channel's acoustic flow is held by viscosity
// (a physical scale of the air, not fitted to a result).
inline constexpr double air_sealing_gap = 0.14e-3;  // m

// The height above the road of the monopoles where the air leaves the patch: the mouth of the
// wedge between tread and road a groove opens into is a few millimetres high. Below 5 kHz
// (kh < 0.4) the source and its image in the road are in phase whatever the height within it.
inline constexpr double air_pumping_source_height = 0.004;  // m

struct AirPumpingGeometry {
  int window = 0;      // cells along x (the contact window's columns)
  int lateral = 0;     // lines across
  double dx = 0.0;     // m
  double dy = 0.0;     // m
  int substeps = 1;    // p: steps per cell of travel
  double dt = 0.0;     // s per step
  double sealing_gap = air_sealing_gap;  // m
};

// One step's air flows, m³/s out of the patch (positive: air leaves), and volumes (m³).
struct AirPumpingStep {
  bool ready = false;       // false for the first p steps: no state p steps back to compare with
  double front_flow = 0.0;  // through the front edge (the leading edge, +x)
  double rear_flow = 0.0;   // through the rear edge
  double closed_flow = 0.0;  // of which from closed regions
  double thin_flow = 0.0;    // and from thin cells (gaps below the sealing gap)
  double closed_volume = 0.0;   // the air in closed regions now
  double enclosed_volume = 0.0;  // the air inside the patch now (closed, open and thin cells)
  int closed_regions = 0;
  int open_regions = 0;
};

// A run's air pumping, step by step (rolling_tyre.hpp fills it when asked).
struct AirPumpingTrace {
  Eigen::VectorXd front_flow, rear_flow, closed_flow, thin_flow;  // m³/s out of the patch, per step
  Eigen::VectorXd closed_volume, enclosed_volume;      // m³
  double front_edge_x = 0.0;  // m: the steady patch's leading edge (window coordinates, axle at 0)
  double rear_edge_x = 0.0;   // and its trailing edge, where the flows leave
  double seconds = 0.0;       // wall time of the air pumping in the step loop
  int most_closed_regions = 0;  // at any step
};

// Holds the last p steps' gaps and where each cell's air went; sized once, so that step()
// allocates nothing (it runs inside the contact loop).
class AirPumping {
 public:
  explicit AirPumping(const AirPumpingGeometry& geometry);

  // gap: each window point's air gap (m; p = i + window·j), force: its contact force (N; > 0
  // means in contact, where the gap is taken as 0).
  AirPumpingStep step(const Eigen::Ref<const Eigen::VectorXd>& gap, const Eigen::Ref<const Eigen::VectorXd>& force);

  const AirPumpingGeometry& geometry() const noexcept { return geometry_; }

 private:
  enum Destination : signed char { none = 0, front = 1, rear = 2 };
  struct Slot {
    std::vector<double> gap;
    std::vector<signed char> destination;
    std::vector<char> closed;
    std::vector<char> thin;
  };
  AirPumpingGeometry geometry_;
  std::size_t steps_ = 0;
  std::vector<Slot> ring_;  // the last p steps
  std::vector<int> first_, last_;  // per line: the first and last column in contact
  std::vector<int> label_;  // region of each conducting inside cell, −1 otherwise
  std::vector<int> stack_;  // the flood fill's
  std::vector<char> opens_front_, opens_rear_;  // per region
  // This step's state, built beside the ring's slot and then swapped into it.
  std::vector<double> gap_;
  std::vector<signed char> destination_;
  std::vector<char> closed_;
  std::vector<char> thin_;
};

}  // namespace rollnoise
