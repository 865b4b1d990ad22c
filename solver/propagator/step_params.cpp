#include "propagator/step_params.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "scene/time_step.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

namespace {

// fluid.density_diffusion_form: auto takes the renormalised form where spheres settle under
// gravity onto a floor, whose weight bends the fluid's density profile (sph/density_diffusion.hpp),
// and spares its pass elsewhere (no spheres, no gravity, a column periodic in z).
bool renormalised_density_diffusion(const Scene& scene) {
  const std::string& form = scene.fluid.density_diffusion_form;
  if (form != "auto") return form == "renormalised";
  return scene.gravity[2] != 0.0 && !scene.periodic_z() && !scene.particles.empty();
}

}  // namespace

StepParams compile_step_params(const Scene& scene) {
  StepParams p;
  p.box = scene.box;
  p.gravity = scene.gravity;
  const bool variational = scene.pressure_coupling == PressureCoupling::kVariational;

  const FluidSpec& fs = scene.fluid;
  FluidStepParams& f = p.fluid;
  f.eos = TaitEquationOfState::from_sound_speed(fs.density, fs.sound_speed, fs.gamma);
  f.smoothing_factor = fs.smoothing_factor;
  f.spacing = fs.spacing;
  f.fill_height = scene.fill_height();
  f.momentum = MomentumParams{fs.viscosity, fs.alpha_artificial, scene.time.cfl};
  f.kinematic_viscosity = fs.viscosity / fs.density;
  f.max_dt = scene.time.max_dt_sph;
  f.relax_steps = scene.startup.relax_steps;
  f.relax_damping = scene.startup.damping;
  // no hydrostatic correction where no hydrostatic pressure is (periodic in z)
  f.diffusion = DensityDiffusion{fs.density_diffusion,
                                 fs.sound_speed,
                                 f.eos,
                                 scene.periodic_z() ? 0.0 : scene.gravity[2],
                                 f.fill_height,
                                 renormalised_density_diffusion(scene)};
  if (scene.hydrostatic_split)
    f.split = HydrostaticPressure{f.eos.rho0, scene.gravity[2], f.fill_height};

  CouplingParams& c = p.coupling;
  c.variational = variational;
  c.sphere_kernel_scale = scene.sphere_kernel_scale;
  c.drag_kernel_scale = scene.drag_kernel_scale;
  const std::array<double, 3>& g = scene.gravity;
  const double g_norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  if (scene.drag_upstream && g_norm > 0.0)
    c.drag_upstream = {g[0] / g_norm, g[1] / g_norm, g[2] / g_norm};
  if (scene.drag_voidage_upstream) {  // the floor: the bottom wall, or the plate if periodic
    c.voidage_upstream.on = true;
    c.voidage_upstream.floor_z = scene.box.lo[2];
    c.voidage_upstream.has_floor = !scene.periodic_z() || scene.flow.distributor;
    c.voidage_upstream.period = scene.periodic_z() ? scene.box.length(2) : 0.0;
  }
  c.voidage_floor = scene.voidage_floor;
  if (scene.periodic_z() && scene.flow.distributor)
    c.distributor = DistributorPlane{scene.box.lo[2], scene.box.length(2)};
  c.double_smoothing = scene.double_smoothing.enabled;
  if (c.double_smoothing) {
    c.big_h_over_d = scene.double_smoothing.h_over_d;
    c.is_big_species.assign(scene.species.size(), 0);
    double d_big = 0.0;
    for (const auto& name : scene.double_smoothing.big_species) {
      const int k = scene.species_index(name);
      c.is_big_species[k] = 1;
      d_big = std::max(d_big, scene.species[k].d_max());
    }
    c.big_cutoff = kernel::kSupport * c.big_h_over_d * d_big;
  }

  DemStepParams& d = p.dem;
  const DemTimeStep ts = dem_time_step(scene);
  d.contact_time = ts.contact_time;
  d.dt_max = ts.dt_max;
  d.free_dt_max = ts.free_dt_max;
  d.multirate = scene.time.multirate && scene.fluid.enabled;
  d.multirate_margin = scene.time.multirate_margin;
  try {
    d.law = make_contact_law(
        ContactParams{scene.contact.normal, scene.contact.tangential, scene.contact.rolling});
  } catch (const std::invalid_argument& e) {
    throw SceneError(fmt::format("{}: key 'contact.rolling': {}", scene.source, e.what()));
  }
  d.rotation = contact_law_has_history(d.law);
  d.skin = scene.contact.skin;
  d.gravity = scene.gravity;
  for (const ParticleGroupSpec& g : scene.particles)
    if (g.rigid) d.fixed_groups.push_back(g.fixed ? 1 : 0);
  if (scene.periodic_z()) {
    const double none = std::numeric_limits<double>::infinity();
    d.walls = SphereWalls(scene.flow.distributor ? scene.box.lo[2] : -none,
                          scene.flow.top_plane > 0.0 ? scene.flow.top_plane : none);
  }
  d.fluid_force = scene.fluid.enabled;
  d.drag = scene.drag;
  d.fluid = drag::Fluid{fs.density, fs.viscosity};
  d.variational = variational;
  return p;
}

}  // namespace sphdem
