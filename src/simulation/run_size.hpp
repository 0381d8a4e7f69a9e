#pragma once
// What a run holds in memory and writes to disk, counted from its sizes before it starts
// (core/run_estimate.hpp refuses the run when it cannot fit): simulate's point and tyre runs,
// and the verbs whose size grows with their arguments (road, greens, calibrate). Rough but on
// the safe side: the large arrays only, each counted once.
#include <cstdint>
#include <string>

#include "core/run_estimate.hpp"
#include "radiation/tyre_radiation.hpp"
#include "simulation/tyre_step_outputs.hpp"

namespace rollnoise {

// A point model (sdof, coupled_sdof): `samples` time samples of `points` contact points, four
// fields in memory (road, displacement, force, gap), three in contact.csv; and the history
// engine's kernel, `lags` matrices of points × points, held twice by the direct engine (as made
// and reversed side by side).
RunEstimate estimate_point_run(std::uint64_t samples, std::uint64_t points, std::uint64_t lags, const std::string& source);

// A tyre model. The contact loop streams its fields (tyre_step_outputs.hpp): memory holds the
// per-step totals, the road under the window by column, and the tread velocity on the radiation
// mesh; contact.h5 holds what [output] fields asks for, counted uncompressed (deflate only helps).
// The history engine: `direct` holds the whole sheared kernel, one window × window matrix a step
// of the run, twice (contact/direct_history_engine.hpp), which on the default grid is tens of GB
// a tenth of a second; `modal` holds a few numbers a pole. The contact step holds a few window ×
// window matrices whatever the engine (G0, its symmetric and skew parts, the local compliance,
// a factor). The radiation holds, per solving thread, about one matrix of collocation points ×
// sources of its finest mesh (complex), when an anchor is solved rather than loaded.
struct TyreRunSize {
  std::uint64_t samples = 0;          // steps
  std::uint64_t window_points = 0;    // the contact window, Nw·Ny
  std::uint64_t window_columns = 0;   // Nw
  std::uint64_t lateral = 0;          // the belt, Ny × Nθ
  std::uint64_t circumferential = 0;
  bool direct_history = false;        // [rolling] history = "direct"
  std::uint64_t modal_poles = 0;      // the modal engine's poles (all modes)
  bool radiating = false;             // whether the tread velocity goes to the radiation
  std::uint64_t radiation_block = 0;  // samples of it held at once when streamed (0: the whole record)
  std::uint64_t radiation_solve_bytes = 0;  // one anchor's solve on the finest mesh, times the solving threads
  std::uint64_t receivers = 0;        // WAV files
  std::uint64_t audio_frames = 0;     // of each
  bool absorbing_pass_by = false;     // the pass-by filters its image path over an absorbing road
  ContactFields fields = ContactFields::contact;
  SurfaceBlock block;                 // the belt velocity's decimation for ContactFields::contact
};
RunEstimate estimate_tyre_run(const TyreRunSize& size, const std::string& source);

// TyreRunSize::radiation_solve_bytes for `settings` (its sample rate set): the finest mesh level's
// collocation points × sources, complex, per solving thread. Counted on the undeformed body of
// the same spec (the deformed one is known only after the contact stage; their counts differ by
// the patch's graded cells, a few per cent).
std::uint64_t radiation_solve_bytes(const TyreRadiationSettings& settings, std::size_t threads);

// `rollnoise road` on a generated road: `samples` along each of `lines` lines (--length /
// --spacing, --lines), held as doubles and written to road.csv (x and one column a line).
RunEstimate estimate_road_run(std::uint64_t samples, std::uint64_t lines, const std::string& source);

// `rollnoise greens`: the receptance and mobility at `frequencies` × `distances` (complex, in
// memory), written twice to CSV (four numbers a row) and once to greens.h5.
RunEstimate estimate_greens_run(std::uint64_t frequencies, std::uint64_t distances);

// `rollnoise calibrate`: `lines` measured lines over all FRFs, `parameters` of them fitted (the
// Jacobian holds two residuals a line per parameter); fit.csv has 11 numbers a line.
RunEstimate estimate_calibration_run(std::uint64_t lines, std::uint64_t parameters, const std::string& source);

}  // namespace rollnoise
