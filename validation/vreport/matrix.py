"""The regime matrix (issue 14): every regime with the same defaults, from the report's
rows and the validation gtests' records; and the extremes matrix (issue 15) from
extremes_test's records."""
import math
import os
import subprocess

from .rows import fmt_err
from .scenes.suspension_monodisperse import SuspensionMonodisperse
from .scenes.untuned_fronts import UntunedFronts


# Seven regimes are measured (in part) by validation gtests, not by sphdem runs (a shear
# wave's initial field, a bed without gravity, the sand column's base loads, a sphere or a
# grain in columns the reduced mode does not run, the periodic columns): each records its
# numbers with RecordProperty, ctest writes them to BUILD/GTEST_XML/<test>.xml
# (tests/validation/CMakeLists.txt) before this report runs, and the report runs a test
# itself when its file is missing or older than the test's executable. A regime read from
# a test is PART at best.
GTEST_XML = os.path.join("tests", "validation", "gtest-xml")


def gtest_results(build, test, nice=0, folder="validation"):
    """{'Suite.Name': (passed, {property: value})} of the test `test`'s last run (its
    executable in BUILD/tests/FOLDER)."""
    import xml.etree.ElementTree as ET
    exe = os.path.join(build, "tests", folder, test)
    xml = os.path.join(build, GTEST_XML, test + ".xml")
    if not os.access(exe, os.X_OK):
        return None
    if not os.path.exists(xml) or os.path.getmtime(xml) < os.path.getmtime(exe):
        os.makedirs(os.path.dirname(xml), exist_ok=True)
        print(f"[matrix] running {test} (no record newer than its executable)", flush=True)
        cmd = ([] if not nice else ["nice", "-n", str(nice)]) + [exe, f"--gtest_output=xml:{xml}"]
        subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=os.path.dirname(exe))
        if not os.path.exists(xml):
            return None
    out = {}
    for case in ET.parse(xml).getroot().iter("testcase"):
        props = {k: v for k, v in case.attrib.items()}
        for prop in case.iter("property"):
            props[prop.get("name")] = prop.get("value")
        passed = case.find("failure") is None and case.get("result", "completed") == "completed"
        out[f"{case.get('classname')}.{case.get('name')}"] = (passed, props)
    return out


class Regime:
    """One row of the matrix: the report rows it reads ((scene, quantity prefix), with the
    row's own verdict, or (scene, prefix, target) judged here on |error|; a tuple of
    prefixes reads the first one the report measured) and the gtests (test, 'Suite.Name',
    [(property, label), ...]); `elsewhere` names what the mode does not run (the longer runs
    and the commands that make them). A regime is PART at best when a part is not measured,
    is measured by a stand-in (a later prefix), or is read from a gtest rather than from the
    regime's own run."""

    def __init__(self, regime, scene, criterion, rows=(), gtests=(), elsewhere=""):
        self.regime, self.scene, self.criterion = regime, scene, criterion
        self.rows, self.gtests, self.elsewhere = rows, gtests, elsewhere

    def evaluate(self, report_rows, build, nice):
        measured, statuses = [], []
        for scene, prefixes, *target in self.rows:
            # alternatives in order, the criterion's own run first; a part not measured
            # (or measured by a stand-in) leaves the regime PART at best
            prefixes = prefixes if isinstance(prefixes, tuple) else (prefixes,)
            found = [p for p in prefixes if any(r.scene == scene and r.quantity.startswith(p) and r.status != "SKIP"
                                                and (target or r.target is not None) for r in report_rows)]
            if not found or found[0] != prefixes[0]:
                measured.append(f"[{prefixes[0]}: not in this report" + ("; in its place:]" if found else "]"))
                statuses.append("SKIP")
            if not found:
                continue
            for r in report_rows:
                if r.scene != scene or not r.quantity.startswith(found[0]):
                    continue
                if target:  # the matrix's own criterion on a row the report only informs with
                    ok = r.error is not None and math.isfinite(r.error) and abs(r.error) <= target[0]
                    measured.append(f"{r.quantity}: {r.simulated} ({fmt_err(r)}; matrix target "
                                    f"{100 * target[0]:g} %)")
                    statuses.append("PASS" if ok else "FAIL")
                elif r.target is not None:
                    measured.append(f"{r.quantity}: {r.simulated} ({fmt_err(r)})")
                    statuses.append(r.status)
        for test, name, props in self.gtests:
            res = gtest_results(build, test, nice)
            if res is None or name not in res:
                measured.append(f"{test} {name}: no result")
                statuses.append("FAIL")
                continue
            passed, values = res[name]
            shown = ", ".join(f"{label} {values.get(key, '?')}" for key, label in props)
            measured.append(f"{shown} (ctest {test}, {name})")
            statuses.append("PASS" if passed else "FAIL")
        if not statuses:
            status = "NOT RUN"
        elif "FAIL" in statuses:
            status = "FAIL"
        elif "MISS" in statuses:
            status = "MISS"
        elif "SKIP" in statuses and "PASS" not in statuses:
            status = "SKIP"
        elif "SKIP" in statuses or self.gtests:
            status = "PART"   # every part measured passes; a part was left out, stood in for or read from a test
        else:
            status = "PASS"
        return measured, status


