#pragma once
// Measured FRFs from UFF dataset 58/58b files (read by core/uff58.hpp): the records of
// function type 4 (frequency response function) whose ordinate is motion over force.
//
// - The quantity comes from the specific data type codes of records 9 and 10: numerator 8
//   displacement, 11 velocity or 12 acceleration (receptance, mobility, accelerance) over
//   denominator 13 excitation force (9 reaction force, or 0 when the writer leaves it out).
//   Writers that code the numerator as 0/1 (unknown, general) usually say it in the units
//   label, such as "(1/N)*(m/s²)": the label decides then. Force over motion (impedance,
//   dynamic stiffness, apparent mass) and anything else is an error.
// - Units labels scale the data to SI: m, mm, m/s, mm/s, m/s², mm/s², g over N or kN;
//   an unrecognised label leaves the data as it is (SI assumed) with a note.
// - The abscissa is frequency in Hz (or kHz, rad/s, as its units label says).
// - The response and reference node and direction are kept. Both directions must lie on
//   one axis; when their signs differ the data is negated, so that it reads in the model's
//   convention (response positive along the force).
// - Records of other function types (time data, PSDs, coherences) and other datasets are left
//   out with a note when the file holds FRFs; a file with no FRF is an error that says what it
//   holds.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "calibrate/frf_csv_reader.hpp"
#include "core/uff58.hpp"

namespace rollnoise {

// The FRFs among records read from `source`; `skipped_datasets` are the numbers of the other
// datasets of the file.
FrfFile select_uff_frfs(const std::vector<Uff58Record>& records, const std::vector<int>& skipped_datasets,
                        const std::string& source, const FrfReadOptions& options);

FrfFile parse_uff_frfs(std::string_view bytes, const std::string& source, const FrfReadOptions& options);
FrfFile read_uff_frfs(const std::filesystem::path& path, const FrfReadOptions& options);

}  // namespace rollnoise
