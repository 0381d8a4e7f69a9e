#include "simulation/tyre_step_outputs.hpp"

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <span>
#include <stdexcept>

#include "acoustics/band_power.hpp"
#include "core/output_directory.hpp"
#include "core/sparse_rows_product.hpp"
#include "response/surface_response.hpp"

namespace rollnoise {

std::optional<ContactFields> contact_fields_from(const std::string& name) {
  if (name == "contact") return ContactFields::contact;
  if (name == "all") return ContactFields::all;
  if (name == "none") return ContactFields::none;
  return std::nullopt;
}

const char* to_string(ContactFields fields) {
  switch (fields) {
    case ContactFields::contact:
      return "contact";
    case ContactFields::all:
      return "all";
    case ContactFields::none:
      break;
  }
  return "none";
}

namespace {
// Steps over which the radiating body's patch is measured before the response stage starts
// (the forces wait meanwhile: 4096 × 2040 doubles, 67 MB on the 5 kHz grid). A run of at most
// this many steps (0.36 s at 80 km/h) is measured whole.
constexpr std::size_t patch_steps = 4096;
// 256 steps to a chunk: 2 MB of window field at 2040 points, large enough for deflate to find
// the road's repeats (it moves one cell per cell of travel) and few enough calls into HDF5.
constexpr std::size_t chunk_steps = 256;
// Rows of the radiating velocity written to tread_velocity_ at a time (stage_tread_row).
constexpr std::size_t staged_steps = 8;
constexpr int deflate_level = 1;  // the fastest: level 4 saved 3 % more on the fields (measured)

int blocks(int cells, int block) { return (cells + block - 1) / block; }
}  // namespace

TyreStepOutputs::TyreStepOutputs(const RollingModes& modes, TyreStepOutputSettings settings)
    : modes_(modes), settings_(std::move(settings)), texture_(modes.grid()) {
  settings_.surface_block.around = std::max(1, settings_.surface_block.around);
  if (settings_.surface_block.across <= 0) settings_.surface_block.across = modes.grid().lateral;
}

TyreStepOutputs::~TyreStepOutputs() = default;

// HDF5 reports a failed write as a failed call; the system's reason (a full disk, a file-size
// limit) is left in errno by its POSIX driver.
template <class Write>
void TyreStepOutputs::writing(Write&& write) {
  errno = 0;
  try {
    write();
  } catch (const std::runtime_error& error) {
    if (errno != 0) throw_output_error(settings_.contact_h5, errno);
    throw OutputError("cannot write " + settings_.contact_h5.string() + ": " + error.what());
  }
}

void TyreStepOutputs::start(const SteadyRolling& steady) {
  const TyreGrid& grid = modes_.grid();
  const int across = grid.lateral, around = grid.circumferential;
  response_ = std::make_unique<SurfaceResponse>(modes_, steady.force, across);
  u_.resize(across, around);
  v_.resize(across, around);
  radiating_.resize(static_cast<Eigen::Index>(across) * around);
  // The belt cell under each contact point (index j + Ny·g of the belt field): the tread there
  // is held against the road and does not radiate (take()).
  cell_under_.resize(static_cast<std::size_t>(grid.points()));
  for (int j = 0; j < grid.lateral; ++j) {
    const int row = std::clamp(static_cast<int>(grid.y(j) / (grid.width / across)), 0, across - 1);
    for (int i = 0; i < grid.window; ++i)
      cell_under_[static_cast<std::size_t>(i + grid.window * j)] = row + static_cast<Eigen::Index>(across) * grid.grid_index(i);
  }
  if (settings_.tread_sampling) {
    indentation_ = steady.indentation;
    patch_forces_.resize(grid.points(), static_cast<Eigen::Index>(std::min(settings_.samples, patch_steps)));
    patch_lengths_.reserve(static_cast<std::size_t>(patch_forces_.cols()));
    patch_widths_.reserve(static_cast<std::size_t>(patch_forces_.cols()));
  }
  if (settings_.fields != ContactFields::none) writing([&] { open_contact_h5(*response_); });
}

void TyreStepOutputs::open_contact_h5(const SurfaceResponse& response) {
  const TyreGrid& grid = modes_.grid();
  h5_ = std::make_unique<Hdf5Writer>(settings_.contact_h5);
  Hdf5Writer& h5 = *h5_;
  h5.attribute("/", "software", std::string("rollnoise ") + ROLLNOISE_VERSION);
  h5.attribute("/", "fields", std::string(to_string(settings_.fields)));
  h5.attribute("/", "speed_m_per_s", settings_.speed);
  h5.attribute("/", "static_load_N", settings_.load);
  h5.attribute("/", "time_step_s", modes_.time_step());
  h5.attribute("/", "substeps_per_cell", static_cast<double>(modes_.substeps()));
  h5.attribute("/", "radius_m", grid.radius);
  h5.attribute("/", "belt_width_m", grid.width);
  Eigen::VectorXd time(static_cast<Eigen::Index>(settings_.samples));
  for (Eigen::Index n = 0; n < time.size(); ++n) time(n) = static_cast<double>(n) * modes_.time_step();
  h5.write("/time", time, "s", "time of each sample; t = 0 is the start of the run in steady rolling");

  const Hdf5Writer::StreamLayout layout{chunk_steps, deflate_level};
  const auto window = static_cast<std::size_t>(grid.window), lateral = static_cast<std::size_t>(grid.lateral);
  const std::string shape = "[sample][y][x]: x[i] along the direction of travel from the axle, y[j] across the belt";
  const bool full = settings_.fields == ContactFields::all;
  window_names_ = {"/contact/force"};
  if (full) window_names_.insert(window_names_.end(), {"/contact/road", "/contact/displacement"});
  const std::string descriptions[] = {"contact force on each window point ",
                                      "road height under each window point (as the contact reads it) ",
                                      "vertical position of the tread surface, in the road's datum "};
  const char* units[] = {"N", "m", "m"};
  for (std::size_t f = 0; f < window_names_.size(); ++f)
    window_streams_.push_back(h5.slices(window_names_[f], settings_.samples, lateral, window, units[f],
                                        descriptions[f] + shape, layout));
  std::vector<double> x(window), y(lateral);
  for (std::size_t i = 0; i < window; ++i) x[i] = grid.x(static_cast<int>(i));
  for (std::size_t j = 0; j < lateral; ++j) y[j] = grid.y(static_cast<int>(j));
  for (const std::string& name : window_names_) {
    h5.attribute(name, "x_m", x);
    h5.attribute(name, "y_m", y);
  }

  // The belt surface: positions around (fixed in space, from the bottom in the direction of
  // travel) by positions across the whole belt.
  const int around = grid.circumferential, across = grid.lateral;
  const int block_around = full ? 1 : settings_.surface_block.around, block_across = full ? 1 : settings_.surface_block.across;
  const int columns = blocks(around, block_around), rows = blocks(across, block_across);
  std::vector<double> arc(static_cast<std::size_t>(columns), 0.0), lateral_y(static_cast<std::size_t>(rows), 0.0);
  for (int g = 0; g < columns; ++g) {
    const int first = g * block_around, last = std::min(around, first + block_around) - 1;
    arc[static_cast<std::size_t>(g)] = 0.5 * (first + last) * grid.dx();
  }
  for (int j = 0; j < rows; ++j) {
    const int first = j * block_across, last = std::min(across, first + block_across) - 1;
    lateral_y[static_cast<std::size_t>(j)] = 0.5 * (response.lateral_position(first) + response.lateral_position(last));
  }
  const std::string layout_text = "[sample][y][position around]";
  const std::string velocity_text =
      "radial velocity of the belt surface at each fixed position, du/dt there (what radiates; not the velocity of "
      "the material passing it) " + layout_text;
  surface_velocity_ = h5.slices(
      "/surface/velocity", settings_.samples, static_cast<std::size_t>(rows), static_cast<std::size_t>(columns), "m/s",
      full ? velocity_text
           : velocity_text + ", the mean over blocks of " + std::to_string(block_around) + " cells around by " +
                 std::to_string(block_across) + " across (the attributes give the blocks' centres)",
      layout);
  std::vector<const char*> surfaces = {"/surface/velocity"};
  if (full) {
    surface_displacement_ = h5.slices("/surface/displacement", settings_.samples, static_cast<std::size_t>(across),
                                      static_cast<std::size_t>(around), "m",
                                      "radial displacement of the belt (outward positive towards the road at the "
                                      "bottom) " + layout_text, layout);
    surfaces.push_back("/surface/displacement");
  }
  for (const char* name : surfaces) {
    h5.attribute(name, "arc_position_m", arc);
    h5.attribute(name, "y_m", lateral_y);
    h5.attribute(name, "block_cells_around", static_cast<double>(block_around));
    h5.attribute(name, "block_cells_across", static_cast<double>(block_across));
  }
  road_strip_.assign(lateral * strip_length(), 0.0f);
  slice_.resize(static_cast<std::size_t>(std::max<Eigen::Index>(static_cast<Eigen::Index>(across) * around, grid.points())));
  blocks_.resize(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns));
}

