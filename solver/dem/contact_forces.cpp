#include "dem/contact_forces.hpp"

#include <stdexcept>
#include <type_traits>

namespace sphdem {

void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list,
                            const LinearSpringDashpot& law, const HaloImages& images,
                            double wall_z) {
  const long n = static_cast<long>(s.n_owned);
  const double bf = law.beta_factor();
  // Chunks taken in turn: a bed and a dilute suspension above it differ in contacts per
  // sphere. Below 256 spheres a parallel region costs more than the work.
#pragma omp parallel for schedule(dynamic, 256) if (n > 256)
  for (long i = 0; i < n; ++i)
    store_contact_row<NormalContact>(s, i, normal_contact_row(s, list, law, bf, images, wall_z, i));
}

template <class Model>
void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list, const Model& model,
                            ContactHistory& history, const HaloImages& images, double wall_z, double dt) {
  static_assert(Model::kHistory, "the normal-only law has its own pass");
  if (history.pair.size() != list.neighbour.size() || history.wall.size() != s.n_owned)
    throw std::logic_error("compute_contact_forces: the contact history is not loaded for this list");
  const long n = static_cast<long>(s.n_owned);
  const double bf = model.normal.beta_factor();
#pragma omp parallel for schedule(dynamic, 256) if (n > 256)  // as the normal-only pass
  for (long i = 0; i < n; ++i)
    store_contact_row<Model>(
        s, i, history_contact_row(s, list, model, bf, history, images, wall_z, dt, i));
}

template void compute_contact_forces(DemParticles&, const ContactNeighbourList&, const FrictionalContact&,
                                     ContactHistory&, const HaloImages&, double, double);
template void compute_contact_forces(DemParticles&, const ContactNeighbourList&, const FrictionalRollingContact&,
                                     ContactHistory&, const HaloImages&, double, double);

void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list, const ContactLaw& law,
                            ContactHistory& history, const HaloImages& images, double wall_z, double dt) {
  std::visit(
      [&](const auto& model) {
        if constexpr (std::decay_t<decltype(model)>::kHistory)
          compute_contact_forces(s, list, model, history, images, wall_z, dt);
        else
          compute_contact_forces(s, list, model.normal, images, wall_z);
      },
      law);
}

}  // namespace sphdem
