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


if __name__ == "__main__":
    unittest.main()
