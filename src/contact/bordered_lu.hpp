#pragma once
// Solves M_AA·z_A = −q_A for index sets A that differ from a base set B by a few indices, from
// one LU factorisation of M_BB and a small Schur complement of the difference (the bordered
// "Schur-complement update" of active-set QP solvers: Gill, Murray, Saunders & Wright, Math.
// Program. 49 (1990) 17–42; Bisschop & Meeraus 1977).
//
// With N = A \ B (added) and R = B \ A (removed), the unknowns z_B, z_N and multipliers λ_R obey
//   M_BB z_B + M_BN z_N + E_R λ = −q_B,   M_NB z_B + M_NN z_N = −q_N,   E_Rᵀ z_B = 0,
// which is M_AA z_A = −q_A with z_R = 0 (the multiplier frees the rows of R). With C = [M_BN E_R],
// Rᵀ-rows D = [M_NB; E_Rᵀ], X = M_BB⁻¹C and y = [z_N; λ]:
//   S·y = [−q_N; 0] − D·M_BB⁻¹(−q_B),   S = [M_NN 0; 0 0] − D·X,   z_B = M_BB⁻¹(−q_B) − X·y.
// Each index that joins the difference costs one solve with M_BB's factor (batched) and a row
// and a column of S; the set moving by a few indices per call costs O(|B|²) per index instead of
// a new O(|A|³) factorisation. The base is refactorised on the current set when the difference
// outgrows `capacity`, so round-off never accumulates across many updates: X is always one solve
// away from a fresh factor.
//
// The storage is allocated once, at construction: nothing is allocated per solve.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "core/dense_lu.hpp"

namespace rollnoise {

class BorderedLu {
 public:
  // `matrix`: n × n, every principal block of which must be nonsingular (a P-matrix);
  // `capacity`: the most indices by which a set may differ from the base before refactorising.
  BorderedLu(std::shared_ptr<const Eigen::MatrixXd> matrix, Eigen::Index capacity);

  // z = M_AA⁻¹·(−q_A) on A = {i : set[i] != 0}, zero elsewhere.
  void solve(const std::vector<char>& set, const Eigen::VectorXd& q, Eigen::VectorXd& z);

  // Moves the base to other indices: index i becomes new_index[i] (or leaves, < 0). Valid when
  // M is the same on the new indices, M(new_index[a], new_index[b]) = M(a, b) (a contact matrix
  // that depends on x_a − x_b, shifted along x). A base index that leaves forces a
  // refactorisation at the next solve.
  void relabel(const std::vector<Eigen::Index>& new_index);
  // Refactorises at the next solve (for example after a change that the base cannot follow).
  void invalidate() noexcept { base_valid_ = false; }

  Eigen::Index base_size() const noexcept { return base_count_; }
  Eigen::Index differences() const noexcept { return changes_; }
  long factorisations() const noexcept { return factorisations_; }

 private:
  void rebase(const std::vector<char>& set);
  void drop_change(Eigen::Index slot);
  void add_changes(const std::vector<char>& set);

  std::shared_ptr<const Eigen::MatrixXd> m_;
  Eigen::Index n_;
  Eigen::Index capacity_;
  DenseLu base_lu_;        // M_BB
  bool base_valid_ = false;
  long factorisations_ = 0;
  Eigen::Index base_count_ = 0;
  std::vector<Eigen::Index> base_;           // B, in factor order
  std::vector<Eigen::Index> base_position_;  // per index: its position in B, or −1
  // The difference from the base, one slot per index: which index, whether added (in A, not B)
  // or removed (in B, not A); per index, its slot or −1.
  Eigen::Index changes_ = 0;
  std::vector<Eigen::Index> change_index_;
  std::vector<char> change_added_;
  std::vector<Eigen::Index> change_slot_;
  Eigen::MatrixXd x_;  // n × capacity: X = M_BB⁻¹·C, column per slot (rows 0…|B|−1 used)
  Eigen::MatrixXd d_;  // n × capacity: Dᵀ, column per slot (M_{a,B}ᵀ for added a, e_pos for removed)
  Eigen::MatrixXd s_;  // capacity × capacity: S
  DenseLu schur_lu_;
  Eigen::VectorXd y0_, y_;
};

}  // namespace rollnoise
