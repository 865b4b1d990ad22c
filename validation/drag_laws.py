"""The solver's five dense-bed drag laws against the correlations of experiments (issue 37).

Closed forms only: the laws are written again here from their papers' formulas, as
solver/coupling/drag_laws.hpp implements them, and nothing imports or calls the solver.

Convention. Every law gives the drag proper on one sphere, the part apart from -V grad p,
    f = C(eps, Re) 3 pi mu d u_s,   u_s = eps (u_f - v)  (superficial slip),
    Re = rho_f |u_s| d / mu.
The laws (`LAWS`):
  di_felice  Di Felice (1994) with Dallavalle's C_d: C = (0.63 + 4.8/sqrt Re)^2 Re/24 eps^-xi,
             xi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2).
  rong       Rong, Dong & Yu (2013), Chem. Eng. Sci. 99:44: as di_felice with
             beta = 2.65 (eps + 1) - (5.3 - 3.5 eps) eps^2 exp(-(1.5 - log10 Re)^2 / 2).
  tenneti    Tenneti, Garg & Subramaniam (2011), Int. J. Multiphase Flow 37:1072: C = eps F,
             F = (1 + 0.15 Re^0.687)/eps^3 + 5.81 phi/eps^3 + 0.48 phi^(1/3)/eps^4
                 + phi^3 Re (0.95 + 0.61 phi^3/eps^2),  phi = 1 - eps.
  koch_hill  Hill, Koch & Ladd (2001) as Benyahia, Syamlal & O'Brien (2006), Powder Technol.
             162:166, extended it (MFiX's form): C = eps F, Re_h = Re/2 (see koch_hill_f).
  beetstra   Beetstra, van der Hoef & Kuipers (2007), AIChE J. 53:489, monodisperse:
             C = f_mono(eps, Re).
Tenneti's and Koch-Hill's F is the whole fluid force over 3 pi mu d u_s; in a periodic array
eps (-grad p) = n f, so the drag proper is eps F.

References, independent of the solver:
  1. Homogeneous suspension / liquid fluidised bed: the steady superficial slip solves
     C 3 pi mu d u_s = eps (rho_p - rho_f) g V, V = pi d^3/6; the band u_t eps^n with n
     between Richardson & Zaki (1954), Trans. Inst. Chem. Eng. 32:35 (d/D -> 0:
     4.65 (Re_t < 0.2), 4.4 Re_t^-0.03 (< 1), 4.4 Re_t^-0.1 (< 500), 2.4 above) and
     Garside & Al-Dibouni (1977), Ind. Eng. Chem. Process Des. Dev. 16:206
     ((5.1 - n)/(n - 2.7) = 0.1 Re_t^0.9), widened by 5 % each side; u_t from
     Dallavalle's C_d (theory.single_sphere_terminal_dallavalle), Re_t = rho_f u_t d / mu.
  2. Fixed bed: Ergun (1952), Chem. Eng. Prog. 48:89,
     dP/L = 150 mu U phi^2/(eps^3 d^2) + 1.75 rho_f U^2 phi/(eps^3 d), U superficial. The
     gradient carries the drag proper, G eps = n f (n = phi/V), so a law predicts
     dP/L = n C 3 pi mu d U / eps at Re = rho_f U d / mu.
  3. Minimum fluidisation: Wen & Yu (1966), AIChE J. 12:610,
     Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7, Ar = d^3 rho_f (rho_p - rho_f) g / mu^2.
     A law's (and Ergun's) U_mf: its fixed-bed gradient at eps_mf equals the bed's buoyant
     weight per volume, phi_mf (rho_p - rho_f) g.

Run `/usr/bin/python3 validation/drag_laws.py` for the three markdown tables
(bench/TRADEOFF.md, "Drag laws against the experiments' correlations"); `self_check()`
asserts the Stokes limit of every law and Wen-Yu's U_mf of 1 mm glass in water.
Standard library only (math), with theory.py's bisect and Dallavalle terminal speed.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import theory  # noqa: E402

G = theory.G
LAWS = ("di_felice", "rong", "tenneti", "koch_hill", "beetstra")
MIN_RE = 1e-12  # the solver's Re floor (kMinRe): the laws are finite at Re -> 0, their pieces not


# --- the laws: C(eps, Re) = f / (3 pi mu d u_s) ------------------------------------------
def _log_bump(re):
    """exp(-(1.5 - log10 Re)^2 / 2), the Re-dependence of Di Felice's and Rong's exponents."""
    return math.exp(-0.5 * (1.5 - math.log10(re)) ** 2)


def dallavalle_c(re):
    """C_d Re / 24 with Dallavalle's C_d = (0.63 + 4.8/sqrt Re)^2: 0.96 at Re -> 0."""
    return (0.63 * math.sqrt(re) + 4.8) ** 2 / 24.0


