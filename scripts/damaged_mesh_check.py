#!/usr/bin/python3
"""Runs `vdc mesh check` on randomly damaged copies of a mesh file and counts the outcomes.

    scripts/damaged_mesh_check.py VDC MESH [--copies 150] [--seed 1] [--timeout 20]

Each copy is the original with bytes overwritten, cut short, or a stretch of itself spliced in
(a fixed seed makes the copies the same every run). The verdict per copy: loaded (exit 0),
refused (exit 1 with one 'vdc: ' line naming the file), crashed (killed by a signal, or any
other exit), hung (still running after --timeout seconds). Exit status 1 if any copy crashed,
hung or was refused without naming the file. Not a CI test (the gtest suite loads damaged copies
in-process); a reproducible check of the loader as a user would run it.
"""
import argparse
import collections
import os
import random
import subprocess
import sys
import tempfile


def damaged(original, rng):
    data = bytearray(original)
    kind = rng.choice(["flip", "cut", "splice"])
    if kind == "flip":
        for _ in range(rng.randint(1, 16)):
            data[rng.randrange(len(data))] = rng.randrange(256)
    elif kind == "cut":
        data = data[:rng.randrange(1, len(data))]
    else:
        start = rng.randrange(len(data))
        length = rng.randint(1, min(4096, len(data) - start))
        at = rng.randrange(len(data))
        data[at:at] = data[start:start + length]
    return kind, bytes(data)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("vdc")
    parser.add_argument("mesh")
    parser.add_argument("--copies", type=int, default=150)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=20.0)
    args = parser.parse_args()

    with open(args.mesh, "rb") as f:
        original = f.read()
    rng = random.Random(args.seed)
    extension = os.path.splitext(args.mesh)[1]
    verdicts = collections.Counter()
    bad = []
    with tempfile.TemporaryDirectory() as directory:
        for n in range(args.copies):
            kind, data = damaged(original, rng)
            path = os.path.join(directory, "copy%03d%s" % (n, extension))
            with open(path, "wb") as f:
                f.write(data)
            try:
                run = subprocess.run([args.vdc, "mesh", "check", path], capture_output=True,
                                     text=True, errors="replace", timeout=args.timeout)
            except subprocess.TimeoutExpired:
                verdicts["hung"] += 1
                bad.append((n, kind, "hung"))
                continue
            stderr_lines = [l for l in run.stderr.splitlines() if l.startswith("vdc: ")]
            if run.returncode == 0:
                verdicts["loaded"] += 1
            elif run.returncode == 1 and len(stderr_lines) == 1 and path in stderr_lines[0]:
                verdicts["refused"] += 1
            elif run.returncode == 1:
                verdicts["refused without naming the file"] += 1
                bad.append((n, kind, run.stderr.strip()))
            else:
                verdicts["crashed"] += 1
                bad.append((n, kind, "exit %d" % run.returncode))
    for n, kind, what in bad[:20]:
        print("copy %d (%s): %s" % (n, kind, what))
    print(", ".join("%d %s" % (verdicts[k], k) for k in
                    ["loaded", "refused", "refused without naming the file", "crashed", "hung"]))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
