"""The scenes, one module each, and the registry SCENES: the order in which the report runs,
evaluates and prints them. A scene: name, runs(mode) -> [Run], evaluate(results, ctx) -> [Row]."""
from .block_bidisperse import BlockBidisperse
from .block_monodisperse import BlockMonodisperse
from .convergence import Convergence
from .fluidised_bed_scene import FluidisedBed
from .homogeneous_suspensions import HomogeneousSuspensions
from .sand_column import SandColumn
from .seeds import Seeds
from .single_particle import SingleParticle
from .suspension_monodisperse import SuspensionMonodisperse
from .suspension_two_species import SuspensionOfTwoSpecies
from .theory_check import TheoryCheck
from .untuned_fronts import UntunedFronts


def two_densities():
    # 0.4 s: the light-only zone between the fronts widens at U1 - U2 = 3 mm/s and is thinner
    # than the kernel support 2h = 0.6 mm until 0.2 s; the light front crosses ~8 layers
    # (validation/README.md, session 44: -0.3 % over 0.4 s, -16 % over the first 0.1 s)
    return SuspensionOfTwoSpecies("suspension_two_densities", "cases/suspension_two_densities.yaml", 0.002, False, 0.4)


def bidisperse():
    # 0.06 s left the small front 1.26 layers of travel (3.43 mm/s over 42 ms): 0.08 s gives ~2
    return SuspensionOfTwoSpecies("suspension_bidisperse", "cases/suspension_bidisperse.yaml", 0.00198, True, 0.08)


# One entry per scene. To add a scene: a class with `name`, `runs(mode)` and
# `evaluate(results, ctx)` (see validation/README.md), then one line here.
SCENES = [
    TheoryCheck(),
    SingleParticle(),
    BlockMonodisperse(),
    SuspensionMonodisperse(),
    UntunedFronts(),   # issue 38: a scene no case ships, every preset (full mode only)
    BlockBidisperse(),
    two_densities(),
    bidisperse(),
    SandColumn(),
    HomogeneousSuspensions(),
    FluidisedBed(),
    Convergence(),     # issue 38: dx, dx/1.5, dx/2 at a fixed coupling kernel; c0, CFL, box (full mode only)
    # issue 38: the settling suspensions' rows on 4 placements (full mode only), instances of their own
    Seeds([SuspensionMonodisperse(), two_densities(), bidisperse()]),
]