void TyreStepOutputs::take(const ContactStep& step) {
  if (!response_) throw std::logic_error("TyreStepOutputs: take() before start()");
  const TyreGrid& grid = modes_.grid();
  texture_.push(step.road);
  const double total = step.force.sum();
  if (total > snapshot_total_) {
    snapshot_total_ = total;
    snapshot_force_ = step.force;
    snapshot_time_ = step.time;
  }
  if (h5_) {
    const auto p = static_cast<std::size_t>(modes_.substeps()), length = strip_length();
    for (std::size_t j = 0; j < static_cast<std::size_t>(grid.lateral); ++j)
      for (std::size_t i = 0; i < static_cast<std::size_t>(grid.window); ++i)
        road_strip_[j * length + i * p + step.index] =
            static_cast<float>(step.road(static_cast<Eigen::Index>(i + static_cast<std::size_t>(grid.window) * j)));
    writing([&] {
      // The window fields are [j][i] in C order: p = i + Nw·j is already that order.
      const Eigen::VectorXd* fields[] = {&step.force, &step.road, &step.displacement};
      for (std::size_t f = 0; f < window_streams_.size(); ++f) {
        std::transform(fields[f]->data(), fields[f]->data() + fields[f]->size(), slice_.begin(),
                       [](double value) { return static_cast<float>(value); });
        window_streams_[f]->append(slice_.data());
      }
    });
  }
  if (!settings_.tread_sampling || sampling_.rows() > 0) {  // no radiating body, or it is known
    respond(step.index, step.force);
    return;
  }
  // Until the radiating body is known, the forces wait (the response stage is a recursion from
  // step 0, so it waits with them), and the patch is measured.
  const ContactExtent extent = contact_extent(grid, step.force);
  patch_lengths_.push_back(extent.length(grid));
  patch_widths_.push_back(extent.width(grid));
  patch_forces_.col(static_cast<Eigen::Index>(step.index)) = step.force;
  if (step.index + 1 == static_cast<std::size_t>(patch_forces_.cols())) body_known();
}