def di_felice_c(eps, re):
    xi = 3.7 - 0.65 * _log_bump(re)
    return dallavalle_c(re) * eps ** (-xi)


def rong_c(eps, re):
    beta = 2.65 * (eps + 1.0) - (5.3 - 3.5 * eps) * eps * eps * _log_bump(re)
    return dallavalle_c(re) * eps ** (-beta)


def tenneti_f(eps, re):
    """Tenneti et al.'s whole force F over 3 pi mu d u_s."""
    phi = 1.0 - eps
    e3, p3 = eps ** 3, phi ** 3
    return ((1.0 + 0.15 * re ** 0.687) / e3 + 5.81 * phi / e3 + 0.48 * phi ** (1.0 / 3.0) / (e3 * eps)
            + p3 * re * (0.95 + 0.61 * p3 / (eps * eps)))


def _koch_hill_blend(phi, a, b, c):
    """F0 (a, b, c = 17.14, 8.48, 8.16) or F2 (17.89, 11.03, 15.41) of Benyahia et al."""
    dense = 10.0 * phi / (1.0 - phi) ** 3
    if phi >= 0.4:
        return dense
    w = math.exp(-10.0 * (0.4 - phi) / phi) if phi > 0.0 else 0.0
    phi_ln_phi = phi * math.log(phi) if phi > 0.0 else 0.0
    dilute = ((1.0 + 3.0 * math.sqrt(0.5 * phi) + 135.0 / 64.0 * phi_ln_phi + a * phi)
              / (1.0 + 0.681 * phi - b * phi * phi + c * phi ** 3))
    return (1.0 - w) * dilute + w * dense


def koch_hill_f(eps, re):
    """Koch-Hill's whole force F over 3 pi mu d u_s, MFiX's form (Benyahia et al. 2006):
    Re_h = Re/2; F = 1 + 3 Re_h/8 (phi <= 0.01, Re_h <= (F2 - 1)/(3/8 - F3)),
    F0 + F1 Re_h^2 (phi > 0.01, Re_h up to where it meets F2 + F3 Re_h), else F2 + F3 Re_h."""
    phi, re_h = 1.0 - eps, 0.5 * re
    f0 = _koch_hill_blend(phi, 17.14, 8.48, 8.16)
    f2 = _koch_hill_blend(phi, 17.89, 11.03, 15.41)
    f3 = 0.9351 * phi + 0.03667 if phi < 0.0953 else 0.0673 + 0.212 * phi + 0.0232 / eps ** 5
    if phi <= 0.01:
        return 1.0 + 0.375 * re_h if re_h <= (f2 - 1.0) / (0.375 - f3) else f2 + f3 * re_h
    f1 = math.sqrt(2.0 / phi) / 40.0 if phi <= 0.1 else 0.11 + 5.1e-4 * math.exp(11.6 * phi)
    re_meet = (f3 + math.sqrt(f3 * f3 - 4.0 * f1 * (f0 - f2))) / (2.0 * f1)
    return f0 + f1 * re_h * re_h if re_h <= re_meet else f2 + f3 * re_h


def beetstra_f_mono(eps, re):
    """Beetstra et al.'s monodisperse factor; the same as theory.beetstra_f_mono."""
    phi, e2 = 1.0 - eps, eps * eps
    low = 10.0 * phi / e2 + e2 * (1.0 + 1.5 * math.sqrt(phi))
    num = 1.0 / eps + 3.0 * eps * phi + 8.4 * re ** -0.343
    den = 1.0 + 10.0 ** (3.0 * phi) * re ** (-0.5 * (1.0 + 4.0 * phi))
    return low + 0.413 * re / (24.0 * e2) * num / den


def coefficient(law, eps, re):
    """C(eps, Re): the drag proper on one sphere over 3 pi mu d u_s (Re floored as the solver)."""
    re = max(re, MIN_RE)
    if law == "di_felice":
        return di_felice_c(eps, re)
    if law == "rong":
        return rong_c(eps, re)
    if law == "tenneti":
        return eps * tenneti_f(eps, re)
    if law == "koch_hill":
        return eps * koch_hill_f(eps, re)
    if law == "beetstra":
        return beetstra_f_mono(eps, re)
    raise ValueError(f"unknown drag law {law!r}; one of {LAWS}")


