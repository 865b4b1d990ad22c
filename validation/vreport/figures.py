"""Figures: matplotlib with the Agg backend (no display needed), and Context, which saves
a scene's figures to OUT/figures/ and keeps their names for VALIDATION.md."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


class Context:
    def __init__(self, fig_dir):
        self.fig_dir = fig_dir
        self.figures = []

    def save(self, fig, name):
        fig.tight_layout()
        fig.savefig(os.path.join(self.fig_dir, name), dpi=110)
        plt.close(fig)
        self.figures.append(name)


class NoFigures:
    """A context that drops the figures of a scene evaluated for its numbers only (the
    convergence and seed scenes evaluate other scenes' runs)."""
    figures = ()

    @staticmethod
    def save(fig, name):
        plt.close(fig)
