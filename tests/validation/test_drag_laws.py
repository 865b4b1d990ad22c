"""validation/drag_laws.py, the Python laws behind bench/TRADEOFF.md's drag-law tables:
its self-check, and its coefficients at the values worked apart from the papers that
tests/unit/drag_law_test.cpp holds the solver's laws to (the two agree through them)."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "validation"))
import drag_laws  # noqa: E402

WORKED = [  # (law, eps, Re, C): the drag proper over 3 pi mu d u_s
    ("rong", 0.4, 0.1, 30.41172922), ("rong", 0.6, 10, 9.975009838),
    ("rong", 0.9, 500, 23.10354189), ("tenneti", 0.4, 0.1, 34.57130777),
    ("tenneti", 0.6, 10, 13.30382002), ("koch_hill", 0.4, 0.1, 0.4 * 93.75161838),
    ("koch_hill", 0.9, 500, 0.9 * 35.00333972), ("beetstra", 0.4, 0.1, 37.84597706),
]


class DragLaws(unittest.TestCase):
    def test_self_check(self):
        drag_laws.self_check()

    def test_worked_values(self):
        for law, eps, re, c in WORKED:
            self.assertAlmostEqual(drag_laws.coefficient(law, eps, re) / c, 1.0, delta=2e-9,
                                   msg=f"{law} eps {eps} Re {re}")

    def test_expanded_voidage_inverts_the_suspension_slip(self):
        # the inverse of suspension_slip (a round trip, any law), and past u_t nothing holds
        for law in ("di_felice", "rong"):
            for eps in (0.45, 0.6, 0.8):
                U = drag_laws.suspension_slip(law, 1e-3, 2500.0, 1000.0, 8.9e-4, eps)
                self.assertAlmostEqual(drag_laws.expanded_voidage(law, 1e-3, 2500.0, 1000.0, 8.9e-4, U),
                                       eps, delta=1e-9, msg=f"{law} eps {eps}")
        self.assertEqual(drag_laws.expanded_voidage("di_felice", 1e-3, 2500.0, 1000.0, 8.9e-4, 1.0), 1.0)

    def test_expanded_voidage_in_the_stokes_limit(self):
        # 2 um glass in water (Re ~ 1e-6): Di Felice's C -> 0.96 eps^-3.7 (Dallavalle's 4.8^2/24,
        # the exponent's bump e^-18), and the balance C 3 pi mu d U = eps (rho_p - rho_f) g V
        # gives U = u_t eps^4.7 / 0.96 with Stokes's u_t: eps = (0.96 U / u_t)^(1 / 4.7)
        d, rho_p, rho_f, mu, g = 2e-6, 2500.0, 1000.0, 8.9e-4, drag_laws.G
        u_t = (rho_p - rho_f) * g * d ** 2 / (18.0 * mu)
        for eps in (0.5, 0.7):
            U = u_t * eps ** 4.7 / 0.96
            self.assertAlmostEqual(drag_laws.expanded_voidage("di_felice", d, rho_p, rho_f, mu, U), eps,
                                   delta=2e-4)

if __name__ == "__main__":
    unittest.main()
