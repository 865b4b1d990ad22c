#include "scene/time_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "dem/contact_model.hpp"

namespace sphdem {

DemTimeStep dem_time_step(const Scene& scene) {
  // A species with a size law counts with its smallest sphere (shortest t_c, 2.44).
  const LinearSpringDashpot& law = scene.contact.normal;
  double t_contact = std::numeric_limits<double>::infinity();
  double t_drag = std::numeric_limits<double>::infinity();
  std::vector<double> masses;
  for (const auto& sp : scene.species) {
    const double d = sp.d_min();
    const double m = sp.density * M_PI * std::pow(d, 3) / 6.0;
    masses.push_back(m);
    t_drag = std::min(t_drag, m / (3.0 * M_PI * scene.fluid.viscosity * d));
  }
  for (std::size_t a = 0; a < masses.size(); ++a) {
    auto consider = [&](double m12) {
      const ContactClosedForm c(law.k, law.beta_for(m12), m12);
      if (!(c.omega > 0))
        throw SceneError(
            fmt::format("{}: key 'contact.damping': overdamped contact (eta >= omega0) "
                        "for species '{}'",
                        scene.source, scene.species[a].name));
      t_contact = std::min(t_contact, c.contact_time());
    };
    consider(masses[a]);  // wall
    for (std::size_t b = a; b < masses.size(); ++b)
      consider(masses[a] * masses[b] / (masses[a] + masses[b]));
  }
  // With tangential friction, dt_DEM also resolves the undamped period of a sticking
  // contact, pi sqrt(m_t/k_t) with m_t = 2/7 m12 (the normal one for k_t = 2/7 k). The
  // rolling spring is slower (k_r/I_r <= 0.8 mu_r^2 k/m for equal spheres).
  if (scene.contact.tangential.model != TangentialParams::Model::kNone) {
    const double kt = scene.contact.tangential.stiffness_ratio * law.k;
    for (std::size_t a = 0; a < masses.size(); ++a) {
      t_contact = std::min(t_contact, M_PI * std::sqrt(2.0 / 7.0 * masses[a] / kt));  // wall
      for (std::size_t b = a; b < masses.size(); ++b)
        t_contact = std::min(t_contact, M_PI * std::sqrt(2.0 / 7.0 * masses[a] * masses[b] /
                                                         (masses[a] + masses[b]) / kt));
    }
  }
  return {t_contact, std::min(t_contact / scene.time.dem_steps_per_contact, 0.1 * t_drag),
          0.1 * t_drag};
}

}  // namespace sphdem
