#!/usr/bin/env bash
# Fetches CGAL's sample meshes for the evaluation from Debian's archive and writes each as an OFF
# mesh in metres, centred on its bounding box and scaled to household size. Two sets:
#   untuned       the "objects no one tuned for" (doc/evaluation.md): elephant, spool, helmet
#   distractors   unknown objects for `vdc evaluate-scenes` (doc/evaluation.md, "Scenes with
#                 several objects"), none of them in its library: cow, camel
# homer.off and bunny00.off are never used: they are kept back for checking.
# The meshes are CGAL's sample data, shipped in bookworm's libcgal-demo as
# usr/share/doc/libcgal-dev/data.tar.gz (CC0 1.0 by libcgal-dev's debian/copyright: files without
# their own copyright notice). apt-get download only: nothing is installed.
# Idempotent: a mesh already in the cache is kept.
# Usage: scripts/fetch_evaluation_objects.sh CACHE_DIR [untuned|distractors]
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 CACHE_DIR [untuned|distractors]" >&2
  exit 2
fi
cache=$1
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)

# name  member of data.tar.gz  largest extent [m]
case "${2:-untuned}" in
  untuned)
    objects=(
      "elephant data/meshes/elephant.off 0.20"
      "spool data/meshes/spool.off 0.12"
      "helmet data/meshes/helmet.off 0.20"
    ) ;;
  distractors)
    objects=(
      "cow data/meshes/cow.off 0.16"
      "camel data/meshes/camel.off 0.16"
    ) ;;
  *) echo "fetch_evaluation_objects: unknown set '$2' (untuned or distractors)" >&2; exit 2 ;;
esac

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
  # Rescales an ASCII OFF (its counts possibly on the header's line): the vertex lines are
  # rewritten, the faces kept as they are.
  python3 - "$cache/unpacked/$member" "$cache/$name.off" "$extent" <<'EOF'
import sys

src, dst, extent = sys.argv[1], sys.argv[2], float(sys.argv[3])
lines = [l.split("#")[0].strip() for l in open(src)]
lines = [l for l in lines if l]
header = lines[0].split()
if header[0] != "OFF":
    sys.exit(f"{src}: expected an 'OFF' header, got '{lines[0]}'")
if len(header) > 1:  # "OFF nv nf ne" on one line
    lines = ["OFF", " ".join(header[1:])] + lines[1:]
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
