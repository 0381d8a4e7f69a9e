#pragma once
// A study file (ARCHITECTURE.md, `rollnoise study`; the key names are a contract):
//
//   [study]  name, case (the base case, relative to the study file), reference_surface
//   [set]    section.key = value      fixed overrides of every case, as with --set
//   [vary]   section.key = [values]   the product of these lists is the set of cases
//
// `road.surface` replaces the base case's whole [road] table and `tyre.file` its [tyre] table,
// so a base case on a generated road can be run on library surfaces.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace rollnoise {

struct StudyKey {
  std::string section;  // tyre, road, rolling, radiation, output
  std::string key;
  std::string dotted() const { return section + "." + key; }
  // road.surface and tyre.file: a library file, whose path is relative to the study file.
  bool names_file() const { return (section == "road" && key == "surface") || (section == "tyre" && key == "file"); }
  // Whether setting the key replaces its whole table (road.surface, tyre.file).
  bool replaces_table() const { return names_file(); }
};

struct StudyParameter {
  StudyKey key;
  toml::array values;               // one value for [set], the list for [vary]; files made absolute
  std::vector<std::string> labels;  // each value as results.csv shows it (a file: its stem)
};

struct StudySpec {
  std::filesystem::path file;        // the study file
  std::string name;
  std::filesystem::path base_case;   // absolute
  std::string reference_surface;     // absolute path of a road.surface value; empty: none
  std::vector<StudyParameter> fixed;   // [set], in key order (TOML tables are sorted by key)
  std::vector<StudyParameter> varied;  // [vary], in key order: results.csv columns, case ids
  // The number of cases: the product of the list lengths (saturating at SIZE_MAX).
  std::size_t case_count() const;
};

// Reads and checks a study file: unknown sections, [study] keys, sections or keys of a case
// (keys are checked against those the base case holds or the readers know), empty lists and
// lists of tables are InputErrors naming the file and key.
StudySpec read_study_file(const std::filesystem::path& path);

}  // namespace rollnoise
