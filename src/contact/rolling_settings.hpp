#pragma once
// The [rolling] table of a case: speed, duration, time step, static load and the solver's
// choices.
#include <string>

#include "contact/history_engine.hpp"
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

// [rolling] for a tyre: the time step follows from the grid (Δt = dx/v), so it is not a key.
struct TyreRollingSettings {
  double speed = 0.0;             // m/s
  double duration = 0.0;          // s
  double static_load = 0.0;       // W, N
  HistoryKind history = HistoryKind::automatic;
  int points_circumferential = 512;
  int points_lateral = 16;
  double contact_window = 0.2;    // m, length of the fixed window around the bottom
};
TyreRollingSettings read_tyre_rolling_settings(const ConfigTable& rolling);

}  // namespace rollnoise