# --- 1. homogeneous suspension / liquid fluidised bed -------------------------------------
def suspension_slip(law, d, rho_p, rho_f, mu, eps, g=G):
    """Steady superficial slip of a homogeneous suspension (or a fluidised bed's U):
    C(eps, Re) 3 pi mu d u_s = eps (rho_p - rho_f) g V."""
    weight = eps * (rho_p - rho_f) * g * math.pi * d ** 3 / 6.0

    def balance(u):
        return coefficient(law, eps, rho_f * u * d / mu) * 3.0 * math.pi * mu * d * u - weight

    return theory.bisect(balance, 1e-12, 10.0)


def richardson_zaki_n(re_t):
    """Richardson & Zaki's exponent for d/D -> 0."""
    if re_t < 0.2:
        return 4.65
    if re_t < 1.0:
        return 4.4 * re_t ** -0.03
    if re_t < 500.0:
        return 4.4 * re_t ** -0.1
    return 2.4


def rz_band(d, rho_p, rho_f, mu, eps, widen=0.05, g=G):
    """The experiments' band of the superficial slip: u_t eps^n, n between Richardson & Zaki's
    and Garside & Al-Dibouni's, widened by `widen` each side. Returns (lo, hi, u_t, Re_t,
    n_rz, n_gad)."""
    u_t = theory.single_sphere_terminal_dallavalle(d, rho_p, rho_f, mu, g)
    re_t = rho_f * u_t * d / mu
    n_rz, n_gad = richardson_zaki_n(re_t), theory.garside_al_dibouni_n(re_t)
    lo = u_t * eps ** max(n_rz, n_gad) * (1.0 - widen)
    hi = u_t * eps ** min(n_rz, n_gad) * (1.0 + widen)
    return lo, hi, u_t, re_t, n_rz, n_gad


def band_offset(u, lo, hi):
    """0 inside [lo, hi], else u/edge - 1 of the nearer edge (> 0 above, < 0 below)."""
    if u > hi:
        return u / hi - 1.0
    if u < lo:
        return u / lo - 1.0
    return 0.0


# --- 2. fixed bed ------------------------------------------------------------------------
def ergun_gradient(d, rho_f, mu, eps, U):
    """Ergun's dP/L at superficial velocity U."""
    phi = 1.0 - eps
    return 150.0 * mu * U * phi ** 2 / (eps ** 3 * d * d) + 1.75 * rho_f * U * U * phi / (eps ** 3 * d)


def fixed_bed_gradient(law, d, rho_f, mu, eps, U):
    """A law's dP/L: n C 3 pi mu d U / eps, n = phi/V, Re = rho_f U d / mu."""
    n = (1.0 - eps) / (math.pi * d ** 3 / 6.0)
    return n * coefficient(law, eps, rho_f * U * d / mu) * 3.0 * math.pi * mu * d * U / eps


# --- 3. minimum fluidisation -------------------------------------------------------------
def archimedes(d, rho_p, rho_f, mu, g=G):
    return d ** 3 * rho_f * (rho_p - rho_f) * g / mu ** 2


def expanded_voidage(law, d, rho_p, rho_f, mu, U, g=G):
    """The voidage at which a bed fluidised at superficial U is held by the law's drag: the
    eps whose suspension_slip is U (it rises with eps), in [0.36, 1); 1 where even eps -> 1
    does not hold the spheres (U past u_t)."""
    lo, hi = 0.36, 1.0 - 1e-9
    if suspension_slip(law, d, rho_p, rho_f, mu, hi, g) <= U:
        return 1.0
    return theory.bisect(lambda e: suspension_slip(law, d, rho_p, rho_f, mu, e, g) - U, lo, hi)


def wen_yu_umf(d, rho_p, rho_f, mu, g=G):
    """Wen & Yu's U_mf: Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7."""
    re_mf = math.sqrt(33.7 ** 2 + 0.0408 * archimedes(d, rho_p, rho_f, mu, g)) - 33.7
    return re_mf * mu / (rho_f * d)