void TyreStepOutputs::body_known() {
  // The run's mean patch so far (all of it when the run has at most patch_steps steps), as the
  // run's totals average it (Eigen's mean of the same values).
  const Eigen::VectorXd lengths = Eigen::Map<const Eigen::VectorXd>(patch_lengths_.data(), static_cast<Eigen::Index>(patch_lengths_.size()));
  const Eigen::VectorXd widths = Eigen::Map<const Eigen::VectorXd>(patch_widths_.data(), static_cast<Eigen::Index>(patch_widths_.size()));
  sampling_ = settings_.tread_sampling(RadiatingPatch{lengths.mean(), widths.mean(), indentation_});
  if (sampling_.rows() == 0) throw std::logic_error("TyreStepOutputs: an empty tread sampling");
  tread_row_.resize(sampling_.rows());
  if (!settings_.tread_sink) {
    tread_velocity_.resize(static_cast<Eigen::Index>(settings_.samples), sampling_.rows());
    staged_rows_.resize(static_cast<Eigen::Index>(staged_steps), sampling_.rows());
  }
  respond_waiting_steps();
  patch_forces_.resize(0, 0);
}

// The waiting steps are all of a run of up to 4096 steps, responded to after the contact loop:
// the recursion (evaluate: the modal engine and the transforms to the belt) and what is taken
// from its fields (use: the spectra, the radiating velocity, contact.h5) are about 2 : 1 in
// cost, so they run as a pipeline on two threads, a ring of field buffers between them (issue
// 12: the response stage was the largest part of a warm run beside the contact). Each half
// runs its steps in order, so the results are those of respond() step by step, bit for bit.
void TyreStepOutputs::respond_waiting_steps() {
  const auto steps = static_cast<std::size_t>(patch_forces_.cols());
  if (!settings_.pipelined) {
    for (std::size_t n = 0; n < steps; ++n) {
      settings_.cancel.throw_if_cancelled();
      respond(n, patch_forces_.col(static_cast<Eigen::Index>(n)));
    }
    return;
  }
  constexpr std::size_t ring = 4;
  struct Slot {
    Eigen::MatrixXd u, v;
  };
  std::vector<Slot> slots(ring, Slot{u_, v_});  // allocated here, not in the loop
  std::mutex mutex;
  std::condition_variable changed;
  std::size_t evaluated = 0, used = 0;  // steps finished by each half
  bool stop = false;
  std::exception_ptr failure;
  const auto fail = [&](std::exception_ptr error) {
    const std::lock_guard lock(mutex);
    if (!failure) failure = error;
    stop = true;
    changed.notify_all();
  };
  std::jthread user([&] {
    try {
      for (std::size_t n = 0; n < steps; ++n) {
        {
          std::unique_lock lock(mutex);
          changed.wait(lock, [&] { return stop || evaluated > n; });
          if (evaluated <= n) return;  // stopped
        }
        const Slot& slot = slots[n % ring];
        use(n, patch_forces_.col(static_cast<Eigen::Index>(n)), slot.u, slot.v);
        const std::lock_guard lock(mutex);
        used = n + 1;
        changed.notify_all();
      }
    } catch (...) {
      fail(std::current_exception());
    }
  });
  try {
    for (std::size_t n = 0; n < steps; ++n) {
      // Up to 4096 waiting steps, seconds of work on a fine grid: polled like the step loop, so
      // that Ctrl-C here does not wait for the watchdog.
      settings_.cancel.throw_if_cancelled();
      {
        std::unique_lock lock(mutex);
        changed.wait(lock, [&] { return stop || n < used + ring; });  // the slot is free
        if (stop) break;
      }
      Slot& slot = slots[n % ring];
      evaluate(n, patch_forces_.col(static_cast<Eigen::Index>(n)), slot.u, slot.v);
      const std::lock_guard lock(mutex);
      evaluated = n + 1;
      changed.notify_all();
    }
  } catch (...) {
    fail(std::current_exception());
  }
  user.join();
  if (failure) std::rethrow_exception(failure);
}

