#pragma once
// The per-cell contact laws of a road (cell_contact_law.hpp) for the cells a rolling tyre's
// contact points meet: cells dx × dy centred at x₀ + m·step along the road (m = 0 … positions − 1)
// on each lateral line y_j, each solved exactly on a pixel grid of the road's own sample spacing
// (halfspace_load_path.hpp). Cell index: m·lines + j.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contact/cell_contact_law.hpp"
#include "contact/halfspace_load_path.hpp"

namespace rollnoise {

class RoadSurface;
class ProgressReporter;

// The tread rubber the road's texture meets: E at the contact's time scale and ν.
struct TreadRubber {
  double youngs_modulus = 0.0;  // Pa
  double poisson_ratio = 0.0;
};

struct ContactCellGrid {
  double dx = 0.0, dy = 0.0;    // cell size along and across the road, m
  double x0 = 0.0, step = 0.0;  // centre of position 0 and the spacing of positions, m
  std::size_t positions = 0;
  std::vector<double> lines;    // y of each lateral line's cell centres, m
};

// The pixels of a cell: 4 along the road (dx/4, sub-millimetre for dx < 4 mm) and as many of the
// same size across as fit dy. Each pixel's height is the mean of the road's samples inside it
// (samples × samples of the road's own spacing): the texture is coarse-grained to the pixels, as
// a low-pass, so that the exact contact of a cell stays at about 60 pixels (its cost grows as
// their cube) while every sample of the road counts. A road sampled coarser than dx/4 cannot
// show the texture inside a cell: an InputError naming `key` in `source`, with the spacing
// needed.
struct CellPixels {
  std::size_t nx = 0, ny = 0;
  std::size_t samples = 1;  // road samples per pixel along each axis
};
CellPixels cell_pixels(double dx, double dy, std::optional<double> road_spacing, const std::string& source,
                       const std::string& key);

// The force at which a law's table ends (extrapolated linearly beyond): the pressure E* over
// the cell, a strain of order one, far above any cell's force in rolling.
double contact_law_force_cap(double dx, double dy, const TreadRubber& rubber);

// Every cell's pixel heights (the pixel means, float: a run's cells are millions of pixels),
// cell-major: ((m·lines + j)·nx + a)·ny + b, read from the road once.
struct CellHeights {
  std::vector<float> values;
  std::size_t per_cell = 0;
};
CellHeights read_cell_heights(const RoadSurface& road, const ContactCellGrid& grid, CellPixels pixels);
// A digest of everything the laws are made from: every cell's pixel heights, the layout, the
// rubber and the table's form (contact_law_cache.hpp).
// 16 hex digits (FnvDigest::hex).
std::string texture_law_digest(const CellHeights& heights, const ContactCellGrid& grid, CellPixels pixels,
                               const TreadRubber& rubber);

// Visits every cell's exact law (halfspace_load_path.hpp) up to `force_cap`, on `threads`
// threads: visit(cell, path, top) with cell = m·lines + j and the cell's first-touch height,
// called from the worker threads, each cell once (a visitor writes only that cell's slots).
using CellPathVisitor = std::function<void(std::size_t cell, const std::vector<LoadPathPoint>& path, double top)>;
void for_each_cell_path(const CellHeights& heights, const ContactCellGrid& grid, CellPixels pixels,
                        const TreadRubber& rubber, double force_cap, int threads, const CellPathVisitor& visit,
                        ProgressReporter* progress = nullptr);
// Sets cell `cell` of `laws` from its exact path: δ_sub = δ_hs − c_punch·F at each force level
// (cell_contact_law.hpp), and its first-touch height `top`.
void set_law_from_path(CellContactLaws& laws, std::size_t cell, const std::vector<LoadPathPoint>& path, double top,
                       double punch_compliance);

// The compliance of a flat punch of the cell's size on those pixels, 1/(1ᵀK⁻¹1), m/N.
double cell_punch_compliance(const ContactCellGrid& grid, CellPixels pixels, const TreadRubber& rubber);

// Where the laws are kept between runs: the cache folder (none: not kept), and what the caller
// is told (whether they came from it; warnings about an entry that could not be used or written).
struct TextureLawCache {
  std::optional<std::filesystem::path> folder;
  bool* from_cache = nullptr;
  std::vector<std::string>* warnings = nullptr;
};

// Every cell's law, on `threads` threads (positions in blocks, the road read in order along x),
// or read from `cache`. The same road, grid and rubber give the same laws for any thread count,
// computed or cached.
std::shared_ptr<CellContactLaws> make_texture_contact_laws(const RoadSurface& road, const ContactCellGrid& grid,
                                                           CellPixels pixels, const TreadRubber& rubber, int threads,
                                                           ProgressReporter* progress = nullptr,
                                                           const TextureLawCache* cache = nullptr);

}  // namespace rollnoise
