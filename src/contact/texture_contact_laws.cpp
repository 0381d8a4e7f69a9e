#include "contact/texture_contact_laws.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <filesystem>
#include <thread>

#include "contact/contact_law_cache.hpp"
#include "contact/halfspace_load_path.hpp"
#include "core/fnv_digest.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "road/road_surface.hpp"

namespace rollnoise {
namespace {

// Positions per block of cells handed to the threads (each block's cells split evenly over them).
constexpr std::size_t kBlock = 256;

std::string metres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g m", value);
  return text;
}

}  // namespace

CellPixels cell_pixels(double dx, double dy, std::optional<double> road_spacing, const std::string& source,
                       const std::string& key) {
  const double spacing = road_spacing.value_or(dx / 4.0);
  if (spacing > dx / 4.0 * (1.0 + 1e-9))
    throw InputError(source, key,
                     "the road is sampled every " + metres(spacing) +
                         ", fewer than 4 samples across a contact cell of " + metres(dx) +
                         ": the texture contact law needs a spacing of at most " + metres(dx / 4.0));
  CellPixels p;
  p.nx = 4;
  p.ny = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(dy / (dx / 4.0))));
  p.samples = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(dx / 4.0 / spacing)));
  return p;
}

double contact_law_force_cap(double dx, double dy, const TreadRubber& rubber) {
  return rubber.youngs_modulus / (1.0 - rubber.poisson_ratio * rubber.poisson_ratio) * dx * dy;
}

CellHeights read_cell_heights(const RoadSurface& road, const ContactCellGrid& grid, CellPixels pixels) {
  const std::size_t lines = grid.lines.size();
  CellHeights out;
  out.per_cell = pixels.nx * pixels.ny;
  out.values.assign(grid.positions * lines * out.per_cell, 0.0f);
  const double px = grid.dx / static_cast<double>(pixels.nx), py = grid.dy / static_cast<double>(pixels.ny);
  const std::size_t s = pixels.samples;
  const double weight = 1.0 / static_cast<double>(s * s);
  // In blocks along the road, and across the road outermost within a block. A generated road
  // keeps a bounded part of itself: the aggregate road its tiles along x (5 m), a texture or
  // profile surface its lines along x, one per lateral position. Read in cell order, a fine
  // surface's hundreds of lateral lines were made again for every few cells (captif_fine's
  // 0.2 s run had not read its heights in 14 minutes); read across the whole run for each
  // lateral position, the aggregate road's tiles were made again for every line. A block of
  // 2048 positions (4 m at 80 km/h) spans at most two tiles and makes each line once a block.
  constexpr std::size_t block = 2048;
  std::vector<double> sum(block * pixels.nx);
  for (std::size_t first = 0; first < grid.positions; first += block) {
    const std::size_t count = std::min(block, grid.positions - first);
    for (std::size_t j = 0; j < lines; ++j)
      for (std::size_t b = 0; b < pixels.ny; ++b) {
        std::fill(sum.begin(), sum.end(), 0.0);
        for (std::size_t sb = 0; sb < s; ++sb) {
          const double y = grid.lines[j] - 0.5 * grid.dy +
                           (static_cast<double>(b) + (static_cast<double>(sb) + 0.5) / static_cast<double>(s)) * py;
          for (std::size_t m = 0; m < count; ++m) {
            const double x0 = grid.x0 + static_cast<double>(first + m) * grid.step - 0.5 * grid.dx;
            for (std::size_t a = 0; a < pixels.nx; ++a)
              for (std::size_t sa = 0; sa < s; ++sa)
                sum[m * pixels.nx + a] += road.height(
                    x0 + (static_cast<double>(a) + (static_cast<double>(sa) + 0.5) / static_cast<double>(s)) * px, y);
          }
        }
        for (std::size_t m = 0; m < count; ++m)
          for (std::size_t a = 0; a < pixels.nx; ++a)
            out.values[(((first + m) * lines + j) * pixels.nx + a) * pixels.ny + b] =
                static_cast<float>(weight * sum[m * pixels.nx + a]);
      }
  }
  return out;
}

std::string texture_law_digest(const CellHeights& heights, const ContactCellGrid& grid, CellPixels pixels,
                               const TreadRubber& rubber) {
  FnvDigest d;
  d.text("texture contact laws");
  d.unsigned_integer(CellContactLaws::levels);
  for (const double v : {rubber.youngs_modulus, rubber.poisson_ratio, grid.dx, grid.dy, grid.x0, grid.step}) d.real(v);
  for (const std::size_t v : {pixels.nx, pixels.ny, pixels.samples, grid.positions, grid.lines.size()}) d.unsigned_integer(v);
  for (const double y : grid.lines) d.real(y);
  d.words(reinterpret_cast<const char*>(heights.values.data()), heights.values.size() * sizeof(float));
  return d.hex();
}

