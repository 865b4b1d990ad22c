#pragma once
// The limits of the model a scene must respect, checked before it runs (`sphdem check`
// lists every breach, `sphdem run` refuses the scene): past them the solver would run
// and give a quiet wrong answer, so it names the limit and the key to change instead.
//  - a sphere small against the kernel its drag reads the voidage with: the voidage
//    (2.50) at a sphere includes its own volume, 1 - V W(0) for a lone sphere, and the
//    drag law's voidage function then gives it the drag of a suspension. V W(0) <= 0.025
//    (d/h <= 0.48; a terminal slip within 5 % of the lone sphere's, validation/README.md;
//    with double smoothing, a big sphere's kernel is its own and the fluid's in quadrature);
//  - a sphere's terminal Reynolds number within its drag law's range (the table's
//    reynolds_max, coupling/drag_law_table.hpp: Stokes' law (2.73) up to Re = 2, where
//    Schiller-Naumann's 1 + 0.15 Re^0.687 is 1.24);
//  - spheres no lighter than the fluid under gravity: they would rise through the
//    free surface, above which the model has no fluid;
//  - the sound speed's expected density error (scene/sound_speed_rule.hpp) within the
//    weakly compressible limit, 1 %, and the compression's share of the lightest
//    species' buoyant weight within kBuoyancyErrorLimit (2 %);
//  - the coupling the spheres can run with: a drag law with a voidage function for any
//    group at voidage < kLoneSphereVoidage, drag at all for spheres free to move, and the
//    single smoothing for spheres that can settle into a bed (the double one forces the
//    interpolated coupling, unstable over a packed bed);
//  - the spring's expected largest overlap (scene/contact_stiffness_rule.hpp) within
//    10 % of d, past which a soft-sphere contact no longer models two touching spheres
//    (not for blocks whose spheres all move rigidly).
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace sphdem {

// The share of its drag kernel (of width h) a sphere of diameter d fills, V W(0), and
// the largest a scene may have.
inline constexpr double kSelfVoidageLimit = 0.025;
double sphere_kernel_share(double d, double h);

struct LimitBreach {
  std::string key;      // the scene key to change
  std::string message;  // the limit, the scene's value and the allowed range
};

std::vector<LimitBreach> scene_limit_breaches(const Scene& sc);

// "FILE: key 'K': message", one line per breach.
std::string describe_breaches(const Scene& sc, const std::vector<LimitBreach>& breaches);

// Thrown by `sphdem run` for a scene with breaches; what() lists every one.
void refuse_scene_past_limits(const Scene& sc);

}  // namespace sphdem
