#!/usr/bin/env bash
# Test insitu_snapshots_on_ranks: `mpirun -np 2 sphdem run` with output.vtk.every writes each
# rank's piece and, per frame, a .pvtp index of the pieces; ParaView (pvpython) opens the
# .pvd time collections as one dataset with every fluid particle and every sphere.
#
#   snapshots_on_ranks.sh SPHDEM CASE WORK_DIR
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: $0 SPHDEM CASE WORK_DIR" >&2; exit 2; }
bin=$1 case=$2 work=$3
readme=$(cd "$(dirname "$0")/../.." && pwd)/pipelines/README.md
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMP_NUM_THREADS=1
rm -rf "$work"; mkdir -p "$work"; cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
env -u DISPLAY mpirun -np 2 "$bin" run "$case" --out out --no-insitu --set time.end=0.001 \
  --set output.vtk.every=0.0005 --set startup.relax_steps=2 >run.log 2>&1 || { cat run.log; fail "run"; }
fluid=$(sed -n 's/.* \([0-9]*\) fluid + \([0-9]*\) wall SPH particles, \([0-9]*\) spheres.*/\1 \2 \3/p' run.log)
read -r nf nw ns <<<"$fluid"
[ -n "$ns" ] || fail "no particle counts in the run's first line"
[ "$(ls out/vtk/fluid_*.pvtp | wc -l)" -eq 3 ] || fail "expected 3 fluid .pvtp indexes"
cat > read.py <<'PY'
import re
import sys
from paraview.simple import PVDReader, servermanager
# The point arrays of each collection against the channel's list in pipelines/README.md
# (the backticked names of its bullet; `species_names` is a field array named there).
readme = open(sys.argv[2]).read()
for name in ("fluid", "particles"):
    r = PVDReader(FileName=sys.argv[1] + "/" + name + ".pvd")
    r.UpdatePipeline(r.TimestepValues[-1])
    data = servermanager.Fetch(r)
    print(name, len(r.TimestepValues), data.GetNumberOfPoints())
    bullet = re.search(r"^- `%s` \(vtkPolyData\):(.*?)(?=^- )" % name, readme, re.S | re.M).group(1)
    listed = set(re.findall(r"`(\w+)`", bullet)) - {"species_names"}
    pd = data.GetPointData()
    written = {pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())}
    if listed != written:
        print(f"{name}: arrays written {sorted(written)}, pipelines/README.md lists {sorted(listed)}")
PY
pvpython=$(command -v pvpython || echo /usr/bin/pvpython)
env -u DISPLAY timeout 120 "$pvpython" --force-offscreen-rendering read.py out/vtk "$readme" >read.log 2>&1 ||
  { cat read.log; fail "pvpython"; }
cat read.log
grep -qx "fluid 3 $((nf + nw))" read.log || fail "the fluid collection is not 3 frames of $((nf + nw)) points"
grep -qx "particles 3 $ns" read.log || fail "the sphere collection is not 3 frames of $ns points"
! grep -q "arrays written" read.log || fail "the arrays differ from pipelines/README.md's channels"
echo "ok: 2 ranks' pieces open in ParaView as one dataset: $((nf + nw)) fluid, $ns spheres"
