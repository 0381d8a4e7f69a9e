#pragma once
// What a study writes beside its cases (ARCHITECTURE.md, outputs): results.csv (one row per
// case: the varied keys, LAeq_<receiver>_dB, LWA_dB, rolling_resistance_N, wall_time_s,
// status), spectra.csv (long form), summary.json, and plots with their gnuplot scripts: level
// against log speed per surface with the fitted L = a + b·lg(v/v0) as CPX reports draw it,
// the spectra per surface at each speed, and each surface's difference to the reference.
// Everything but the wall times is read from the cases' own outputs, so it does not depend on
// which rank or thread ran a case, or on whether an earlier run did.
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/study_cases.hpp"
#include "study/study_file.hpp"
#include "study/study_run.hpp"

namespace rollnoise {

// Writes the files into `out` (each replaced atomically by a rename); returns summary.json's
// content. `run` holds what the caller adds to the summary (threads, ranks, wall time).
nlohmann::json write_study_results(const std::filesystem::path& out, const StudySpec& spec,
                                   const std::vector<StudyCase>& cases, const std::vector<CaseOutcome>& outcomes,
                                   const nlohmann::json& run, bool plots);

// The reference speed of the CPX fits, km/h.
inline constexpr double kReferenceSpeedKmh = 80.0;

}  // namespace rollnoise
