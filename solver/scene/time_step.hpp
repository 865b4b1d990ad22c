#pragma once
// The DEM time step a scene needs (3.7): a fraction of the shortest contact time over
// every pair of species and the wall, and well below the lightest sphere's Stokes
// relaxation time. The SPH step follows the particles at run time (Simulation::next_dt).
#include "scene/scene.hpp"

namespace sphdem {

struct DemTimeStep {
  double contact_time = 0;  // shortest t_c (2.44), or the sticking period with friction
  double dt_max = 0;        // min(t_c / time.dem_steps_per_contact, 0.1 m/(3 pi mu d))
  double free_dt_max = 0;   // 0.1 m/(3 pi mu d): a sphere in no contact
};

// Throws SceneError naming contact.damping for an overdamped pair.
DemTimeStep dem_time_step(const Scene& scene);

}  // namespace sphdem
