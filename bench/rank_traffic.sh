#!/usr/bin/env bash
# What the ranks exchange per step of the coupled solver, against the written model
# (issue 36's weak-scaling model; bench/RESULTS.md, session 32). The monodisperse
# suspension (cases/suspension_monodisperse.yaml) widened in x and y so that each rank owns
# about N particles (fluid + wall + spheres), run for STEPS_TIME on R ranks x 1 thread with
# the multi-rate half step off (every half step then sub-steps every sphere: the model's
# schedule). The run's last lines give the DEM sub-steps per step S, the halo copies per
# owned particle g_f and g_s, and the bytes each rank sent to others per owned particle.
#
# Model (the fills of one step without a list rebuild, read from the code, 8 B a double):
#   fluid copy: x y z vx vy vz rho h 1/h (refresh) + P cs eps omega p_term thx thy thz
#               + the density diffusion's psi and volume                = 19 doubles
#   sphere copy: x y z vx vy vz wx wy wz after the first half step (the fluid passes read
#               them), fmx fmy fmz shepard, the drag gain, and the interpolation's reverse
#               scatter of 12                                           = 26
#               and before each of the S sub-steps' contact passes, for the copies in the
#               contact lists only (c per owned sphere): 9 S
#   bytes / owned / step = 8 (N_f g_f 19 + N_s (26 g_s + 9 S c)) / (N_f + N_s)
# List rebuilds (migration, the halo's build fills) come on top, every ~20-80 steps.
# Usage: bash bench/rank_traffic.sh [BUILD_DIR=build]   (PER_RANK, RANKS to override)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
PER_RANK=${PER_RANK:-"1e4 1e5"}
RANKS=${RANKS:-"2 4"}
STEPS_TIME=${STEPS_TIME:-2e-4}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMP_NUM_THREADS=1
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
echo "commit $(git rev-parse --short HEAD) build $BUILD, $(nproc --all) cores, $(date -u +%FT%TZ)"
for n in $PER_RANK; do
  for R in $RANKS; do
    # the shipped 4 x 4 mm column holds 27 868 particles: 1742 per mm^2 of floor
    L=$(python3 -c "import math; print(round(math.sqrt($R * $n / 1742.0) / 0.2) * 0.2e-3)")
    mpirun -np "$R" "$BUILD/app/sphdem" run cases/suspension_monodisperse.yaml --no-insitu \
      -o "$OUT/o_${n}_$R" --set "domain.size=[$L,$L,0.006]" --set "particles.0.max=[$L,$L,0.0048]" \
      --set time.end="$STEPS_TIME" --set startup.relax_steps=0 --set time.multirate=false \
      --set checkpoint.at_end=false >"$OUT/run_${n}_$R.txt" 2>&1
    rm -rf "$OUT/o_${n}_$R"
  done
done
python3 - "$OUT" "$PER_RANK" "$RANKS" <<'PY'
import re, sys
out, per_rank, ranks = sys.argv[1], sys.argv[2].split(), sys.argv[3].split()
print(f"{'per rank':>8} {'R':>2} {'particles':>9} {'S':>5} {'g_f':>6} {'g_s':>6} {'c':>6} "
      f"{'exch/step':>9} {'coll/step':>9} {'B/owned/step':>12} {'model':>7} {'meas/model':>10}")
for n in per_rank:
    for R in ranks:
        text = open(f"{out}/run_{n}_{R}.txt").read()
        nf, nw, ns = map(int, re.search(r"(\d+) fluid \+ (\d+) wall SPH particles, (\d+) spheres", text).groups())
        m = re.search(r"per step \(([\d.]+) DEM sub-steps\): ([\d.]+) exchanges and ([\d.]+) other "
                      r"collectives a rank, (\d+) bytes sent to other ranks per owned particle; "
                      r"copies of other ranks. particles per owned particle at the end: fluid ([\d.]+), spheres ([\d.]+) "
                      r"\(([\d.]+) in the contact lists", text)
        S, ex, coll, b, gf, gs, c = (float(v) for v in m.groups())
        Nf = nf + nw
        model = 8 * (Nf * gf * 19 + ns * (26 * gs + 9 * S * c)) / (Nf + ns)
        print(f"{n:>8} {R:>2} {Nf + ns:>9} {S:>5.1f} {gf:>6.3f} {gs:>6.3f} {c:>6.3f} {ex:>9.1f} {coll:>9.1f} "
              f"{b:>12.0f} {model:>7.0f} {b / model:>10.3f}")
PY
