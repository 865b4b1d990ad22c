#pragma once
// Rigid groups (constant-porosity blocks, thesis §4.5): the spheres of a group share its
// summed force, impulse or pressure-force change equally per unit mass. The sums run over
// the owned spheres in index order; on ranks each rank's sums are then added in rank
// order (one all-gather of four numbers a group), so every rank shares the same totals.
#include <algorithm>
#include <vector>

#include "dem/dem_particles.hpp"
#include "domain/rank_comm.hpp"

namespace sphdem {

class RigidGroups {
 public:
  RigidGroups(const DemParticles& s, const RankComm& comm) : comm_(comm) {
    for (std::size_t i = 0; i < s.size(); ++i) n_ = std::max(n_, s.rigid_group[i] + 1);
    n_ = static_cast<int>(comm_.max(static_cast<double>(n_)));  // a rank may hold no member
    fx_.assign(n_, 0);
    fy_.assign(n_, 0);
    fz_.assign(n_, 0);
    m_.assign(n_, 0);
  }
  int count() const { return n_; }
  // Groups that never move (a fixed bed): their sums read as zero, so every share is zero.
  void set_fixed(const std::vector<char>& fixed) { fixed_ = fixed; }

  // Sums value(j, fx, fy, fz) over the owned spheres of each group, and their masses.
  template <class Value>
  void sum(const DemParticles& s, Value value) {
    std::fill(fx_.begin(), fx_.end(), 0.0);
    std::fill(fy_.begin(), fy_.end(), 0.0);
    std::fill(fz_.begin(), fz_.end(), 0.0);
    std::fill(m_.begin(), m_.end(), 0.0);
    for (long j = 0; j < static_cast<long>(s.n_owned); ++j) {
      const int gr = s.rigid_group[j];
      if (gr < 0) continue;
      double fx, fy, fz;
      value(j, fx, fy, fz);
      fx_[gr] += fx;
      fy_[gr] += fy;
      fz_[gr] += fz;
      m_[gr] += s.mass[j];
    }
    if (!comm_.parallel()) {
      hold_fixed();
      return;
    }
    std::vector<double> all(4 * n_);
    for (int g = 0; g < n_; ++g) {
      all[4 * g] = fx_[g], all[4 * g + 1] = fy_[g], all[4 * g + 2] = fz_[g];
      all[4 * g + 3] = m_[g];
    }
    comm_.sum(all);
    for (int g = 0; g < n_; ++g) {
      fx_[g] = all[4 * g], fy_[g] = all[4 * g + 1], fz_[g] = all[4 * g + 2];
      m_[g] = all[4 * g + 3];
    }
    hold_fixed();
  }
  // Adds (add) or sets each member's (x, y, z) to its group's last sum over its mass.
  void share(const DemParticles& s, std::vector<double>& x, std::vector<double>& y,
             std::vector<double>& z, bool add) const {
    for (std::size_t j = 0; j < s.n_owned; ++j) {
      const int gr = s.rigid_group[j];
      if (gr < 0) continue;
      if (add) {
        x[j] += fx_[gr] / m_[gr];
        y[j] += fy_[gr] / m_[gr];
        z[j] += fz_[gr] / m_[gr];
      } else {
        x[j] = fx_[gr] / m_[gr];
        y[j] = fy_[gr] / m_[gr];
        z[j] = fz_[gr] / m_[gr];
      }
    }
  }

 private:
  void hold_fixed() {
    for (int g = 0; g < n_ && g < static_cast<int>(fixed_.size()); ++g)
      if (fixed_[g]) fx_[g] = fy_[g] = fz_[g] = 0.0;
  }
  RankComm comm_;
  int n_ = 0;
  std::vector<char> fixed_;  // per group
  std::vector<double> fx_, fy_, fz_, m_;
};

}  // namespace sphdem
