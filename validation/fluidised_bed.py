"""A fluidised bed's run (cases/fluidised_bed.yaml, issue 37) against the experiments'
correlations and the drag law's own closure.

Reads DIR/case.yaml (the resolved scene: particles, fluid, law) and DIR/log.csv
(superficial_velocity U, pressure_drop dP, bed_height H, bed_weight W = N V (rho_p -
rho_f) g / A). The bed's mean voidage is eps = 1 - W / ((rho_p - rho_f) g H).

Rows (each a number and its reference):
  fixed-bed branch  dP at each rising U below 0.6 U_mf against the law's own n f / eps H
                    (drag_laws.fixed_bed_gradient at the bed's eps: the solver against its
                    closure) and against Ergun (1952) at the same eps (the experiments).
  U_mf              where the rising branch's fit dP = a U + b U^2 (points below 0.8 W) meets
                    W (pipelines/fluidisation.py, as the figure draws it), against Wen & Yu (1966)
                    and against Ergun's balance and the law's own at the bed's eps_mf (the
                    mean eps at U below 0.6 U_mf).
  plateau           mean dP over the rising U in [1.5, 5] U_mf against W (target 2 %).
  expansion         eps at each U in [1.5, 5] U_mf against the band u_t eps^n of
                    Richardson & Zaki and Garside & Al-Dibouni widened by 5 % (drag_laws.rz_band),
                    as U = u_t eps^n solved for eps. Where the schedule holds U for MIN_HOLD or
                    longer (a steady bed, as the experiments read it), one row per hold: the mean
                    eps over the hold's second half, with its drift (last minus first) there;
                    else the rows of the rising ramp (a bed still expanding; drift nan). Each
                    row also carries the law's own expanded eps at that U
                    (drag_laws.expanded_voidage: the solver's closure, the evidence of a miss).

`/usr/bin/python3 validation/fluidised_bed.py DIR` prints the rows (markdown); `rows(DIR)`
returns them for the report. numpy and PyYAML.
"""
import csv
import os
import sys

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "pipelines"))
import drag_laws  # noqa: E402
import fluidisation  # noqa: E402  (U_mf's construction, shared with the figure)

FIXED_BELOW = 0.6  # of U_mf: the fixed-bed branch
MIN_HOLD = 0.5  # s: a hold of U this long is read as a steady expanded bed


def read_log(path):
    with open(path) as fh:
        rows = list(csv.DictReader(fh))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def scene(run_dir):
    with open(os.path.join(run_dir, "case.yaml")) as fh:
        c = yaml.safe_load(fh)
    sp = c["species"]
    if len(sp) != 1:
        raise SystemExit(f"{run_dir}/case.yaml: one species expected (got {len(sp)})")
    return dict(d=sp[0]["diameter"], rho_p=sp[0]["density"], rho_f=c["fluid"]["density"],
                mu=c["fluid"]["viscosity"], law=c["drag"]["law"], g=-c["gravity"][2])


def bed_voidage(s, W, H):
    return 1.0 - W / ((s["rho_p"] - s["rho_f"]) * s["g"] * H)


