#pragma once
// History engines compute u⁰(n) = Σ_{k≥1} G[k]·F(n−k), the displacement at step n caused by
// all earlier forces (the paper's eq. 3), including the pre-history: a constant preload force
// for all t < 0, so that a run starts in static equilibrium (MODEL.md §2).
//
// `direct` is the reference; faster engines (modal) plug in behind the same interface and
// must agree with it to ~1e-9 relative.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "greens/discrete_kernel.hpp"

namespace rollnoise {

enum class HistoryKind { automatic, direct, modal };

HistoryKind parse_history_kind(const std::string& name);
std::string to_string(HistoryKind kind);

class HistoryEngine {
 public:
  virtual ~HistoryEngine() = default;
  virtual std::string name() const = 0;
  // u⁰ at the current step.
  virtual void history(Eigen::Ref<Eigen::VectorXd> u0) const = 0;
  // Records the force of the current step and moves on to the next step.
  virtual void advance(const Eigen::Ref<const Eigen::VectorXd>& force) = 0;
};

// The history engine `kind` for `kernel`, for a run of at most `steps` steps, with the force
// `preload` acting for all t < 0. `automatic` picks the fastest engine valid for the kernel.
// Kinds not available for this model are an InputError naming [rolling] history.
std::unique_ptr<HistoryEngine> make_history_engine(HistoryKind kind,
                                                   std::shared_ptr<const DiscreteKernel> kernel,
                                                   std::size_t steps,
                                                   const Eigen::VectorXd& preload);

}  // namespace rollnoise
