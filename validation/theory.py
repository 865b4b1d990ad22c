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


if __name__ == "__main__":
    v = di_felice_block_slip(1e-4, 2500, 1000, 8.9e-4, 0.9)
    print(f"Di Felice block slip at eps=0.9: {v*1e3:.4f} mm/s "
          f"(polynomial residual {di_felice_polynomial_residual(v, 1e-4, 2500, 1000, 8.9e-4, 0.9):.2e})")
    s = StokesTransient(1e-4, 2500, 1000, 8.9e-4)
    print(f"Stokes: v_T = {s.v_terminal*1e3:.4f} mm/s, t_d = {s.t_relax*1e3:.4f} ms")
    u, ut, ret, n = richardson_zaki(1e-4, 2500, 1000, 8.9e-4, 0.9)
    print(f"R-Z: u_t = {ut*1e3:.4f} mm/s, Re_t = {ret:.4f}, n = {n:.4f}, u = {u*1e3:.4f} mm/s")
    print(f"eps=0.8 block: {di_felice_block_slip(1e-4, 2500, 1000, 8.9e-4, 0.8)*1e3:.4f} mm/s")


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
