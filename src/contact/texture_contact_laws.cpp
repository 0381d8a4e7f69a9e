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

// Positions per block: the road is read for a block in order along x, then its cells are solved
// on the threads (a generated road keeps a few tiles, so reading it out of order costs).
constexpr std::size_t kBlock = 256;

std::string metres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g m", value);
  return text;
}

}  // namespace

double pixel_height(const RoadSurface& road, double x, double y, double px, double py, std::size_t samples) {
  const double n = static_cast<double>(samples);
  double sum = 0.0;
  for (std::size_t a = 0; a < samples; ++a)
    for (std::size_t b = 0; b < samples; ++b)
      sum += road.height(x + (static_cast<double>(a) + 0.5) * px / n, y + (static_cast<double>(b) + 0.5) * py / n);
  return sum / (n * n);
}

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

void fill_block_heights(const RoadSurface& road, const ContactCellGrid& grid, CellPixels pixels, std::size_t first,
                        std::size_t count, std::vector<double>& heights) {
  const std::size_t lines = grid.lines.size();
  const double px = grid.dx / static_cast<double>(pixels.nx), py = grid.dy / static_cast<double>(pixels.ny);
  for (std::size_t m = 0; m < count; ++m) {
    const double xc = grid.x0 + static_cast<double>(first + m) * grid.step;
    for (std::size_t j = 0; j < lines; ++j)
      for (std::size_t a = 0; a < pixels.nx; ++a)
        for (std::size_t b = 0; b < pixels.ny; ++b)
          heights[((m * lines + j) * pixels.nx + a) * pixels.ny + b] =
              pixel_height(road, xc - 0.5 * grid.dx + static_cast<double>(a) * px,
                           grid.lines[j] - 0.5 * grid.dy + static_cast<double>(b) * py, px, py, pixels.samples);
  }
}

std::uint64_t texture_law_digest(const RoadSurface& road, const ContactCellGrid& grid, CellPixels pixels,
                                 const TreadRubber& rubber) {
  FnvDigest d;
  d.text("texture contact laws");
  d.unsigned_integer(CellContactLaws::levels);
  for (const double v : {rubber.youngs_modulus, rubber.poisson_ratio, grid.dx, grid.dy, grid.x0, grid.step}) d.real(v);
  for (const std::size_t v : {pixels.nx, pixels.ny, pixels.samples, grid.positions, grid.lines.size()}) d.unsigned_integer(v);
  for (const double y : grid.lines) d.real(y);
  const std::size_t n = pixels.nx * pixels.ny;
  std::vector<double> heights(kBlock * grid.lines.size() * n);
  for (std::size_t first = 0; first < grid.positions; first += kBlock) {
    const std::size_t count = std::min(kBlock, grid.positions - first);
    fill_block_heights(road, grid, pixels, first, count, heights);
    d.words(reinterpret_cast<const char*>(heights.data()), count * grid.lines.size() * n * sizeof(double));
  }
  return d.value();
}

double cell_punch_compliance(const ContactCellGrid& grid, CellPixels pixels, const TreadRubber& rubber) {
  const HalfspaceLoadPath probe(pixels.nx, pixels.ny, grid.dx / static_cast<double>(pixels.nx),
                                grid.dy / static_cast<double>(pixels.ny), rubber.youngs_modulus, rubber.poisson_ratio);
  return probe.punch_compliance();
}

void for_each_cell_path(const RoadSurface& road, const ContactCellGrid& grid, CellPixels pixels,
                        const TreadRubber& rubber, double force_cap, int threads, const CellPathVisitor& visit,
                        ProgressReporter* progress) {
  const std::size_t lines = grid.lines.size();
  const std::size_t n = pixels.nx * pixels.ny;
  if (lines == 0 || grid.positions == 0 || n == 0 || !(grid.dx > 0.0) || !(grid.dy > 0.0))
    throw std::invalid_argument("for_each_cell_path: an empty grid");
  const double px = grid.dx / static_cast<double>(pixels.nx), py = grid.dy / static_cast<double>(pixels.ny);
  const int workers = std::max(1, threads);
  std::vector<double> heights(kBlock * lines * n);
  for (std::size_t first = 0; first < grid.positions; first += kBlock) {
    const std::size_t count = std::min(kBlock, grid.positions - first);
    fill_block_heights(road, grid, pixels, first, count, heights);
    // The block's cells, split evenly over the threads; each cell is solved on its own, so the
    // split does not change a number.
    const std::size_t cells = count * lines;
    std::vector<std::exception_ptr> failures(static_cast<std::size_t>(workers));
    const auto work = [&](int w) {
      try {
        HalfspaceLoadPath path(pixels.nx, pixels.ny, px, py, rubber.youngs_modulus, rubber.poisson_ratio);
        for (std::size_t c = static_cast<std::size_t>(w); c < cells; c += static_cast<std::size_t>(workers)) {
          const std::span<const double> cell(heights.data() + c * n, n);
          visit(first * lines + c, path.trace(cell, force_cap), *std::max_element(cell.begin(), cell.end()));
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
    if (progress) progress->update(first + count);
  }
}

std::shared_ptr<CellContactLaws> make_texture_contact_laws(const RoadSurface& road, const ContactCellGrid& grid,
                                                           CellPixels pixels, const TreadRubber& rubber, int threads,
                                                           ProgressReporter* progress, const TextureLawCache* cache) {
  const double cap = contact_law_force_cap(grid.dx, grid.dy, rubber);
  // The flat punch's compliance sets the floor of every law's compliance (cell_contact_law.hpp).
  const double punch = cell_punch_compliance(grid, pixels, rubber);
  const std::size_t cells = grid.positions * grid.lines.size();
  std::filesystem::path entry;
  if (cache && cache->from_cache) *cache->from_cache = false;
  if (cache && cache->folder) {
    entry = *cache->folder / contact_law_cache_name(texture_law_digest(road, grid, pixels, rubber));
    std::string warning;
    if (auto stored = read_contact_law_cache(entry, cells, cap, 1e-3 * punch, warning)) {
      if (cache->from_cache) *cache->from_cache = true;
      return stored;
    }
    if (!warning.empty() && cache->warnings) cache->warnings->push_back(warning);
  }
  auto laws = std::make_shared<CellContactLaws>(cells, cap, 1e-3 * punch);
  for_each_cell_path(
      road, grid, pixels, rubber, cap, threads,
      [&](std::size_t cell, const std::vector<LoadPathPoint>& path, double top) {
        std::array<double, CellContactLaws::levels> approaches{};
        for (int k = 0; k < CellContactLaws::levels; ++k) {
          const double f = laws->force_level(k);
          approaches[static_cast<std::size_t>(k)] = std::max(0.0, approach_at_force(path, f) - punch * f);
        }
        laws->set(cell, top, approaches);
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
