#pragma once
// The contact law a tyre meets on a road (`rollnoise road --contact-law`): cells dx × dy tiled
// over the surface, each cell's exact law of the tread rubber pressed onto its texture
// (contact/texture_contact_laws.hpp), and their mean and spread, so that a user sees before a
// run what [rolling] contact_law = "texture" will roll on.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <vector>

#include "contact/cell_contact_law.hpp"
#include "contact/texture_contact_laws.hpp"

namespace rollnoise {

class RoadSurface;

struct SurfaceContactLawOptions {
  TreadRubber rubber;
  double cell_dx = 0.0, cell_dy = 0.0;  // m
  int threads = 1;
};

struct SurfaceContactLaw {
  SurfaceContactLawOptions options;
  CellPixels pixels;
  double punch_compliance = 0.0;  // m/N, a flat punch of the cell's size
  // The law over the cells at each approach δ from a cell's first touch (the rubber's whole
  // approach δ_hs; the tyre adds only δ_hs − c_punch·F): the mean force, the mean contact area
  // and the 10th and 90th percentiles of the force over the cells. Rows up to the approach at
  // which the first cell reaches its table's end (E*·dx·dy).
  std::vector<double> approach_m, force_n, area_m2, force_p10_n, force_p90_n;
  // Per cell (index m·lines + j): its centre, and its table (first-touch height, δ_sub at the
  // force levels) as the rolling step reads it.
  std::vector<double> cell_x_m, cell_y_m;
  std::shared_ptr<CellContactLaws> laws;
};

// Cells tiled over x in [0, length) and y in [−width/2, width/2). The road must be sampled at
// dx/4 or finer (an InputError naming `source` and `key`, as the rolling run's).
SurfaceContactLaw surface_contact_law(const RoadSurface& road, double length, double width,
                                      const SurfaceContactLawOptions& options, const std::string& source,
                                      const std::string& key);

// contact_law.csv (the mean law) and contact_laws.h5 (everything) into `folder`.
void write_surface_contact_law(const std::filesystem::path& folder, const SurfaceContactLaw& law);

}  // namespace rollnoise
