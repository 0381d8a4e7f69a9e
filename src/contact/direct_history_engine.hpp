#pragma once
// The reference history engine: the paper's eq. 3 summed as written, one matrix–vector product
// over the whole stored history per step (O(n·N²) at step n).
#include "contact/history_engine.hpp"

namespace rollnoise {

class DirectHistoryEngine : public HistoryEngine {
 public:
  DirectHistoryEngine(std::shared_ptr<const DiscreteKernel> kernel, std::size_t steps,
                      const Eigen::VectorXd& preload);

  std::string name() const override { return "direct"; }
  void history(Eigen::Ref<Eigen::VectorXd> u0) const override;
  void advance(const Eigen::Ref<const Eigen::VectorXd>& force) override;

 private:
  std::shared_ptr<const DiscreteKernel> kernel_;
  Eigen::Index points_;
  std::size_t lags_;  // K: G[0 … K−1]
  // The kernel reversed and side by side, [G[K−1] … G[1]], so that the history of the last
  // m steps, stored oldest first, meets its lags in one contiguous matrix–vector product.
  Eigen::MatrixXd reversed_;
  // F(0), F(1), … stacked; room for the whole run is reserved up front (no allocation in the
  // step loop).
  Eigen::VectorXd forces_;
  std::size_t step_ = 0;
  // Contribution of the preload acting for t < 0: (Σ_{k>n} G[k])·F_pre at step n, updated by
  // subtracting G[n]·F_pre each step.
  Eigen::VectorXd pre_history_;
  Eigen::VectorXd preload_;
};

}  // namespace rollnoise
