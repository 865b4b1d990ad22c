"""Scene sand_column (Zhao et al. 2014): the excess pore pressure at the base, the grains'
settling speed against Masliyah (their number mean and each size class), the bed at rest,
its bulk density and the segregation (pooled over seeds, and each seed) (full mode: the
0.1 m column, the 1 m column's first 0.3 s, the whole 1 m run with --long or --run-dir)."""
import csv
import math
import os

import numpy as np

import theory

from ..rows import Row, failed_run_rows
from ..runs import Run, read_csv, snapshot_arrays
from .common import time_average


class SandColumn:
    """Zhao et al. 2014 sand column. The 1 m, 21 103-grain scene (cases/sand_column.yaml)
    takes 6-10 h on 2 cores to its end, so the full report runs its first 0.3 s (the
    peak excess pore pressure), the whole run only with --long or taken from a run made by
    hand over several sittings (--run-dir sand_column_1m=DIR), and the 0.1 m column (cases/sand_column_reduced.yaml, 2 115
    grains, 0.6 s) to a bed at rest (segregation, bulk density, the momentum balance); in
    reduced mode the ctest sand_column_validation runs the 0.1 m column already, so the
    report leaves it to that test."""
    name = "sand_column"
    case = "cases/sand_column_reduced.yaml"
    # The 1 m column (the case itself) for its first 0.3 s: the suspension settles at its
    # steady speed from ~0.1 s while few grains have reached the wall, which is when the
    # fluid carries the whole buoyant weight (eq. 15). The whole run is 10-20 h.
    CASE_1M = "cases/sand_column.yaml"
    START_1M = {"time.end": "0.3", "output.log_interval": "0.002", "output.vtk.every": "0.01"}
    LOAD = ("fluid_load_base: the forces of the wall particles on the column (SPH pairs with the fluid, "
            "variational pairs with the spheres) less the clear column's weight, i.e. the base's mean excess "
            "pore pressure as the wall feels it (analysis/pore_pressure.hpp)")
    BALANCE = ("conservation check: while every grain settles at a steady speed clear of the base, the fluid "
               "carries their whole buoyant weight, whatever the drag law")
    SHORT = ("the 0.1 m column is too short for eq. 15: its grains reach their steady speed (~0.1 s) after "
             "the lowest have landed, so at no time does the fluid carry them all")

    # The segregation check pools the 0.1 m column over the case's seed and these (as
    # tests/validation/sand_column_validation.cpp): one such column segregates by only 2-3
    # random-mixture deviations, the statistic's own scatter being 1.
    EXTRA_SEEDS = (2015, 2016, 2017)

    def runs(self, mode):
        if mode == "reduced":
            return []
        return ([Run("sand_column_reduced", self.case, {})]
                + [Run(f"sand_column_reduced_seed{s}", self.case, {"particles.0.seed": str(s)})
                   for s in self.EXTRA_SEEDS]
                + [Run("sand_column_1m_start", self.CASE_1M, self.START_1M)]
                + [Run("sand_column_1m", self.CASE_1M, {}, long=True)])

    def evaluate(self, results, ctx):
        whole = results.get("sand_column_1m")
        rows = self.whole_run_rows(whole) if whole is not None else []
        r = results.get("sand_column_reduced")
        if r is None:
            return rows + [Row(self.name, "peak excess pore pressure, segregation, bed bulk density", "–", "–", "–",
                               None, None, None, kind="comparison", reference_kind="independent",
                               skip="reduced mode: ctest sand_column_validation runs the reduced column, its "
                                    "case's seed (the segregation pools four: full mode, or the test's --pooled)")]
        start = results.get("sand_column_1m_start")
        if start is not None:
            rows += self.peak_rows(start, ", 1 m column (the case), first 0.3 s", True) + self.speed_rows(start)
        rows += self.peak_rows(r, ", 0.1 m column", False) + self.rows_of(r, ", 0.1 m column")
        seeds = [r] + [results.get(f"sand_column_reduced_seed{s}") for s in self.EXTRA_SEEDS]
        for x in seeds:
            if x is not None and not x.ok:
                rows += failed_run_rows(self.name, x, f"the 0.1 m column, {x.run.key} (pooled for the segregation)")
        rows += self.segregation_rows([x for x in seeds if x is not None and x.ok], ", 0.1 m column")
        return rows

    def whole_run_rows(self, r):
        """The 1 m column to its end (hours: --long, or --run-dir sand_column_1m=DIR): the
        dissipation of the excess pore pressure, the bed at rest, its bulk density and the
        segregation, from one column."""
        if r.log is None:
            return failed_run_rows(self.name, r, "the 1 m column to its end")
        t = r.log["time"]
        how = f", 1 m column (the case) to t = {t[-1]:.3g} s"
        if not r.ok:
            how += f" (stopped before its end, {float(r.case['time']['end']):g} s)"
        rows = self.dissipation_rows(r, how)
        if r.ok:
            rows += self.rows_of(r, how) + self.segregation_rows([r], how)
        return rows

    def dissipation_rows(self, r, how):
        """When the fluid's load on the base (4H/c0 mean) has fallen from its peak to a tenth
        of it, in Zhao's normalised time [T] = t g d^2 (rho_s - rho_f) / (18 mu H) (their eq. 11,
        d the mean diameter): their linear dissipation ends at [T] = 7.2 (Fig. 11)."""
        sand, fl = r.case["species"][0], r.case["fluid"]
        law = sand["size_distribution"]
        d = 0.5 * (law["min"] + law["max"])
        H = r.case["domain"]["size"][2]
        t_c = 18 * fl["viscosity"] * H / (r.g() * d * d * (sand["density"] - fl["density"]))
        t, load = r.log["time"], self.period_mean(r, "fluid_load_base")
        k = int(np.nanargmax(load))
        after = np.nonzero(load[k:] <= 0.1 * load[k])[0]
        src = "Zhao et al. Fig. 11: linear dissipation from [T] = 0.54 to 7.2 (25 mm column, 6000 grains)"
        if len(after) == 0:
            last = int(np.nonzero(np.isfinite(load))[0][-1])   # the last whole window
            return [Row(self.name, f"excess pore pressure at the base dissipated to a tenth of its peak{how}",
                        "[T] = 7.2", src, f"not yet: {load[last]:.4f} at [T] = {t[last] / t_c:.2f} (peak "
                        f"{load[k]:.4f} at [T] = {t[k] / t_c:.2f})", None, None, r, kind="comparison",
                        reference_kind="independent")]
        td = t[k + after[0]]
        return [Row(self.name, f"excess pore pressure at the base dissipated to a tenth of its peak (the fluid's "
                               f"load, 4H/c0 mean){how}", "[T] = 7.2", src,
                    f"[T] = {td / t_c:.2f} (t = {td:.3g} s; peak {load[k]:.4f} at [T] = {t[k] / t_c:.2f})",
                    td / t_c / 7.2 - 1, None, r, kind="comparison", reference_kind="independent",
                    note=f"t_c = 18 μ H / (g d² (ρs − ρf)) = {t_c:.3f} s with d = {d * 1e3:.1f} mm (the law's mean); "
                         "the reading is the end of the linear part, not a threshold, and Zhao's column is half as "
                         "wide at n = 0.876: informative")]

    @staticmethod
    def eq15(r):
        """(1 - n)(rho_s/rho_f - 1) at the case's target porosity (RSA meets it to ~0.3 %)."""
        sand, rho_f = r.case["species"][0], r.case["fluid"]["density"]
        return (1 - r.case["particles"][0]["voidage"]) * (sand["density"] / rho_f - 1)

    @staticmethod
    def period_mean(r, column):
        """The log column's mean over one acoustic period 4H/c0 centred on each sample (the
        weakly compressible column rings at that period after the release); NaN where the
        window runs past either end of the run."""
        t, y = r.log["time"], r.log[column]
        p = r.acoustic_period()
        return np.array([time_average(t, y, ti - p / 2, ti + p / 2) if t[0] <= ti - p / 2 and ti + p / 2 <= t[-1]
                         else np.nan for ti in t])

    @staticmethod
    def end_mean(r, column, periods=2):
        """The log column's mean over the last `periods` acoustic periods (the bed at rest
        still rings with the column: +-0.02 in the fluid's load at ~30 ms)."""
        t = r.log["time"]
        return time_average(t, r.log[column], t[-1] - periods * r.acoustic_period(), t[-1])

    def peak_rows(self, r, how, primary):
        """The peak of the base's excess pore pressure as the wall feels it (the fluid's load on
        it); the check when primary."""
        if not r.ok or r.log is None:
            return failed_run_rows(self.name, r, "peak excess pore pressure" + how)
        u_th, t = self.eq15(r), r.log["time"]
        load = self.period_mean(r, "fluid_load_base")
        wall = self.period_mean(r, "wall_load_base")
        v = np.abs(r.log[f"vz_mean:{r.case['species'][0]['name']}"])
        k = int(np.nanargmax(load))
        state = (f"at the peak the spheres' wall load is {wall[k]:.3f} and the grains' mean speed "
                 f"{v[k]:.3g} m/s (largest {v.max():.3g} m/s); the 4H/c0 mean spans {np.nanmin(load):.4f}–"
                 f"{np.nanmax(load):.4f} over the run (windows centred in [{t[0] + r.acoustic_period() / 2:.3g}, "
                 f"{t[-1] - r.acoustic_period() / 2:.3g}] s)")
        src = "Zhao et al. eq. 15: (1 − n)(ρs/ρf − 1)"
        return [Row(self.name, f"peak excess pore pressure at the base / (ρf g H), the fluid's load on the wall, "
                               f"mean over 4H/c0, at t = {t[k]:.3g} s{how}", f"{u_th:.4f}", src, f"{load[k]:.4f}",
                    load[k] / u_th - 1, 0.10 if primary else None, r, kind="health",
                    note=self.BALANCE + "; " + self.LOAD + "; " + state + ("" if primary else "; " + self.SHORT))]

    def speed_rows(self, r):
        """The grains' settling speed against Masliyah's multispecies hindered settling with
        the case's drag law: the targeted row reads the spheres in the mixture's interior
        from the run's VTK snapshots (number mean and each size class), the log's number
        mean over every grain (landed ones included) informs."""
        if not r.ok or r.log is None:
            return []
        sand, fl = r.case["species"][0], r.case["fluid"]
        law, eps = sand["size_distribution"], r.case["particles"][0]["voidage"]
        t, v = r.log["time"], np.abs(r.log[f"vz_mean:{sand['name']}"])
        t0, t1 = 0.1, t[-1]
        species, weights = theory.uniform_size_species(law["min"], law["max"], sand["density"], 1 - eps)
        def masliyah(push=None):
            return theory.masliyah_velocities(species, fl["density"], fl["viscosity"], drag=theory.brown_lawler_drag,
                                              push=push)[0]
        w = masliyah()
        ref = sum(wi * ni for wi, ni in zip(w, weights))
        src = (f"Masliyah's multispecies hindered settling (theory.masliyah_velocities) with the case's drag "
               f"(Brown–Lawler C_d, Di Felice's ε^−χ), the uniform law in 200 sizes at ε = {eps}: "
               f"{min(w):.3f}–{max(w):.3f} m/s")
        rows = self.mixture_speed_rows(r, species, w, masliyah, ref, src)
        dallavalle = theory.di_felice_block_slip(0.5 * (law["min"] + law["max"]), sand["density"], fl["density"],
                                                 fl["viscosity"], eps)
        # the grains already on the wall count with speed 0: a fraction ~(w + s) t / H of
        # each size by time t, s the bed's rise ~ w (1 - eps)/(1 - eps_bed - (1 - eps))
        rise = ref * (1 - eps) / (0.58 - (1 - eps))
        landed = (ref + rise) * 0.5 * (t0 + t1) / r.case["domain"]["size"][2]
        mean = time_average(t, v, t0, t1)
        rows.append(Row(self.name, f"grains' mean settling speed (number mean of every grain, log.csv), t ∈ "
                                   f"[{t0:.2g}, {t1:.2g}] s, 1 m column (the case)", f"{ref:.3f} m/s", src,
                        f"{mean:.3f} m/s", mean / ref - 1, None, r, kind="comparison",
                        reference_kind="own-closure",
                        note=f"the grains that have landed count with speed 0, about {landed:.0%} of them at the "
                             f"window's middle (the row above reads the mixture's interior only); with Dallavalle's "
                             f"C_d (Di Felice's law as the blocks use it) the {0.5e3 * (law['min'] + law['max']):.1f} "
                             f"mm grain alone gives {dallavalle:.3f} m/s"))
        return rows

    MIXTURE = (0.15, 0.85)   # the mixture's interior, fractions of the column's height
    CLASS_TARGET = 0.10      # each tenth of the size law against Masliyah at its grains' sizes
    CANCEL_TARGET = 0.01     # the classes' contact pushes over the mixture, a fraction of its weight

    def mixture_speed_rows(self, r, species, w, masliyah, ref, src):
        """Masliyah's speeds hold in the mixture at its initial composition: below the top,
        which the fastest size leaves at w_max t, and above the bed and the kinematic shocks
        rising from it. The spheres with z in MIXTURE x H in every snapshot of the last two
        acoustic periods (the column rings at 4H/c0 by +-12 % in speed): their number mean
        against the law's number mean (the target, 5 %) and each of ten size classes
        against Masliyah's speed at the class's own grains' sizes (10 % each).
        Masliyah's model has no contacts between grains. What they carry is measured per
        class from each grain's momentum balance, m dv/dt = f_fluid + m g + f_contact: the
        contacts' mean downward push over the window, as a fraction of the class's weight, is
        f_fluid,z / (m g) - 1 + (1/g) d(speed)/dt (the class's speed a line over the window).
        Masliyah with that push (theory.masliyah_velocities(push=...)) is the evidence a
        class that misses its target needs; the pushes cancel over the mixture (Newton's
        third law among the grains, a conservation check) when they are contact forces."""
        label = "grains' settling speed in the mixture's interior"
        snaps = snapshot_arrays(r.dir)
        if snaps is None:
            return [Row(self.name, label, f"{ref:.3f} m/s", src, "not measured", None, 0.05, r, kind="comparison",
                        reference_kind="own-closure",
                        skip="no VTK snapshots (the run needs output.vtk.every and sphdem built with ParaView; "
                             "pvpython converts them)")]
        H = r.case["domain"]["size"][2]
        g = r.g()
        times = snaps["time"]
        t1 = float(times[-1])
        t0 = t1 - 2 * r.acoustic_period()
        lo, hi = self.MIXTURE[0] * H, self.MIXTURE[1] * H
        ds = np.array([d for d, _, _ in species])
        edges = np.linspace(ds[0] - 0.5 * (ds[1] - ds[0]), ds[-1] + 0.5 * (ds[1] - ds[0]), 11)

        def size_class(d):   # 0 ... 9
            return np.clip(np.digitize(d, edges) - 1, 0, 9)
        frames = [k for k, tk in enumerate(times) if t0 <= tk <= t1 + 1e-12]
        has_force = all(f"s{k}_fz" in snaps for k in frames)
        means, cls, own = [], [[] for _ in range(10)], [[] for _ in range(10)]
        fluid_share, mass = [[] for _ in range(10)], [[] for _ in range(10)]
        for k in frames:
            z, vz, d = snaps[f"s{k}_z"], snaps[f"s{k}_vz"], snaps[f"s{k}_d"]
            inside = (z > lo) & (z < hi)
            means.append(float(np.mean(-vz[inside])))
            c = size_class(d)
            m = snaps[f"s{k}_rho"] * np.pi * d ** 3 / 6 if has_force else None
            for i in range(10):
                sel = inside & (c == i)
                cls[i].append(float(np.mean(-vz[sel])) if np.any(sel) else np.nan)
                own[i].append(d[sel])
                if has_force and np.any(sel):
                    fluid_share[i].append(float(np.sum(snaps[f"s{k}_fz"][sel]) / (np.sum(m[sel]) * g)))
                    mass[i].append(float(np.sum(m[sel])))
        mean = float(np.mean(means))
        spread = float(np.std(means) / mean)
        note = (f"{len(frames)} snapshots in t ∈ [{t0:.3g}, {t1:.3g}] s (two periods 4H/c0), spheres with "
                f"z ∈ [{lo:.2f}, {hi:.2f}] m: the initial mixture between the bed's shocks and the top the "
                f"fastest grains leave; frame-to-frame spread {spread:.1%} (the column's ringing); each size class "
                f"in the rows below: their spread of speeds discriminates the drag law's size dependence "
                f"(Brown–Lawler's C_d): a Stokes drag would spread them as d², a Newton drag as d^½")
        rows = [Row(self.name, f"{label} (number mean), 1 m column (the case)", f"{ref:.3f} m/s", src,
                    f"{mean:.3f} m/s", mean / ref - 1, 0.05, r, kind="comparison", reference_kind="own-closure",
                    note=note)]
        t_frames = np.array([times[k] for k in frames])

        def class_reference(w, i):   # the mean of each grain's own speed, so it follows the class's sizes
            return float(np.mean(np.interp(np.concatenate(own[i]), ds, w)))

        push = None
        if has_force and len(frames) >= 2 and all(len(fs) == len(frames) for fs in fluid_share):
            push = [float(np.mean(fluid_share[i])) - 1 + np.polyfit(t_frames, np.array(cls[i]), 1)[0] / g
                    for i in range(10)]
            w_pushed = masliyah([push[i] for i in size_class(ds)])
            weights = [float(np.mean(mass[i])) for i in range(10)]
            net = sum(p * m for p, m in zip(push, weights)) / sum(weights)
            rows.append(Row(self.name, "the contacts' downward pushes on the ten size classes, summed over the "
                                       "mixture's interior, over its weight", "0", "Newton's third law among the grains",
                            f"{net:+.4f} (the classes' pushes {push[0]:+.3f} … {push[-1]:+.3f} of their weights)",
                            net, self.CANCEL_TARGET, r, kind="health",
                            note="conservation check: contact forces between grains cancel in pairs (grains at the "
                                 "interior's edges and the walls exchange a little with the rest); it fails if the "
                                 "remainder of the grains' momentum balance is not contact forces"))
        for i in range(10):
            u = float(np.nanmean(cls[i]))
            u_ref = class_reference(w, i)
            band = f"{1e3 * edges[i]:.1f}–{1e3 * edges[i + 1]:.1f} mm"
            known, shown = None, []
            if push is not None:
                u_pushed = class_reference(w_pushed, i)
                pushed = Row(self.name, f"same, size class {i + 1} of 10 ({band}), against Masliyah with the "
                                        f"contacts' measured push", f"{u_pushed:.3f} m/s",
                             f"Masliyah with a push of {push[i]:+.3f} of the class's weight (f_fluid,z / (m g) − 1 "
                             f"+ (1/g) d(speed)/dt over the window)", f"{u:.3f} m/s", u / u_pushed - 1, None, r,
                             kind="comparison", reference_kind="own-closure",
                             note="the fluid side of Masliyah's model at the force the class carries: the mixture's "
                                  "buoyancy, the return flow and the drag at the class's slip")
                rows.append(pushed)
                known = (f"Masliyah's model has no contacts between grains, and the collisions push this class "
                         f"{'down' if push[i] > 0 else 'up'} with {abs(push[i]):.1%} of its weight")
                shown = [pushed] if abs(pushed.error) <= 0.5 * self.CLASS_TARGET else []
            rows.append(Row(self.name, f"same, size class {i + 1} of 10 ({band}), 1 m column", f"{u_ref:.3f} m/s",
                            "the same model at the class's grains' sizes", f"{u:.3f} m/s", u / u_ref - 1,
                            self.CLASS_TARGET, r, kind="comparison", reference_kind="own-closure",
                            known=known, evidence=shown))
        return rows

    @staticmethod
    def thirds_difference(r):
        """Bottom - top third's mean diameter of a run and a random mixture's standard
        deviation of that difference, sigma_d sqrt(1/n_b + 1/n_t), sigma_d = (max - min)/
        sqrt(12) for the uniform law; the three thirds' means. None without size_thirds.csv."""
        path = os.path.join(r.dir, "size_thirds.csv")
        if not os.path.exists(path):
            return None
        with open(path) as fh:   # first column: bottom, middle, top
            thirds = list(csv.DictReader(fh))
        mean_d = np.array([float(row["mean_d"]) for row in thirds])
        count = np.array([float(row["count"]) for row in thirds])
        law = r.case["species"][0]["size_distribution"]
        sd = (law["max"] - law["min"]) / math.sqrt(12.0) * math.sqrt(1 / count[0] + 1 / count[-1])
        return mean_d[0] - mean_d[-1], sd, mean_d

    def segregation_rows(self, runs, how):
        """Coarse grains at the base, pooled over independent columns (seeds): the bottom -
        top differences add, and so do their variances. Pooled, each seed's column also has
        its row, informative: one 0.1 m column is too short to segregate beyond the
        statistic's own scatter."""
        found = [(x, self.thirds_difference(x)) for x in runs]
        found = [(x, f) for x, f in found if f is not None]
        if not found:
            return []
        diff = sum(f[0] for _, f in found)
        sd = math.sqrt(sum(f[1] ** 2 for _, f in found))
        rows = [Row(self.name, f"mean grain diameter, bottom − top third, pooled over {len(found)} seeds, in units "
                               f"of a random mixture's deviation{how}", "> 3", "Zhao et al.: coarse grains at the base",
                    f"{diff / sd:+.2f}", 3.0 / diff * sd if diff > 0 else float("inf"), 1.0, found[0][0],
                    kind="comparison", reference_kind="independent", ratio=True,
                    note="the bottom − top differences of independent columns add, and so do their variances")]
        if len(found) > 1:
            for x, (d, sd_x, thirds) in found:
                law = x.case["species"][0]["size_distribution"]
                diameters = x.case["domain"]["size"][2] / (0.5 * (law["min"] + law["max"]))
                rows.append(Row(self.name, f"same, seed {x.case['particles'][0]['seed']} alone{how}", "> 3",
                                "Zhao et al.: coarse grains at the base",
                                f"{d / sd_x:+.2f} (bottom / middle / top third's mean d {thirds[0] * 1e3:.3f} / "
                                f"{thirds[1] * 1e3:.3f} / {thirds[2] * 1e3:.3f} mm)",
                                3.0 * sd_x / d if d > 0 else float("inf"), None, x, kind="comparison",
                                reference_kind="independent", ratio=True,
                                note=f"no target: a column {diameters:.0f} mean diameters tall is too short to "
                                     f"segregate beyond the statistic's own scatter (1): its first grains land during "
                                     f"their acceleration, loosely in size order, so the middle third is as coarse as "
                                     f"the bottom"))
        return rows

    def rows_of(self, r, how):
        """The rows of the bed at rest."""
        if not r.ok or r.log is None:
            return failed_run_rows(self.name, r, "the bed at rest" + how)
        rows = []
        sand = r.case["species"][0]
        u_th, t = self.eq15(r), r.log["time"]
        load, wall = self.end_mean(r, "fluid_load_base"), self.end_mean(r, "wall_load_base")
        v_end = abs(r.log[f"vz_mean:{sand['name']}"][-1])
        rows.append(Row(self.name, f"momentum balance of the bed at rest: the fluid's load on the wall + the spheres' "
                                   f"contact load, mean over the last 2 × 4H/c0 (to t = {t[-1]:.2g} s){how}",
                        f"{u_th:.4f}", "the grains' buoyant weight, eq. 15 (action–reaction: every force from below "
                        "is in one of the two)", f"{load:.4f} + {wall:.4f} = {load + wall:.4f}",
                        (load + wall) / u_th - 1, 0.03, r, kind="health",
                        note=f"conservation check (any model); a bed at rest puts its weight on its contacts: the "
                             f"fluid's share {load / u_th:.1%} is open; mean grain speed at the end "
                             f"{v_end * 1e3:.2g} mm/s; 3 %: the case's target porosity against the one RSA placed "
                             f"(0.3 %), the log's samples (5 ms) of the column's ringing (±0.02 at ~30 ms)"))
        bd = read_csv(os.path.join(r.dir, "bulk_density.csv"))
        if bd is not None:
            rows.append(Row(self.name, f"largest bulk density of the profile at the end{how}", "1965 kg/m³",
                            "Zhao et al. (final sediment)", f"{np.max(bd['bulk_density']):.0f} kg/m³",
                            np.max(bd["bulk_density"]) / 1965 - 1, 0.03, r, kind="comparison",
                            reference_kind="independent",
                            note="3 %: random packings of frictional spheres span n = 0.40-0.45; the kernel "
                                 "smooths the 22 mm bed with the water above (biased low)"))
        return rows
