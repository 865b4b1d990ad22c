"""A species' suspension front from its spheres (numpy only, no ParaView: com_tracks.py
calls it each analysis, tests/unit/test_fronts.py checks it).

The solid volume is deposited cloud-in-cell on fine layers (FINE per front layer dz), so
the sums add over ranks; the profile the front is read from is that deposit averaged over
a front layer dz (a running mean), sampled every fine layer. Read on the dz layers
themselves (each sphere counted in its layer, the half value interpolated between layer
centres) a front sharper than dz moved in steps of the layer's period: a periodic error of
~0.2 dz, several per cent of a line fit over a fall of one or two layers."""
import numpy as np

FINE = 20   # fine layers per front layer


def layer_volumes(z, vol, species, ns, z_lo, dz, nb):
    """Solid volume per species and layer, shape (ns, nb), deposited cloud-in-cell onto
    the layers' centres z_lo + (k + 1/2) dz; a sphere beyond the first or last centre goes
    whole to that layer. Sums over ranks add (each rank deposits its own spheres)."""
    x = (np.asarray(z) - z_lo) / dz - 0.5
    k = np.floor(x).astype(int)
    w_up = x - k
    lo = np.clip(k, 0, nb - 1)
    up = np.clip(k + 1, 0, nb - 1)
    sp = np.asarray(species).astype(int) * nb
    out = np.bincount(sp + lo, weights=vol * (1 - w_up), minlength=ns * nb)
    out += np.bincount(sp + up, weights=vol * w_up, minlength=ns * nb)
    return out.reshape(ns, nb)


def layer_profile(fine, fine_per_layer=FINE):
    """The fine deposit (one species) averaged over one front layer around each fine
    layer (the mean of fine layers i - w/2 … i + w/2 - 1 for w = fine_per_layer, the ends
    reflected: a constant offset of half a fine layer, which no speed sees)."""
    w = fine_per_layer
    padded = np.concatenate([fine[w - 1::-1], fine, fine[:-w - 1:-1]])
    c = np.cumsum(np.concatenate([[0.0], padded]))
    lo = np.arange(fine.size) + w - w // 2
    return (c[lo + w] - c[lo]) / w


def front_height(frac, c0, z_lo, dz):
    """Highest height where frac (per layer of thickness dz, bottom first) still reaches
    c0 / 2, interpolated linearly between the centres of the layer and the one above."""
    above = np.nonzero(frac >= 0.5 * c0)[0]
    if c0 <= 0 or above.size == 0:
        return float("nan")
    k = above[-1]
    zc = z_lo + (k + 0.5) * dz
    if k + 1 >= frac.size:
        return zc
    f0, f1 = frac[k], frac[k + 1]
    return zc + dz * (f0 - 0.5 * c0) / (f0 - f1)
