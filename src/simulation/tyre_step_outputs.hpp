#pragma once
// What a tyre run keeps of each contact step, taken as the contact loop produces it
// (ContactStepSink), so the run's memory does not grow with its length beyond what it streams
// (issue 13): the response stage (the belt's surface field), contact.h5 written chunk by chunk,
// the belt's velocity spectra for the energy budget, the radiating tread velocity for the
// radiation stage, the road under the window for the texture spectra, the contact forces at the
// instant of the largest total force, and one belt point over a revolution (Fig. 5b).
//
// contact.h5 by [output] fields:
//  - "contact" (the default): the window's force at every step; the road the window read, as
//    the strip of road it rolled over (road_strip[j][i·p + n] is what point (i, j) read at step
//    n, p sub-steps per cell: each height once, not once per window column); and the belt's
//    radial velocity averaged over blocks of cells (SurfaceBlock below) at every step. float32,
//    chunked, shuffle + deflate: about 42 MB per simulated second at 80 km/h on the 5 kHz grid
//    (measured: docs/performance.md);
//  - "all": also the road and the tread surface's displacement over the window at every step, the
//    belt's displacement, and the belt's velocity at every cell (about 1.5 GB per second);
//  - "none": no contact.h5 (contact.csv and the other outputs as usual).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "contact/rolling_modes.hpp"
#include "contact/rolling_tyre.hpp"
#include "contact/texture_under_contact.hpp"
#include "core/cancellation.hpp"
#include "core/hdf5_writer.hpp"

namespace rollnoise {

class PointAveragedPsd;
class SurfaceResponse;

enum class ContactFields { contact, all, none };

// "contact", "all", "none"; std::nullopt for anything else.
std::optional<ContactFields> contact_fields_from(const std::string& name);
const char* to_string(ContactFields fields);

// The default decimation of the belt's velocity in contact.h5: block means of this many cells
// around (15.5 mm at 1024 cells, the 5 kHz grid at 80 km/h) by this many across (0: the whole
// width). A block mean is what a coarser mesh sees of the field (as the radiation's coarser
// meshes take area means of the finer cells), so nothing aliases into it. Across the whole
// width: the belt's lateral mean is what radiates best (its lowest lateral order), and it keeps
// the default file within 50 MB per simulated second.
struct SurfaceBlock {
  int around = 8;
  int across = 0;
};

// The mean contact patch of a run's first steps and the steady indentation (m): the radiating
// body's flat.
struct RadiatingPatch {
  double length = 0.0, width = 0.0, indentation = 0.0;
};

struct TyreStepOutputSettings {
  ContactFields fields = ContactFields::contact;
  std::filesystem::path contact_h5;  // where contact.h5 goes (unused for ContactFields::none)
  std::size_t samples = 0;           // steps the run will take
  double speed = 0.0;                // m/s
  double load = 0.0;                 // N
  SurfaceBlock surface_block;
  // The belt → radiation input mesh (belt_sampling.hpp), made once the radiating body is known:
  // the tyre flattened over the run's mean contact patch, measured over its first steps
  // (all of them up to 4096: tyre_step_outputs.cpp). Empty: no radiating velocity kept.
  std::function<Eigen::SparseMatrix<double>(const RadiatingPatch&)> tread_sampling;
  PointAveragedPsd* belt_psd = nullptr;  // receives every step's belt velocity (index j + Ny·g)
  CancellationToken cancel;              // Ctrl-C (polled where the waiting steps catch up)
  // The steps that wait for the radiating body respond on two threads, the response's recursion
  // on one and what is taken from its fields on the other (the same results bit for bit); false:
  // step by step on the calling thread (the reference, for tests).
  bool pipelined = true;
  // Set: each step's radiating velocity (tread points of the input mesh) goes to it once the
  // radiating body is known, in step order, instead of being kept (tread_velocity() stays
  // empty): a run too long to keep the record streams it (issue 13, TyreSoundStream).
  std::function<void(std::span<const double>)> tread_sink;
};

class TyreStepOutputs final : public ContactStepSink {
 public:
  TyreStepOutputs(const RollingModes& modes, TyreStepOutputSettings settings);
  ~TyreStepOutputs() override;
  TyreStepOutputs(const TyreStepOutputs&) = delete;
  TyreStepOutputs& operator=(const TyreStepOutputs&) = delete;

