"""The rows of the report: Row (one line of VALIDATION.md: its kind (KINDS), the kind of
reference a comparison has (REFERENCE_KINDS), and its status PASS, FAIL, MISS (a target missed
for a reason that rows of the same report measure), INFO (no target) or SKIP), the rows every
run gets (its safeguards, and the note on the rows of a run whose safeguards bit), the row of
a run that failed, the rule that settles a MISS, the table's formatting of errors, targets and
kinds, and the summary count and exit status."""
import math
import os

import numpy as np

from .runs import safeguards_hit

# What a row checks; the summary counts each kind apart. (short label, meaning)
KINDS = {
    "comparison": ("cmp", "a simulated quantity against a reference that could be wrong: theory, experiment, "
                          "another code"),
    "health": ("health", "the run's soundness: safeguard counters, density errors, at-rest checks, and conservation "
                         "checks (momentum balances, signs and bands that hold for any model)"),
    "self-check": ("self", "theory.py against itself, or a reference computed from the formula the solver implements "
                           "with no simulation in between"),
}
# A comparison's reference (Row.reference_kind): (short label, meaning)
REFERENCE_KINDS = {
    "independent": ("ind", "independent of the drag closure the solver uses: Stokes' analytic solution, Kynch with "
                           "an independent hindered speed (Richardson-Zaki, Garside-Al-Dibouni), experiments, another "
                           "code"),
    "own-closure": ("own", "computed from the closure the solver implements: (4.4) from its Di Felice law, (4.5) "
                           "from its polydisperse drag, Masliyah with its drag law, the law's own balance"),
}


class Row:
    """One line of the report. error is relative (sim/ref - 1) unless the quantity says;
    target is the largest |error| allowed, None for a row that only informs. kind is one of
    KINDS; a comparison names its reference_kind (REFERENCE_KINDS). `known`, the reason a
    target is missed, comes with `evidence`, rows of the same report that measure that reason:
    settle_misses makes the row a MISS when they do, else it stays a FAIL."""

    def __init__(self, scene, quantity, reference, source, simulated, error, target, result=None, *, kind,
                 reference_kind=None, note="", skip=None, ratio=False, known=None, evidence=None, count=False):
        if kind not in KINDS or (reference_kind in REFERENCE_KINDS) != (kind == "comparison"):
            raise ValueError(f"row {quantity!r}: kind {kind!r}, reference kind {reference_kind!r}")
        if known and evidence is None:
            raise ValueError(f"row {quantity!r}: a known reason needs its evidence, rows of this report")
        self.scene, self.quantity, self.reference, self.source = scene, quantity, reference, source
        self.simulated, self.error, self.target, self.note = simulated, error, target, note
        self.kind, self.reference_kind = kind, reference_kind
        self.known, self.evidence = known, evidence or []
        self.resolution = result.resolution() if result is not None and result.case else "–"
        self.wall = result.wall if result is not None else None
        self.result = result  # the run the row reads (sweep.py reads its log)
        self.skip = skip
        self.ratio = ratio   # error is simulated / limit (shown as a ratio, passes when <= target)
        self.count = count   # error is a count (shown as one, passes when <= target)
        if skip:
            self.status = "SKIP"
        elif not self.measured():
            self.status = "FAIL" if target is not None else "INFO"
        elif target is None:
            self.status = "INFO"
        else:
            self.status = "PASS" if abs(error) <= target else "FAIL"

    def measured(self):
        """Whether the row has a value: not skipped, its error finite."""
        return not self.skip and self.error is not None and math.isfinite(self.error)

    def kind_label(self):
        """'cmp·ind', 'cmp·own', 'health' or 'self' (VALIDATION.md's column)."""
        label = KINDS[self.kind][0]
        return label + "·" + REFERENCE_KINDS[self.reference_kind][0] if self.reference_kind else label


def settle_misses(rows):
    """A target missed for a reason (a FAIL row's `known`) is reported as MISS, listed in
    VALIDATION.md and not counted as a failure of the report (which guards against
    regressions), only when its evidence is rows of this same report with a measured value;
    otherwise it stays a FAIL. The note names the reason and the rows that show it."""
    for row in rows:
        if row.status != "FAIL" or not row.known or not row.measured():
            continue
        shown = [e for e in row.evidence if e.measured() and any(e is r for r in rows)]
        if shown:
            row.status = "MISS"
            why = (f"target missed: {row.known}; shown by this report's "
                   + "; ".join(f"{e.quantity}: {e.simulated} ({fmt_err(e)})" for e in shown))
        else:
            why = f"target missed: {row.known}, but no row of this report shows it, so a FAIL"
        row.note = (row.note + "; " if row.note else "") + why