void TyreStepOutputs::respond(std::size_t index, const Eigen::Ref<const Eigen::VectorXd>& force) {
  evaluate(index, force, u_, v_);
  use(index, force, u_, v_);
}

// Material that starts at the top (g = Nθ/2) moves one cell towards −x every p steps: the
// revolution (Fig. 5b) takes one displacement of each of the first Nθ cells' steps, at the cell
// it returns (or −1 on other steps).
int TyreStepOutputs::revolution_cell(std::size_t index) const {
  const auto substeps = static_cast<std::size_t>(modes_.substeps());
  const int around = modes_.grid().circumferential;
  if (index % substeps != 0 || index / substeps >= static_cast<std::size_t>(around)) return -1;
  return ((around / 2 - static_cast<int>(index / substeps)) % around + around) % around;
}

// Only contact.h5's "all" fields need the whole displacement; the revolution takes its one
// point directly, and the velocity is evaluated alone.
void TyreStepOutputs::evaluate(std::size_t index, const Eigen::Ref<const Eigen::VectorXd>& force, Eigen::MatrixXd& u,
                               Eigen::MatrixXd& v) {
  const bool field = surface_displacement_ != nullptr;
  response_->step(force, field ? &u : nullptr, v);
  const int mid = modes_.grid().lateral / 2;
  if (const int g = revolution_cell(index); g >= 0 && !field) u(mid, g) = response_->displacement_at(mid, g);
}