MATRIX = [
    Regime("one 100 µm sphere released 1, 7 and 30 mm deep", "single_particle",
           "slip within 1 % of (4.1) at each depth; the case's at each preset (full mode: fast, balanced, accurate)",
           rows=[("single_particle", "superficial slip")],
           gtests=[("regime_depth_validation", "SphereAtDepth.SevenMillimetres",
                    [("slip_error", "7 mm deep: slip against (4.1)")]),
                   ("regime_depth_validation", "SphereAtDepth.ThirtyMillimetres",
                    [("slip_error", "30 mm deep")])],
           elsewhere="the presets fast and accurate (the case runs at balanced): the full mode only"),
    Regime("one 2.8 mm grain in a 1 m water column (c0 ≈ 44 m/s)", "inertial grain",
           "terminal slip within 2 % of Brown–Lawler",
           gtests=[("regime_depth_validation", "InertialGrain.TerminalSlipAtTheMetreColumnsSoundSpeed",
                    [("slip_error", "mean slip over 0.15–0.28 s against Brown–Lawler")])],
           elsewhere="reduced: a 0.15 m column at the 1 m column's c0 = 44 m/s and resolution (the extra drag "
                     "grows with c0, not with the depth itself); the grain in the 1 m column not run"),
    Regime("blocks ε = 0.9 and 0.8, 2 and 4 mm tall", "block_monodisperse",
           "infinite-block slip within 2 % of (4.4); ε = 0.8 at each preset (full mode: fast, balanced, accurate)",
           rows=[("block_monodisperse", "ε = 0.8, infinite-block", 0.02)],
           elsewhere="the presets fast and accurate (the case runs at balanced): the full mode only"),
    Regime("the monodisperse suspension", "suspension_monodisperse",
           "interface within 8 % of Kynch; a sediment forms and comes to rest (density error < 1 %, fluid kinetic "
           "energy decaying, sediment voidage 0.36–0.45)",
           rows=[("suspension_monodisperse", (SuspensionMonodisperse.SHIPPED + "interface velocity",
                                              "interface velocity −dz_top/dt")),
                 ("suspension_monodisperse", "sediment"),
                 ("suspension_monodisperse", SuspensionMonodisperse.SHIPPED + "sediment"),
                 ("suspension_monodisperse", SuspensionMonodisperse.SHIPPED + "largest overlap"),
                 ("suspension_monodisperse", "largest overlap")],
           elsewhere="the case as shipped to its end (1 s, hours; its interface over the whole fall is the criterion): "
                     "the full report with --long; without it the interface over the case's first 60 ms (full) or "
                     "35 ms of a 2 × 2 mm column (reduced) stands in. The sediment at rest also in a 2 × 2 mm column "
                     "with 2.4 mm of suspension at k = 10 to 0.6 s (full report)"),
    Regime("suspension front, untuned scene, every preset",
           "validation/scenes/untuned_front.yaml (no case ships it: 250 µm glass in water-glycerol, defaults)",
           "upper interface within 8 % of Kynch (4.4) over the whole fall (0.2 s to 1.6 s or 1 mm above the "
           "sediment), ε0 = 0.7, 0.8, 0.9, 0.95 at h/d = 2, at each of fast, balanced and accurate",
           rows=[("untuned_fronts", UntunedFronts.PREFIX)],
           elsewhere="full mode only (12 runs of 2–30 min each); the reduced report leaves it out"),
    Regime("a random packed bed under clear water, in contact, under gravity",
           "packed-bed stability: 2523 sand grains (2.8 mm) at ε 0.42 under 80 mm of water, every coupling, time-step "
           "and contact-stiffness key at its default",
           "at rest on its contacts: the base's contacts carry the grains' buoyant weight within 1 %, the fluid's excess "
           "load on the base under 2 % of it (means over the last 4H/c0); no grain moves 0.01 d over the last 50 ms, the "
           "fluid's rms speed under 1e-3 of the terminal speed (health checks)",
           gtests=[("packed_bed_stability_validation", "RandomBedInContact.RestsOnItsContactsUnderGravity",
                    [("contacts_over_buoyant_weight", "contacts / buoyant weight"),
                     ("fluid_over_buoyant_weight", "fluid's excess / buoyant weight"),
                     ("creep_over_d", "largest displacement over 50 ms (d)"),
                     ("fluid_rms_over_terminal", "fluid rms speed / terminal speed")])]),
    Regime("the reduced sand column", "cases/sand_column_reduced.yaml; cases/sand_column.yaml's first 0.3 s",
           "grains' speed in the mixture within 5 % of Masliyah with the case's drag (the 1 m column: in the 0.1 m "
           "one the lowest grains land before the rest reach their speed); bed at rest; the base's loads close the "
           "momentum balance",
           rows=[("sand_column", "grains' settling speed in the mixture's interior")],
           gtests=[("sand_column_validation", "SandColumn.BaseLoadsCloseTheMomentumBalance",
                    [("worst_window_error", "worst window's imbalance / eq. 15"),
                     ("at_rest_error", "at rest")]),
                   ("sand_column_validation", "SandColumn.BedBulkDensityMatchesZhao",
                    [("bed_mean_speed_m_per_s", "mean sphere speed at the end (m/s)")])],
           elsewhere="the grains' speed against Masliyah: the 1 m column's first 0.3 s (~1 h on 2 cores), in the "
                     "full report only"),
    Regime("a homogeneous suspension, periodic in z, ε = 0.8, Re_t 0.86", "cases/suspension_homogeneous.yaml",
           "slip within 3 % of the drag law's balance, and inside Richardson–Zaki's band (their exponent to "
           "Garside–Al-Dibouni's) widened by 5 %",
           gtests=[("periodic_column_validation", "HomogeneousSuspension.SlipAgainstTheLawsBalanceAndRichardsonZaki",
                    [("slip_over_law", "slip / the law's balance"), ("slip_over_rz_low", "slip / band's low end"),
                     ("slip_over_rz_high", "slip / band's high end")])]),
    Regime("a fixed bed, ε = 0.44, Re 0.1–100, five laws", "cases/fixed_bed.yaml",
           "pressure gradient within 2 % of each law's n f_d/ε; against Ergun recorded (bench/TRADEOFF.md: no "
           "law within 10 % at every ε and Re)",
           gtests=[("periodic_column_validation", "FixedBed.PressureGradientAgainstTheLawAndErgun",
                    [(f"{law}_re{re}_over_ergun", f"{law} Re {re / 10:g}: G / Ergun")
                     for law in ("di_felice", "rong") for re in (1, 100, 1000)])]),
    Regime("viscosity at ε = 1 and ε = 0.6", "decaying shear wave (spheres fixed)",
           "effective viscosity within 5 % of μ at the 6 mm cases' h and c0",
           gtests=[("viscosity_validation", "Viscosity.WaterAtTheSixMillimetreCasesResolution",
                    [("morris_error", "ε = 1: μ_eff/μ − 1")]),
                   ("viscosity_validation", "Viscosity.WaterAmongFixedSpheresAtVoidageSixTenths",
                    [("voidage", "ε"), ("mu_eff_error", "μ_eff/μ − 1")])]),
]


