#include "dem/contact_forces.hpp"

#include <type_traits>

#include "domain/row_partition.hpp"

namespace sphdem {

void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list,
                            const LinearSpringDashpot& law, const HaloImages& images,
                            SphereWalls walls) {
  const long n = static_cast<long>(s.n_owned);
  const double bf = law.beta_factor();
  // A bed and a dilute suspension above it differ in contacts per sphere: contiguous
  // shares of equal cost (domain/row_partition.hpp), as the DEM sub-step's force pass.
#pragma omp parallel if (n > kMinParallelSpheres)
  for (auto [i, end] = thread_rows(list.offset, n, kContactRowCost); i < end; ++i)
    store_contact_row<NormalContact>(s, i, normal_contact_row(s, list, law, bf, images, walls, i));
}

template <class Model>
void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list, const Model& model,
                            ContactHistory& history, const HaloImages& images, SphereWalls walls,
                            double dt) {
  static_assert(Model::kHistory, "the normal-only law has its own pass");
  history.require_aligned(list, s.n_owned);
  const long n = static_cast<long>(s.n_owned);
  const double bf = model.normal.beta_factor();
#pragma omp parallel if (n > kMinParallelSpheres)  // as the normal-only pass
  for (auto [i, end] = thread_rows(list.offset, n, kContactRowCost); i < end; ++i)
    store_contact_row<Model>(
        s, i, history_contact_row(s, list, model, bf, history, images, walls, dt, i));
}

template void compute_contact_forces(DemParticles&, const ContactNeighbourList&,
                                     const FrictionalContact&, ContactHistory&, const HaloImages&,
                                     SphereWalls, double);
template void compute_contact_forces(DemParticles&, const ContactNeighbourList&,
                                     const FrictionalRollingContact&, ContactHistory&,
                                     const HaloImages&, SphereWalls, double);

void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list,
                            const ContactLaw& law, ContactHistory& history,
                            const HaloImages& images, SphereWalls walls, double dt) {
  std::visit(
      [&](const auto& model) {
        if constexpr (std::decay_t<decltype(model)>::kHistory)
          compute_contact_forces(s, list, model, history, images, walls, dt);
        else
          compute_contact_forces(s, list, model.normal, images, walls);
      },
      law);
}

}  // namespace sphdem