void TyreStepOutputs::use(std::size_t index, const Eigen::Ref<const Eigen::VectorXd>& force, const Eigen::MatrixXd& u,
                          const Eigen::MatrixXd& v) {
  const TyreGrid& grid = modes_.grid();
  const int around = grid.circumferential, across = grid.lateral;
  if (settings_.belt_psd) settings_.belt_psd->push(std::span<const double>(v.data(), static_cast<std::size_t>(v.size())));
  if (settings_.tread_sampling) {
    // The radiating velocity leaves out the cells in contact: the road holds the tread there,
    // and what the tread displaces escapes only through the texture's channels (air pumping,
    // not modelled). Left in, the contact patch would pump into the mesh's 2 mm clearance (the
    // flat of the deformed tyre, or the undeformed cylinder's lowest line) and be amplified by
    // the very horn the mesh resolves.
    radiating_ = v.reshaped();
    for (std::size_t p = 0; p < cell_under_.size(); ++p)
      if (force(static_cast<Eigen::Index>(p)) > 0.0) radiating_(cell_under_[p]) = 0.0;
    multiply_sparse_rows(sampling_, radiating_.data(), tread_row_.data());  // a kept vector: no temporary per step
    if (settings_.tread_sink)
      settings_.tread_sink(std::span<const double>(tread_row_.data(), static_cast<std::size_t>(tread_row_.size())));
    else
      stage_tread_row(index);
  }
  if (const int g = revolution_cell(index); g >= 0) revolution_.push_back(u(across / 2, g));
  if (!h5_) return;
  writing([&] {
    // The belt fields are Ny × Nθ column-major: written row by row ([y][around]).
    const auto row_major = [&](const Eigen::MatrixXd& field) {
      for (int j = 0; j < across; ++j)
        for (int g = 0; g < around; ++g)
          slice_[static_cast<std::size_t>(j) * static_cast<std::size_t>(around) + static_cast<std::size_t>(g)] =
              static_cast<float>(field(j, g));
    };
    if (surface_displacement_) {
      row_major(u);
      surface_displacement_->append(slice_.data());
      row_major(v);
      surface_velocity_->append(slice_.data());
      return;
    }
    const int ba = settings_.surface_block.around, bc = settings_.surface_block.across;
    const int columns = blocks(around, ba), rows = blocks(across, bc);
    const auto mean_into = [&](int jb, int gb, double sum, int j1, int g1) {
      blocks_[static_cast<std::size_t>(jb) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(gb)] =
          static_cast<float>(sum / ((j1 - jb * bc) * (g1 - gb * ba)));
    };
    for (int jb = 0; jb < rows; ++jb) {
      // Four whole blocks side by side, each summed in its own order (cell by cell around, then
      // across): four independent chains of additions instead of one (perf: the block sums had
      // waited on the adder's latency).
      const int j1 = std::min(across, (jb + 1) * bc);
      int gb = 0;
      for (; gb + 4 <= columns && (gb + 4) * ba <= around; gb += 4) {
        double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
        for (int o = 0; o < ba; ++o) {
          const int g = gb * ba + o;
          for (int j = jb * bc; j < j1; ++j) {
            s0 += v(j, g);
            s1 += v(j, g + ba);
            s2 += v(j, g + 2 * ba);
            s3 += v(j, g + 3 * ba);
          }
        }
        mean_into(jb, gb, s0, j1, (gb + 1) * ba);
        mean_into(jb, gb + 1, s1, j1, (gb + 2) * ba);
        mean_into(jb, gb + 2, s2, j1, (gb + 3) * ba);
        mean_into(jb, gb + 3, s3, j1, (gb + 4) * ba);
      }
      for (; gb < columns; ++gb) {
        const int g1 = std::min(around, (gb + 1) * ba);
        double sum = 0.0;
        for (int g = gb * ba; g < g1; ++g)
          for (int j = jb * bc; j < j1; ++j) sum += v(j, g);
        mean_into(jb, gb, sum, j1, g1);
      }
    }
    surface_velocity_->append(blocks_.data());
  });
}

