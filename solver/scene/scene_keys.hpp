#pragma once
// The one table of scene keys: every key of a scene file, in the order of its section,
// with its type, unit, default, range and meaning (scene/scene_key.hpp). The loader reads
// each key through its row; cases/README.md's tables, the fuzz dictionary and the
// fidelity presets' defaults are rendered or derived from it, and the tests hold the
// loader and writer to it (tests/unit/scene_keys_test.cpp). Adding a key: its row here,
// its field in scene/scene.hpp, and its read and write in its section's file
// (scene/scene_sections.hpp).
#include <cstddef>
#include <stdexcept>
#include <string_view>

#include "coupling/drag_law_table.hpp"
#include "dem/rolling_model.hpp"
#include "dem/tangential_model.hpp"
#include "scene/insitu_pipelines.hpp"
#include "scene/scene_key.hpp"

namespace sphdem {

namespace key_choices {
inline constexpr const char* kFidelity[] = {"fast", "balanced", "accurate", nullptr};
inline constexpr const char* kSizeLaw[] = {"list", "uniform", "normal", "lognormal", nullptr};
inline constexpr const char* kBasis[] = {"number", "volume", nullptr};
inline constexpr const char* kGroupType[] = {"single", "lattice", "random", nullptr};
inline constexpr const char* kLattice[] = {"simple_cubic", "fcc", nullptr};
inline constexpr const char* kContactModel[] = {"linear_spring_dashpot", nullptr};
inline constexpr const char* kTangentialModel[] = {"none", "linear_history", nullptr};
inline constexpr const char* kRollingModel[] = {"none", "epsd", nullptr};
inline constexpr const char* kVoidageSmoothing[] = {"single", "double", nullptr};
inline constexpr const char* kPressureCoupling[] = {"interpolated", "variational", nullptr};
inline constexpr const char* kDensityDiffusionForm[] = {"auto", "renormalised", "hydrostatic",
                                                        nullptr};
}  // namespace key_choices

// clang-format off
inline constexpr SceneKey kSceneKeys[] = {
    // ---- top level
    key_rows::text("name", "scene", "name of the scene, printed by `check`"),
    key_rows::text("description", "", "one line on what the scene is"),
    key_rows::choice("fidelity", key_choices::kFidelity, "balanced",
        "preset for the keys the scene leaves unset (table below; also `--fidelity` on `run` and `check`): a key the scene sets wins; `check` prints the three side by side"),
    key_rows::map("domain", "the box"),
    key_rows::vector3("domain.size", "m", {0.004, 0.004, 0.006}, above(0),
        "box [Lx, Ly, Lz]: [0, Lx] × [0, Ly] × [0, Lz], periodic in x and y, a wall at z = 0 (§1)")
        .limits("Lx, Ly must also pass the `fluid.spacing` checks"),
    key_rows::boolean("domain.periodic_z", false,
        "`true`: periodic in z as well, a column without wall or free surface whose fluid is driven by `flow` (a homogeneous suspension, a bed on a distributor); Lz/dx a whole number"),
    key_rows::vector3("gravity", "m/s²", {0, 0, -9.81}, any_finite(),
        "g of 2.32 and 2.35; |g| enters u_m and √(2 g H), the hydrostatic start uses |g_z|"),

    // ---- fluid
    key_rows::map("fluid", "the fluid (SPH)"),
    key_rows::boolean("fluid.enabled", true,
        "`false`: no SPH particles (dry DEM: spheres under gravity and contacts only)"),
    key_rows::number("fluid.density", "kg/m³", 1000, above(0),
        "ρf = ρ0: the Tait reference density (2.58); ε ρf the superficial density (2.52)"),
    key_rows::number("fluid.viscosity", "Pa s", 8.9e-4, above(0),
        "μ: the Morris viscous term (physics.md §1), the drag laws (2.73–2.88), Δt ≤ 0.125 h²/ν"),
    key_rows::number("fluid.spacing", "m", 2.0e-4, above(0),
        "dx of the initial simple-cubic lattice: m_a = ρ_a dx³ and h = σ dx at the start")
        .limits("Lx/dx and Ly/dx whole numbers, Lx and Ly ≥ 4.8 σ dx, the fill height ≥ 3 dx"),
    key_rows::number("fluid.smoothing_factor", "–", 1.5, closed(1, 3),
        "σ in h = σ (m/ρ)^(1/3) (2.26, 2.65)"),
    key_rows::number("fluid.fill_height", "m", 0, at_least(0),
        "H, the free surface: the hydrostatic start and √(2 g H) in c0")
        .note("0, meaning Lz").limits("≤ Lz, ≥ 3 dx"),
    key_rows::number("fluid.expected_speed", "m/s", 0, at_least(0),
        "u_m in B = 100 ρ0 u_m²/γ (2.60–2.64), through c0")
        .note("0, meaning auto (below)"),
    key_rows::number("fluid.resolution", "–", 1, closed(0.25, 4),
        "layers per `fluid.spacing`: dx = spacing / resolution, rounded to whole layers of the periodic widths; a preset's is dropped (with a note in `check`) where the box, the column or a sphere's share of its kernel would not take it, the scene's own is an error there; resolved to 1 in case.yaml")
        .note("the preset's"),
    key_rows::number("fluid.sound_speed_factor", "–", 10, closed(5, 100),
        "f in the automatic c0 = f max(u_m, √(2 |g| H)): an expected density error about 1/(2 f²)")
        .note("the preset's"),
    key_rows::number("fluid.sound_speed", "m/s", 0, at_least(0),
        "c0 of B = ρ0 c0²/γ (2.59, 2.64); `check` prints its Mach number and expected density error (`scene/sound_speed_rule.hpp`)")
        .note("0, meaning auto (below)"),
    key_rows::number("fluid.alpha_artificial", "–", 0, closed(0, 2),
        "Monaghan's α (2.56) on approaching pairs; it adds a viscosity of its own (bench/TRADEOFF.md)"),
    key_rows::number("fluid.density_diffusion", "–", 0.1, closed(0, 1),
        "δ of the density diffusion (δ-SPH, `sph/density_diffusion.hpp`): damps the acoustic noise without a shear viscosity; 0 = off"),
    key_rows::choice("fluid.density_diffusion_form", key_choices::kDensityDiffusionForm, "auto",
        "what the diffusion leaves alone: `renormalised` (Antuono et al. 2010) subtracts each pair's difference along the renormalised density gradient, so a density varying linearly, as under a suspension's weight, gets none (one more fluid pass); `hydrostatic` (Fourtakas et al. 2019, DualSPHysics's DDT) only the pure fluid's hydrostatic profile, and where a suspension's weight bends that profile (its top, the floor) it makes and removes fluid volume, a spurious flow through the suspension (validation/README.md, session 38); `auto`: `renormalised` where spheres settle under gravity onto a floor (not periodic in z), else `hydrostatic`"),
    key_rows::integer("fluid.gamma", "–", 7, closed(1, 7), "Tait exponent γ (2.58)"),
    key_rows::integer("fluid.wall_layers", "layers", 3, closed(2, 8),
        "layers of fixed wall particles below z = 0 (§1, walls)")
        .note("max(3, ⌈2σ⌉)").limits("≥ ⌈2σ⌉"),

    // ---- species
    key_rows::list("species", "the species of spheres: {name, diameter, density} or {name, size_distribution, density}"),
    key_rows::text("species.N.name", "",
        "the name groups and log columns use (no `:`, `,` or space; unique)").required(),
    key_rows::number("species.N.diameter", "m", 0, above(0),
        "d of every sphere: V = π d³/6 in the voidage (2.50), the drag, the contact mass")
        .required().limits("either `diameter` or `size_distribution`"),
    key_rows::map("species.N.size_distribution",
        "a size law of the number of spheres (`scene/size_distribution.*`): each sphere draws its own d; only `random` groups take such a species")
        .limits("either `diameter` or `size_distribution`"),
    key_rows::number("species.N.density", "kg/m³", 0, above(0), "ρp: m = ρp V (2.35)").required(),
    key_rows::choice("species.N.size_distribution.law", key_choices::kSizeLaw, "",
        "the law; only the keys of the chosen law are allowed").required(),
    key_rows::numbers("species.N.size_distribution.diameters", "m", above(0),
        "the size classes (no value twice)").required().when("law=list"),
    key_rows::numbers("species.N.size_distribution.fractions", "–", left_open(0, 1),
        "the share of each class, one per diameter, summing to 1 (± 1e-6)").required().when("law=list"),
    key_rows::choice("species.N.size_distribution.basis", key_choices::kBasis, "",
        "what `fractions` count (volume: as from a sieve analysis)").required().when("law=list"),
    key_rows::number("species.N.size_distribution.min", "m", 0, above(0),
        "smallest diameter: the bound, or the truncation").required().when("law=uniform|normal|lognormal"),
    key_rows::number("species.N.size_distribution.max", "m", 0, above(0),
        "largest diameter").required().when("law=uniform|normal|lognormal").limits("> `min`"),
    key_rows::number("species.N.size_distribution.mean", "m", 0, above(0),
        "mean of the normal law before truncation").required().when("law=normal"),
    key_rows::number("species.N.size_distribution.std", "m", 0, above(0),
        "standard deviation before truncation").required().when("law=normal"),
    key_rows::number("species.N.size_distribution.median", "m", 0, above(0),
        "median: ln d ~ N(ln median, sigma_ln²) before truncation").required().when("law=lognormal"),
    key_rows::number("species.N.size_distribution.sigma_ln", "–", 0, above(0),
        "standard deviation of ln d before truncation").required().when("law=lognormal"),

    // ---- particles
    key_rows::list("particles", "groups of spheres placed at t = 0"),
    key_rows::choice("particles.N.type", key_choices::kGroupType, "single",
        "one sphere, a lattice block, or a random suspension (random sequential addition; below voidage 0.65 collective rearrangement)"),
    key_rows::text("particles.N.species", "",
        "a `species.N.name` (one `diameter` for `single` and `lattice`); random and lattice: also a list of names, a mixture")
        .required(),
    key_rows::numbers("particles.N.fractions", "–", left_open(0, 1),
        "number fractions of the mixture, one per species, summing to 1 (± 1e-6)")
        .when("type=random|lattice").note("[1]; required with two species or more"),
    key_rows::vector3("particles.N.velocity", "m/s", {0, 0, 0}, any_finite(), "velocity at release"),
    key_rows::number("particles.N.velocity_jitter", "m/s", 0, at_least(0),
        "each velocity component plus a uniform random number in [−jitter, jitter]"),
    key_rows::whole64("particles.N.velocity_seed", 1, "seed of the jitter"),
    key_rows::boolean("particles.N.rigid", false,
        "a constant-porosity block: the group moves rigidly, sharing the total force (thesis §4.5)"),
    key_rows::boolean("particles.N.fixed", false,
        "the group never moves: a fixed bed the fluid flows through (its spheres still take the fluid's forces, which it returns; implies `rigid`)"),
    key_rows::vector3("particles.N.position", "m", {0, 0, 0}, any_finite(), "centre of the sphere")
        .when("type=single").note("the box's centre").limits("inside the box, z ≥ d/2"),
    key_rows::vector3("particles.N.min", "m", {0, 0, 0}, any_finite(), "low corner of the region")
        .when("type=lattice|random").limits("0 ≤ min < max ≤ `domain.size`"),
    key_rows::vector3("particles.N.max", "m", {0, 0, 0}, any_finite(), "high corner of the region")
        .when("type=lattice|random").note("`domain.size`").limits("0 ≤ min < max ≤ `domain.size`"),
    key_rows::choice("particles.N.lattice", key_choices::kLattice, "simple_cubic",
        "simple cubic, or face-centred cubic (4 sites a cell in (100) layers, as LAMMPS' `lattice fcc`)")
        .when("type=lattice"),
    key_rows::number("particles.N.voidage", "–", 0.9, half_open(0.2595, 1),
        "target voidage ε of the region")
        .when("type=lattice|random")
        .limits("simple cubic ≥ 1 − π/6 = 0.4764, fcc ≥ 1 − π/(3√2) = 0.2595, random ≥ 0.36 (random close packing; equal spheres reach 0.4-0.42)"),
    key_rows::whole64("particles.N.seed", 0,
        "seed of the positions and diameters (random), of the species' shuffle over the sites (mixed lattice)")
        .when("type=random|lattice").limits("lattice: a mixed one only"),

    // ---- contact
    key_rows::map("contact", "the contact law: normal (below), tangential and rolling parts"),
    key_rows::choice("contact.model", key_choices::kContactModel, "linear_spring_dashpot",
        "the normal force of 2.36"),
    key_rows::number_or_auto("contact.stiffness", "N/m", above(0),
        "k of 2.36; contact time t_c = π/ω (2.44); `auto`: the softest k whose largest overlap stays under `contact.max_overlap` d at impact and under the sediment's weight (`scene/contact_stiffness_rule.hpp`)")
        .note("`auto`"),
    key_rows::number("contact.max_overlap", "fraction of d", 0.01, left_open(0, 0.2),
        "the overlap `contact.stiffness: auto` allows").note("the preset's"),
    key_rows::number("contact.damping", "kg/s", 0, at_least(0), "β of 2.36, η = β/(2 m12) (2.44)")
        .limits("not with `restitution`"),
    key_rows::number("contact.restitution", "–", 1, left_open(0, 1),
        "e_n: β chosen per pair from m12 so that 2.46 gives it")
        .note("unset").limits("not with `damping`"),
    key_rows::boolean("contact.clip_attraction", false,
        "`true`: the normal force never pulls (LAMMPS gran/hooke)"),
    key_rows::number("contact.skin", "fraction of the largest d", 0.3, closed(0, 2), "the Verlet list's skin"),
    key_rows::map("contact.tangential", "friction (`dem/tangential_model.hpp`); off by default"),
    key_rows::choice("contact.tangential.model", key_choices::kTangentialModel, "none",
        "`linear_history`: a linear spring on the tangential displacement with a dashpot and the Coulomb limit (Luding 2008; LAMMPS gran/hooke/history)"),
    key_rows::number("contact.tangential.stiffness_ratio", "–", TangentialParams{}.stiffness_ratio,
        left_open(0, 1), "k_t / k: with 2/7 a sticking contact oscillates at the normal frequency")
        .when("model=linear_history").note("2/7"),
    key_rows::number("contact.tangential.damping", "kg/s", 0, at_least(0), "γ_t: F_t = −k_t ξ − γ_t v_t")
        .when("model=linear_history").limits("not with `restitution`"),
    key_rows::number("contact.tangential.restitution", "–", 1, left_open(0, 1),
        "e_t: γ_t per pair so that a sticking contact (mass 2/7 m12) has this restitution, as 2.46")
        .when("model=linear_history").note("unset").limits("not with `damping`"),
    key_rows::number("contact.tangential.friction", "–", 0, at_least(0),
        "Coulomb's μ, sphere–sphere and sphere–wall").required().when("model=linear_history"),
    key_rows::map("contact.rolling", "rolling resistance (`dem/rolling_model.hpp`); off by default"),
    key_rows::choice("contact.rolling.model", key_choices::kRollingModel, "none",
        "`epsd`: the elastic–plastic spring–dashpot of Ai et al. (2011, type C; LIGGGHTS epsd); needs `contact.tangential.model: linear_history`"),
    key_rows::number("contact.rolling.friction", "–", 0, closed(0, 1),
        "μ_r: the torque is capped at μ_r R_eff |F_n|").required().when("model=epsd"),
    key_rows::number("contact.rolling.damping_ratio", "–", RollingParams{}.damping_ratio, at_least(0),
        "η_r of the dashpot C_r = η_r 2 √(I_r k_r)").when("model=epsd"),

    // ---- drag, coupling
    key_rows::map("drag", "the drag law"),
    key_rows::choice("drag.law", drag::kDragLawNames.names, "di_felice",
        "f_d(ε, u_s) of 2.68; the laws are in the table below (`coupling/drag_law_table.hpp`); a law without a voidage function only where every group's ε ≥ 0.99, `none` only where every group is rigid or fixed (`scene/scene_limits.hpp`)"),
    key_rows::map("coupling", "how the fluid and the spheres exchange momentum"),
    key_rows::number("coupling.voidage_floor", "–", 0.3, closed(0.05, 0.95),
        "floor on ε_a of 2.50 (the log column `voidage_clamped` counts its hits)"),
    key_rows::choice("coupling.voidage_smoothing", key_choices::kVoidageSmoothing, "single",
        "`single` (2.50), or `double` (thesis §3.4, 3.8–3.10): the big species smoothed apart with their own kernel, then the fluid's; `double` only where every group is rigid or fixed under gravity (it forces the interpolated coupling, unstable over a packed bed)"),
    key_rows::names("coupling.big_species", nullptr, "the species smoothed apart")
        .when("voidage_smoothing=double").note("the species with the largest diameter"),
    key_rows::number("coupling.big_h_over_d", "–", 1.5, closed(0.5, 5),
        "h_b / d of the big spheres' kernel (3.9)").when("voidage_smoothing=double"),
    key_rows::choice("coupling.pressure_coupling", key_choices::kPressureCoupling, "variational",
        "`interpolated` (2.68–2.71: V_j(−∇P + ∇·τ) at each sphere, returned with the drag) or `variational` (the pressure forces derive from the fluid's internal energy, pair by pair)")
        .note("`variational`; `interpolated` with `voidage_smoothing: double` or without fluid"),
    key_rows::boolean("coupling.hydrostatic_split", true,
        "the pair forces carry P − P_h(z) and P_h's forces are added exactly, P_h = ρ0 |g| × the depth below the fill height, zero above it (variational only, gravity along −z)")
        .note("`true` where it applies"),
    key_rows::number_or_auto("coupling.sphere_kernel_scale", "–", closed(1, 3),
        "H/h: each sphere's volume spread over the fluid with the kernel at H (2.50, 2.69–2.72, the variational forces); `auto` chooses 1, 1.25 or 1.5 from the scene (`scene/kernel_width_rule.hpp`)")
        .note("`auto`").limits("the periodic width ≥ 2.4 scale σ dx"),
    key_rows::number("coupling.drag_kernel_scale", "–", 1, closed(1, 3),
        "H_drag/h: the kernel the drag's fields are gathered with (ε, u_f and the Shepard sum at a sphere) and the reaction spreads with")
        .note("a given `sphere_kernel_scale`; 1 under `auto`").limits("≤ `sphere_kernel_scale`"),
    key_rows::boolean("coupling.drag_upstream", true,
        "the drag's fields at a sphere (ε and u_f of 2.74) gathered from the fluid on the side gravity points to, the half of its kernel the fluid passing a settling or fluidised sphere comes from, where that half holds at least a quarter of the Shepard sum and the sphere is not alone (voidage under 0.99; else the whole kernel, as at the floor and for a lone sphere): the clear liquid above a suspension then does not speed its top spheres into a skin that overturns (validation/README.md, session 37); the Shepard sum and the reaction keep the whole kernel")
        .note("`true` under gravity"),
    key_rows::boolean("coupling.drag_voidage_upstream", false,
        "the voidage the drag reads at a fluid particle (ε_drag, which the spheres above it gather with `drag_upstream`) from the spheres at or below it: 1 − 2 Σ_{z_j ≤ z_a} V_j W_aj, the lower half of 2.50 doubled, equal to the whole kernel's in a uniform suspension; under a suspension's top it reads the suspension, not the clear liquid above it, and the top spheres do not pack into a skin; the whole kernel within a support of the floor or the distributor plate, for a lone sphere (ε ≥ 0.99) and with `voidage_smoothing: double`. For a suspension settling from rest onto the floor: the lower face of a falling block or cloud would read the clear liquid under it and fall fast (validation/README.md, session 45). Needs gravity along −z and `drag_upstream`")
        .note("`false`"),

    // ---- time, startup, output
    // ---- flow (domain.periodic_z)
    key_rows::map("flow", "the imposed flow of a column periodic in z: a uniform body force, the mean pressure gradient, set each step so that the fluid's superficial velocity follows U(t) (`propagator/flow_controller.hpp`)"),
    key_rows::numbers("flow.times", "s", at_least(0),
        "times of the schedule, increasing; U is linear between them and held after the last")
        .note("[0]").limits("as many as `flow.superficial_velocity`; needs `domain.periodic_z`"),
    key_rows::numbers("flow.superficial_velocity", "m/s", any_finite(),
        "U(t) along +z at `flow.times`: the fluid's momentum over ρf and the box's volume (0: a homogeneous suspension settling through fluid at rest on the mean)")
        .note("[0]").limits("needs `domain.periodic_z`"),
    key_rows::boolean("flow.distributor", false,
        "`true`: a plane at z = 0 that stops the spheres (their bottom wall, with `contact`'s law) and lets the fluid through: a bed rests on it"),
    key_rows::number("flow.top_plane", "m", 0, at_least(0),
        "height of a frictionless plane that holds the spheres the flow carries up (the fluid passes it); 0: none")
        .limits("above every group, at most Lz − the largest diameter (no contact across the periodic face); needed where U passes a species' terminal speed"),

    key_rows::map("time", "the time steps"),
    key_rows::number("time.end", "s", 0.02, above(0), "simulated time after release"),
    key_rows::number("time.cfl", "–", 0.25, left_open(0, 1),
        "Δt_SPH ≤ cfl h_a / v_sig (3.5), and ≤ 0.125 h²/ν, 0.25 √(h/|a|), `max_dt_sph`")
        .note("the preset's"),
    key_rows::number("time.dem_steps_per_contact", "–", 20, closed(5, 1000),
        "Δt_DEM ≤ t_c / N (3.7), and ≤ 0.1 m/(3πμd)").note("the preset's"),
    key_rows::boolean("time.multirate", true,
        "with fluid, spheres beyond a margin of every neighbour take one step of their fluid force per half step, the others the contact sub-steps (`propagator/dem_substepper.hpp`)"),
    key_rows::number("time.multirate_margin", "–", 4, closed(0, 100),
        "that margin, in the farthest a sphere goes in a half step; a half step in which one went half of it starts again sub-stepped"),
    key_rows::number("time.max_dt_sph", "s", 1e-3, above(0), "upper cap on Δt_SPH"),
    key_rows::map("startup", "the relaxation before release"),
    key_rows::integer("startup.relax_steps", "steps", 200, closed(0, 1000000),
        "fluid-only steps with the spheres held, before t = 0"),
    key_rows::number("startup.damping", "–", 0.02, half_open(0, 1),
        "fraction of the fluid velocity removed in each relaxation step"),
    key_rows::map("output", "what a run writes besides its log and checkpoints"),
    key_rows::number("output.log_interval", "s", 0, at_least(0), "period of the rows of `log.csv`")
        .note("0, meaning `time.end` / 200"),
    key_rows::number("output.progress_interval", "s (wall clock)", 2, at_least(0),
        "time between progress lines on the terminal"),
    key_rows::map("output.vtk", "full snapshots for ParaView"),
    key_rows::number("output.vtk.every", "s", 0, at_least(0),
        "simulated time between `DIR/vtk/*.vtp` snapshots with `.pvd` time collections; 0 = none"),

    // ---- checkpoint, watchdog
    key_rows::map("checkpoint", "checkpoints (`run/checkpoints.hpp`)"),
    key_rows::number("checkpoint.every", "s", 0, at_least(0),
        "simulated time between checkpoints `DIR/checkpoints/ckpt_<step>.h5`; 0 = none by this clock"),
    key_rows::number("checkpoint.wall_interval", "s (wall clock)", 1800, at_least(0),
        "wall time between checkpoints; 0 = none by this clock"),
    key_rows::integer("checkpoint.keep", "–", 2, closed(1, 1000),
        "newest checkpoints kept (an older one is the fallback when the newest does not read back whole)"),
    key_rows::boolean("checkpoint.at_end", true,
        "a checkpoint after the last step (`sphdem resume DIR --set time.end=T` extends the run)"),
    key_rows::map("watchdog", "checks of the state after every step (`analysis/watchdog.*`)"),
    key_rows::boolean("watchdog.enabled", true,
        "stop a run going wrong naming the particle, the quantity and the likely cause"),
    key_rows::number_or_auto("watchdog.density_error", "–", above(0),
        "bound on |ρ/(ε ρ0) − 1| of any fluid particle; `auto`: twice the expected density error of c0 (`scene/sound_speed_rule.hpp`), within [1 %, 2 %]; a warning once past 1.5 times the expected one")
        .note("`auto`"),
    key_rows::number("watchdog.overlap", "–", 0.1, above(0),
        "bound on any sphere's largest overlap / d (the soft-sphere limit `check` refuses past); a warning once past the spring's expected overlap"),
    key_rows::number("watchdog.safeguard_share", "–", 0.01, closed(0, 1),
        "bound on the share of the fluid held at `coupling.voidage_floor` or with Ω clamped, in one step"),

    // ---- insitu
    key_rows::map("insitu", "the in-situ analysis through Catalyst (needs a build with ParaView)"),
    key_rows::boolean("insitu.enabled", true,
        "run the in-situ pipelines (`sphdem run --no-insitu` also turns them off)"),
    key_rows::number("insitu.every", "s", 0, at_least(0), "simulated time between analyses")
        .note("0, meaning `time.end` / 50"),
    key_rows::names("insitu.pipelines", kInSituPipelineNames.names,
        "which pipelines of `pipelines/` run (pipelines/README.md)").note("all"),
    key_rows::integer("insitu.snapshot_every", "analyses", 5, closed(1, 1000000),
        "analyses between PNG snapshots"),
    key_rows::number("insitu.grid_spacing", "m", 0, at_least(0),
        "node spacing of the voidage map (rounded to whole nodes across the periodic widths)")
        .note("0, meaning `fluid.spacing`"),
    key_rows::number("insitu.reference_velocity", "m/s", 0, at_least(-1),
        "the Kynch line on the voidage–height–time map: > 0 as given; 0 the Di Felice hindered settling speed (4.2–4.4) of the first lattice or random group at its voidage (d32 for a size law); < 0 none")
        .note("0, meaning auto"),
};
// clang-format on

inline constexpr std::size_t kSceneKeyCount = sizeof(kSceneKeys) / sizeof(kSceneKeys[0]);

// The row of a key path (list indices as N). Throws std::logic_error for a key not in
// the table: a constant expression where the path is one, so a misspelt key in a
// constexpr context does not compile.
constexpr const SceneKey& scene_key(std::string_view path) {
  for (const SceneKey& k : kSceneKeys)
    if (k.key == path) return k;
  throw std::logic_error("not a scene key");
}

// The default value of a number, integer or boolean key.
constexpr double scene_default(std::string_view path) {
  return scene_key(path).number;
}

}  // namespace sphdem
