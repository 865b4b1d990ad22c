#!/usr/bin/python3
"""Figures from the reduced in-situ data of one sphdem run.

Usage:  /usr/bin/python3 pipelines/figures.py DIR

DIR is a run directory, finished or interrupted. The script reads DIR/insitu/:

  voidage_height.h5   datasets time (nt,) [s], z (nz,) [m, cell centres],
                      voidage (nt, nz); optional file attributes
                      reference_interface_velocity [m/s], column_height [m]
  interfaces.csv      time,z_top,z_bottom            [s, m, m]; nan = not found
  com.csv             time,com_z:S1,...,com_z:all,vz_mean:S..,front_z:S..    [s, m, m/s]

and writes DIR/figures/:

  voidage_height_time.png   voidage map (time x height) with both interfaces and,
                            when the h5 file gives reference_interface_velocity,
                            the Kynch line z = z_top(t0) - v_ref (t - t0)
  interfaces.png            z_top and z_bottom against time (same Kynch line)
  com_tracks.png            centre-of-mass height of each species and of all
  fluidisation_curve.png    a bed in a column periodic in z (from DIR/log.csv):
                            pressure drop against U, rising and falling branches,
                            the bed's buoyant weight per area, the plateau, U_mf
  bed_height.png            the bed's height and U against time

Any input may be missing, empty, header-only or have a single row (an interrupted
run): the figure that needs it is skipped with one message on stderr.
Exit status: 0 if at least one figure was written, 1 if none, 2 for a bad DIR.

Importable: make_figures(run_dir) returns the list of written paths and raises
BadRunDir for a bad DIR.
"""

import csv
import math
import os
import re
import sys
import warnings

import numpy as np
import matplotlib
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib import patheffects

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fluidisation  # noqa: E402  (U_mf's construction, shared with validation/fluidised_bed.py)

FIGSIZE = (7.0, 4.5)   # inches
DPI = 120
MAP_CMAP = "viridis"   # perceptually uniform
M_TO_MM = 1e3
S_TO_MS = 1e3

MAP_PNG = "voidage_height_time.png"
INTERFACES_PNG = "interfaces.png"
COM_PNG = "com_tracks.png"
FLUIDISATION_PNG = "fluidisation_curve.png"
BED_HEIGHT_PNG = "bed_height.png"


class BadRunDir(Exception):
    """DIR is not a usable run directory (missing, not a directory, no insitu/)."""


class Skip(Exception):
    """An input cannot give a figure; the message says why."""


def _warn(msg):
    print("figures: " + msg, file=sys.stderr)


# --------------------------------------------------------------------------- inputs

def scene_name(run_dir):
    """The scene name from DIR/case.yaml (key `name`), else the directory name."""
    fallback = os.path.basename(os.path.normpath(os.path.abspath(run_dir))) or "run"
    path = os.path.join(run_dir, "case.yaml")
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
    except OSError:
        return fallback
    name = None
    try:
        import yaml  # PyYAML, present for Debian's python3 but not required
        doc = yaml.safe_load(text)
        if isinstance(doc, dict) and doc.get("name") is not None:
            name = str(doc["name"]).strip()
    except Exception:  # no yaml module, or a file it cannot parse
        name = None
    if name is None:
        # Tiny parser: a top-level `name: value` line, optional quotes and comment.
        for line in text.splitlines():
            m = re.match(r"""^name\s*:\s*(?:"([^"]*)"|'([^']*)'|([^#]*))""", line)
            if m:
                name = next(g for g in m.groups() if g is not None).strip()
                break
    return name if name else fallback


def _sort_by_time(t, *arrays):
    """Rows with a finite time, in increasing time; for a repeated time (a restart
    that wrote the same time again) the last row written wins."""
    t = np.asarray(t, dtype=float)
    rows = np.nonzero(np.isfinite(t))[0]
    # Stable sort of the reversed order, then unique keeps the first = last written.
    rows = rows[::-1]
    rows = rows[np.argsort(t[rows], kind="stable")]
    _, first = np.unique(t[rows], return_index=True)
    rows = rows[first]
    return (t[rows],) + tuple(np.asarray(a)[rows] for a in arrays)