def matrix_markdown(entries):
    out = ["## Regime matrix (issue 14): every regime with the same defaults", "",
           "No scene of the matrix sets a coupling key, and the reduced mode's block and suspension runs take the contact a "
           "user gets (contact.stiffness auto, the default sub-steps; the full mode keeps the cases' stiffness, the sources'); "
           "the values are this report's rows and the validation tests' records. "
           "PASS: every part is read from the regime's own run in this report and passes. PART: every part measured "
           "passes, but a part was left out of this report (the last column says which), stood in for by another run, "
           "or read from a validation test (ctest) rather than from the regime's own run.", "",
           "| regime | scene | criterion | measured | status | not in this run |", "|---|---|---|---|---|---|"]
    for reg, measured, status in entries:
        cells = [reg.regime, reg.scene, reg.criterion, "; ".join(measured) or "–", status, reg.elsewhere or "–"]
        out.append("| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |")
    return out + [""]


def extremes_markdown(build, nice=0):
    """The extremes matrix (issue 15) from extremes_test's records: each row runs stable
    and physical or is refused with the key to change (its short variants, as in ctest)."""
    res = gtest_results(build, "extremes_test", nice, folder="extremes")
    out = ["## Extremes (issue 15): stable and physical, or refused with the reason", "",
           "Short variants, as `ctest -L extremes` runs them (`extremes_test --full` for the full times). "
           "A row that runs keeps every state finite, its density error < 1 %, the voidage floor and "
           "Ω clamp unused, the fluid at rest where the scene is at rest and a lone sphere's slip "
           "within 5 % of its drag law's terminal speed.", "",
           "| row | regime | outcome | measured | status |", "|---|---|---|---|---|"]
    if res is None:
        return out + ["| – | extremes_test not built | – | – | NOT RUN |", ""]
    for name, (passed, props) in res.items():
        cells = [name.split("/")[-1], props.get("regime", "?"), props.get("outcome", "?"),
                 props.get("measured", "–").strip().replace("\n", " "), "PASS" if passed else "FAIL"]
        out.append("| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |")
    return out + [""]
