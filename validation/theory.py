"""Closed-form references of the validation scenes, written independently of the solver.

Equation numbers are the thesis's as quoted in physics.md §5. Nothing here imports or
calls the solver; tests/validation/closed_forms.hpp is the C++ twin of the first two
and the two must agree (report.py checks 4.4 against the thesis value 4.924 mm/s).
"""
import math

G = 9.81


def bisect(f, a, b, iters=200):
    """Root of f on [a, b]; f(a) and f(b) must have opposite signs."""
    fa, fb = f(a), f(b)
    if (fa < 0) == (fb < 0):
        raise ValueError(f"bisect: no sign change on [{a}, {b}] ({fa}, {fb})")
    for _ in range(iters):
        m = 0.5 * (a + b)
        fm = f(m)
        if (fm < 0) == (fa < 0):
            a, fa = m, fm
        else:
            b = m
    return 0.5 * (a + b)


# --- 4.1: Stokes settling of one sphere from rest --------------------------------------
class StokesTransient:
    """v(t) = (rho_p - rho_f) V g / b (1 - exp(-t/t_d)), b = 3 pi mu d, t_d = m/b (4.1).

    m = rho_p V: no added mass and no Basset history, as the thesis's (4.1).
    """

    def __init__(self, d, rho_p, rho_f, mu, g=G):
        V = math.pi * d ** 3 / 6.0
        b = 3.0 * math.pi * mu * d
        self.v_terminal = (rho_p - rho_f) * V * g / b
        self.t_relax = rho_p * V / b

    def speed(self, t):
        return self.v_terminal * (1.0 - math.exp(-t / self.t_relax))


# --- Di Felice (1994) with Dallavalle's C_d ----------------------------------------------
def dallavalle_cd(re):
    return (0.63 + 4.8 / math.sqrt(re)) ** 2


def di_felice_xi(re):
    return 3.7 - 0.65 * math.exp(-0.5 * (1.5 - math.log10(re)) ** 2)


def di_felice_block_slip(d, rho_p, rho_f, mu, eps, g=G):
    """Terminal superficial slip of a constant-porosity block (4.2-4.4).

    Force balance on one sphere: (rho_p - rho_av) V g = 1/8 C_d eps^-xi pi d^2 rho_f v^2,
    rho_av = eps rho_f + (1 - eps) rho_p, Re = rho_f v d / mu; root by bisection.
    In batch settling (no net volume flux) the superficial slip equals the speed of the
    spheres, so this is also the hindered settling speed of a suspension at eps (Kynch).
    """
    V = math.pi * d ** 3 / 6.0
    rho_av = eps * rho_f + (1.0 - eps) * rho_p
    weight = (rho_p - rho_av) * V * g

    def balance(v):
        re = rho_f * v * d / mu
        return 0.125 * dallavalle_cd(re) * eps ** (-di_felice_xi(re)) * math.pi * d * d * rho_f * v * v - weight

    return bisect(balance, 1e-9, 10.0)


def di_felice_polynomial_residual(v, d, rho_p, rho_f, mu, eps, g=G):
    """The thesis's polynomial form of (4.4), 0.3969 Re^2 + 6.048 Re^1.5 + 23.04 Re
    - (4/3) Ar eps^(1+xi) = 0, Ar = d^3 rho_f (rho_p - rho_f) g / mu^2, as a cross-check
    of the force-balance form above (residual relative to the Ar term)."""
    re = rho_f * v * d / mu
    ar = d ** 3 * rho_f * (rho_p - rho_f) * g / mu ** 2
    rhs = 4.0 / 3.0 * ar * eps ** (1.0 + di_felice_xi(re))
    return (0.3969 * re ** 2 + 6.048 * re ** 1.5 + 23.04 * re - rhs) / rhs


def single_sphere_terminal_dallavalle(d, rho_p, rho_f, mu, g=G):
    """Terminal speed of one sphere with Dallavalle's C_d (Di Felice's law at eps = 1)."""
    return di_felice_block_slip(d, rho_p, rho_f, mu, 1.0 - 1e-15, g)


# --- Richardson & Zaki (1954) with the Garside & Al-Dibouni (1977) exponent -------------
def garside_al_dibouni_n(re_t):
    """(5.1 - n)/(n - 2.7) = 0.1 Re_t^0.9 (Garside & Al-Dibouni 1977, Ind. Eng. Chem.
    Process Des. Dev. 16:206-214), Re_t = rho_f u_t d / mu of one sphere at its terminal
    speed: n -> 5.1 as Re_t -> 0 and -> 2.7 as Re_t -> inf."""
    x = 0.1 * re_t ** 0.9
    return (5.1 + 2.7 * x) / (1.0 + x)