def read_csv_columns(path):
    """A numeric CSV with a header as {column: float array}, in increasing time.

    Rows with the wrong number of fields or a value that is not a number (a line cut
    off when the run was interrupted) are dropped. Raises Skip when the file is
    missing, empty, or has fewer than two usable rows."""
    rel = os.path.join("insitu", os.path.basename(path))
    if not os.path.isfile(path):
        raise Skip(rel + " not found")
    try:
        with open(path, newline="", encoding="utf-8", errors="replace") as f:
            lines = [ln for ln in f if ln.strip() and not ln.lstrip().startswith("#")]
    except OSError as e:
        raise Skip("cannot read %s: %s" % (rel, e))
    if not lines:
        raise Skip(rel + " is empty")
    reader = csv.reader(lines)
    header = [h.strip() for h in next(reader)]
    if "time" not in header:
        raise Skip("%s has no 'time' column (header: %s)" % (rel, ",".join(header)))
    rows = []
    for rec in reader:
        if len(rec) != len(header):
            continue
        try:
            rows.append([float(x) for x in rec])
        except ValueError:
            continue
    if len(rows) < 2:
        raise Skip("%s has %s (need at least 2)" % (
            rel, "only a header" if not rows else "only 1 data row"))
    data = np.array(rows, dtype=float)
    cols = _sort_by_time(data[:, header.index("time")], data)
    t, data = cols
    if t.size < 2:
        raise Skip("%s has fewer than 2 rows with a valid time" % rel)
    out = {h: data[:, i] for i, h in enumerate(header)}
    out["time"] = t
    return out


def _open_h5(h5py, path):
    try:
        # Do not take (or wait for) the HDF5 file lock: the solver may be writing.
        return h5py.File(path, "r", locking=False)
    except (TypeError, ValueError):  # h5py/HDF5 without the locking option
        return h5py.File(path, "r")


def _float_attr(attrs, key):
    """A finite float file attribute, or None when absent / NaN / not a number."""
    if key not in attrs:
        return None
    try:
        v = float(np.asarray(attrs[key], dtype=float).ravel()[0])
    except (TypeError, ValueError, IndexError):
        return None
    return v if math.isfinite(v) else None


def read_voidage(path):
    """dict(time (nt,), z (nz,), voidage (nt, nz), v_ref, column_height) or Skip."""
    rel = os.path.join("insitu", os.path.basename(path))
    if not os.path.isfile(path):
        raise Skip(rel + " not found")
    try:
        import h5py
    except ImportError:
        raise Skip("h5py is not available to read " + rel)
    try:
        with _open_h5(h5py, path) as f:
            missing = [k for k in ("time", "z", "voidage") if k not in f]
            if missing:
                raise Skip("%s has no dataset %s" % (rel, ", ".join(missing)))
            t = np.asarray(f["time"][()], dtype=float).ravel()
            z = np.asarray(f["z"][()], dtype=float).ravel()
            eps = np.asarray(f["voidage"][()], dtype=float)
            v_ref = _float_attr(f.attrs, "reference_interface_velocity")
            height = _float_attr(f.attrs, "column_height")
    except Skip:
        raise
    except Exception as e:  # truncated / corrupt file, not HDF5, ...
        raise Skip("cannot read %s: %s" % (rel, e))
    if eps.ndim == 1 and z.size == 1:
        eps = eps.reshape(-1, 1)
    if eps.ndim != 2 or eps.shape[1] != z.size:
        raise Skip("%s: voidage has shape %s, expected (time, %d)" % (
            rel, eps.shape, z.size))
    # An interrupted run may have extended one dataset and not yet the other.
    n = min(t.size, eps.shape[0])
    t, eps = _sort_by_time(t[:n], eps[:n])
    if t.size < 2:
        raise Skip("%s has %s (need at least 2)" % (
            rel, "no time rows" if t.size == 0 else "only 1 time row"))
    if not np.all(np.isfinite(z)) or z.size < 1:
        raise Skip("%s: z is empty or not finite" % rel)
    order = np.argsort(z, kind="stable")
    z, eps = z[order], eps[:, order]
    if not np.any(np.isfinite(eps)):
        raise Skip("%s: voidage has no finite value" % rel)
    if v_ref is not None and v_ref <= 0:
        v_ref = None
    return dict(time=t, z=z, voidage=eps, v_ref=v_ref, column_height=height)


