#!/usr/bin/env bash
# Fetches CGAL sample meshes that are NOT in the scene evaluation's library, as unknown
# distractors for `vdc evaluate-scenes` (doc/evaluation.md, "Scenes with several objects"): the
# same source as scripts/fetch_evaluation_objects.sh (bookworm's libcgal-demo, CC0 1.0 sample
# data), written as OFF meshes in metres, centred on their bounding box and scaled to household
# size. homer.off and bunny00.off are never used: they are kept back for checking.
# Idempotent: a mesh already in the cache is kept.
# Usage: scripts/fetch_scene_distractors.sh CACHE_DIR
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 CACHE_DIR" >&2
  exit 2
fi
cache=$(mkdir -p "$1" && cd "$1" && pwd)

# name  member of data.tar.gz  largest extent [m]
objects=(
  "cow data/meshes/cow.off 0.16"
  "camel data/meshes/camel.off 0.16"
)

shopt -s nullglob
debs=("$cache"/libcgal-demo_*.deb)
if [[ ${#debs[@]} -eq 0 ]]; then
  (cd "$cache" && apt-get download libcgal-demo)
  debs=("$cache"/libcgal-demo_*.deb)
fi
data_tar=$cache/unpacked/usr/share/doc/libcgal-dev/data.tar.gz
if [[ ! -s $data_tar ]]; then
  mkdir -p "$cache/unpacked"
  dpkg-deb --fsys-tarfile "${debs[0]}" |
    tar -x -C "$cache/unpacked" ./usr/share/doc/libcgal-dev/data.tar.gz
fi

for entry in "${objects[@]}"; do
  read -r name member extent <<<"$entry"
  [[ -s "$cache/$name.off" ]] && continue
  tar -xzf "$data_tar" -C "$cache/unpacked" "$member"
  # Rescales an ASCII OFF (header possibly followed by its counts on the same line): vertex lines
  # rewritten, faces kept.
  python3 - "$cache/unpacked/$member" "$cache/$name.off" "$extent" <<'PYTHON'
import sys

src, dst, extent = sys.argv[1], sys.argv[2], float(sys.argv[3])
tokens_lines = [l.split("#")[0].split() for l in open(src)]
lines = [t for t in tokens_lines if t]
if lines[0][0] != "OFF":
    sys.exit(f"{src}: expected an 'OFF' header, got '{' '.join(lines[0])}'")
if len(lines[0]) > 1:  # "OFF nv nf ne" on one line
    lines = [["OFF"], lines[0][1:]] + lines[1:]
nv, nf = int(lines[1][0]), int(lines[1][1])
vertices = [[float(x) for x in l[:3]] for l in lines[2 : 2 + nv]]
lo = [min(v[i] for v in vertices) for i in range(3)]
hi = [max(v[i] for v in vertices) for i in range(3)]
scale = extent / max(h - l for h, l in zip(hi, lo))
centre = [(h + l) / 2 for h, l in zip(hi, lo)]
with open(dst, "w") as out:
    out.write(f"OFF\n{nv} {nf} 0\n")
    for v in vertices:
        out.write(" ".join(f"{(v[i] - centre[i]) * scale:.6f}" for i in range(3)) + "\n")
    out.write("\n".join(" ".join(l) for l in lines[2 + nv : 2 + nv + nf]) + "\n")
PYTHON
  echo "fetch_scene_distractors: $cache/$name.off (from libcgal-demo $member, largest extent $extent m)"
done
