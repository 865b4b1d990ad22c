#pragma once
// The spheres' kernel width for the variational pressure coupling, chosen from the scene's
// own numbers (coupling.sphere_kernel_scale: auto, the default; the measurements behind
// it are in bench/TRADEOFF.md). The variational coupling gives a moving sphere an extra
// drag, the kernel-sized hole it carries through the fluid particles, scaling as
// rho_f c0 v V^2 / h^4; the drag at the terminal speed is (rho_p - rho_f) g V. Their ratio
//   R = rho_f c0 v_T V / ((rho_p - rho_f) g h^4),   V = pi d^3 / 6,
// with v_T the scene's drag law's terminal speed at eps = 1 (largest over the species, at
// each one's largest diameter). Measured extra slip error: ~3 % R with the spheres'
// kernel at h, ~0.3 % R at 1.25 h, none at 1.5 h. The rule takes the narrowest width
// whose extra error stays within 0.5 %: 1 for R <= 0.17, 1.25 for R <= 1.7, else 1.5
// (which any periodic width that holds the fluid's own kernel holds too); the drag's
// fields keep h (a wide drag kernel smears the fronts of blocks and suspensions). The
// interpolated coupling has no such drag: h.
#include <string>

#include "coupling/drag_law_table.hpp"
#include "scene/scene.hpp"

namespace sphdem {

struct KernelWidthChoice {
  double scale = 1.0;       // coupling.sphere_kernel_scale
  double drag_scale = 1.0;  // coupling.drag_kernel_scale
  double ratio = 0.0;       // R above (0: not computed)
  std::string reason;       // what was chosen and why, for `sphdem check`
};

// The slip at which the drag law carries a sphere's weight in a uniform suspension at
// voidage eps (4.2-4.4): the hindered settling speed, the Kynch interface's (4.6).
double settling_speed(const drag::DragLaw& law, double d, double rho_p, double rho_f, double mu,
                      double g, double eps);

// The drag law's terminal speed of a sphere (d, rho_p) alone in the fluid (eps = 1).
double terminal_speed(const drag::DragLaw& law, double d, double rho_p, double rho_f, double mu,
                      double g);

// R of the species that gives the largest (0 without species, fluid, gravity or weight).
double extra_drag_ratio(const Scene& sc);

// The width the rule gives for the resolved scene (c0, h, drag law set).
KernelWidthChoice choose_sphere_kernel_width(const Scene& sc);

}  // namespace sphdem