def _edges(c, floor_at_zero):
    """Cell edges from (sorted) centres; midpoints, the ends extrapolated."""
    c = np.asarray(c, dtype=float)
    if c.size == 1:
        e = np.array([0.0, 2.0 * c[0]] if c[0] > 0 else [c[0] - 0.5, c[0] + 0.5])
    else:
        mid = 0.5 * (c[1:] + c[:-1])
        e = np.concatenate([[c[0] - (mid[0] - c[0])], mid, [c[-1] + (c[-1] - mid[-1])]])
    if floor_at_zero and c[0] >= 0:
        e[0] = max(e[0], 0.0)
    return e


def _first_valid_top(interfaces):
    """(t0, z0) of the first finite z_top, or None."""
    if interfaces is None or "z_top" not in interfaces:
        return None
    ok = np.nonzero(np.isfinite(interfaces["z_top"]))[0]
    if ok.size == 0:
        return None
    i = ok[0]
    return float(interfaces["time"][i]), float(interfaces["z_top"][i])


# --------------------------------------------------------------------------- drawing

def _new_figure():
    fig = Figure(figsize=FIGSIZE, dpi=DPI)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(1, 1, 1)
    ax.tick_params(labelsize=10)
    return fig, ax


def _save(fig, out_dir, name):
    try:
        os.makedirs(out_dir, exist_ok=True)
    except OSError as e:
        raise Skip("cannot create %s: %s" % (out_dir, e))
    path = os.path.join(out_dir, name)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # tight_layout's occasional complaints
        fig.tight_layout()
    try:
        fig.savefig(path, dpi=DPI)
    except OSError as e:
        raise Skip("cannot write %s: %s" % (path, e))
    return path


def _plot_series(ax, t, z, clip_markers=True, **style):
    """A line through the finite values; a value with no finite neighbour (which a
    line alone would not show, e.g. an interface found once) gets a marker, drawn
    whole at the edge of the axes when clip_markers is False."""
    t, z = np.asarray(t, dtype=float), np.asarray(z, dtype=float)
    (line,) = ax.plot(t, z, **style)
    ok = np.isfinite(z)
    prev = np.concatenate([[False], ok[:-1]])
    nxt = np.concatenate([ok[1:], [False]])
    alone = ok & ~prev & ~nxt
    if np.any(alone):
        keep = {k: v for k, v in style.items() if k in ("path_effects", "zorder")}
        ax.plot(t[alone], z[alone], linestyle="none", marker="o",
                markersize=max(4.0, 2.5 * line.get_linewidth()),
                color=line.get_color(), clip_on=clip_markers, **keep)
    return line


def _kynch_label(v_ref):
    return "Kynch: v = %s mm/s" % ("%.3g" % (v_ref * M_TO_MM))


def _draw_kynch(ax, t0z0, v_ref, t_end, z_floor, **style):
    """The line z = z0 - v_ref (t - t0) from t0, in ms/mm, stopped at t_end (s) and
    at the height z_floor (m) so that it stays inside the plot."""
    if t0z0 is None or v_ref is None:
        return False
    t0, z0 = t0z0
    t1 = min(t_end, t0 + max(z0 - z_floor, 0.0) / v_ref)
    if not t1 > t0:
        return False
    t = np.array([t0, t1])
    ax.plot(t * S_TO_MS, (z0 - v_ref * (t - t0)) * M_TO_MM, linestyle=":",
            label=_kynch_label(v_ref), **style)
    return True