def richardson_zaki(d, rho_p, rho_f, mu, eps, g=G):
    """u = u_t eps^n (Richardson & Zaki 1954), u_t from Dallavalle's C_d, n from
    Garside & Al-Dibouni. Returns (u, u_t, Re_t, n)."""
    u_t = single_sphere_terminal_dallavalle(d, rho_p, rho_f, mu, g)
    re_t = rho_f * u_t * d / mu
    n = garside_al_dibouni_n(re_t)
    return u_t * eps ** n, u_t, re_t, n


def acoustic_period(fill_height, c0):
    """Period of the column's first acoustic mode (closed bottom, free top): 4 H / c0."""
    return 4.0 * fill_height / c0


def beetstra_f_mono(eps, re):
    """Beetstra, van der Hoef & Kuipers (2007) monodisperse drag factor (thesis 2.85-2.86):
    F = f_mono 3 pi mu d u_s at voidage eps and Re = rho_f d |u_s| / mu."""
    phi = 1.0 - eps
    stokes = 10.0 * phi / eps ** 2 + eps ** 2 * (1.0 + 1.5 * math.sqrt(phi))
    inertial = (0.413 * re / (24.0 * eps ** 2) * (1.0 / eps + 3.0 * eps * phi + 8.4 * re ** -0.343)
                / (1.0 + 10.0 ** (3.0 * phi) * re ** (-(1.0 + 4.0 * phi) / 2.0)))
    return stokes + inertial


def bidisperse_block_slip(d1, d2, n1, rho_p, rho_f, mu, eps, g=G):
    """Terminal superficial slip of a bidisperse constant-porosity block (thesis eq. 4.5):
    u_T = (rho_p - rho_f) g <d>^2 / (18 mu [f_mono(eps, <Re>)/eps + (Sigma - 1)/eps^2]),
    Sigma = sum x_i / y_i^2, y_i = d_i/<d>, <d> the Sauter mean, x_i volume fractions from
    the number fraction n1 of size d1. It is the block's force balance with the drag (2.88)."""
    v1, v2 = n1 * d1 ** 3, (1.0 - n1) * d2 ** 3
    x1, x2 = v1 / (v1 + v2), v2 / (v1 + v2)
    dm = 1.0 / (x1 / d1 + x2 / d2)
    sigma = x1 / (d1 / dm) ** 2 + x2 / (d2 / dm) ** 2

    def residual(u):
        re = rho_f * dm * u / mu
        return u - (rho_p - rho_f) * g * dm ** 2 / (18.0 * mu * (beetstra_f_mono(eps, re) / eps
                                                                  + (sigma - 1.0) / eps ** 2))
    return bisect(residual, 1e-9, 1.0)


# --- Multispecies hindered settling (Masliyah 1979) with Di Felice's drag ----------------
def di_felice_drag(us, d, rho_f, mu, eps):
    """Di Felice (1994) drag with Dallavalle's C_d on one sphere (thesis 2.76-2.79):
    f = 1/8 C_d eps^-xi pi d^2 rho_f |u_s| u_s, Re = rho_f |u_s| d / mu, u_s the
    superficial slip eps (u_f - v). Signed like u_s; 0 at u_s = 0."""
    if us == 0.0:
        return 0.0
    re = rho_f * abs(us) * d / mu
    return 0.125 * dallavalle_cd(re) * eps ** (-di_felice_xi(re)) * math.pi * d * d * rho_f * abs(us) * us


def brown_lawler_cd(re):
    """Brown & Lawler (2003): C_d = 24/Re (1 + 0.150 Re^0.681) + 0.407/(1 + 8710/Re)."""
    return 24.0 / re * (1.0 + 0.150 * re ** 0.681) + 0.407 / (1.0 + 8710.0 / re)


def brown_lawler_drag(us, d, rho_f, mu, eps):
    """The sand column's drag (Zhao et al. 2014): Brown-Lawler's C_d with Di Felice's
    voidage function, f = 1/8 C_d eps^-xi pi d^2 rho_f |u_s| u_s; as di_felice_drag."""
    if us == 0.0:
        return 0.0
    re = rho_f * abs(us) * d / mu
    return 0.125 * brown_lawler_cd(re) * eps ** (-di_felice_xi(re)) * math.pi * d * d * rho_f * abs(us) * us