std::size_t TyreStepOutputs::strip_length() const {
  return static_cast<std::size_t>(modes_.grid().window - 1) * static_cast<std::size_t>(modes_.substeps()) +
         settings_.samples;
}

// A row of tread_velocity_ (samples × points, column-major) is a store a column apart, each on
// another page (perf: a fifth of use()'s own time). Rows are kept staged_steps at a time and
// written as blocks: each column's part is then one cache line.
void TyreStepOutputs::stage_tread_row(std::size_t index) {
  if (staged_ == 0) staged_first_ = index;
  staged_rows_.row(static_cast<Eigen::Index>(staged_)) = tread_row_.transpose();
  ++staged_;
  if (staged_ == staged_steps || index + 1 == settings_.samples) write_staged_rows();
}

void TyreStepOutputs::write_staged_rows() {
  if (staged_ == 0) return;
  const auto rows = static_cast<Eigen::Index>(staged_);
  tread_velocity_.middleRows(static_cast<Eigen::Index>(staged_first_), rows) = staged_rows_.topRows(rows);
  staged_ = 0;
}

void TyreStepOutputs::finish() {
  write_staged_rows();  // a run that ended early
  if (!h5_) return;
  writing([&] {
    const TyreGrid& grid = modes_.grid();
    const std::size_t length = strip_length();
    auto strip = h5_->slices("/contact/road_strip", static_cast<std::size_t>(grid.lateral), 0, length, "m",
                             "the road the window rolled over, as the contact reads it: point (i, j) of the window "
                             "read road_strip[j][i*p + n] at step n (p = substeps_per_cell), at x = x0_m + (i*p + n)*"
                             "spacing_m along the road and y = y_m[j]",
                             {static_cast<std::size_t>(grid.lateral), deflate_level});
    for (std::size_t j = 0; j < static_cast<std::size_t>(grid.lateral); ++j) strip->append(road_strip_.data() + j * length);
    strip->finish();
    strip.reset();
    h5_->attribute("/contact/road_strip", "x0_m", grid.x(0));
    h5_->attribute("/contact/road_strip", "spacing_m", grid.dx() / modes_.substeps());
    std::vector<double> y(static_cast<std::size_t>(grid.lateral));
    for (int j = 0; j < grid.lateral; ++j) y[static_cast<std::size_t>(j)] = grid.y(j);
    h5_->attribute("/contact/road_strip", "y_m", y);
    for (auto& stream : window_streams_) stream->finish();
    if (surface_displacement_) surface_displacement_->finish();
    surface_velocity_->finish();
    window_streams_.clear();
    surface_displacement_.reset();
    surface_velocity_.reset();
    h5_->close();
  });
  h5_.reset();
}

std::vector<double> TyreStepOutputs::revolution() const {
  if (revolution_.size() < static_cast<std::size_t>(modes_.grid().circumferential)) return {};
  return revolution_;
}

}  // namespace rollnoise