def figure_map(vh, interfaces, title, out_dir):
    t, z, eps = vh["time"], vh["z"], vh["voidage"]
    te, ze = _edges(t, True), _edges(z, True)
    fin = eps[np.isfinite(eps)]
    lo, hi = float(fin.min()), float(fin.max())
    vmax = min(hi, 1.0)
    vmin = max(min(lo, vmax), 0.0)
    if vmax - vmin < 1e-6:  # uniform field: give the colour bar some range
        vmin = max(vmax - 0.05, 0.0)
        if vmax - vmin < 1e-6:
            vmax = vmin + 0.05
    extend = {(False, False): "neither", (True, False): "min",
              (False, True): "max", (True, True): "both"}[(lo < vmin, hi > vmax)]

    fig, ax = _new_figure()
    cmap = matplotlib.colormaps[MAP_CMAP].with_extremes(bad="0.8")
    mesh = ax.pcolormesh(te * S_TO_MS, ze * M_TO_MM, np.ma.masked_invalid(eps).T,
                         cmap=cmap, vmin=vmin, vmax=vmax, shading="flat")
    cb = fig.colorbar(mesh, ax=ax, extend=extend, pad=0.02)
    cb.set_label("voidage ε (–)", fontsize=11)
    xlim = (te[0] * S_TO_MS, te[-1] * S_TO_MS)
    ylim = (ze[0] * M_TO_MM, ze[-1] * M_TO_MM)

    # Lines over the map: white with a dark outline, visible on dark and light cells.
    halo = [patheffects.Stroke(linewidth=3.2, foreground="black"), patheffects.Normal()]
    drawn = False
    if interfaces is not None:
        ti = interfaces["time"] * S_TO_MS
        for key, ls, label in (("z_top", "-", "z_top (upper interface)"),
                               ("z_bottom", "--", "z_bottom (sediment top)")):
            if key in interfaces and np.any(np.isfinite(interfaces[key])):
                _plot_series(ax, ti, interfaces[key] * M_TO_MM, color="white",
                             linestyle=ls, linewidth=1.6, label=label,
                             path_effects=halo)
                drawn = True
    drawn |= _draw_kynch(ax, _first_valid_top(interfaces), vh["v_ref"], te[-1], ze[0],
                         color="#ff4040", linewidth=2.2, path_effects=[
                             patheffects.Stroke(linewidth=3.6, foreground="black"),
                             patheffects.Normal()])
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    if drawn:
        leg = ax.legend(loc="upper right", fontsize=9, framealpha=0.85)
        leg.get_frame().set_facecolor("white")
    ax.set_xlabel("time t (ms)", fontsize=11)
    ax.set_ylabel("height z (mm)", fontsize=11)
    ax.set_title("%s: laterally averaged voidage" % title, fontsize=12)
    return _save(fig, out_dir, MAP_PNG)


def figure_interfaces(interfaces, v_ref, z_max, title, out_dir):
    if not any(k in interfaces and np.any(np.isfinite(interfaces[k]))
               for k in ("z_top", "z_bottom")):
        raise Skip("insitu/interfaces.csv: no interface found at any time (all nan)")
    t = interfaces["time"]
    fig, ax = _new_figure()
    for key, ls, color, label in (("z_top", "-", "C0", "z_top (upper interface)"),
                                  ("z_bottom", "--", "C1", "z_bottom (sediment top)")):
        if key in interfaces and np.any(np.isfinite(interfaces[key])):
            _plot_series(ax, t * S_TO_MS, interfaces[key] * M_TO_MM, False,
                         linestyle=ls, color=color, linewidth=2.0, label=label)
    vals = np.concatenate([interfaces[k][np.isfinite(interfaces[k])]
                           for k in ("z_top", "z_bottom") if k in interfaces])
    top = max(float(vals.max()), 0.0)
    if z_max is not None and z_max > top:
        top = z_max
    top = top * 1.05 if top > 0 else 1e-3
    bottom = min(float(vals.min()), 0.0)
    _draw_kynch(ax, _first_valid_top(interfaces), v_ref, t[-1], bottom,
                color="0.25", linewidth=1.8)
    ax.set_xlim(t[0] * S_TO_MS, t[-1] * S_TO_MS)
    ax.set_ylim(bottom * M_TO_MM, top * M_TO_MM)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=9)
    ax.set_xlabel("time t (ms)", fontsize=11)
    ax.set_ylabel("interface height z (mm)", fontsize=11)
    ax.set_title("%s: interfaces" % title, fontsize=12)
    return _save(fig, out_dir, INTERFACES_PNG)


