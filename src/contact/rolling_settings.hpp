#pragma once
// The [rolling] table of a case: speed, duration, time step, static load and the solver's
// choices.
#include <string>

#include "contact/history_engine.hpp"
#include "contact/rolling_tyre.hpp"
#include "greens/discrete_kernel.hpp"

namespace rollnoise {

class ConfigTable;

struct RollingSettings {
  double speed = 1.0;        // v, m/s
  double duration = 1.0;     // s
  double time_step = 1e-4;   // Δt, s
  double static_load = 0.0;  // W, N
  HistoryKind history = HistoryKind::automatic;
  Discretisation discretisation = Discretisation::step;

  // Number of steps after t = 0 (the run has steps + 1 samples, t = 0 … duration).
  std::size_t steps() const;
};

// Reads and validates [rolling] for a point model; unknown keys are rejected.
RollingSettings read_rolling_settings(const ConfigTable& rolling);

// [rolling] for a tyre: the time step follows from the grid and the band (Δt = dx/(p·v), p
// sub-steps per cell), so it is not a key.
struct TyreRollingSettings {
  double speed = 0.0;             // m/s
  double duration = 0.0;          // s
  double static_load = 0.0;       // W, N
  HistoryKind history = HistoryKind::automatic;
  int points_circumferential = 512;
  int points_lateral = 16;
  double contact_window = 0.2;    // m, length of the fixed window around the bottom
  // The nominal centre of the highest third-octave band the run must carry (Hz); 0: one cell
  // per step, whatever band that gives. See substeps_for_band.
  // Hz; 0: one step per cell. With sub-steps, the fixed contact points meeting the passing
  // texture modulate the contact at the cell-passing frequency v/dx: above about 0.5·v/dx the
  // force bands lie far above a twice-finer grid's (at 80 km/h +8, +15, +23 dB at 3.15, 4 and
  // 5 kHz), so the band is not carried by default until contact points move with the tread.
  double band_top = 0.0;
  // road_sampling = "lowpass" (default) | "cell_mean" | "point" (before issue 10 §3): how the
  // contact points read texture finer than the cells (rolling_tyre.hpp, RoadSampling).
  RoadSampling road_sampling = RoadSampling::lowpass;
};

// The upper edge f_2 of the third-octave band nearest `band_top` (IEC 61260-1; 5623 Hz for the
// 5 kHz band).
double band_top_edge(double band_top);
// Sub-steps per cell p for a tyre grid of spacing dx rolling at v so that the contact steps carry
// the whole band_top band: the radiation stage computes up to 0.99 of the Nyquist frequency
// 1/(2Δt), so p is the least integer ≥ 1 with 0.99·p·v/(2·dx) ≥ band_top_edge(band_top).
// band_top = 0: p = 1.
int substeps_for_band(double band_top, double dx, double speed);
TyreRollingSettings read_tyre_rolling_settings(const ConfigTable& rolling);

}  // namespace rollnoise