def rows(run_dir):
    s, log = scene(run_dir), read_log(os.path.join(run_dir, "log.csv"))
    U, dP, H, W = (log[k] for k in ("superficial_velocity", "pressure_drop", "bed_height",
                                    "bed_weight"))
    up = list(fluidisation.rising(U))
    weight = sum(W[i] for i in up) / len(up)
    umf = fluidisation.u_mf(U, dP, weight)[0]
    fixed = [i for i in up if 0.05 * umf < U[i] < FIXED_BELOW * umf]
    eps_mf = sum(bed_voidage(s, W[i], H[i]) for i in fixed) / len(fixed)
    d, rho_p, rho_f, mu, g = s["d"], s["rho_p"], s["rho_f"], s["mu"], s["g"]
    out = {"U_mf": umf, "eps_mf": eps_mf, "weight": weight,
           "U_mf_wen_yu": drag_laws.wen_yu_umf(d, rho_p, rho_f, mu, g),
           "U_mf_ergun": drag_laws.u_mf("ergun", d, rho_p, rho_f, mu, eps_mf, g),
           "U_mf_law": drag_laws.u_mf(s["law"], d, rho_p, rho_f, mu, eps_mf, g)}
    branch = []
    for i in fixed[:: max(1, len(fixed) // 8)]:
        eps = bed_voidage(s, W[i], H[i])
        law = drag_laws.fixed_bed_gradient(s["law"], d, rho_f, mu, eps, U[i]) * H[i]
        ergun = drag_laws.ergun_gradient(d, rho_f, mu, eps, U[i]) * H[i]
        branch.append((U[i], eps, dP[i], law, ergun))
    out["branch"] = branch
    out["plateau"] = fluidisation.plateau(U, dP, umf)
    band = drag_laws.rz_band(d, rho_p, rho_f, mu, 0.5, 0.0, g)
    u_t, n_rz, n_gad = band[2], band[4], band[5]

    def band_at(u):  # U = u_t eps^n (1 -+ 5 %): the band of eps at this U
        e_lo = (u / (u_t * 1.05)) ** (1.0 / min(n_rz, n_gad))
        e_hi = (u / (u_t * 0.95)) ** (1.0 / max(n_rz, n_gad))
        return min(e_lo, e_hi), max(e_lo, e_hi)

    lo_u, hi_u = (f * umf for f in fluidisation.EXPANDED)
    held = [(u, k) for u, k in fluidisation.holds(log["time"], U, MIN_HOLD) if lo_u <= u <= hi_u]
    exp_rows = []
    def own(u):  # the law's own expanded voidage at U (the solver's closure)
        return drag_laws.expanded_voidage(s["law"], d, rho_p, rho_f, mu, u, g)

    for u, k in held:
        eps = [bed_voidage(s, W[i], H[i]) for i in k]
        exp_rows.append((u, sum(eps) / len(eps), *band_at(u), eps[-1] - eps[0], own(u)))
    if not held:
        expanded = list(fluidisation.expanded(U, umf))
        for i in expanded[:: max(1, len(expanded) // 8)]:
            exp_rows.append((U[i], bed_voidage(s, W[i], H[i]), *band_at(U[i]), float("nan"), own(U[i])))
    out["expansion"], out["expansion_held"] = exp_rows, bool(held)
    return out


def _pct(x):
    return f"{100.0 * x:+.1f} %"


def markdown(r):
    mm = 1e3
    lines = [f"U_mf {r['U_mf'] * mm:.2f} mm/s (eps_mf {r['eps_mf']:.3f}): Wen-Yu "
             f"{r['U_mf_wen_yu'] * mm:.2f} ({_pct(r['U_mf'] / r['U_mf_wen_yu'] - 1)}), Ergun at eps_mf "
             f"{r['U_mf_ergun'] * mm:.2f} ({_pct(r['U_mf'] / r['U_mf_ergun'] - 1)}), the law's own "
             f"{r['U_mf_law'] * mm:.2f} ({_pct(r['U_mf'] / r['U_mf_law'] - 1)})",
             f"plateau {r['plateau']:.1f} Pa against the buoyant weight per area {r['weight']:.1f} Pa "
             f"({_pct(r['plateau'] / r['weight'] - 1)})", "",
             "| U (mm/s) | eps | dP (Pa) | law's n f/eps H | vs law | Ergun | vs Ergun |",
             "|---|---|---|---|---|---|---|"]
    for U, eps, dP, law, ergun in r["branch"]:
        lines.append(f"| {U * mm:.2f} | {eps:.3f} | {dP:.1f} | {law:.1f} | {_pct(dP / law - 1)} | "
                     f"{ergun:.1f} | {_pct(dP / ergun - 1)} |")
    how = "held (mean over each hold's second half, drift over it)" if r["expansion_held"] else "rising"
    lines += ["", f"expansion, U {how}:", "",
              "| U (mm/s) | U/U_mf | eps | RZ-GAD band ±5 % | offset | drift | the law's own eps | vs law |",
              "|---|---|---|---|---|---|---|---|"]
    for U, eps, lo, hi, drift, law in r["expansion"]:
        off = drag_laws.band_offset(eps, lo, hi)
        lines.append(f"| {U * mm:.1f} | {U / r['U_mf']:.2f} | {eps:.3f} | {lo:.3f}-{hi:.3f} | {_pct(off)} | "
                     f"{drift:+.4f} | {law:.3f} | {_pct(eps / law - 1)} |")
    return "\n".join(lines)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit("usage: fluidised_bed.py RUN_DIR")
    print(markdown(rows(sys.argv[1])))