  void start(const SteadyRolling& steady) override;
  void take(const ContactStep& step) override;
  // After the last step: writes what is buffered and closes contact.h5. OutputError naming the
  // file and the system's reason if it cannot be written.
  void finish();

  const TextureUnderContact& texture() const noexcept { return texture_; }
  // samples × tread points of the radiation's input mesh: the belt's velocity there, with the
  // cells in contact left out (they are held by the road). Empty without tread_sampling, and
  // with a tread_sink (which takes the rows instead).
  Eigen::MatrixXd& tread_velocity() noexcept { return tread_velocity_; }
  // The window's forces at the step of the largest total force, and that step's time.
  const Eigen::VectorXd& snapshot_force() const noexcept { return snapshot_force_; }
  double snapshot_time() const noexcept { return snapshot_time_; }
  // The radial displacement of one material point (mid-width) over one revolution, starting at
  // the top of the tyre; empty if the run is shorter.
  std::vector<double> revolution() const;

 private:
  void open_contact_h5(const SurfaceResponse& response);
  // The response stage and what follows it, for step `index` with its forces.
  void respond(std::size_t index, const Eigen::Ref<const Eigen::VectorXd>& force);
  // respond() in two halves: the belt's fields of the step (the response's recursion), and
  // what is taken from them (the spectra, the radiating velocity, the revolution, contact.h5).
  int revolution_cell(std::size_t index) const;
  void evaluate(std::size_t index, const Eigen::Ref<const Eigen::VectorXd>& force, Eigen::MatrixXd& u, Eigen::MatrixXd& v);
  void use(std::size_t index, const Eigen::Ref<const Eigen::VectorXd>& force, const Eigen::MatrixXd& u,
           const Eigen::MatrixXd& v);
  // The waiting steps 0 … n − 1 (forces in patch_forces_), the two halves on two threads.
  void respond_waiting_steps();
  // tread_row_ as row `index` of tread_velocity_, through staged_rows_ (consecutive indices).
  void stage_tread_row(std::size_t index);
  void write_staged_rows();
  // The patch is measured: the mesh is made and the waiting steps respond.
  void body_known();
  std::size_t strip_length() const;
  template <class Write>
  void writing(Write&& write);

  const RollingModes& modes_;
  TyreStepOutputSettings settings_;
  TextureUnderContact texture_;
  std::unique_ptr<SurfaceResponse> response_;
  std::unique_ptr<Hdf5Writer> h5_;
  std::vector<std::string> window_names_;  // force, road (and displacement)
  std::vector<std::unique_ptr<Hdf5Writer::SliceStream>> window_streams_;
  std::unique_ptr<Hdf5Writer::SliceStream> surface_displacement_, surface_velocity_;
  Eigen::MatrixXd u_, v_;             // Ny × Nθ belt fields of the step
  Eigen::VectorXd radiating_;         // the belt velocity with the cells in contact zeroed
  std::vector<Eigen::Index> cell_under_;  // belt cell (j + Ny·g) under each window point
  std::vector<float> slice_, blocks_;
  std::vector<float> road_strip_;  // Ny × ((Nw − 1)·p + samples), row-major
  // Empty until body_known(). Row-major: each tread point's sum gathers its belt cells in a
  // register, in the same column order as the column-major scatter (the same sums bit for bit);
  // the scatter's read-modify-write of the result had been half of use()'s own time (perf).
  Eigen::SparseMatrix<double, Eigen::RowMajor> sampling_;
  double indentation_ = 0.0;
  Eigen::MatrixXd patch_forces_;  // P × steps: the forces waiting for the radiating body
  std::vector<double> patch_lengths_, patch_widths_;
  Eigen::MatrixXd tread_velocity_;
  Eigen::VectorXd tread_row_;  // one step's (for tread_sink, or copied into tread_velocity_)
  Eigen::MatrixXd staged_rows_;  // rows of tread_velocity_ not yet written (stage_tread_row)
  std::size_t staged_ = 0, staged_first_ = 0;
  Eigen::VectorXd snapshot_force_;
  double snapshot_total_ = -1.0, snapshot_time_ = 0.0;
  std::vector<double> revolution_;
};

}  // namespace rollnoise
