"""Scene block_monodisperse (thesis §4.5): a rigid block at constant voidage against the Di
Felice slip (4.4), its face effect (a taller block, the infinite-block limit), and the
error-versus-h/d curve."""
import theory

from ..figures import plt
from ..rows import Row, failed_run_rows
from ..runs import Run
from .common import face_extrapolation, time_average, whole_periods


class BlockMonodisperse:
    """Thesis §4.5: rigid block at constant voidage against the Di Felice slip (4.4), and
    the error-versus-h/d curve. The slip is averaged over whole acoustic periods 4H/c0
    of the column after the start-up transient, as tests/validation/block_validation.cpp."""
    name = "block_monodisperse"
    case = "cases/block_monodisperse.yaml"
    TARGET = 0.04            # issue 4: under 4 % at h/d = 2
    # h/d sweep: every spacing must divide the periodic width and the width must hold
    # 4.8 sigma dx, so the sweep runs in a 4.8 mm box (4.8 mm / dx = 32, 24, 16, 12, 8).
    SWEEP_WIDTH = 0.0048
    SWEEP = {"reduced": (4, 6), "full": (1.5, 2, 3, 4, 6)}   # reduced: the two cheap points
    THESIS_ERROR = {2: 0.043, 6: 0.14}   # physics.md §5
    STARTUP = 0.003
    LONG_END = 0.06
    # Why a block misses (4.4): (4.4) is the slip of an unbounded block; the kernel smooths
    # the voidage over the faces of the case's 2 mm block, so its outer sphere layers see
    # clear water and the block falls faster. The evidence: the infinite-block limit of the
    # block and its taller twin (face_rows) within the target.
    FACES = "the finite block's kernel-smeared faces: a block without faces (the infinite-block limit) meets (4.4)"
    # issue 38: the matrix's row (ε = 0.8, the infinite-block limit) at every preset; the
    # case runs at the default (balanced), these beside it in the full mode (each sets the
    # keys the case leaves unset: c0, the CFL number, the DEM sub-steps)
    PRESETS = ("fast", "accurate")

    def _sets(self, mode, width=None, hd=None):
        s = {"output.log_interval": 1e-4}
        if mode == "reduced":
            # 2 mm periodic width (the block is laterally infinite either way), 16 ms as
            # block_validation.cpp, and the stiffness a user gets, auto (issue 38: the matrix
            # at the defaults; the case's k = 10 N/m is the thesis's §4.3, which the full
            # mode keeps): the rigid lattice (spacing 1.7 d, 0.4 mm above the wall at the
            # end) has no contact, so k only sets the DEM sub-step, which re-evaluates the
            # drag (relaxation ~1 ms, 50 SPH steps): 2 sub-steps per SPH step at ε 0.9, 4 at
            # ε 0.8 (auto's k 0.12 and 0.48 N/m).
            width = width or 0.002
            s.update({"time.end": 0.016, "contact.stiffness": "auto"})
        if hd:
            # the sweep in both modes (not a matrix row): no contact in a rigid lattice, so
            # k only sets the DEM sub-step; at h/d = 6 the case's k = 10 N/m would cost 50
            # sub-steps per step, auto 6, 0.01 N/m 2.
            # Checked: at eps = 0.9 the mean slip with 5 sub-steps per t_c at k = 10 N/m
            # and with k = 0.01 N/m agree to 1e-5.
            s["contact.stiffness"] = 0.01
        if width:
            s["domain.size"] = f"[{width},{width},0.006]"
            s["particles.0.max"] = f"[{width},{width},0.0045]"
        if hd:
            s["fluid.spacing"] = f"{hd * 1e-4:.6g}"
        return s

    def runs(self, mode):
        out = [Run("block_eps0.9", self.case, self._sets(mode)),
               Run("block_eps0.8", self.case, dict(self._sets(mode), **{"particles.0.voidage": 0.8}))]
        # a block twice as tall (1-5 mm instead of 2.5-4.5 mm): the excess slip comes from
        # the spheres within a kernel support of the block's faces, so it should halve
        for eps in ((0.8,) if mode == "reduced" else (0.9, 0.8)):
            w = 0.002 if mode == "reduced" else 0.004
            out.append(Run(f"block_eps{eps}_tall", self.case,
                           dict(self._sets(mode), **{"particles.0.voidage": eps, "particles.0.min": "[0,0,0.001]",
                                                     "particles.0.max": f"[{w},{w},0.005]"})))
        if mode == "full":
            # ε = 0.8 rings by ±35 % in |v| at a period nearer 8 ms than 4H/c0 = 7 ms, so
            # a mean over two nominal periods depends on the window: both heights again
            # over 60 ms (eight periods)
            for r in [x for x in out if x.key in ("block_eps0.8", "block_eps0.8_tall")]:
                out.append(Run(r.key + "_long", self.case, dict(r.sets, **{"time.end": self.LONG_END})))
                out += [Run(f"{r.key}_{p}", self.case, dict(r.sets, fidelity=p)) for p in self.PRESETS]
        for hd in self.SWEEP[mode]:
            out.append(Run(f"block_sweep_hd{hd:g}", self.case, self._sets(mode, self.SWEEP_WIDTH, hd)))
        return out

    def measure(self, r):
        """(mean slip, reference, eps, window) of one block run."""
        sp = r.species()
        rho_f, mu = r.fluid()
        eps = r.case["particles"][0]["voidage"]
        ref = theory.di_felice_block_slip(sp["diameter"], sp["density"], rho_f, mu, eps, r.g())
        t, slip = r.log["time"], r.log[f"slip_z_mean:{sp['name']}"]
        # whole periods after 3 ms of start-up: the block's slip reaches 63 % of its
        # terminal value at ~0.8 ms (measured, eps = 0.9), so 3 ms is > 3 relaxation times
        t0, t1, n = whole_periods(r, self.STARTUP)
        if n < 1:
            return float("nan"), ref, eps, (t1, t1)
        return time_average(t, slip, t0, t1), ref, eps, (t0, t1)

    def evaluate(self, results, ctx):
        faces, limits = self.face_rows(results)
        rows = []
        fig, ax = plt.subplots(figsize=(6, 4))
        for key in ("block_eps0.9", "block_eps0.8"):
            r = results[key]
            if not r.ok or r.log is None:
                rows += failed_run_rows(self.name, r, key)
                continue
            slip, ref, eps, (t0, t1) = self.measure(r)
            rows.append(Row(self.name, f"mean slip, ε = {eps:g}, t ∈ [{t0 * 1e3:.1f}, {t1 * 1e3:.1f}] ms "
                                       f"({round((t1 - t0) / r.acoustic_period())} × 4H/c0)",
                            f"{ref * 1e3:.4g} mm/s", "Di Felice block slip (4.4)",
                            f"{slip * 1e3:.4g} mm/s", slip / ref - 1, self.TARGET, r, kind="comparison",
                            reference_kind="own-closure", known=self.FACES,
                            evidence=[x for x in limits.get(eps, []) if abs(x.error) <= self.TARGET]))
            # Why the slip exceeds (4.4): with no net volume flux through the column the
            # superficial slip eps_i (u_f - v) equals -v when eps_i = eps, so slip / |v|
            # measures the mean voidage the spheres see, eps_i = eps slip / |v|. It is
            # above eps because the spheres within a kernel support of the block's top
            # and bottom faces see partly clear water. (4.4) at that eps_i:
            v = -time_average(t_log := r.log["time"], r.log[f"vz_mean:{r.species()['name']}"], t0, t1)
            eps_i = eps * slip / v
            sp = r.species()
            rho_f, mu = r.fluid()
            ref_i = theory.di_felice_block_slip(sp["diameter"], sp["density"], rho_f, mu, eps_i, r.g())
            rows.append(Row(self.name, f"same slip against (4.4) at the voidage the spheres see, "
                                       f"ε_i = ε · slip/|v| = {eps_i:.4f} (|v| = {v * 1e3:.4g} mm/s)",
                            f"{ref_i * 1e3:.4g} mm/s", "Di Felice block slip (4.4) at ε_i",
                            f"{slip * 1e3:.4g} mm/s", slip / ref_i - 1, None, r, kind="comparison",
                            reference_kind="own-closure",
                            note="explains the error above: kernel smoothing of ε at the block's faces"))
            t = t_log
            line, = ax.plot(t * 1e3, r.log[f"slip_z_mean:{r.species()['name']}"] * 1e3, label=f"sphdem ε = {eps:g}")
            ax.axhline(ref * 1e3, color=line.get_color(), ls="--", label=f"(4.4) ε = {eps:g}")
            ax.axvspan(t0 * 1e3, t1 * 1e3, color=line.get_color(), alpha=0.08)
        rows += faces
        ax.set_xlabel("t (ms)")
        ax.set_ylabel("superficial slip (mm/s)")
        ax.set_title("rigid block: slip against Di Felice (4.4); shaded: averaging window")
        ax.legend(fontsize=8)
        ctx.save(fig, "block_slip.png")
        return rows + self.sweep_rows(results, ctx)

    def face_rows(self, results):
        """The finite block's face effect, error(H_b) = a + b / H_b from the two block heights:
        the rows, and the infinite-block limits a by ε (the evidence of a missed target)."""
        rows, limits = [], {}
        for eps, suffix in ((0.9, ""), (0.8, ""), (0.8, "_long")) + tuple((0.8, "_" + p) for p in self.PRESETS):
            short, tall = results.get(f"block_eps{eps}{suffix}"), results.get(f"block_eps{eps}_tall{suffix}")
            if tall is None or short is None:
                continue
            if not tall.ok or tall.log is None or not short.ok or short.log is None:
                rows += failed_run_rows(self.name, tall, f"block_eps{eps}_tall")
                continue
            h1, e1, h2, e2, a, b = face_extrapolation(short, tall, lambda r: self.measure(r)[:2])
            s2, ref, _, (t0, t1) = self.measure(tall)
            window = ""
            if suffix == "_long":
                window = f", {t1 * 1e3:.0f} ms runs (window {t0 * 1e3:.1f}–{t1 * 1e3:.1f} ms)"
            elif suffix:
                window = f", preset {suffix[1:]}"
            rows.append(Row(self.name, f"ε = {eps:g}, block {h2 * 1e3:.3g} mm tall instead of {h1 * 1e3:.3g} mm: mean "
                                       f"slip{window}", f"{ref * 1e3:.4g} mm/s", "Di Felice block slip (4.4)",
                            f"{s2 * 1e3:.4g} mm/s", e2, None, tall, kind="comparison", reference_kind="own-closure",
                            note=f"the face effect should halve: {e1:+.2%} → {e2:+.2%}"))
            limit = Row(self.name, f"ε = {eps:g}, infinite-block limit a of error = a + b/H_b "
                                   f"(H_b = {h1 * 1e3:.3g}, {h2 * 1e3:.3g} mm; b = {b * 1e3:.3g} % mm){window}",
                        f"{ref * 1e3:.4g} mm/s", "Di Felice block slip (4.4)", f"{ref * (1 + a) * 1e3:.4g} mm/s",
                        a, None, tall, kind="comparison", reference_kind="own-closure",
                        note="extrapolation: the bulk drag against (4.4)" +
                        ("; the same two blocks over eight periods, against the two of the rows above (the "
                         "ε = 0.8 block rings by ±35 % in |v| at a period nearer 8 ms than 4H/c0)" if suffix == "_long"
                         else ""))
            rows.append(limit)
            if suffix in ("", "_long"):  # the evidence of the case's own runs, not another preset's
                limits.setdefault(eps, []).append(limit)
        return rows, limits

    def sweep_rows(self, results, ctx):
        """The error-versus-h/d curve: its rows and its figure."""
        rows, pts = [], []
        for key, r in results.items():
            if not key.startswith("block_sweep_hd"):
                continue
            if not r.ok or r.log is None:
                rows += failed_run_rows(self.name, r, key)
                continue
            slip, ref, eps, (t0, t1) = self.measure(r)
            hd = r.hd()
            err = slip / ref - 1
            pts.append((hd, err))
            target = self.TARGET if abs(hd - 2) < 1e-9 else None
            v = -time_average(r.log["time"], r.log[f"vz_mean:{r.species()['name']}"], t0, t1)
            note = f"ε_i = ε · slip/|v| = {eps * slip / v:.4f}"
            if not target:
                note += "; curve point (thesis: 4.3 % at h/d = 2, 14 % at 6)"
            rows.append(Row(self.name, f"h/d sweep ({self.SWEEP_WIDTH * 1e3:g} mm box): mean slip, ε = {eps:g}",
                            f"{ref * 1e3:.4g} mm/s", "Di Felice block slip (4.4)",
                            f"{slip * 1e3:.4g} mm/s", err, target, r, kind="comparison", reference_kind="own-closure",
                            note=note))
        if pts:
            pts.sort()
            fig, ax = plt.subplots(figsize=(5, 4))
            ax.plot([p[0] for p in pts], [100 * p[1] for p in pts], "o-",
                    label=f"sphdem, {self.SWEEP_WIDTH * 1e3:g} mm box")
            main = results.get("block_eps0.9")
            if main is not None and main.ok and main.log is not None:
                slip, ref, _, _ = self.measure(main)
                w = main.case["domain"]["size"][0]
                ax.plot([main.hd()], [100 * (slip / ref - 1)], "D", label=f"sphdem, {w * 1e3:g} mm box (row above)")
            ax.plot(list(self.THESIS_ERROR), [100 * e for e in self.THESIS_ERROR.values()], "s",
                    mfc="none", label="thesis (|error|)")
            ax.axhspan(-100 * self.TARGET, 100 * self.TARGET, color="g", alpha=0.1, label="±4 %")
            ax.axhline(0, color="k", lw=0.5)
            ax.set_xlabel("h/d = dx/d")
            ax.set_ylabel("slip error against (4.4) (%)")
            ax.set_title("rigid block ε = 0.9: error versus resolution")
            ax.legend(fontsize=8)
            ctx.save(fig, "block_error_vs_hd.png")
        return rows
