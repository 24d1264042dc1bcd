#!/usr/bin/env python3
"""Scores `eomgen check` on the corpus of real derivations against their answer keys (README.md beside this).

Usage: score.py [--eomgen PATH] [--entries NAME...] [--json OUT] [--write-docs | --check-docs] [--details]
                [--rerun-keys]

Reads each entry's answer key from its key.json (what its key.py printed; --rerun-keys runs every key.py again,
a few minutes of SymPy, and fails when one no longer prints its key.json), runs `eomgen check MODEL
derivation.md [--map-file map.toml] --format json`, matches them line by line and prints the table. --write-docs rewrites the table in docs/checker.md between
the CORPUS markers; --check-docs exits 1 when the table there differs from this run's (what CI runs).
Exit 2 when an entry is broken (a key that does not run, a check that fails or takes over its limit).
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
DOCS = os.path.join(ROOT, "docs", "checker.md")
BEGIN = "<!-- BEGIN CORPUS (tests/checker/corpus/score.py --write-docs rewrites this part) -->"
END = "<!-- END CORPUS -->"
CHECK_LIMIT_S = 60


def entries(names):
    out = []
    for name in sorted(os.listdir(HERE)):
        d = os.path.join(HERE, name)
        if not os.path.isdir(d) or (names and name not in names):
            continue
        if all(os.path.isfile(os.path.join(d, f)) for f in ("derivation.md", "model.toml", "key.py")):
            out.append(name)
    return out


def run_key(d, rerun):
    stored = os.path.join(d, "key.json")
    if not rerun:
        if not os.path.isfile(stored):
            raise RuntimeError("no key.json: run score.py --rerun-keys (or python3 key.py > key.json)")
        with open(stored, encoding="utf-8") as f:
            return json.load(f)
    r = subprocess.run([sys.executable, "key.py"], cwd=d, capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        raise RuntimeError(f"key.py exited {r.returncode}: {r.stderr.strip()[-500:]}")
    key = json.loads(r.stdout)
    if os.path.isfile(stored):
        with open(stored, encoding="utf-8") as f:
            if json.load(f) != key:
                raise RuntimeError("key.py no longer prints key.json (run python3 key.py > key.json and look at the change)")
    return key


def run_check(eomgen, d):
    cmd = [eomgen, "check", "model.toml", "derivation.md", "--format", "json"]
    if os.path.isfile(os.path.join(d, "map.toml")):
        cmd += ["--map-file", "map.toml"]
    start = time.monotonic()
    r = subprocess.run(cmd, cwd=d, capture_output=True, text=True, timeout=CHECK_LIMIT_S)
    seconds = time.monotonic() - start
    if r.returncode not in (0, 5):
        raise RuntimeError(f"eomgen check exited {r.returncode}: {(r.stderr or r.stdout).strip()[-500:]}")
    return json.loads(r.stdout), seconds


# The key's roles of rows that are not claims (README.md): never judged true or false.
NOT_CLAIMS = ("definition", "given", "condition", "trial")
RELATION = re.compile(r"=|<|>|\\(approx|simeq|equiv|leq?|geq?|neq?|cong|propto|sim|ll|gg)(?![A-Za-z])")


def relation_line(lines, n):
    """The line of the relation sign a key line means: n itself when it holds one, else the nearest line above
    (up to 6) that does, the key having named a line the equation's side reaches rather than its sign."""
    for k in range(n, max(n - 7, 0), -1):
        if 0 < k <= len(lines) and RELATION.search(lines[k - 1]):
            return k
    return n


def score_entry(key, report, text=""):
    """Per key line: slip / flagged / false alarm / silent drop / not comparable (README.md, "How the score is
    taken"). Returns the counts and the lines behind each."""
    lines = text.split("\n")
    by_line = {}
    for e in key["lines"]:
        by_line.setdefault(relation_line(lines, e["line"]), []).append(e)
    verdicts = {}
    for e in report.get("equations", []):
        verdicts.setdefault(e["line"], []).append(e)
    # A relation written across two displays (`… =$$` then `$$= …`) has two signs; the checker puts the link at
    # the first, a key may name the second. A key line with no verdict takes the last verdict of a line up to 3
    # above it that has more than one (or that is no key line).
    for line in sorted(by_line):
        if line in verdicts:
            continue
        for above in range(line - 1, max(line - 4, 0), -1):
            vs = verdicts.get(above, [])
            if vs and (len(vs) > 1 or above not in by_line):
                verdicts[line] = [vs.pop()]
                break
            if above in by_line:
                break
    problem_lines = {p.get("line") for p in report.get("problems", []) if isinstance(p, dict)}
    s = {"lines": len(by_line), "slips": [], "flagged": [], "missed": [], "false_alarms": [], "silent": [],
         "not_comparable": [], "not_claims": [], "claims_not_judged": [], "corrections": [], "off_key_disagrees": []}
    for line, es in sorted(by_line.items()):
        slip = any(e["truth"] is False for e in es)
        vs = verdicts.get(line, [])
        disagrees = [v for v in vs if v["verdict"] == "disagrees"]
        if slip:
            s["slips"].append(line)
            if disagrees:
                s["flagged"].append(line)
                if any(v.get("corrected") for v in disagrees):
                    s["corrections"].append(line)
            else:
                s["missed"].append(line)
        elif disagrees:
            s["false_alarms"].append(line)
        if not vs and line not in problem_lines:
            s["silent"].append(line)
        elif not vs or all(v["verdict"] == "not read" for v in vs):
            # Not read (a problem with its place, or a row's "not read"): said, so not silent, and not compared.
            s["not_comparable"].append(line)
        elif all(v["verdict"] in ("not comparable", "not judged", "not read") for v in vs):
            # A row the checker took for a definition, an assumption or a condition is not judged; that is right
            # only where the key says it is not a claim. A claim taken for one was not compared: not comparable.
            if all(v["verdict"] == "not judged" for v in vs) and all(e["role"] in NOT_CLAIMS for e in es):
                s["not_claims"].append(line)
            else:
                s["not_comparable"].append(line)
                if any(v["verdict"] == "not judged" for v in vs) and any(e["role"] not in NOT_CLAIMS for e in es):
                    s["claims_not_judged"].append(line)
    s["off_key_disagrees"] = sorted(l for l, vs in verdicts.items()
                                    if l not in by_line and any(v["verdict"] == "disagrees" for v in vs))
    return s