void set_law_from_path(CellContactLaws& laws, std::size_t cell, const std::vector<LoadPathPoint>& path, double top,
                       double punch_compliance) {
  std::array<double, CellContactLaws::levels> approaches{};
  for (int k = 0; k < CellContactLaws::levels; ++k) {
    const double f = laws.force_level(k);
    approaches[static_cast<std::size_t>(k)] = std::max(0.0, approach_at_force(path, f) - punch_compliance * f);
  }
  laws.set(cell, top, approaches);
}

double cell_punch_compliance(const ContactCellGrid& grid, CellPixels pixels, const TreadRubber& rubber) {
  const HalfspaceLoadPath probe(pixels.nx, pixels.ny, grid.dx / static_cast<double>(pixels.nx),
                                grid.dy / static_cast<double>(pixels.ny), rubber.youngs_modulus, rubber.poisson_ratio);
  return probe.punch_compliance();
}

void for_each_cell_path(const CellHeights& heights, const ContactCellGrid& grid, CellPixels pixels,
                        const TreadRubber& rubber, double force_cap, int threads, const CellPathVisitor& visit,
                        ProgressReporter* progress) {
  const std::size_t n = pixels.nx * pixels.ny;
  const std::size_t cells = grid.positions * grid.lines.size();
  if (cells == 0 || n == 0 || heights.per_cell != n || heights.values.size() != cells * n)
    throw std::invalid_argument("for_each_cell_path: the heights do not match the grid");
  const double px = grid.dx / static_cast<double>(pixels.nx), py = grid.dy / static_cast<double>(pixels.ny);
  const int workers = std::max(1, threads);
  // Cells in blocks, each block split evenly over the threads; each cell is solved on its own,
  // so the split does not change a number.
  const std::size_t block = kBlock * grid.lines.size();
  for (std::size_t first = 0; first < cells; first += block) {
    const std::size_t count = std::min(block, cells - first);
    std::vector<std::exception_ptr> failures(static_cast<std::size_t>(workers));
    const auto work = [&](int w) {
      try {
        HalfspaceLoadPath path(pixels.nx, pixels.ny, px, py, rubber.youngs_modulus, rubber.poisson_ratio);
        std::vector<double> cell(n);
        for (std::size_t c = first + static_cast<std::size_t>(w); c < first + count; c += static_cast<std::size_t>(workers)) {
          std::copy_n(heights.values.begin() + static_cast<std::ptrdiff_t>(c * n), n, cell.begin());
          visit(c, path.trace(cell, force_cap), *std::max_element(cell.begin(), cell.end()));
        }
      } catch (...) {
        failures[static_cast<std::size_t>(w)] = std::current_exception();
      }
    };
    std::vector<std::jthread> pool;
    for (int w = 1; w < workers; ++w) pool.emplace_back(work, w);
    work(0);
    pool.clear();
    for (const std::exception_ptr& failure : failures)
      if (failure) std::rethrow_exception(failure);
    if (progress) progress->update((first + count) / grid.lines.size());
  }
}

std::shared_ptr<CellContactLaws> make_texture_contact_laws(const RoadSurface& road, const ContactCellGrid& grid,
                                                           CellPixels pixels, const TreadRubber& rubber, int threads,
                                                           ProgressReporter* progress, const TextureLawCache* cache) {
  const CellHeights heights = read_cell_heights(road, grid, pixels);
  const double cap = contact_law_force_cap(grid.dx, grid.dy, rubber);
  // The flat punch's compliance sets the floor of every law's compliance (cell_contact_law.hpp).
  const double punch = cell_punch_compliance(grid, pixels, rubber);
  const std::size_t cells = grid.positions * grid.lines.size();
  std::filesystem::path entry;
  if (cache && cache->from_cache) *cache->from_cache = false;
  if (cache && cache->folder) {
    entry = *cache->folder / contact_law_cache_name(texture_law_digest(heights, grid, pixels, rubber));
    std::string warning;
    if (auto stored = read_contact_law_cache(entry, cells, cap, 1e-3 * punch, warning)) {
      if (cache->from_cache) *cache->from_cache = true;
      return stored;
    }
    if (!warning.empty() && cache->warnings) cache->warnings->push_back(warning);
  }
  auto laws = std::make_shared<CellContactLaws>(cells, cap, 1e-3 * punch);
  for_each_cell_path(
      heights, grid, pixels, rubber, cap, threads,
      [&](std::size_t cell, const std::vector<LoadPathPoint>& path, double top) {
        set_law_from_path(*laws, cell, path, top, punch);
      },
      progress);
  if (!entry.empty()) {
    // A cache that cannot be written costs the next run the computation, not this run its result.
    try {
      std::filesystem::create_directories(entry.parent_path());
      write_contact_law_cache(entry, *laws);
    } catch (const std::exception& e) {
      if (cache->warnings) cache->warnings->push_back(std::string("the contact laws could not be cached: ") + e.what());
    }
  }
  return laws;
}

}  // namespace rollnoise