def uniform_size_species(d_min, d_max, rho, phi_total, bins=200):
    """A size law uniform by number on [d_min, d_max] as `bins` species of the bins' mid
    diameters, each with its share of the solid volume fraction phi_total (the share goes
    as d^3). Returns (species list for masliyah_velocities, number weights)."""
    ds = [d_min + (k + 0.5) * (d_max - d_min) / bins for k in range(bins)]
    vol = sum(d ** 3 for d in ds)
    return [(d, rho, phi_total * d ** 3 / vol) for d in ds], [1.0 / bins] * bins


def masliyah_velocities(species, rho_f, mu, g=G, drag=di_felice_drag, push=None):
    """Lab-frame settling speeds of a uniform multispecies suspension, no net volume flux
    (Masliyah 1979, Chem. Eng. Sci. 34:1166; Lockett & Al-Habbooby 1973; Patwardhan & Tien
    1985), with the Di Felice drag of the scenes in place of Masliyah's Richardson-Zaki f.

    species: list of (d_i, rho_i, phi_i). eps = 1 - sum phi_j and
      rho_susp = eps rho_f + sum phi_j rho_j                                (M1)
    Each sphere carries its weight less the buoyancy of the suspension (the mean pressure
    gradient of a suspension at rest on its base is rho_susp g) with the drag of its own
    superficial slip u_s,i = eps (u_f - v_i):
      (rho_i - rho_susp) V_i g = f_DiFelice(u_s,i; d_i, eps)                 (M2)
    and the volume flux through a horizontal plane vanishes (batch settling):
      eps u_f + sum phi_j v_j = 0  =>  u_f = sum phi_j s_j,  s_j = u_s,j / eps     (M3)
    so species i falls (lab frame, downward positive) at
      w_i = -v_i = s_i - sum_j phi_j s_j.                                   (M4)
    One species: rho_susp = rho_av of (4.2-4.4) and w = eps s = u_s, i.e.
    di_felice_block_slip. `drag` replaces the Di Felice law (brown_lawler_drag for the sand
    column). `push`, one per species, adds a downward force of that fraction of the sphere's
    weight rho_i V_i g to (M2) (the contacts' mean push a run measures, which the model
    lacks). Returns (w list, u_s list, eps, rho_susp)."""
    phi_tot = sum(p for _, _, p in species)
    eps = 1.0 - phi_tot
    rho_susp = eps * rho_f + sum(p * r for _, r, p in species)
    slips = []
    for i, (d, rho, phi) in enumerate(species):
        weight = (rho - rho_susp + (push[i] * rho if push else 0.0)) * math.pi * d ** 3 / 6.0 * g
        if weight == 0.0:
            slips.append(0.0)
            continue
        mag = bisect(lambda u: drag(u, d, rho_f, mu, eps) - abs(weight), 1e-12, 10.0)
        slips.append(math.copysign(mag, weight))
    s = [u / eps for u in slips]
    u_f = sum(p * si for (_, _, p), si in zip(species, s))
    w = [si - u_f for si in s]
    return w, slips, eps, rho_susp


