#!/usr/bin/env python3
"""Mutation score of eomgen's dimensional analysis (issue 29).

Each shipped model and example (models/, examples/) is mutated one term at a time in T, V, R, the forces and the
constraints of several terms: a factor of a dimensioned parameter (a length, a mass, an acceleration), of a
velocity or of t added, a division by a length, a dimensioned parameter removed or squared, the argument of a sin
or cos multiplied by a length. Every such mutation breaks the
dimensions. Each mutated file goes through `eomgen generate`; a mutation counts as reported at the right place when
the error names the file, the line of the mutated string and a column inside the mutated term. Prints the table and
every mutation missed or misplaced, with why. Usage: tests/units/mutations.py [EOMGEN] [--check] (default
build/generator/eomgen). With --check it exits 1 when fewer than 95 % are reported at the mutated term or any
mutation is not reported at all (the issue's target; ctest runs it so).
"""
import os
import re
import subprocess
import sys
import tempfile
import tomllib

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ARGS = [a for a in sys.argv[1:] if a != "--check"]
CHECK = "--check" in sys.argv[1:]
EOMGEN = ARGS[0] if ARGS else os.path.join(ROOT, "build", "generator", "eomgen")
DIMENSIONLESS = {"", "1", "rad", "deg", "rev"}


def top_level_terms(text):
    """(term, offset) at '+'/'-' of depth 0 after an operand, as generator/model/dimensions.cpp splits them."""
    out, depth, start, prev = [], 0, 0, ""
    for i, c in enumerate(text):
        if c == "(":
            depth += 1
        elif c == ")":
            depth -= 1
        if c in "+-" and depth == 0 and prev:
            operand_end = prev.isalnum() or prev in ")'._"
            exponent = prev in "eE" and i >= 2 and text[i - 2].isdigit()
            if operand_end and not exponent:
                out.append((text[start:i], start))
                start = i
        if not c.isspace():
            prev = c
    out.append((text[start:], start))
    return out


def mutations(term, params, coords):
    """(description, mutated term) pairs, each changing the term's dimension."""
    lengths = [p for p, u in params.items() if u == "m"]
    masses = [p for p, u in params.items() if u == "kg"]
    accelerations = [p for p, u in params.items() if u.replace(" ", "") in ("m/s^2", "m/s2")]
    body = term.rstrip()
    out = []
    for group in (lengths, masses, accelerations):
        if group:
            out.append((f"times {group[0]}", f"{body}*{group[0]}"))
    if coords:
        out.append((f"times {coords[0]}'", f"{body}*{coords[0]}'"))
    if lengths:
        out.append((f"divided by {lengths[-1]}", f"{body}/{lengths[-1]}"))
    out.append(("times t", f"{body}*t"))
    dimensioned = [p for p, u in params.items() if u not in DIMENSIONLESS]
    for p in dimensioned:
        m = re.search(rf"(?<![A-Za-z0-9_]){re.escape(p)}(?![A-Za-z0-9_'(])", body)
        if not m:
            continue
        squared = body[: m.end()] + "^2" + body[m.end():]
        if body[m.end():m.end() + 1] != "^":
            out.append((f"{p} squared", squared))
        # Removing the factor: "*p" or "p*" next to it.
        before, after = body[: m.start()], body[m.end():]
        if before.endswith("*"):
            out.append((f"{p} removed", before[:-1] + after))
        elif after.startswith("*"):
            out.append((f"{p} removed", before + after[1:]))
        break
    if lengths:
        m = re.search(r"\b(sin|cos)\(", body)
        if m:
            out.append((f"{m.group(1)} of a length", body[: m.end()] + f"{lengths[0]}*" + body[m.end():]))
    return out


def string_line(source, key_line_prefix, text):
    """The 1-based line where the string of `key = "..."` holding `text` starts its content."""
    for n, line in enumerate(source.split("\n"), 1):
        if line.strip().startswith(key_line_prefix) and text.split("\n")[0][:20] in line:
            return n, line.index(text.split("\n")[0][:20]) + 1
    return None, None


def main():
    files = sorted(os.path.join(d, f) for d in ("models", "examples") for f in os.listdir(os.path.join(ROOT, d))
                   if f.endswith(".toml"))
    total = right = elsewhere = 0
    missed = []
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for rel in files:
            path = os.path.join(ROOT, rel)
            source = open(path, encoding="utf-8").read()
            model = tomllib.loads(source)
            params = {p["name"]: p.get("unit", "") for p in model.get("parameters", [])}
            coords = [c["name"] for c in model.get("coordinates", [])]
            fields = []
            lag = model.get("lagrangian", {})
            for key in ("T", "V", "R"):
                if isinstance(lag.get(key), str) and lag[key].strip() not in ("", "0"):
                    fields.append((key, lag[key]))
            for q, text in model.get("forces", {}).items():
                fields.append((q, text))
            for c in model.get("constraints", []):  # a constraint of several terms must stay homogeneous
                if len([t for t, _ in top_level_terms(c["expr"]) if t.strip()]) > 1:
                    fields.append(("expr", c["expr"]))
            n_model = r_model = 0
            for key, text in fields:
                line, column = string_line(source, key, text)
                if line is None or "\n" in text:
                    continue  # multi-line strings: the column arithmetic below assumes one line
                for term, offset in top_level_terms(text):
                    if not term.strip():
                        continue
                    for what, new_term in mutations(term, params, coords):
                        mutated = text[:offset] + new_term + text[offset + len(term.rstrip()):]
                        new_source = source.replace(f'"{text}"', f'"{mutated}"', 1)
                        if new_source == source:
                            continue
                        name = f"m{total}.toml"
                        with open(os.path.join(work, name), "w", encoding="utf-8") as f:
                            f.write(new_source)
                        total += 1
                        n_model += 1
                        p = subprocess.run([EOMGEN, "generate", os.path.join(work, name), "-o", work],
                                           capture_output=True, text=True, timeout=60)
                        message = (p.stderr + p.stdout).strip().split("\n")[0]
                        m = re.match(rf".*{re.escape(name)}:(\d+):(\d+): (.*)", message)
                        lead = len(term) - len(term.lstrip(" +"))
                        start = column + offset + lead
                        end = column + offset + len(new_term)
                        label = f"{rel} {key}: {term.strip()!r} {what}"
                        if p.returncode == 1 and m and int(m.group(1)) == line and start <= int(m.group(2)) <= end:
                            right += 1
                            r_model += 1
                        elif p.returncode == 1 and m:
                            elsewhere += 1
                            missed.append(f"{label}: reported elsewhere, {message}")
                        else:
                            missed.append(f"{label}: not reported (exit {p.returncode})")
            rows.append((rel, n_model, r_model))
    print("| model | mutations | reported at the term |")
    print("|---|---|---|")
    for rel, n, r in rows:
        if n:
            print(f"| {rel} | {n} | {r} |")
    print(f"| all | {total} | {right} ({100.0 * right / max(total, 1):.1f} %) |")
    if missed:
        print("\nMissed or misplaced:")
        for m in missed:
            print("-", m)
    if CHECK:
        unreported = [m for m in missed if ": not reported" in m]
        if right < 0.95 * total or unreported or total == 0:
            print(f"\nbelow the target: {right} of {total} at the term (95 % needed), {len(unreported)} not reported")
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
