#pragma once
// Hindered settling velocity of a uniform suspension (or constant-porosity block) at
// voidage eps under Di Felice-Dallavalle drag: the superficial slip v for which the drag
// carries the buoyant weight, (rho_p - rho_av) V g = f_d(eps, v), rho_av = eps rho_f +
// (1-eps) rho_p (thesis 4.2-4.4). With no net volume flux through the column the
// suspension's interface falls at this speed (Kynch 1952, thesis 4.6).
#include <cmath>

#include "coupling/drag_laws.hpp"

namespace sphdem {

inline double di_felice_hindered_settling(double d, double rho_p, double rho_f, double mu, double g,
                                          double eps) {
  const double V = M_PI * d * d * d / 6.0;
  const double weight = eps * (rho_p - rho_f) * V * g;  // (rho_p - rho_av) V g
  const drag::Fluid fluid{rho_f, mu};
  const drag::DiFeliceDallavalle law;
  double lo = 0.0, hi = 100.0;
  for (int k = 0; k < 200; ++k) {  // the drag grows monotonically with v
    const double v = 0.5 * (lo + hi);
    (law.coefficient(eps, v, d, fluid) * v > weight ? hi : lo) = v;
  }
  return 0.5 * (lo + hi);
}

}  // namespace sphdem
