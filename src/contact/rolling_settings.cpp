#include "contact/rolling_settings.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/fftw_plan.hpp"

namespace rollnoise {

std::size_t RollingSettings::steps() const {
  return static_cast<std::size_t>(std::llround(duration / time_step));
}

RollingSettings read_rolling_settings(const ConfigTable& rolling) {
  RollingSettings s;
  s.speed = rolling.positive("speed");
  s.duration = rolling.positive("duration");
  s.time_step = rolling.positive("time_step");
  s.static_load = rolling.non_negative("static_load");
  s.history = parse_history_kind(
      rolling.choice("history", {"auto", "direct", "modal"}, "auto"));
  s.discretisation =
      parse_discretisation(rolling.choice("discretisation", {"step", "rectangle"}, "step"));
  rolling.reject_unknown_keys();
  const double steps = s.duration / s.time_step;
  if (steps < 1.0) {
    rolling.fail("time_step", "must be smaller than the duration (" + std::to_string(s.duration) + " s)");
  }
  // The direct engine keeps the whole history: past ~2·10⁷ steps it no longer fits in memory.
  if (steps > 2e7) {
    rolling.fail("time_step", "gives " + format_number(steps) +
                                  " steps; at most 2e7 are allowed (raise time_step or shorten duration)");
  }
  if (!std::isfinite(s.speed * s.duration)) {
    rolling.fail("duration", "speed × duration (the length of road rolled over, m) must be a finite number");
  }
  return s;
}

TyreRollingSettings read_tyre_rolling_settings(const ConfigTable& rolling) {
  TyreRollingSettings s;
  s.speed = rolling.positive("speed");
  s.duration = rolling.positive("duration");
  s.static_load = rolling.positive("static_load");
  s.history = parse_history_kind(rolling.choice("history", {"auto", "direct", "modal"}, "auto"));
  if (rolling.contains("points_circumferential")) {
    s.points_circumferential = static_cast<int>(rolling.integer("points_circumferential", 512, 8, 1 << 16));
    if (s.points_circumferential % 2 != 0) rolling.fail("points_circumferential", "must be even");
  }
  s.points_lateral = static_cast<int>(rolling.integer("points_lateral", 16, 1, 1024));
  s.contact_window = rolling.positive("contact_window", 0.2);
  s.band_top = rolling.non_negative("band_top", 5000.0);
  const std::string sampling = rolling.choice("road_sampling", {"lowpass", "cell_mean", "point"}, "lowpass");
  s.road_sampling = sampling == "point" ? RoadSampling::point
                    : sampling == "lowpass" ? RoadSampling::lowpass
                                            : RoadSampling::cell_mean;
  s.contact_law = rolling.choice("contact_law", {"rigid", "texture"}, "rigid") == "texture" ? ContactLaw::texture
                                                                                             : ContactLaw::rigid;
  if (s.contact_law == ContactLaw::texture && rolling.contains("road_sampling"))
    rolling.fail("road_sampling", "applies to contact_law = \"rigid\" only: with \"texture\" each cell meets the road "
                                  "at its highest point; remove one of the two");
  if (s.band_top != 0.0 && (s.band_top < 100.0 || s.band_top > 20000.0))
    rolling.fail("band_top", "must be 0 (one cell per step) or a band centre from 100 to 20000 Hz");
  if (rolling.contains("time_step")) {
    rolling.fail("time_step", "is derived from the grid for a tyre (Δt = 2πR/points_circumferential/speed/p, p the "
                              "sub-steps that band_top needs); remove it");
  }
  if (rolling.contains("discretisation") && rolling.text("discretisation") != "step") {
    rolling.fail("discretisation", "only \"step\" is available for a tyre (its modes recur exactly on it)");
  }
  rolling.reject_unknown_keys();
  if (!std::isfinite(s.speed * s.duration)) {
    rolling.fail("duration", "speed × duration (the length of road rolled over, m) must be a finite number");
  }
  return s;
}

double band_top_edge(double band_top) {
  // IEC 61260-1 third octaves (the formulas of acoustics/fractional_octave_bands.hpp, written out
  // here so that contact does not reach down the pipeline): f_m = 1000·10^(x/10), f_2 = f_m·10^(1/20).
  const double x = std::round(10.0 * std::log10(band_top / 1000.0));
  return 1000.0 * std::pow(10.0, x / 10.0) * std::pow(10.0, 1.0 / 20.0);
}

namespace {

// The rule both choices serve: one step of length dx/p carries the band when
// 0.99·p·v/(2·dx) ≥ f_2, i.e. p/dx ≥ 2·f_2/(0.99·v). Returns 2·f_2·length/(0.99·v), the least
// (real) number of steps per `length` of travel; the radiation stage computes up to 0.99 of
// the Nyquist frequency.
double steps_needed(double band_top, double length, double speed) {
  return 2.0 * band_top_edge(band_top) * length / (0.99 * speed);
}

}  // namespace

int circumferential_points_for_band(double band_top, double circumference, double speed) {
  if (!(band_top > 0.0)) throw std::invalid_argument("circumferential_points_for_band: band_top must be > 0");
  // N even; the allowance keeps an exact fit from rounding up.
  const double needed = steps_needed(band_top, circumference, speed);
  const double half = std::ceil(0.5 * needed * (1.0 - 1e-12));
  if (!(half < 1e9)) throw std::invalid_argument("circumferential_points_for_band: the grid would be too large");
  // Rounded up to a length FFTW transforms fast: every step transforms the belt around the tyre
  // (the modal engines and the response stage), and a finer grid only carries more of the band.
  return static_cast<int>(next_fftw_fast_length(2 * static_cast<long>(half), true));
}

int substeps_for_band(double band_top, double dx, double speed) {
  if (band_top <= 0.0) return 1;
  // The small allowance keeps an exact fit from rounding up.
  const double needed = steps_needed(band_top, dx, speed);
  return std::max(1, static_cast<int>(std::ceil(needed * (1.0 - 1e-12))));
}

}  // namespace rollnoise