def figure_com(com, title, out_dir):
    species = [k for k in com if k.startswith("com_z:") and k != "com_z:all"]
    series = [(k.split(":", 1)[1], com[k]) for k in species
              if np.any(np.isfinite(com[k]))]
    has_all = "com_z:all" in com and np.any(np.isfinite(com["com_z:all"]))
    if not series and not has_all:
        raise Skip("insitu/com.csv has no com_z:S column with a finite value")
    t = com["time"] * S_TO_MS
    fig, ax = _new_figure()
    if has_all:  # underneath, so that a species equal to it stays visible
        _plot_series(ax, t, com["com_z:all"] * M_TO_MM, False, color="black",
                     linewidth=3.5, label="all", zorder=2)
    colors = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, (name, z) in enumerate(series):
        _plot_series(ax, t, z * M_TO_MM, False, color=colors[i % len(colors)],
                     linewidth=1.8, label=name, zorder=3)
        front = com.get("front_z:" + name)  # the species' suspension front, when recorded
        if len(series) > 1 and front is not None and np.any(np.isfinite(front)):
            _plot_series(ax, t, front * M_TO_MM, False, color=colors[i % len(colors)],
                         linewidth=1.0, linestyle="--", label=name + " front", zorder=3)
    ax.set_xlim(t[0], t[-1])
    ax.grid(True, alpha=0.3)
    handles, labels = ax.get_legend_handles_labels()
    if has_all:  # species first, "all" last
        handles, labels = handles[1:] + handles[:1], labels[1:] + labels[:1]
    ax.legend(handles, labels, loc="best", fontsize=9, title="species",
              title_fontsize=9, ncol=1 if len(labels) <= 6 else 2)
    ax.set_xlabel("time t (ms)", fontsize=11)
    ax.set_ylabel("centre of mass (—), suspension front (--) z (mm)" if len(series) > 1
                  else "centre-of-mass height z (mm)", fontsize=11)
    ax.set_title("%s: centre-of-mass height" % title, fontsize=12)
    return _save(fig, out_dir, COM_PNG)


def _fluidised(log):
    """The log.csv columns of a bed in a column periodic in z, or Skip."""
    need = ("superficial_velocity", "pressure_drop", "bed_height", "bed_weight")
    if log is None or any(k not in log for k in need):
        raise Skip("log.csv has no %s column (an older run)" % "/".join(need))
    if not np.any(log["bed_weight"] > 0):
        raise Skip("no bed on a distributor (log.csv bed_weight is 0)")
    return log


def figure_fluidisation(log, title, out_dir):
    """Pressure drop against U, the branches where U rises and falls apart, the bed's
    buoyant weight per area, and (fluidisation.py, as validation/fluidised_bed.py reads
    them) the rising branch's fixed-bed fit, U_mf where it meets the weight and the plateau
    over 1.5-5 U_mf."""
    log = _fluidised(log)
    U, dp = log["superficial_velocity"], log["pressure_drop"]
    weight = float(np.nanmedian(log["bed_weight"]))
    dU = np.diff(U, prepend=U[0])
    fig, ax = _new_figure()
    for sel, label, style in ((dU > 0, "U rising", "-"), (dU < 0, "U falling", "--")):
        if np.any(sel):
            ax.plot(U[sel] * M_TO_MM, dp[sel], linestyle=style, marker=".", markersize=3,
                    linewidth=1.2, label=label)
    ax.axhline(weight, color="black", linestyle=":", linewidth=1.2,
               label="buoyant weight per area %.4g Pa" % weight)
    fit = fluidisation.u_mf(U, dp, weight)
    if fit is not None:
        u_mf, a, b = fit
        uu = np.linspace(0.0, u_mf, 50)
        ax.plot(uu * M_TO_MM, a * uu + b * uu * uu, color="grey", linestyle=":", linewidth=1.0,
                label="fixed-bed fit a U + b U²")
        ax.axvline(u_mf * M_TO_MM, color="grey", linestyle="-.", linewidth=1.0,
                   label="U_mf %.3g mm/s (the fit meets the weight)" % (u_mf * M_TO_MM))
        level = fluidisation.plateau(U, dp, u_mf)
        if np.isfinite(level):
            ax.axhline(level, color="grey", linestyle="--", linewidth=0.8,
                       label="plateau %.4g Pa (1.5-5 U_mf, rising)" % level)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="lower right", fontsize=9)
    ax.set_xlabel("superficial velocity U (mm/s)", fontsize=11)
    ax.set_ylabel("pressure drop (Pa)", fontsize=11)
    ax.set_title("%s: fluidisation curve" % title, fontsize=12)
    return _save(fig, out_dir, FLUIDISATION_PNG)


