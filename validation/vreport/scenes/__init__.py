"""The scenes, one module each, and the registry SCENES: the order in which the report runs,
evaluates and prints them. A scene: name, runs(mode) -> [Run], evaluate(results, ctx) -> [Row]."""
from .block_bidisperse import BlockBidisperse
from .block_monodisperse import BlockMonodisperse
from .fluidised_bed_scene import FluidisedBed
from .homogeneous_suspensions import HomogeneousSuspensions
from .sand_column import SandColumn
from .single_particle import SingleParticle
from .suspension_monodisperse import SuspensionMonodisperse
from .suspension_two_species import SuspensionOfTwoSpecies
from .theory_check import TheoryCheck
from .untuned_fronts import UntunedFronts


# One entry per scene. To add a scene: a class with `name`, `runs(mode)` and
# `evaluate(results, ctx)` (see validation/README.md), then one line here.
SCENES = [
    TheoryCheck(),
    SingleParticle(),
    BlockMonodisperse(),
    SuspensionMonodisperse(),
    UntunedFronts(),   # issue 38: a scene no case ships, every preset (full mode only)
    BlockBidisperse(),
    # 0.06 s left the light front 0.71 layers of travel (2.1 mm/s over 42 ms): 0.1 s gives ~1.8
    SuspensionOfTwoSpecies("suspension_two_densities", "cases/suspension_two_densities.yaml", 0.002, False, 0.1),
    # 0.06 s left the small front 1.26 layers of travel (3.43 mm/s over 42 ms): 0.08 s gives ~2
    SuspensionOfTwoSpecies("suspension_bidisperse", "cases/suspension_bidisperse.yaml", 0.00198, True, 0.08),
    SandColumn(),
    HomogeneousSuspensions(),
    FluidisedBed(),
]