def u_mf(law, d, rho_p, rho_f, mu, eps_mf=0.42, g=G):
    """U at which the fixed-bed gradient at eps_mf is the buoyant weight per volume,
    phi_mf (rho_p - rho_f) g; law is one of LAWS or "ergun"."""
    weight = (1.0 - eps_mf) * (rho_p - rho_f) * g
    if law == "ergun":
        def grad(U):
            return ergun_gradient(d, rho_f, mu, eps_mf, U)
    else:
        def grad(U):
            return fixed_bed_gradient(law, d, rho_f, mu, eps_mf, U)
    return theory.bisect(lambda U: grad(U) - weight, 1e-12, 10.0)


# --- the tables --------------------------------------------------------------------------
WATER = dict(rho_f=1000.0, mu=8.9e-4)
GLASS = 2500.0
SUSPENSION_D = (50e-6, 100e-6, 1.5e-3)
SUSPENSION_EPS = (0.5, 0.6, 0.7, 0.8, 0.9)
BED_EPS = (0.4, 0.45, 0.5)
BED_RE = (0.1, 1.0, 10.0, 100.0)
BED_TOL = 0.10
UMF_D = (0.5e-3, 1e-3, 2e-3, 3e-3)
EPS_MF = 0.42
UMF_TOL = 0.10  # this section's choice (as the fixed bed's), not the correlation's own scatter


def _pct(x):
    s = f"{100.0 * x:+.1f}"
    return s.replace("-", "\u2212") + " %"


def _size(d):
    return f"{d * 1e3:g} mm" if d >= 1e-3 else f"{d * 1e6:.0f} µm"


def _num(x, fmt):
    return (fmt % x).replace("-", "\u2212")


def suspension_table(counts):
    rho_f, mu = WATER["rho_f"], WATER["mu"]
    lines = ["| d (Re_t) | ε | band (mm/s, ±5 %) | " + " | ".join(LAWS) + " |",
             "|---|---|---|" + "---|" * len(LAWS)]
    for d in SUSPENSION_D:
        for eps in SUSPENSION_EPS:
            lo, hi, u_t, re_t, n_rz, n_gad = rz_band(d, GLASS, rho_f, mu, eps)
            cells = []
            for law in LAWS:
                u = suspension_slip(law, d, GLASS, rho_f, mu, eps)
                off = band_offset(u, lo, hi)
                counts[law] = counts.get(law, 0) + (off == 0.0)
                where = "inside" if off == 0.0 else _pct(off) + (" above" if off > 0 else " below")
                cells.append(f"{_num(1e3 * u, '%.3g')}: {where}")
            head = f"{_size(d)} ({re_t:.3g})"
            lines.append(f"| {head} | {eps} | {1e3 * lo:.3g}–{1e3 * hi:.3g} | " + " | ".join(cells) + " |")
    return lines


def suspension_header():
    rho_f, mu = WATER["rho_f"], WATER["mu"]
    rows = []
    for d in SUSPENSION_D:
        _, _, u_t, re_t, n_rz, n_gad = rz_band(d, GLASS, rho_f, mu, 0.5)
        rows.append(f"{_size(d)}: u_t {1e3 * u_t:.4g} mm/s, Re_t {re_t:.3g}, "
                    f"n {n_rz:.3f} (R–Z) / {n_gad:.3f} (G–A-D)")
    return rows


def fixed_bed_table(counts):
    rho_f, mu, d = WATER["rho_f"], WATER["mu"], 1e-3  # the ratio depends on eps and Re only
    lines = ["| ε | Re | Ergun ΔP/L · d²/(μU) | " + " | ".join(LAWS) + " |",
             "|---|---|---|" + "---|" * len(LAWS)]
    for eps in BED_EPS:
        for re in BED_RE:
            U = re * mu / (rho_f * d)
            ref = ergun_gradient(d, rho_f, mu, eps, U)
            cells = []
            for law in LAWS:
                rel = fixed_bed_gradient(law, d, rho_f, mu, eps, U) / ref - 1.0
                counts[law] = counts.get(law, 0) + (abs(rel) <= BED_TOL)
                cells.append(_pct(rel))
            lines.append(f"| {eps} | {re:g} | {ref * d * d / (mu * U):.4g} | " + " | ".join(cells) + " |")
    return lines


