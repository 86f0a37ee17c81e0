#!/usr/bin/env bash
# Fetches the evaluation's "objects no one tuned for" (doc/evaluation.md) from Debian's archive and
# writes each as an OFF mesh in metres, centred on its bounding box and scaled to household size.
# The meshes are CGAL's sample data, shipped in bookworm's libcgal-demo as
# usr/share/doc/libcgal-dev/data.tar.gz (CC0 1.0 by libcgal-dev's debian/copyright: files without
# their own copyright notice). apt-get download only: nothing is installed.
# Idempotent: a mesh already in the cache is kept.
# Usage: scripts/fetch_evaluation_objects.sh CACHE_DIR
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 CACHE_DIR" >&2
  exit 2
fi
cache=$1
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)

# name  member of data.tar.gz  largest extent [m]
objects=(
  "elephant data/meshes/elephant.off 0.20"
  "spool data/meshes/spool.off 0.12"
  "helmet data/meshes/helmet.off 0.20"
)

missing=0
for entry in "${objects[@]}"; do
  read -r name _ _ <<<"$entry"
  [[ -s "$cache/$name.off" ]] || missing=1
done
if [[ $missing -eq 0 ]]; then
  echo "fetch_evaluation_objects: all meshes present in $cache"
  exit 0
fi

shopt -s nullglob
debs=("$cache"/libcgal-demo_*.deb)
if [[ ${#debs[@]} -eq 0 ]]; then
  (cd "$cache" && apt-get download libcgal-demo)
  debs=("$cache"/libcgal-demo_*.deb)
fi
if [[ ${#debs[@]} -eq 0 ]]; then
  echo "fetch_evaluation_objects: apt-get download libcgal-demo left no .deb in $cache" >&2
  exit 1
fi
deb=${debs[0]}
mkdir -p "$cache/unpacked"
dpkg-deb --fsys-tarfile "$deb" |
  tar -x -C "$cache/unpacked" ./usr/share/doc/libcgal-dev/data.tar.gz
data_tar=$cache/unpacked/usr/share/doc/libcgal-dev/data.tar.gz

for entry in "${objects[@]}"; do
  read -r name member extent <<<"$entry"
  [[ -s "$cache/$name.off" ]] && continue
  tar -xzf "$data_tar" -C "$cache/unpacked" "$member"
  # Rescales an ASCII OFF: the vertex lines are rewritten, the faces kept as they are.
  python3 - "$cache/unpacked/$member" "$cache/$name.off" "$extent" <<'EOF'
import sys

src, dst, extent = sys.argv[1], sys.argv[2], float(sys.argv[3])
lines = [l.split("#")[0].strip() for l in open(src)]
lines = [l for l in lines if l]
if lines[0] != "OFF":
    sys.exit(f"{src}: expected a plain 'OFF' header, got '{lines[0]}'")
nv, nf = (int(x) for x in lines[1].split()[:2])
vertices = [[float(x) for x in l.split()[:3]] for l in lines[2 : 2 + nv]]
lo = [min(v[i] for v in vertices) for i in range(3)]
hi = [max(v[i] for v in vertices) for i in range(3)]
scale = extent / max(h - l for h, l in zip(hi, lo))
centre = [(h + l) / 2 for h, l in zip(hi, lo)]
with open(dst, "w") as out:
    out.write(f"OFF\n{nv} {nf} 0\n")
    for v in vertices:
        out.write(" ".join(f"{(v[i] - centre[i]) * scale:.6f}" for i in range(3)) + "\n")
    out.write("\n".join(lines[2 + nv : 2 + nv + nf]) + "\n")
EOF
  echo "fetch_evaluation_objects: $cache/$name.off (from libcgal-demo $member, largest extent $extent m)"
done
