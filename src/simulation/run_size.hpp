#pragma once
// What a run holds in memory and writes to disk, counted from its sizes before it starts
// (core/run_estimate.hpp refuses the run when it cannot fit): simulate's point and tyre runs,
// and the verbs whose size grows with their arguments (road, greens, calibrate). Rough but on
// the safe side: the large arrays only, each counted once.
#include <cstdint>
#include <string>

#include "core/run_estimate.hpp"
#include "simulation/tyre_step_outputs.hpp"

namespace rollnoise {

// A point model (sdof, coupled_sdof): `samples` time samples of `points` contact points, four
// fields in memory (road, displacement, force, gap), three in contact.csv.
RunEstimate estimate_point_run(std::uint64_t samples, std::uint64_t points, const std::string& source);

// A tyre model. The contact loop streams its fields (tyre_step_outputs.hpp): memory holds the
// per-step totals, the road under the window by column, and the tread velocity on the radiation
// mesh; contact.h5 holds what [output] fields asks for, counted uncompressed (deflate only helps).
struct TyreRunSize {
  std::uint64_t samples = 0;          // steps
  std::uint64_t window_points = 0;    // the contact window, Nw·Ny
  std::uint64_t window_columns = 0;   // Nw
  std::uint64_t lateral = 0;          // the belt, Ny × Nθ
  std::uint64_t circumferential = 0;
  bool radiating = false;             // whether the tread velocity goes to the radiation
  std::uint64_t radiation_block = 0;  // samples of it held at once when streamed (0: the whole record)
  std::uint64_t receivers = 0;        // WAV files
  std::uint64_t audio_frames = 0;     // of each
  ContactFields fields = ContactFields::contact;
  SurfaceBlock block;                 // the belt velocity's decimation for ContactFields::contact
};
RunEstimate estimate_tyre_run(const TyreRunSize& size, const std::string& source);

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
