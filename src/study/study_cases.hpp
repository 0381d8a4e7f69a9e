#pragma once
// The cases of a study: the product of its [vary] lists, each a full case table built from the
// base case, with a readable id that names its folder (cases/<id>/).
#include <cstddef>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "study/study_file.hpp"

namespace rollnoise {

class CaseFile;

struct StudyCase {
  std::size_t index = 0;             // in the product, the last [vary] list varying fastest
  std::string id;                    // e.g. "surface-dac11_speed-13.889"
  std::vector<std::size_t> choice;   // the value taken from each [vary] list
  std::vector<std::string> labels;   // those values as results.csv shows them
};

std::vector<StudyCase> study_cases(const StudySpec& spec);

// The case as a TOML table: the base case with [set] and the case's [vary] values applied
// (road.surface and tyre.file first, replacing their tables), library paths made absolute, so
// that the text (case_text) is a case file that runs anywhere.
toml::table study_case_table(const StudySpec& spec, const StudyCase& c);
std::string study_case_text(const toml::table& table);
// The case ready to run (library files merged), named as the base case for messages.
CaseFile study_case_file(const StudySpec& spec, const toml::table& table);

}  // namespace rollnoise