class TwoSpeciesKynch:
    """Kynch (1952) construction for a uniform two-species suspension settling from rest
    (the heavy or faster species first), with the Masliyah velocities above: from the top,
    clear liquid | zone B (slower species alone at phi_B) | zone A (the initial mixture).

    Lower front (A -> B), where the faster species ends: continuity of that species,
    whose concentration is 0 in B, gives
      U_1 = w_fast^A                                                        (K1)
    Continuity of the slower species across the same front fixes its concentration in B:
      phi_slow^A (w_slow^A - U_1) = phi_B (w_slow^B(phi_B) - U_1)            (K2)
    with w_slow^B(phi) its monodisperse hindered speed at eps = 1 - phi (M4 with one
    species = (4.4)). The branch taken is w_slow^B(phi_B) <= U_1 (zone B falls behind the
    lower front; phi_B -> phi_slow^A + phi_fast^A as the densities become equal).
    Upper front (B -> clear), by continuity of the slower species into clear liquid:
      U_2 = w_slow^B(phi_B)                                                  (K3)
    All speeds downward positive, lab frame. Both fronts are shocks here (dilute: the
    flux phi w(phi) is concave, so the characteristics run into them)."""

    def __init__(self, fast, slow, rho_f, mu, g=G):
        (d1, r1, p1), (d2, r2, p2) = fast, slow
        (w1, w2), (us1, us2), self.eps0, self.rho_susp = masliyah_velocities([fast, slow], rho_f, mu, g)
        self.w_fast_A, self.w_slow_A, self.us_A = w1, w2, (us1, us2)
        self.u1 = w1

        def w_slow_alone(phi):
            return masliyah_velocities([(d2, r2, phi)], rho_f, mu, g)[0][0]
        self.w_slow_alone = w_slow_alone
        flux_in = p2 * (self.u1 - w2)   # slow species left behind by the lower front, per unit area and time

        def excess(phi):                # phi_B (U_1 - w_B(phi_B)) - flux_in: increases with phi on the branch
            return phi * (self.u1 - w_slow_alone(phi)) - flux_in
        phi_hi = 0.6
        # lowest phi on the branch: where the slow species alone falls as fast as the front
        lo = 1e-9
        if w_slow_alone(lo) > self.u1:
            lo = bisect(lambda phi: w_slow_alone(phi) - self.u1, lo, phi_hi)
        self.phi_B = lo if excess(lo) >= 0.0 else bisect(excess, lo, phi_hi)
        self.eps_B = 1.0 - self.phi_B
        self.u2 = w_slow_alone(self.phi_B)


def mixture_self_check(d=1e-4, rho=2450.0, rho_f=1000.0, mu=8.9e-4, eps0=0.9, g=G):
    """Unit check: with both species of equal density the mixture model must reduce to the
    monodisperse reference (4.4): each species falls at di_felice_block_slip(eps0), both
    fronts move at it and zone B holds the whole initial concentration. Also one species
    alone at eps gives (4.4). Returns the largest relative deviation; raises if > 1e-9."""
    ref = di_felice_block_slip(d, rho, rho_f, mu, eps0, g)
    phi = 0.5 * (1.0 - eps0)
    k = TwoSpeciesKynch((d, rho, phi), (d, rho, phi), rho_f, mu, g)
    devs = [k.w_fast_A / ref - 1, k.w_slow_A / ref - 1, k.u1 / ref - 1, k.u2 / ref - 1,
            k.phi_B / (1.0 - eps0) - 1]
    for e in (0.8, 0.9, 0.95):
        w = masliyah_velocities([(d, 1500.0, 1.0 - e)], rho_f, mu, g)[0][0]
        devs.append(w / di_felice_block_slip(d, 1500.0, rho_f, mu, e, g) - 1)
    worst = max(abs(x) for x in devs)
    if worst > 1e-9:
        raise AssertionError(f"mixture model does not reduce to (4.4): deviations {devs}")
    return worst


if __name__ == "__main__":
    v = di_felice_block_slip(1e-4, 2500, 1000, 8.9e-4, 0.9)
    print(f"Di Felice block slip at eps=0.9: {v*1e3:.4f} mm/s "
          f"(polynomial residual {di_felice_polynomial_residual(v, 1e-4, 2500, 1000, 8.9e-4, 0.9):.2e})")
    s = StokesTransient(1e-4, 2500, 1000, 8.9e-4)
    print(f"Stokes: v_T = {s.v_terminal*1e3:.4f} mm/s, t_d = {s.t_relax*1e3:.4f} ms")
    u, ut, ret, n = richardson_zaki(1e-4, 2500, 1000, 8.9e-4, 0.9)
    print(f"R-Z: u_t = {ut*1e3:.4f} mm/s, Re_t = {ret:.4f}, n = {n:.4f}, u = {u*1e3:.4f} mm/s")
    print(f"eps=0.8 block: {di_felice_block_slip(1e-4, 2500, 1000, 8.9e-4, 0.8)*1e3:.4f} mm/s")
    print(f"mixture model, equal densities against (4.4): largest deviation {mixture_self_check():.1e}")
    k = TwoSpeciesKynch((1e-4, 2450, 0.05), (1e-4, 1500, 0.05), 1000, 8.9e-4)
    print(f"two densities (2450/1500, eps0 = 0.9): rho_susp = {k.rho_susp:.1f} kg/m3, heavy/light in the "
          f"mixture {k.w_fast_A*1e3:.4f}/{k.w_slow_A*1e3:.4f} mm/s; heavy front U1 = {k.u1*1e3:.4f} mm/s, "
          f"light-only zone eps_B = {k.eps_B:.4f}, light front U2 = {k.u2*1e3:.4f} mm/s")
