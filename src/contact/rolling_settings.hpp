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
  // 0: derived from band_top (circumferential_points_for_band), or 512 with band_top = 0.
  int points_circumferential = 0;
  int points_lateral = 16;
  double contact_window = 0.2;    // m, length of the fixed window around the bottom
  // The nominal centre of the highest third-octave band the run must carry (Hz; default 5000,
  // the top of ISO 11819-2's CPX range); 0: one step per cell on 512 cells, whatever band that
  // gives. Unless points_circumferential is given, the grid is made fine enough that one step
  // per cell carries the band (circumferential_points_for_band). A given grid too coarse for the
  // band takes sub-steps instead (substeps_for_band), which bring the cell-passing artefact
  // into the bands above about 0.5·v/dx: the fixed contact points meeting the passing texture
  // modulate the contact at v/dx (at 80 km/h on 512 cells +8, +15, +23 dB at 3.15, 4 and 5 kHz
  // against 1024 cells); one step per cell has no such line (it aliases to 0 Hz).
  double band_top = 5000.0;
  // road_sampling = "lowpass" (default) | "cell_mean" | "point" (before issue 10 §3): how the
  // contact points read texture finer than the cells (rolling_tyre.hpp, RoadSampling).
  RoadSampling road_sampling = RoadSampling::lowpass;
  // contact_law = "rigid" (default) | "texture": how a cell meets the texture inside it
  // (rolling_tyre.hpp, ContactLaw).
  ContactLaw contact_law = ContactLaw::rigid;
};

// The upper edge f_2 of the third-octave band nearest `band_top` (IEC 61260-1; 5623 Hz for the
// 5 kHz band).
double band_top_edge(double band_top);
// Sub-steps per cell p for a tyre grid of spacing dx rolling at v so that the contact steps carry
// the whole band_top band: the radiation stage computes up to 0.99 of the Nyquist frequency
// 1/(2Δt), so p is the least integer ≥ 1 with 0.99·p·v/(2·dx) ≥ band_top_edge(band_top).
// band_top = 0: p = 1.
int substeps_for_band(double band_top, double dx, double speed);
// The number of cells around a tyre of circumference L such that one step per cell (Δt = dx/v)
// carries the band_top band: the least even N with 0.99·v·N/(2·L) ≥ band_top_edge(band_top),
// rounded up to the next even length that FFTW transforms fast (core/fftw_plan.hpp;
// at most 2.5 % more cells at 30–130 km/h). The grid then resolves texture wavelengths down to
// 2·dx ≤ 0.99·v/f_2, all those that f = v/λ maps into the band. band_top must be > 0.
int circumferential_points_for_band(double band_top, double circumference, double speed);
TyreRollingSettings read_tyre_rolling_settings(const ConfigTable& rolling);

}  // namespace rollnoise
