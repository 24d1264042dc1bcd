"""Common steps of the corpus' answer keys (tests/checker/corpus/README.md): SymPy only, no eomgen.

A key builds the system's Lagrangian from its own kinematics, and decides each line of the text with
`Mechanics.on_motion` (an equation of motion or a consequence of them: its residual vanishes once the
accelerations are replaced by their solution), `same` (two expressions are identical) or its own SymPy.
"""
import json
import os
import sys

import sympy as sp

t = sp.Symbol("t", real=True)


def coords(*names):
    """Coordinates as functions of t: coords("x", "theta") -> (x(t), theta(t))."""
    out = tuple(sp.Function(n, real=True)(t) for n in names)
    return out if len(out) > 1 else out[0]


def d(q, k=1):
    """The k-th time derivative of a coordinate."""
    return sp.diff(q, t, k)


def _numerically_nonzero(e):
    """e is clearly not 0 at one of three fixed random points (derivatives, coordinates, then symbols given values in
    [0.3, 1.3]): then no simplifier need try to prove it 0, which can take minutes (bead_rotating_rod's λ)."""
    import random
    rng = random.Random(28)
    for _ in range(3):
        x = e
        try:
            for group in (sorted(x.atoms(sp.Derivative), key=lambda v: -v.derivative_count),
                          None, None):
                atoms = group if group is not None else (x.atoms(sp.core.function.AppliedUndef) or x.free_symbols)
                x = x.subs({a: rng.uniform(0.3, 1.3) for a in atoms})
            value = complex(sp.N(x, 30))
        except Exception:  # pragma: no cover - a value that cannot be evaluated proves nothing
            return False
        if value == value and abs(value) > 1e-8:  # (not NaN)
            return True
    return False


def _simplified_zero(e):
    e = sp.expand(e)
    if e == 0:
        return True
    if _numerically_nonzero(e):
        return False
    for f in (sp.simplify, lambda x: sp.trigsimp(sp.expand_trig(x)), lambda x: sp.simplify(sp.expand_trig(sp.expand(x)))):
        try:
            if f(e) == 0:
                return True
        except Exception:  # pragma: no cover - SymPy's simplifiers may fail on odd input
            pass
    return False


def same(a, b):
    """a and b are the same expression (of coordinates, their derivatives and parameters)."""
    return _simplified_zero(sp.sympify(a) - sp.sympify(b))


def derivation_lines(entry_dir):
    """The lines of the entry's derivation.md (split at newlines), as line_of() and locator() take them."""
    with open(os.path.join(entry_dir, "derivation.md"), encoding="utf-8") as fh:
        return fh.read().split("\n")


def locator(lines):
    """at(snippet, nth=1): line_of() on these lines, as each key writes its key.line(at(...), ...)."""
    return lambda snippet, nth=1: line_of(lines, snippet, nth)


def line_of(lines, snippet, nth=1):
    """1-based number of the nth of `lines` (derivation.md split at newlines) that contains snippet; stops the key
    when there is none, so that a line number cannot silently drift."""
    hits = [i + 1 for i, line in enumerate(lines) if snippet in line]
    if len(hits) < nth:
        raise SystemExit(f"key.py: {snippet!r} not found {nth} time(s) in derivation.md")
    return hits[nth - 1]


class Mechanics:
    """Euler-Lagrange equations d/dt dL/dq' - dL/dq = Q of L in the coordinates qs (functions of t)."""

    def __init__(self, L, qs, forces=None):
        self.L = sp.sympify(L)
        self.qs = list(qs)
        self.Q = list(forces) if forces is not None else [0] * len(self.qs)
        self.el = [sp.diff(sp.diff(self.L, d(q)), t) - sp.diff(self.L, q) - Qi for q, Qi in zip(self.qs, self.Q)]
        acc = [d(q, 2) for q in self.qs]
        sol = sp.solve(self.el, acc, dict=True)
        if len(sol) != 1:
            raise ValueError("the Euler-Lagrange equations do not determine the accelerations")
        self.accelerations = {a: sp.simplify(sol[0][a]) for a in acc}

    def momentum(self, q):
        return sp.diff(self.L, d(q))

    def energy(self):
        """h = sum q' dL/dq' - L."""
        return sp.expand(sum(d(q) * sp.diff(self.L, d(q)) for q in self.qs) - self.L)

    def on_motion(self, lhs, rhs=0):
        """lhs = rhs holds along every motion: zero after q'' -> its solution (q''' by differentiating it)."""
        r = sp.sympify(lhs) - sp.sympify(rhs)
        r = r.subs({sp.diff(a, t): sp.diff(v, t) for a, v in self.accelerations.items()})
        r = r.subs(self.accelerations)
        r = r.subs(self.accelerations)
        return _simplified_zero(r)


class Key:
    """The answer key of one text: its entries, printed as JSON by emit()."""

    ROLES = {"claim", "definition", "given", "condition", "approximation", "limit", "trial", "combination",
             "kinematics"}

    def __init__(self, source, system, style):
        self.data = {"source": source, "system": system, "style": style, "lines": []}

    def line(self, line, text, role, truth, why, correct=None):
        if role not in self.ROLES:
            raise ValueError(f"line {line}: unknown role {role!r}")
        if role in {"definition", "given", "condition", "trial"} and truth is not None and truth is not False:
            raise ValueError(f"line {line}: a {role} is null, or false where it contradicts the model")
        if role not in {"definition", "given", "condition", "trial"} and truth is None:
            raise ValueError(f"line {line}: a {role} needs truth true or false")
        entry = {"line": int(line), "text": text, "role": role, "truth": None if truth is None else bool(truth),
                 "why": why}
        if correct is not None:
            entry["correct"] = correct
        self.data["lines"].append(entry)

    def emit(self):
        json.dump(self.data, sys.stdout, indent=1, ensure_ascii=False)
        sys.stdout.write("\n")