def safeguard_rows(scene, results):
    """Every run's safeguards: the voidage floor (fluid particles whose voidage was raised to
    it) and the Omega clamp (terms bounded), from the count the run prints at its end over
    every step (a run made before that line existed: the largest count in a logged step of
    its log.csv), target 0 (a safeguard that bites replaces the model); and the largest
    density error, informative against the weakly compressible 1 %."""
    rows = []
    for key, r in results.items():
        if not r.ok or r.log is None or "voidage_clamped" not in r.log:
            continue
        sg = r.safeguards
        if sg is not None:
            floor, clamp = sg["floor_steps"], sg["clamp_steps"]
            rows.append(Row(scene, f"{key}: voidage floor and Ω clamp, steps with a hit over every step", "0",
                            "safeguards (physics.md §1), not models",
                            f"{floor} floor, {clamp} clamp of {sg['steps']} steps (largest {sg['floor_largest']} "
                            f"and {sg['clamp_largest']} particles)", float(floor + clamp), 0.0, r, kind="health",
                            count=True))
        else:
            floor, clamp = int(np.max(r.log["voidage_clamped"])), int(np.max(r.log["omega_bounded"]))
            rows.append(Row(scene, f"{key}: voidage floor and Ω clamp hits, largest count in a logged step", "0",
                            "safeguards (physics.md §1), not models", f"{floor} floor, {clamp} clamp",
                            float(floor + clamp), 0.0, r, kind="health", count=True))
        rho = float(np.max(r.log["max_density_error"]))
        rows.append(Row(scene, f"{key}: largest density error |ρ/ρ₀ − 1| over the run", "1 %",
                        "weakly compressible limit (c0 ≥ 10 u_max)", f"{100 * rho:.2f} %", rho / 0.01, None, r,
                        kind="health", ratio=True))
    return rows


def mark_safeguard_hits(rows):
    """A row read from a run whose safeguards bit says so in its note (the safeguard rows
    themselves say it in their value)."""
    for row in rows:
        hit = safeguards_hit(row.result) if row.result is not None else ""
        if hit and "Ω clamp" not in row.quantity:
            row.note = f"{row.note}; {hit}" if row.note else hit


def failed_run_rows(scene, result, what):
    """A FAIL row (health) for a run that did not end, with sphdem's own reason (its 'run failed'
    line)."""
    why = ""
    out = os.path.join(result.dir, "sphdem.out")
    if os.path.exists(out):
        lines = [l for l in open(out, errors="replace") if "run failed" in l]
        why = (": " + lines[-1].strip().split("run failed: ", 1)[-1][:400]) if lines else ""
    return [Row(scene, what, "–", "–", f"run failed (exit {result.returncode}, {result.dir}/sphdem.out){why}",
                None, 0.0, result, kind="health")]


def fmt_err(row):
    if row.error is None or not math.isfinite(row.error):
        return "–"
    if row.count:
        return f"{row.error:.0f}"
    if row.ratio:
        return f"{row.error:.3g} × limit"
    return f"{100 * row.error:+.2f} %"


def fmt_target(row):
    if row.target is None:
        return "–"
    if row.count:
        return f"≤ {row.target:.0f}"
    return f"≤ {row.target:g} × limit" if row.ratio else f"≤ {100 * row.target:.3g} %"


def summary_line(rows, matrix=()):
    """The count: comparisons with an independent reference and with the solver's own closure,
    health checks and theory.py's self-checks apart, each by status; the skipped rows; and the
    regime matrix's PART entries (matrix: its (regime, measured, status) entries)."""
    def count(kind, reference_kind=None):
        sel = [r for r in rows if r.kind == kind and r.reference_kind == reference_kind and r.status != "SKIP"]
        n = {k: sum(r.status == k for r in sel) for k in ("PASS", "FAIL", "MISS", "INFO")}
        return f"{len(sel)} ({n['PASS']} pass, {n['FAIL']} fail, {n['MISS']} miss, {n['INFO']} informative)"
    line = (f"{len(rows)} rows: comparisons with an independent reference {count('comparison', 'independent')}, "
            f"with the solver's own closure {count('comparison', 'own-closure')}; health checks {count('health')}; "
            f"theory.py's self-checks {count('self-check')}; {sum(r.status == 'SKIP' for r in rows)} skipped")
    if matrix:
        line += f"; regime matrix: {sum(status == 'PART' for _, _, status in matrix)} of {len(matrix)} PART"
    return line


def exit_status(rows, strict):
    """1 on a failed row; with strict also on a missed target (MISS), else 0."""
    return 1 if any(r.status == "FAIL" or (strict and r.status == "MISS") for r in rows) else 0
