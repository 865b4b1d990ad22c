"""Scene single_particle (thesis §4.4): one sphere from rest in still water against the
Stokes transient (4.1)."""
import numpy as np

import theory

from ..figures import plt
from ..rows import Row, failed_run_rows
from ..runs import Run


class SingleParticle:
    """Thesis §4.4: one sphere from rest in still water against the Stokes transient (4.1)."""
    name = "single_particle"
    case = "cases/single_particle.yaml"
    TARGET_TRANSIENT = 0.01   # issue 4: Stokes transient (4.1) under 1 %
    TARGET_SLIP = 0.01        # issue 4: 1 % (the drag sees the slip)
    TARGET_V_END = 0.03       # issue 2: terminal speed within 3 % (see the note of the row)
    # issue 38: the matrix's short rows at every preset; the case runs at the default
    # (balanced), these beside it in the full mode (each sets the keys the case leaves
    # unset: c0, the CFL number, the DEM sub-steps)
    PRESETS = ("fast", "accurate")

    def runs(self, mode):
        # 4 mm box kept in both modes: a periodic box of 2 mm would slow the sphere by
        # its images (Hasimoto: 1.76 phi^(1/3) ~ 5 %).
        sets = {"time.end": 0.008 if mode == "reduced" else 0.0125, "output.log_interval": 1e-4}
        out = [Run("single_particle", self.case, sets)]
        if mode == "full":
            out += [Run(f"single_particle_{p}", self.case, dict(sets, fidelity=p)) for p in self.PRESETS]
        return out

    def evaluate(self, results, ctx):
        rows = self.rows_of(results["single_particle"], ctx, "")
        for p in self.PRESETS:
            if f"single_particle_{p}" in results:
                rows += self.rows_of(results[f"single_particle_{p}"], None, f", preset {p}")
        return rows

    def rows_of(self, r, ctx, preset):
        """The rows of one run (preset: the label's suffix); its figure when ctx is given."""
        if not r.ok or r.log is None:
            return failed_run_rows(self.name, r, "v(t)" + preset)
        sp = r.species()
        rho_f, mu = r.fluid()
        st = theory.StokesTransient(sp["diameter"], sp["density"], rho_f, mu, r.g())
        name = sp["name"]
        t, v, slip = r.log["time"], -r.log[f"vz_mean:{name}"], r.log[f"slip_z_mean:{name}"]
        ref = np.array([st.speed(x) for x in t])
        dev = (v - ref) / st.v_terminal
        early = t <= 3 * st.t_relax
        i = int(np.argmax(np.abs(dev[early])))
        rows = [
            Row(self.name, "v(t), t ≤ 3 t_d: max |v − v₄.₁| / v_T" + preset,
                f"0 (v_T = {st.v_terminal * 1e3:.4g} mm/s, t_d = {st.t_relax * 1e3:.4g} ms)", "Stokes transient (4.1)",
                f"{100 * abs(dev[early][i]):.2f} % at t = {t[early][i] * 1e3:.2f} ms", abs(dev[early][i]),
                self.TARGET_TRANSIENT, r, kind="comparison", reference_kind="own-closure",
                note="(4.1) is the solver's own model of the start: Stokes drag without added mass or Basset "
                     "history, which the solver leaves out too"),
            Row(self.name, f"superficial slip at t = {t[-1] * 1e3:.3g} ms ({t[-1] / st.t_relax:.1f} t_d){preset}",
                f"{ref[-1] * 1e3:.4g} mm/s", "Stokes transient (4.1) at that time (drag sees the slip)",
                f"{slip[-1] * 1e3:.4g} mm/s", slip[-1] / ref[-1] - 1, self.TARGET_SLIP, r, kind="comparison",
                reference_kind="independent"),
            Row(self.name, f"sphere speed v at t = {t[-1] * 1e3:.3g} ms{preset}",
                f"{ref[-1] * 1e3:.4g} mm/s", "Stokes transient (4.1)",
                f"{v[-1] * 1e3:.4g} mm/s", v[-1] / ref[-1] - 1, self.TARGET_V_END, r, kind="comparison",
                reference_kind="independent",
                note="v exceeds the slip by the fluid the sphere's own reaction drags along "
                     "(self-induced velocity of unresolved coupling); target of issue 2"),
        ]
        if ctx is None:
            return rows
        fig, ax = plt.subplots(figsize=(6, 4))
        tt = np.linspace(0, t[-1], 400)
        ax.plot(tt * 1e3, [st.speed(x) * 1e3 for x in tt], "k-", label="Stokes transient (4.1)")
        ax.plot(t * 1e3, v * 1e3, "o", ms=3, label="sphdem: sphere speed −v_z")
        ax.plot(t * 1e3, slip * 1e3, "x", ms=3, label="sphdem: superficial slip")
        ax.axvline(3 * st.t_relax * 1e3, color="grey", ls=":", label="3 t_d")
        ax.set_xlabel("t (ms)")
        ax.set_ylabel("speed (mm/s)")
        ax.set_title(f"single sphere, {r.resolution()}")
        ax.legend()
        ctx.save(fig, "single_particle_vt.png")
        return rows
