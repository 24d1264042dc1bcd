#!/usr/bin/env python3
"""Summarises scripts/build_profile.sh's command_times.tsv: CPU seconds of compiles and links, before and after
run.sh's targets, by target, and the slowest commands."""
import collections
import os
import sys


def target(out):
    """The target a command's output belongs to: CMakeFiles/NAME.dir/... for objects, the file's name for links."""
    parts = out.split("/")
    for p in parts:
        if p.endswith(".dir"):
            return p[:-4]
    return parts[-1]


def main(path):
    part = "run.sh"
    rows = []
    for line in open(path):
        if line.startswith("---"):
            part = "test.sh"
            continue
        cpu, wall, kind, out = line.rstrip("\n").split("\t")
        rows.append((part, float(cpu), float(wall), kind, out))
    build = os.path.dirname(os.path.abspath(path))
    for part in ("run.sh", "test.sh"):
        sel = [r for r in rows if r[0] == part]
        by_kind = collections.Counter()
        count = collections.Counter()
        for r in sel:
            by_kind[r[3]] += r[1]
            count[r[3]] += 1
        print(f"{part}: " + ", ".join(f"{count[k]} {k}s {by_kind[k]:.0f} s CPU" for k in sorted(by_kind)))
    folders = collections.Counter()
    for r in rows:
        folders[(target(r[4]), r[3])] += r[1]
    print("\nCPU seconds by target (compile, link):")
    names = sorted({f for f, _ in folders}, key=lambda f: -(folders[(f, "compile")] + folders[(f, "link")]))
    for f in names:
        print(f"  {f:40s} {folders[(f, 'compile')]:8.0f} {folders[(f, 'link')]:6.0f}")
    print("\nslowest 30 commands (CPU s, wall s):")
    for r in sorted(rows, key=lambda r: -r[1])[:30]:
        rel = os.path.relpath(r[4], build) if os.path.isabs(r[4]) else r[4]
        print(f"  {r[1]:7.1f} {r[2]:7.1f}  {r[3]:7s} {rel}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "build-profile/command_times.tsv")
