"""Scene `theory`: the closed forms themselves, (4.4) at the thesis's parameters and the
two-species model's self-check (no run)."""
import theory

from ..rows import Row


class TheoryCheck:
    """The closed forms themselves: (4.4) at the thesis's parameters against its value."""
    name = "theory"

    def runs(self, mode):
        return []

    def evaluate(self, results, ctx):
        v = theory.di_felice_block_slip(1e-4, 2500, 1000, 8.9e-4, 0.9)
        ref = 4.924e-3
        return [Row(self.name, "Di Felice slip (4.4), ε = 0.9, d = 100 µm, ρp = 2500 (theory.py)",
                    "4.924 mm/s", "thesis §4.5 (closed_forms.hpp tolerance 0.03 mm/s)", f"{v * 1e3:.4f} mm/s",
                    v / ref - 1, 0.03e-3 / ref, None, kind="self-check",
                    note="theory.py and closed_forms.hpp both give 4.9124 mm/s with μ = 8.9e-4, g = 9.81"),
                Row(self.name, "Masliyah–Kynch two-species model (theory.TwoSpeciesKynch) with two equal densities "
                               "(2450/2450, ε0 = 0.9): largest relative deviation of both species' speeds, both "
                               "fronts and φ_B from the monodisperse (4.4), and of one species alone at ε = 0.8, "
                               "0.9, 0.95", "0", "theory.mixture_self_check", f"{theory.mixture_self_check():.1e}",
                    theory.mixture_self_check(), 1e-9, None, kind="self-check")]