def table(results):
    rows = ["| entry | system | style | lines | slips | flagged | false alarms | silent drops | not comparable | "
            "not claims, not judged | corrections printed |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    tot = {k: 0 for k in ("lines", "slips", "flagged", "false", "silent", "nc", "nj", "corr")}
    for name, key, s, secs in results:
        rows.append(f"| {name} | {key['system']} | {key['style']} | {s['lines']} | {len(s['slips'])} | "
                    f"{len(s['flagged'])} | {len(s['false_alarms'])} | {len(s['silent'])} | "
                    f"{len(s['not_comparable'])} | {len(s['not_claims'])} | {len(s['corrections'])} |")
        for k, v in (("lines", s["lines"]), ("slips", len(s["slips"])), ("flagged", len(s["flagged"])),
                     ("false", len(s["false_alarms"])), ("silent", len(s["silent"])),
                     ("nc", len(s["not_comparable"])), ("nj", len(s["not_claims"])),
                     ("corr", len(s["corrections"]))):
            tot[k] += v
    pct = (lambda a, b: f"{100.0 * a / b:.0f} %" if b else "–")
    rows.append(f"| **all {len(results)}** | | | **{tot['lines']}** | **{tot['slips']}** | **{tot['flagged']}** "
                f"({pct(tot['flagged'], tot['slips'])}) | **{tot['false']}** | **{tot['silent']}** | "
                f"**{tot['nc']}** ({pct(tot['nc'], tot['lines'])}) | {tot['nj']} | {tot['corr']} |")
    return "\n".join(rows) + "\n", tot


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--eomgen", default=os.path.join(ROOT, "build", "generator", "eomgen"))
    ap.add_argument("--entries", nargs="*")
    ap.add_argument("--json")
    ap.add_argument("--details", action="store_true", help="print the lines behind each count")
    ap.add_argument("--rerun-keys", action="store_true", help="run each key.py and compare it with its key.json")
    g = ap.add_mutually_exclusive_group()
    g.add_argument("--write-docs", action="store_true")
    g.add_argument("--check-docs", action="store_true")
    a = ap.parse_args()
    if not os.access(a.eomgen, os.X_OK):
        print(f"score.py: {a.eomgen} is not an executable (build it, or give --eomgen)", file=sys.stderr)
        return 2
    results, broken = [], []
    for name in entries(a.entries):
        d = os.path.join(HERE, name)
        try:
            key = run_key(d, a.rerun_keys)
            report, secs = run_check(a.eomgen, d)
        except (RuntimeError, subprocess.TimeoutExpired, json.JSONDecodeError) as e:
            broken.append(f"{name}: {e}")
            continue
        with open(os.path.join(d, "derivation.md"), encoding="utf-8") as f:
            s = score_entry(key, report, f.read())
        results.append((name, key, s, secs))
        if a.details:
            for k in ("missed", "false_alarms", "silent", "not_comparable", "claims_not_judged", "off_key_disagrees"):
                if s[k]:
                    print(f"{name}: {k}: lines {', '.join(map(str, s[k]))}")
    text, tot = table(results)
    print(text, end="")
    if results:
        slowest = max(results, key=lambda r: r[3])
        print(f"slowest check: {slowest[0]}, {slowest[3]:.1f} s (the target: under 10 s)")
    if a.json:
        with open(a.json, "w") as f:
            json.dump([{"entry": n, "source": k["source"], **{x: y for x, y in s.items()}, "seconds": secs}
                       for n, k, s, secs in results], f, indent=1)
    for b in broken:
        print(f"broken: {b}", file=sys.stderr)
    if a.write_docs or a.check_docs:
        with open(DOCS) as f:
            doc = f.read()
        if BEGIN not in doc or END not in doc:
            print(f"score.py: {DOCS} has no CORPUS markers", file=sys.stderr)
            return 2
        head, rest = doc.split(BEGIN, 1)
        _, tail = rest.split(END, 1)
        new = head + BEGIN + "\n" + text + END + tail
        if a.write_docs:
            with open(DOCS, "w") as f:
                f.write(new)
        elif new != doc:
            print("score.py: the corpus table in docs/checker.md is not what this run gives; run "
                  "tests/checker/corpus/score.py --write-docs and commit it", file=sys.stderr)
            return 1
    return 2 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
