#pragma once
// The exchange rule of block principal pivoting (Júdice & Pires, Comput. Oper. Res. 21 (1994)
// 587–596), shared by the linear contact problem (pmatrix_lcp.cpp) and the nonlinear tread's
// contact sets (tread_newton_contact.cpp): every infeasible index changes side at once while
// their number falls, with ten tries more after it last fell; otherwise only one, the last
// (Murty's rule), which ends in finitely many steps for a P-matrix.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

class BlockPivotingExchange {
 public:
  // n: the problem's size (no count of infeasible indices exceeds it).
  explicit BlockPivotingExchange(Eigen::Index n) : n_(n), best_(n + 1) {}

  // Flips basic[i] for the infeasible indices: all those with infeasible(i) (count of them, the
  // last at `last`), or `last` alone. infeasible(i) reads basic[i] before it is flipped.
  template <class Infeasible>
  void exchange(std::vector<char>& basic, Eigen::Index count, Eigen::Index last, Infeasible&& infeasible) {
    if (count < best_ || backups_ > 0) {
      if (count < best_) {
        best_ = count;
        backups_ = kBackups;
      } else {
        --backups_;
      }
      for (Eigen::Index i = 0; i < n_; ++i) {
        char& flag = basic[static_cast<std::size_t>(i)];
        if (infeasible(i)) flag = !flag;
      }
    } else {
      basic[static_cast<std::size_t>(last)] = !basic[static_cast<std::size_t>(last)];
    }
  }

 private:
  static constexpr int kBackups = 10;
  Eigen::Index n_, best_;
  int backups_ = kBackups;
};

}  // namespace rollnoise
