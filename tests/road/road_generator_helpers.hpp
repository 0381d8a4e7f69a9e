#pragma once
// What the tests of the generated roads (texture, iso8608, aggregate) share: building a road from
// a [road] table in TOML, the message of the InputError that building throws, band levels
// averaged over seeds, moments of a height distribution.
#include <cmath>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "core/config_table.hpp"
#include "core/error.hpp"
#include "road/road_profile.hpp"
#include "road/road_surface.hpp"
#include "road/texture_spectrum.hpp"
#include "road/road_test_support.hpp"

namespace rollnoise::test {

inline std::unique_ptr<RoadProfile> profile_from(const std::string& road_table, double x_max = 0.0) {
  toml::table t = toml::parse("[road]\n" + road_table);
  const ConfigTable road(*t["road"].as_table(), "case.toml", "road");
  return make_road_profile(road, -1.0, x_max);
}

inline std::unique_ptr<RoadSurface> surface_from(const std::string& road_table, double x_max = 0.0,
                                                 double half_width = 0.0) {
  toml::table t = toml::parse("[road]\n" + road_table);
  const ConfigTable road(*t["road"].as_table(), "case.toml", "road");
  return make_road_surface(road, -1.0, x_max, half_width);
}

// what() of the InputError that building the profile (or the surface) throws, or "" if it builds.
inline std::string profile_error(const std::string& road_table) {
  try {
    profile_from(road_table);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
inline std::string surface_error(const std::string& road_table) {
  try {
    surface_from(road_table);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Band powers (m^2) by nominal wavelength, accumulated over profiles; level() is their mean in dB.
class BandAverage {
 public:
  void add(std::span<const double> z, double spacing) {
    for (const TextureBand& b : texture_spectrum(z, spacing)) {
      power_[b.nominal_wavelength_m] += std::pow(10.0, b.level_db / 10.0) * 1e-12;
    }
    ++count_;
  }
  bool has(double nominal) const { return power_.count(nominal) > 0; }
  double level(double nominal) const {
    return 10.0 * std::log10(power_.at(nominal) / static_cast<double>(count_) / 1e-12);
  }

 private:
  std::map<double, double> power_;
  int count_ = 0;
};

inline double skewness(std::span<const double> z) {
  double mean = 0.0;
  for (double v : z) mean += v;
  mean /= static_cast<double>(z.size());
  double m2 = 0.0;
  double m3 = 0.0;
  for (double v : z) {
    m2 += (v - mean) * (v - mean);
    m3 += (v - mean) * (v - mean) * (v - mean);
  }
  m2 /= static_cast<double>(z.size());
  m3 /= static_cast<double>(z.size());
  return m3 / std::pow(m2, 1.5);
}

}  // namespace rollnoise::test