def umf_table(counts):
    rho_f, mu = WATER["rho_f"], WATER["mu"]
    lines = ["| d | Ar | Wen–Yu Re_mf | Wen–Yu U_mf (mm/s) | Ergun (ε_mf 0.42) | " + " | ".join(LAWS) + " |",
             "|---|---|---|---|---|" + "---|" * len(LAWS)]
    for d in UMF_D:
        ref = wen_yu_umf(d, GLASS, rho_f, mu)
        ergun = u_mf("ergun", d, GLASS, rho_f, mu, EPS_MF)
        counts["ergun"] = counts.get("ergun", 0) + (abs(ergun / ref - 1.0) <= UMF_TOL)
        cells = []
        for law in LAWS:
            rel = u_mf(law, d, GLASS, rho_f, mu, EPS_MF) / ref - 1.0
            counts[law] = counts.get(law, 0) + (abs(rel) <= UMF_TOL)
            cells.append(_pct(rel))
        lines.append(f"| {d * 1e3:g} mm | {archimedes(d, GLASS, rho_f, mu):.4g} | "
                     f"{ref * rho_f * d / mu:.3g} | {1e3 * ref:.3g} | "
                     f"{1e3 * ergun:.3g} ({_pct(ergun / ref - 1.0)}) | " + " | ".join(cells) + " |")
    return lines


def counts_table(c1, c2, c3):
    n1 = len(SUSPENSION_D) * len(SUSPENSION_EPS)
    n2 = len(BED_EPS) * len(BED_RE)
    n3 = len(UMF_D)
    lines = [f"| law | suspension: inside the band (of {n1}) | fixed bed: within 10 % of Ergun (of {n2}) "
             f"| U_mf: within 10 % of Wen–Yu (of {n3}) | all (of {n1 + n2 + n3}) |",
             "|---|---|---|---|---|"]
    for law in LAWS:
        lines.append(f"| {law} | {c1[law]} | {c2[law]} | {c3[law]} | {c1[law] + c2[law] + c3[law]} |")
    lines.append(f"| Ergun (ε_mf 0.42) | – | – | {c3['ergun']} | – |")
    return lines


def tables():
    """The three tables and the counts, as markdown lines."""
    c1, c2, c3 = {}, {}, {}
    out = ["Glass (ρ_p 2500 kg/m³) in water (ρ_f 1000 kg/m³, μ 8.9e-4 Pa s), g 9.81 m/s².", "",
           "1. Homogeneous suspension / liquid fluidised bed: superficial slip (mm/s) and where it "
           "lies against u_t ε^n (n from Richardson–Zaki to Garside–Al-Dibouni, ±5 %); the % is "
           "from the nearer edge of the widened band.", ""]
    out += ["- " + r for r in suspension_header()] + [""]
    out += suspension_table(c1) + [""]
    out += ["2. Fixed bed: each law's ΔP/L relative to Ergun (the ratio depends on ε and Re only).", ""]
    out += fixed_bed_table(c2) + [""]
    out += [f"3. Minimum fluidisation, ε_mf = {EPS_MF}: U_mf relative to Wen–Yu.", ""]
    out += umf_table(c3) + [""]
    out += ["Counts (10 % for U_mf is this section's choice, as for the fixed bed):", ""]
    out += counts_table(c1, c2, c3)
    return out, (c1, c2, c3)


# --- self-check --------------------------------------------------------------------------
def self_check():
    """Asserts each law's Stokes limit (eps -> 1, Re -> 0) within 5 % of C = 1 and Wen-Yu's
    U_mf of 1 mm glass in water in 8-9.5 mm/s. Returns the values found; Koch-Hill's MFiX
    form is also evaluated just past its dilute cut (phi = 0.01) for the report."""
    found = {}
    for law in LAWS:
        c = coefficient(law, 1.0 - 1e-12, 1e-10)
        found[law] = c
        assert abs(c - 1.0) <= 0.05, f"{law}: C = {c} at eps -> 1, Re -> 0"
    found["koch_hill at phi 0.0099 / 0.0101, Re 1e-10"] = (coefficient("koch_hill", 0.9901, 1e-10),
                                                          coefficient("koch_hill", 0.9899, 1e-10))
    umf = wen_yu_umf(1e-3, GLASS, WATER["rho_f"], WATER["mu"])
    found["wen_yu_umf 1 mm (m/s)"] = umf
    assert 8e-3 <= umf <= 9.5e-3, f"Wen-Yu U_mf of 1 mm glass in water: {umf} m/s"
    return found


if __name__ == "__main__":
    print("\n".join(tables()[0]))
