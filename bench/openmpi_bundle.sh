#!/usr/bin/env bash
# Bundles Debian's Open MPI (mpirun, its components, PMIx) and the libraries a program
# needs into DIR, for running the MPI benchmarks on a machine of the same architecture
# without Open MPI installed (a lent 16-core machine, bench/RESULTS.md session 29). There:
#   source DIR/env.sh && mpirun -np 16 --bind-to core DIR/PROGRAM ARGS
#
#   bash bench/openmpi_bundle.sh DIR PROGRAM...
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,8p' "$0"; exit 2; }
dir=$1; shift
usr=$dir/ompi/usr arch=/usr/lib/x86_64-linux-gnu
mkdir -p "$dir/lib" "$usr/bin" "$usr/lib/x86_64-linux-gnu" "$usr/share"
cp /usr/bin/orterun "$usr/bin/" && ln -sf orterun "$usr/bin/mpirun"
cp -a $arch/openmpi $arch/pmix2 "$usr/lib/x86_64-linux-gnu/"
cp -a /usr/share/openmpi "$usr/share/"
rm -rf "$usr"/lib/x86_64-linux-gnu/{openmpi,pmix2}/include "$usr"/lib/x86_64-linux-gnu/pmix2/lib/*.a
# the libraries of the programs and of mpirun, but the C and C++ runtimes the target has
for f in "$@" /usr/bin/orterun; do
  [ "$f" = /usr/bin/orterun ] || cp "$f" "$dir/"
  ldd "$f" | awk '/=> \//{print $3}' | grep -v -E '/(libc|libm|libstdc\+\+|libgcc_s|libdl|libpthread|librt)\.so' |
    while read -r l; do cp -L -n "$l" "$dir/lib/"; done
done
for l in libatomic.so.1 libnuma.so.1 libuuid.so.1; do cp -L -n $arch/$l "$dir/lib/" 2>/dev/null || true; done
cat >"$dir/env.sh" <<'ENV'
D=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
export OPAL_PREFIX=$D/ompi/usr PMIX_INSTALL_PREFIX=$D/ompi/usr/lib/x86_64-linux-gnu/pmix2
export PATH=$D/ompi/usr/bin:$PATH
export LD_LIBRARY_PATH=$D/lib:$D/ompi/usr/lib/x86_64-linux-gnu/openmpi/lib:$D/ompi/usr/lib/x86_64-linux-gnu/pmix2/lib
export OMPI_MCA_mca_base_component_show_load_errors=0 PMIX_MCA_mca_base_component_show_load_errors=0
export PMIX_MCA_pcompress_base_silence_warning=1 OMPI_MCA_btl=self,vader OMPI_MCA_pml=ob1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
ENV
du -sh "$dir"
