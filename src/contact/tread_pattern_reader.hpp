#pragma once
// The [tyre.pattern] table of a tyre (model file or case): the tread pattern's keys, checked
// against the tyre's circumference and tread width (tread_pattern.hpp).
//   pitches = N  or  pitch_sequence = [ℓ1, ℓ2, …] (relative lengths > 0, scaled to 2πR),
//     with groove_width (m, > 0, shorter along the circumference than the shortest pitch),
//     groove_depth (m, ≥ 0) and groove_angle (degrees from the lateral, default 0, |α| < 80);
//   ribs = [{position, width, depth}, …] (m; each inside the tread: |position| + width/2 ≤ b_t/2);
//   or file = "…": a tread height map (a CSV with columns x, y, z or an HDF5 map, as a road's
//     height map, road/height_map_surface.hpp), x from 0 around the circumference on N lines
//     spaced 2πR/N, y across the tread from its centre line covering ±b_t/2, z ≤ 0 (m).
// Every problem is an InputError naming the file, the key and what is allowed.
#include <optional>

#include "contact/tread_pattern.hpp"

namespace rollnoise {

class ConfigTable;

// The pattern of `tyre` (its [tyre.pattern] table), or none when the tyre has no such table.
// radius: the tread surface's R (m); tread_width: b_t (m), the width that meets the road.
std::optional<TreadPattern> read_tread_pattern(const ConfigTable& tyre, double radius, double tread_width);

}  // namespace rollnoise
