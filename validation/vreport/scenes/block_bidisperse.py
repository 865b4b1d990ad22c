"""Scene block_bidisperse (thesis §4.6, §5.3): rigid bidisperse blocks against (4.5), the
double smoothing against the classic one, and the face effect as the monodisperse block."""
import os

import numpy as np
import yaml

import theory

from ..rows import Row, failed_run_rows
from ..runs import REPO, Run
from .block_monodisperse import BlockMonodisperse
from .common import face_extrapolation, time_average, whole_periods


def two_species_mean(r, prefix, t0, t1):
    """Mean over [t0, t1] of the average of a per-species log column over the species
    (the sphere-count mean when the species are dealt half and half)."""
    names = [sp["name"] for sp in r.case["species"]]
    return float(np.mean([time_average(r.log["time"], r.log[f"{prefix}:{n}"], t0, t1) for n in names]))


class BlockBidisperse:
    """Thesis §4.6/§5.3: rigid bidisperse blocks (half of each size by number) against
    (4.5), the classic single smoothing at h/d_big = 2 against the double smoothing
    (3.8-3.10) at h/d_small = 2. The slip is the mean of the two species' superficial
    slips over whole acoustic periods, as the monodisperse block."""
    name = "block_bidisperse"
    TARGET = 0.04
    PAIRS = {"150_100": "cases/block_bidisperse_150_100.yaml", "200_100": "cases/block_bidisperse_200_100.yaml"}
    DOUBLE = {"fluid.spacing": 2.0e-4, "coupling.voidage_smoothing": "double"}
    # at the spheres' kernel h, as these rows were made (the variational coupling's own
    # default is the width rule's, scene/kernel_width_rule.hpp)
    VARIATIONAL = {"coupling.pressure_coupling": "variational", "coupling.sphere_kernel_scale": 1}

    @staticmethod
    def tall(case):
        """The case's block from z = 1 to 5 mm instead of 2.5 to 4.5 mm, across the same width."""
        hi = yaml.safe_load(open(os.path.join(REPO, case)))["particles"][0]["max"]
        return {"particles.0.min": "[0.0,0.0,0.001]", "particles.0.max": f"[{hi[0]:g},{hi[1]:g},0.005]"}
    SPREAD = ("the kernel at the block's faces under Beetstra's steep voidage dependence, as the rows above. In "
              "16 ms runs (last period; 150/100, 200/100 classic, variational: +6.6, +9.3 % there) the block's "
              "force balance with what each sphere sees accounts for it: the voidage at release +7.6, +10.5 %; "
              "with the window's voidage and pressure force (1.017, 1.020 of ρ_av g V: the variational pairs "
              "push the face spheres up) +6.1, +8.8 %; with each sphere's own slip (spread 4.7, 3.9 %) +6.4, "
              "+9.1 % (bidisperse_block_validation.cpp's balance, run with coupling.pressure_coupling: variational)")
    SMEAR = ("the kernel-smeared block faces, as the monodisperse block, amplified by Beetstra's steeper voidage "
             "dependence. The block's force balance with what each sphere sees accounts for all of it "
             "(tests/validation/bidisperse_block_validation.cpp, 16 ms runs, last period; 150/100 and 200/100 "
             "double, 150/100 and 200/100 classic): the voidage at release gives +5.8, +5.4, +7.6, +10.5 %; "
             "with the window's voidage and pressure force (0.997, 1.003, 0.987, 0.979 of ρ_av g V) +6.2, +5.2, "
             "+8.8, +12.3 %; with each sphere's own slip (the face spheres see the clear fluid's velocity "
             "through the kernel: spread 7.3, 9.7, 4.5, 3.5 %) +7.0, +7.6, +9.0, +12.6 %, against +7.3, +7.4, "
             "+9.3, +12.6 % simulated. An unbounded block has no faces; a taller one halves the error (rows at the end: "
             "the double-smoothing blocks 4 mm tall, and both heights extrapolated to no faces)")

    def runs(self, mode):
        out = []
        for pair, case in self.PAIRS.items():
            base = {"output.log_interval": 1e-4, "contact.stiffness": 0.01}  # rigid lattice: no contacts
            if mode == "reduced":
                # the case's width: in a 2 mm box the shuffled lattice has 7 x 7 sites per layer
                # and the 200/100 block came out +8.1 % (inferred eps_i 0.9017), against
                # +2.8 % in the case's 4 mm box (tests/validation/bidisperse_block_validation)
                base.update({"time.end": 0.016})
                out.append(Run(f"block_{pair}_double", case, dict(base, **self.DOUBLE)))
            else:
                out.append(Run(f"block_{pair}_double", case, dict(base, **self.DOUBLE)))
                # twice as tall (1-5 mm instead of 2.5-4.5 mm), as the monodisperse block: the
                # faces' share should halve, and the two heights extrapolate to no faces
                out.append(Run(f"block_{pair}_doubletall", case, dict(base, **self.DOUBLE, **self.tall(case))))
                out.append(Run(f"block_{pair}_classic", case, base))
                # the variational pressure coupling (single smoothing only): the faces' share
                out.append(Run(f"block_{pair}_classicvar", case, dict(base, **self.VARIATIONAL)))
        return out

    def measure(self, r):
        """The block's mean slip over whole acoustic periods after the start-up, its mean
        speed, and the reference (4.5) at the case's voidage."""
        big, small = r.case["species"][0], r.case["species"][1]
        rho_f, mu = r.fluid()
        eps = r.case["particles"][0]["voidage"]
        ref = theory.bidisperse_block_slip(big["diameter"], small["diameter"], 0.5, big["density"], rho_f, mu,
                                           eps, r.g())
        t0, t1, _ = whole_periods(r, BlockMonodisperse.STARTUP)
        return two_species_mean(r, "slip_z_mean", t0, t1), -two_species_mean(r, "vz_mean", t0, t1), ref

    def evaluate(self, results, ctx):
        rows = []
        for key, r in results.items():
            if not key.startswith("block_") or key.count("_") != 3 or key.endswith("tall"):
                continue
            if not r.ok or r.log is None:
                rows += failed_run_rows(self.name, r, key)
                continue
            big, small = r.case["species"][0], r.case["species"][1]
            rho_f, mu = r.fluid()
            eps = r.case["particles"][0]["voidage"]
            slip, v, ref = self.measure(r)
            double = key.endswith("double")
            variational = key.endswith("classicvar")
            dx = r.case["fluid"]["spacing"]
            how = (f"double smoothing, h/d_small = {dx / small['diameter']:.3g}" if double
                   else f"classic, h/d_big = {dx / big['diameter']:.3g} (h/d_small = {dx / small['diameter']:.3g})")
            if variational:
                how += ", variational pressure coupling"
            rows.append(Row(self.name, f"{big['diameter'] * 1e6:.0f}/{small['diameter'] * 1e6:.0f} µm, {how}: mean slip, "
                                       f"ε = {eps:g}", f"{ref * 1e3:.4g} mm/s", "bidisperse block slip (4.5)",
                            f"{slip * 1e3:.4g} mm/s", slip / ref - 1, self.TARGET, r,
                            known=self.SPREAD if variational else self.SMEAR))
            eps_i = eps * slip / v
            ref_i = theory.bidisperse_block_slip(big["diameter"], small["diameter"], 0.5, big["density"], rho_f, mu,
                                                 eps_i, r.g())
            rows.append(Row(self.name, f"same, against (4.5) at the voidage the spheres see, ε_i = ε · slip/|v| = "
                                       f"{eps_i:.4f}", f"{ref_i * 1e3:.4g} mm/s", "(4.5) at ε_i",
                            f"{slip * 1e3:.4g} mm/s", slip / ref_i - 1, None, r,
                            note="the face effect, as the monodisperse block"))
        rows += self.tall_rows(results)
        return rows

    def tall_rows(self, results):
        """The double-smoothing blocks twice as tall, and the error a + b/H_b extrapolated to
        no faces (H_b -> infinity) from the two heights, as the monodisperse block."""
        rows = []
        for pair in self.PAIRS:
            short, tall = results.get(f"block_{pair}_double"), results.get(f"block_{pair}_doubletall")
            if short is None or tall is None:
                continue
            if not (short.ok and tall.ok and short.log is not None and tall.log is not None):
                rows += failed_run_rows(self.name, tall, f"block_{pair}_doubletall")
                continue
            h1, e1, h2, e2, a, b = face_extrapolation(short, tall, lambda r: self.measure(r)[::2])
            s2, _, ref = self.measure(tall)
            label = pair.replace("_", "/") + " µm, double smoothing"
            rows.append(Row(self.name, f"{label}, block {h2 * 1e3:.3g} mm tall instead of {h1 * 1e3:.3g} mm: mean slip, "
                                       f"ε = {tall.case['particles'][0]['voidage']:g}", f"{ref * 1e3:.4g} mm/s",
                            "bidisperse block slip (4.5)", f"{s2 * 1e3:.4g} mm/s", e2, None, tall,
                            note=f"the faces' share should halve: {e1:+.2%} → {e2:+.2%}"))
            rows.append(Row(self.name, f"{label}, infinite-block limit a of error = a + b/H_b (H_b = {h1 * 1e3:.3g}, "
                                       f"{h2 * 1e3:.3g} mm; b = {b * 1e3:.3g} % mm)", f"{ref * 1e3:.4g} mm/s",
                            "bidisperse block slip (4.5)", f"{ref * (1 + a) * 1e3:.4g} mm/s", a, None, tall,
                            note="extrapolation: the bulk drag against (4.5), what a block without faces would give"))
        return rows