def figure_bed_height(log, title, out_dir):
    """The bed's height and U against time."""
    log = _fluidised(log)
    t = log["time"] * S_TO_MS
    fig, ax = _new_figure()
    ax.plot(t, log["bed_height"] * M_TO_MM, color="black", linewidth=1.6, label="bed height")
    ax.set_xlabel("time t (ms)", fontsize=11)
    ax.set_ylabel("bed height (mm)", fontsize=11)
    ax.grid(True, alpha=0.3)
    twin = ax.twinx()
    twin.plot(t, log["superficial_velocity"] * M_TO_MM, color="tab:blue", linestyle="--",
              linewidth=1.0, label="U")
    twin.set_ylabel("superficial velocity U (mm/s)", fontsize=11, color="tab:blue")
    ax.set_title("%s: bed height" % title, fontsize=12)
    return _save(fig, out_dir, BED_HEIGHT_PNG)


# --------------------------------------------------------------------------- driver

def make_figures(run_dir):
    """Write the figures of run_dir into run_dir/figures; return the written paths.

    A figure whose input is missing or too short is skipped with one message on
    stderr. Raises BadRunDir when run_dir is not a run directory with insitu/."""
    run_dir = os.fspath(run_dir)
    if not os.path.isdir(run_dir):
        raise BadRunDir("%s is not a directory" % run_dir)
    insitu = os.path.join(run_dir, "insitu")
    if not os.path.isdir(insitu):
        raise BadRunDir("%s has no insitu/ directory (not a run directory, or the "
                        "run wrote no in-situ data)" % run_dir)
    out_dir = os.path.join(run_dir, "figures")
    title = scene_name(run_dir)

    def load(reader, name):
        try:
            return reader(os.path.join(insitu, name)), None
        except Skip as e:
            return None, str(e)

    vh, vh_err = load(read_voidage, "voidage_height.h5")
    itf, itf_err = load(read_csv_columns, "interfaces.csv")
    if itf is not None and not ("z_top" in itf or "z_bottom" in itf):
        itf, itf_err = None, "insitu/interfaces.csv has no z_top/z_bottom column"
    com, com_err = load(read_csv_columns, "com.csv")

    written = []

    def attempt(png, err, draw):
        if err is not None:
            _warn("skipped %s: %s" % (png, err))
            return
        try:
            written.append(draw())
        except Skip as e:
            _warn("skipped %s: %s" % (png, e))
        except Exception as e:  # odd data must not cost the other figures
            _warn("skipped %s: unexpected %s: %s" % (png, type(e).__name__, e))

    attempt(MAP_PNG, vh_err, lambda: figure_map(vh, itf, title, out_dir))
    attempt(INTERFACES_PNG, itf_err, lambda: figure_interfaces(
        itf, vh["v_ref"] if vh else None,
        (vh["column_height"] if vh and vh["column_height"] else None), title, out_dir))
    attempt(COM_PNG, com_err, lambda: figure_com(com, title, out_dir))
    try:  # a bed in a column periodic in z: from the run's log.csv
        log = read_csv_columns(os.path.join(run_dir, "log.csv"))
    except Skip:
        log = None
    if log is not None and "bed_weight" in log and np.any(log["bed_weight"] > 0):
        attempt(FLUIDISATION_PNG, None, lambda: figure_fluidisation(log, title, out_dir))
        attempt(BED_HEIGHT_PNG, None, lambda: figure_bed_height(log, title, out_dir))
    return written


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__.split("\n\n")[1].strip(), file=sys.stderr)
        return 2
    try:
        written = make_figures(argv[1])
    except BadRunDir as e:
        _warn(str(e))
        return 2
    for p in written:
        print(p)
    if not written:
        _warn("no figure written")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
