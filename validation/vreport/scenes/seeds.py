"""Scene seeds (issue 38): every row of the settling suspensions measured on four random
placements, reported as mean ± spread (full mode only)."""
import re

import numpy as np
import yaml

from ..figures import NoFigures
from ..rows import Row, failed_run_rows
from ..runs import Run


class Seeds:
    """Issue 38: the suspension scenes' reduced runs (the matrix's 2 mm columns) at SEEDS
    placements: seed k of each random group is the case's seed + k (k = 0 is the case's own
    placement), every other key as the scene sets it. Each scene evaluates each seed's run as
    it evaluates its own; a comparison row becomes one row here: the mean error with the
    sample standard deviation and each seed's value, held to the scene's target by its mean.
    `scenes` are instances of their own (their runs("reduced") sets them up for it)."""
    name = "seeds"
    SEEDS = 4

    def __init__(self, scenes):
        self.scenes = scenes

    def seeded(self, mode):
        """[(scene, its run, [the seeds' runs])]"""
        out = []
        if mode == "reduced":
            return out
        for sc in self.scenes:
            for run in sc.runs("reduced"):
                with open(run.case_path()) as fh:
                    groups = yaml.safe_load(fh)["particles"]
                seeded = []
                for k in range(self.SEEDS):
                    s = dict(run.sets)
                    for i, g in enumerate(groups):
                        if g.get("type") == "random":
                            s[f"particles.{i}.seed"] = int(g.get("seed", 0)) + k
                    seeded.append(Run(f"seeds_{run.key}_s{k}", run.case, s, insitu=run.insitu))
                out.append((sc, run, seeded))
        return out

    @staticmethod
    def words(quantity):
        """A row's quantity without its numbers: the same row on another seed."""
        return re.sub(r"[-+−]?\d[\d.]*", "#", quantity)

    def runs(self, mode):
        return [r for _, _, seeded in self.seeded(mode) for r in seeded]

    def evaluate(self, results, ctx):
        if not results:
            return [Row(self.name, "every settling suspension's rows on 4 random placements", "–", "–", "not run",
                        None, None, None, kind="comparison", reference_kind="own-closure",
                        skip="12 runs of 1-3 min: full mode only")]
        rows = []
        for sc, run, seeded in self.seeded("full"):
            per_seed = []
            for sr in seeded:
                r = results.get(sr.key)
                if r is None or not r.ok or r.log is None:
                    rows += failed_run_rows(self.name, r, sr.key) if r is not None else []
                    continue
                per_seed.append(sc.evaluate({run.key: r}, NoFigures()))
            if len(per_seed) < 2:
                continue
            # a row is the same row on every seed by its words, numbers aside (a window's
            # bounds, a measured voidage); a row some seeds lack (a fit that needs more
            # layers than a seed's front crossed) is averaged over the seeds that have it
            by_words = {}
            for p in per_seed:
                for row in p:
                    if row.kind == "comparison" and row.measured():
                        by_words.setdefault(self.words(row.quantity), []).append(row)
            for found in by_words.values():
                if len(found) < 2:
                    continue
                row, errs = found[0], [x.error for x in found]
                mean, sd = float(np.mean(errs)), float(np.std(errs, ddof=1))
                sim = (f"{100 * mean:+.2f} % ± {100 * sd:.2f} (mean ± sample std over {len(errs)} seeds: "
                       + ", ".join(f"{100 * x:+.2f}" for x in errs) + " %)")
                note = f"worst seed {100 * max(errs, key=abs):+.2f} %"
                if len(found) < len(per_seed):
                    note += f"; measured on {len(found)} of {len(per_seed)} seeds"
                rows.append(Row(self.name, f"{sc.name}: {row.quantity}", row.reference, row.source, sim, mean,
                                row.target, row.result, kind="comparison", reference_kind=row.reference_kind,
                                known=row.known, evidence=row.evidence if row.known else None, note=note))
        return rows
