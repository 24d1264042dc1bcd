"""eomgen from Python: derive a model file's equations of motion, simulate them with the compiled code that
`eomgen run` uses, evaluate the right-hand side over arrays of states, and check a hand derivation.

    import eomgen
    m = eomgen.load("models/door_closing.toml")
    m.parameters                      # {'w': 1.0, 'theta': 0.0523..., 'g': 9.81}
    m.show()                          # T, V, L, the Euler-Lagrange equations, h, momenta (as `eomgen show`)
    sol = m.simulate(2.0, until="psi=-pi/2")
    sol.t, sol["psi"], sol.stopped_by # NumPy arrays and the terminal event
    m.rhs(0.0, states)                # x' at each row of an (N, 2n) array, looping in C++
    eomgen.check(m, open("notes.md").read()).counts

docs/python.md is the reference. Errors are exceptions derived from eomgen.Error: ModelError (its message starts
with file:line:col), UsageError, SimulationError, CompileError, CacheError, CheckError.
"""

from dataclasses import dataclass, field
import errno
import math
import os

import numpy as np

from ._eomgen import (CacheError, CheckError, CompileError, Error, LoadedModel, ModelError, SimulationError,
                      UsageError)
from . import _eomgen

__all__ = ["load", "loads", "family", "check", "Model", "Solution", "Ensemble", "Modes", "Equilibrium", "NormalMode", "Equations", "CheckResult", "EquationCheck",
           "cache_directory", "Error", "ModelError", "UsageError", "SimulationError", "CompileError",
           "CacheError", "CheckError"]


def load(path, name=None):
    """The model file at `path` (a TOML model file, docs/model_files.md); `name` names a model whose file gives no
    name (default: the file name). Reading is cheap: the equations are derived, and the code compiled (or taken
    from the cache), when first asked for."""
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise FileNotFoundError(errno.ENOENT, "no model file", path)
    return Model(_eomgen.read_file(path), path, name or "")


def loads(text, name="model"):
    """A model file's text; `name` is the model's name (its generated code's namespace) unless the text gives one.
    Messages place errors at <string>:line:col."""
    if not isinstance(text, str):
        raise TypeError("loads: a model file's text (str), not " + type(text).__name__)
    return Model(text, "<string>", name)


def family(spec):
    """The model of an n-link planar chain, as `eomgen generate --family SPEC` makes it: "pendulum:n=8" (point masses
    on massless links) or "rods:n=8" (uniform rods); coordinates theta1..thetan, parameters m1..mn, l1..ln, g."""
    text = _eomgen.family_text(str(spec))
    return Model(text, "--family " + str(spec), "")


def cache_directory():
    """The cache of compiled models, shared with `eomgen run` ($XDG_CACHE_HOME/eomgen, default ~/.cache/eomgen)."""
    return _eomgen.cache_directory()


def _is_number(value):
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool)


def _items(values, what):
    """The (name, value) pairs of a dict given for `what` (none for None); TypeError for anything else."""
    if values is None:
        return []
    if not hasattr(values, "items"):
        raise TypeError(what + ": a dict of NAME: value, not " + type(values).__name__)
    return list(values.items())


def _assignments(values, what):
    """{'l': 2, 'alpha': '45 deg'} as ['l=2', 'alpha=45 deg'] (a number with all its digits, in the declared unit
    as on the command line; a string carries its own unit)."""
    out = []
    for name, value in _items(values, what):
        if not isinstance(value, str) and not _is_number(value):
            raise TypeError("{}: the value of {!r} must be a number or a string with a unit, not {}".format(
                what, name, type(value).__name__))
        out.append("{}={}".format(name, value if isinstance(value, str) else repr(float(value))))
    return out


def _si_values(values, what):
    """{'l': 2.0} as [('l', 2.0)]: numbers in SI, for rhs() and check()."""
    out = []
    for name, value in _items(values, what):
        if not _is_number(value):
            raise TypeError("{}: the value of {!r} must be a number (SI), not {}".format(
                what, name, type(value).__name__))
        out.append((str(name), float(value)))
    return out


@dataclass(frozen=True)
class Equations:
    """The derived mechanics, each as `eomgen show` prints it (the model file's language, e.g. 1/2*m*l^2*theta'^2)."""
    T: str
    V: str
    L: str
    h: str
    euler_lagrange: dict  # coordinate -> "d/dt(dL/dq') - dL/dq = Q - dR/dq' + A^T lambda"
    M: list               # the mass matrix, n lists of n
    f: dict               # coordinate -> f_i of M q'' = f
    momenta: dict         # coordinate -> dL/dq'
    warnings: list


class Model:
    """A model file, read. Its equations are derived on first use and its code compiled (or loaded from the cache
    that `eomgen run` fills) on the first simulate() or rhs()."""

    def __init__(self, text, path, name):
        self._m = LoadedModel(text, path, name)
        d = self._m.describe()
        self.name = d["name"]
        self.title = d["title"]
        self.source = d["source"]
        self.path = d["path"]
        self.coordinates = [c["name"] for c in d["coordinates"]]
        self.parameters = {p["name"]: p["value"] for p in d["parameters"]}
        self.outputs = list(d["outputs"])
        self.constraints = list(d["constraints"])
        self.units = {p["name"]: p["unit"] for p in d["parameters"]}
        self.units.update({c["name"]: c["unit"] for c in d["coordinates"]})
        self.initial_state = np.array([c["initial"] for c in d["coordinates"]] +
                                      [c["rate"] for c in d["coordinates"]])
        self.latex_names = {c["name"]: c["latex"] for c in d["coordinates"]}  # how the LaTeX writes each symbol
        self.latex_names.update({p["name"]: p["latex"] for p in d["parameters"]})
        self._equations = None

    def __repr__(self):
        return "<eomgen.Model {} ({}): coordinates {}, parameters {}>".format(
            self.name, self.title or "untitled", ", ".join(self.coordinates), ", ".join(self.parameters))

    @property
    def equations(self):
        """Equations: T, V, L, h, the Euler-Lagrange equations, M and f, the momenta (plain text)."""
        if self._equations is None:
            e = self._m.equations()
            q = self.coordinates
            self._equations = Equations(
                T=e["T"], V=e["V"], L=e["L"], h=e["h"],
                euler_lagrange={q[i]: e["euler_lagrange"][i] + " = " + e["forces"][i] for i in range(len(q))},
                M=[list(row) for row in e["M"]], f=dict(zip(q, e["f"])), momenta=dict(zip(q, e["momenta"])),
                warnings=list(e["warnings"]))
        return self._equations

    def show(self, file=None):
        """Prints what `eomgen show` prints (without its equilibria, which `eomgen modes` computes)."""
        print(self._m.show(), end="", file=file)

    def show_text(self):
        """The text show() prints."""
        return self._m.show()

    def latex(self):
        """The derived mechanics as LaTeX, as `eomgen show --latex` prints it (align environments; needs amsmath)."""
        return self._m.latex()[0]

    def _repr_latex_(self):
        return self._m.latex()[1]

    def simulate(self, t_end=10.0, method="dopri5", rtol=1e-10, atol=1e-12, dt=0.0, samples=200, until=None,
                 set=None, init=None, project_initial=False, max_steps=10_000_000, switch_events=True,
                 sensitivities=None, state_error_only=False, cache=True, interpret=False):
        """Integrates from t = 0 to t_end (or the `until` event, e.g. "psi=-pi/2") as `eomgen run` does, with the
        same defaults, and returns a Solution of samples + 1 rows. `set` and `init` are dicts of values: a number
        is in the unit the model file declares for it (SI where it declares none), a string carries its own unit
        ({"alpha": "30 deg"}); `init` names states (q or q_dot). method: dopri5, dop853, adams, radau5, rk4 or
        symplectic (the last two with dt). `sensitivities` (as `eomgen run --sensitivities`: parameter names and
        "x0:STATE" for initial values) integrates S = dx/d(those) beside the state under the same error control
        (dopri5, dop853, adams, radau5; rk4 and symplectic with dt, the derivative of their own steps;
        docs/sensitivities.md): Solution.S and the rest;
        state_error_only=True leaves S out of the step-size control (as --state-error-only). cache=False compiles
        afresh and keeps nothing. interpret=True runs the derived equations on eomgen's interpreter instead of
        compiling them (as `eomgen run --interpret`: no C++ compiler and no wait, each step slower; docs/interpreter.md)."""
        if isinstance(sensitivities, str):
            sensitivities = [sensitivities]
        r = self._m.simulate(float(t_end), str(method), float(rtol), float(atol), float(dt), int(samples),
                             int(max_steps), _assignments(set, "set"), _assignments(init, "init"),
                             "" if until is None else str(until), bool(project_initial), bool(switch_events),
                             [str(c) for c in (sensitivities or [])], bool(state_error_only), bool(cache),
                             bool(interpret))
        return Solution(self, r)

    def sweep(self, values, grid=True, t_end=10.0, method="dopri5", rtol=1e-10, atol=1e-12, dt=0.0, until=None,
              set=None, init=None, project_initial=False, max_steps=10_000_000, switch_events=True, threads=0,
              cache=True, interpret=False):
        """An ensemble, as `eomgen run --sweep` runs one: `values` maps names (parameters, or states' initial values
        q and q_dot) to 1-D arrays of numbers in their declared units; with grid=True every combination is a member
        (the first name varies slowest), with grid=False the arrays are zipped (equal lengths: member k takes the
        k-th of each, e.g. draws from NumPy for a Monte Carlo study). Every member starts from the model's defaults
        with `set` and `init`, and is integrated as simulate() integrates, on `threads` threads (0: every core,
        without the GIL). Returns an Ensemble: where each member ended, its state, h and outputs there. interpret=True as
        in simulate()."""
        if not hasattr(values, "items") or not values:
            raise TypeError("sweep: a dict of NAME: array of values")
        names = [str(k) for k in values]
        arrays = [np.atleast_1d(np.asarray(v, dtype=float)) for v in values.values()]
        for name, a in zip(names, arrays):
            if a.ndim != 1:
                raise UsageError("sweep: the values of {} must be one-dimensional".format(name))
        if grid:
            mesh = np.meshgrid(*arrays, indexing="ij")
            table = np.column_stack([g.ravel() for g in mesh])
        else:
            if len({len(a) for a in arrays}) != 1:
                raise UsageError("sweep with grid=False: every name needs as many values ({})".format(
                    ", ".join("{} {}".format(n, len(a)) for n, a in zip(names, arrays))))
            table = np.column_stack(arrays)
        r = self._m.sweep(names, table, float(t_end), str(method), float(rtol), float(atol), float(dt),
                          int(max_steps), _assignments(set, "set"), _assignments(init, "init"),
                          "" if until is None else str(until), bool(project_initial), bool(switch_events),
                          int(threads), bool(cache), bool(interpret))
        return Ensemble(self, names, table, r)

    def sample(self, n, dists, seed=0, **options):
        """A Monte Carlo ensemble of n members: `dists` maps names to ("uniform", a, b) or ("normal", mu, sigma)
        (in the declared units) or to a function of a numpy.random.Generator and n returning n values; drawn with
        numpy.random.default_rng(seed), then run as sweep(..., grid=False, **options)."""
        rng = np.random.default_rng(seed)
        values = {}
        for name, d in dists.items():
            if callable(d):
                values[name] = np.asarray(d(rng, n), dtype=float)
            elif isinstance(d, tuple) and len(d) == 3 and d[0] in ("uniform", "normal"):
                values[name] = rng.uniform(d[1], d[2], n) if d[0] == "uniform" else rng.normal(d[1], d[2], n)
            else:
                raise UsageError("sample: {}: give (\"uniform\", a, b), (\"normal\", mu, sigma) or a function of "
                                 "(rng, n)".format(name))
        return self.sweep(values, grid=False, **options)

    def rhs(self, t, x, set=None, cache=True, interpret=False):
        """x' = rhs(t, x) for each row of x (shape (N, 2n): q then q'; or one state of shape (2n,)), t a number or
        one per row; parameters are the model's, with `set` (SI numbers) changed. The loop runs in C++ without the
        GIL on the compiled code that simulate() uses (with interpret=True, on the interpreter's tapes)."""
        return self._m.rhs(np.asarray(t, dtype=float), np.asarray(x, dtype=float), _si_values(set, "set"),
                           bool(cache), bool(interpret))

    def jacobian(self, t, x, set=None, cache=True, interpret=False):
        """(J, Jp): J = dx'/dx, shape (2n, 2n), and Jp = dx'/dp, shape (2n, len(parameters)) in the order of
        `parameters`, at the state x (or (N, 2n, 2n) and (N, 2n, n_p) over the rows of an (N, 2n) array), with the
        model's parameters and `set` (SI). The compiled Jacobians radau5 and the sensitivities use: the header's
        analytic ones where the model has them, else forward differentiation of the compiled rhs; with
        interpret=True, forward differentiation of the interpreter's tapes."""
        return self._m.jacobian(np.asarray(t, dtype=float), np.asarray(x, dtype=float), _si_values(set, "set"),
                                bool(cache), bool(interpret))

    def linearize(self, t, x, set=None, cache=True, interpret=False):
        """(A, B) of the linearization d(dx)/dt = A dx + B dp about the state x at t (x an (N, 2n) array: one pair per
        row), as a generated header's linearization() gives them: A = dx'/dx, B = dx'/dp, what jacobian() returns.
        About an equilibrium, with M, K, C, G and the normal modes: modes()."""
        return self.jacobian(t, x, set=set, cache=cache, interpret=interpret)

    def modes(self, set=None, at=None, momentum=None, inputs=None):
        """What `eomgen modes` finds: the equilibria (exact where the equations can be solved, else from the guesses
        `at`, a dict or a list of dicts of coordinates, the initial state and a scan), the linearization about each
        (M, K, C, G; A and B of dx/dt = A x + B u for the parameters named in `inputs`), the normal modes, the
        eigenvalues and the stability. `set` and `at` in declared units like simulate's; `momentum` ({"p_phi": 1.2},
        SI) reduces a cyclic coordinate away (Routh). Returns a Modes."""
        guesses = [] if at is None else [at] if hasattr(at, "items") else list(at)
        r = self._m.modes(_assignments(set, "set"), [_assignments(g, "at") for g in guesses],
                          _assignments(momentum, "momentum"), [str(i) for i in (inputs or [])])
        return Modes(r)

    @property
    def shared_object(self):
        """The path of the compiled model's shared object in the cache (compiled on first use): its functions as a
        table (eomgen/model_table.hpp), which simulate() and rhs() call."""
        return self._m.shared_object(True)

    def check(self, derivation, path="<string>", sections=(), set=None):
        """eomgen.check(self, derivation, ...)."""
        return check(self, derivation, path=path, sections=sections, set=set)


class Solution:
    """One simulation's samples: t, the state x (q then q'), and every column `eomgen run --csv` writes."""

    def __init__(self, model, r):
        self.model = model
        self.t = r["t"]
        self.x = r["x"]
        n = len(model.coordinates)
        self.q = self.x[:, :n]
        self.qdot = self.x[:, n:]
        self.names = ["t"] + list(r["state_names"]) + list(r["derived_names"])
        self.units = dict(zip(self.names, [r["time_unit"]] + list(r["state_units"]) + list(r["derived_units"])))
        self._columns = {"t": self.t}
        for k, name in enumerate(r["state_names"]):
            self._columns[name] = self.x[:, k]
        for k, name in enumerate(r["derived_names"]):
            self._columns[name] = r["derived"][:, k]
        self.energy = self._columns["energy"]
        self.work = self._columns.get("work")
        self.outputs = {o: self._columns[o] for o in model.outputs}
        self.multipliers = {c: self._columns["lambda_" + c] for c in model.constraints}
        self.residuals = {c: self._columns["residual_" + c] for c in model.constraints}
        self.t_final = r["t_final"]
        self.stopped_by = r["stopped_by"] or None
        self.h0 = r["h0"]
        self.max_drift = r["max_drift"]
        self.max_imbalance = r["max_imbalance"]
        self.parameters = dict(r["parameters"])
        # With sensitivities: S[k, i, c] = d x_i / d (column c) at sample k, and the same for the outputs and the
        # multipliers; an event's dt*/d(column c).
        self.sensitivity_names = list(r.get("sensitivity_names", []))
        self.S = r.get("S")
        self.S_outputs = r.get("S_outputs")
        self.S_multipliers = r.get("S_multipliers")
        self.event_dt = dict(r.get("event_dt", {}))

    def sensitivity(self, of, wrt):
        """d(of)/d(wrt) at every sample: `of` a state (psi, psi_dot), a declared output or lambda_<constraint>,
        `wrt` one of the columns asked for ("theta", "psi(0)")."""
        if self.S is None:
            raise UsageError("no sensitivities: simulate(..., sensitivities=[...]) integrates them")
        if wrt not in self.sensitivity_names:
            raise KeyError("no sensitivity column {!r}; there are {}".format(wrt, ", ".join(self.sensitivity_names)))
        c = self.sensitivity_names.index(wrt)
        states = self.model.coordinates + [q + "_dot" for q in self.model.coordinates]
        if of in states:
            return self.S[:, states.index(of), c]
        if of in self.model.outputs:
            return self.S_outputs[:, self.model.outputs.index(of), c]
        if of.startswith("lambda_") and of[7:] in self.model.constraints:
            return self.S_multipliers[:, self.model.constraints.index(of[7:]), c]
        raise KeyError("no state, output or multiplier {!r}".format(of))

    def __getitem__(self, name):
        try:
            return self._columns[name]
        except KeyError:
            raise KeyError("no column {!r}; there are {}".format(name, ", ".join(self.names))) from None

    def __contains__(self, name):
        return name in self._columns

    def __len__(self):
        return len(self.t)

    def __repr__(self):
        end = "the event " + self.stopped_by if self.stopped_by else "t_end"
        return "<eomgen.Solution of {}: {} samples on [0, {:.6g}], stopped by {}; max drift of h {:.3g}>".format(
            self.model.name, len(self.t), self.t_final, end, self.max_drift)

    def to_array(self):
        """Every column, in the order of `names` (as the CSV of `eomgen run --csv`), as one (N, columns) array."""
        return np.column_stack([self._columns[n] for n in self.names])

    def plot(self, columns=None, ax=None):
        """The coordinates (or `columns`) against t with matplotlib, one axis per unit so that an angle and a length
        do not share a scale; returns the figure. Needs matplotlib (python3-matplotlib)."""
        try:
            import matplotlib.pyplot as plt
        except ImportError as e:
            raise ImportError("Solution.plot needs matplotlib (apt-get install python3-matplotlib)") from e
        columns = list(columns) if columns is not None else list(self.model.coordinates)
        for c in columns:
            self[c]  # a KeyError naming the columns there are
        groups = {}
        for c in columns:
            groups.setdefault(self.units.get(c, ""), []).append(c)
        if ax is not None:
            axes = [ax] * len(groups)
            fig = ax.figure
        else:
            fig, axes = plt.subplots(len(groups), 1, sharex=True, squeeze=False)
            axes = list(axes[:, 0])
        for a, (unit, names) in zip(axes, groups.items()):
            for name in names:
                a.plot(self.t, self[name], label=name)
            a.set_ylabel(unit if unit else "value")
            a.legend(loc="best")
        axes[-1].set_xlabel("t [s]")
        fig.suptitle(self.model.title or self.model.name)
        return fig


@dataclass(frozen=True)
class NormalMode:
    """K0 a = omega^2 M0 a: omega2 (negative where the mode grows), in the parameters where it factors (text), and
    the shape a over the coordinates that remain, scaled to its largest component 1."""
    omega2: float
    omega2_exact: str
    shape: np.ndarray

    @property
    def omega(self):
        """The angular frequency sqrt(omega2) (NaN where omega2 < 0: the mode grows)."""
        return math.sqrt(self.omega2) if self.omega2 >= 0 else float("nan")


@dataclass(frozen=True)
class Equilibrium:
    """One equilibrium and the linearization about it (docs/modes.md)."""
    q: dict              # coordinate -> value there (SI)
    exact: dict          # coordinate -> its value in the parameters (text), None where only a number was found
    M: np.ndarray
    K: np.ndarray
    C: np.ndarray
    G: np.ndarray
    A: np.ndarray        # dx/dt = A x + B u, x = [q, q']
    B: np.ndarray
    multipliers: list    # of the constraints there
    tangent: np.ndarray  # the constraints' tangent space (columns); the identity without constraints
    modes: list          # NormalMode
    eigenvalues: np.ndarray
    stability: str       # "stable", "marginally stable", "unstable", "gyroscopically stabilized"
    growth_rate: float
    gyroscopic: bool
    damped: bool


class Modes:
    """The equilibria of a model and the small oscillations about each (Model.modes)."""

    def __init__(self, r):
        self.coordinates = list(r["coordinates"])
        self.reduced = list(r["reduced"])
        self.constraints = list(r["constraints"])
        self.V_eff = r["V_eff"]
        self.notes = list(r["notes"])
        self.equilibria = []
        for e in r["equilibria"]:
            self.equilibria.append(Equilibrium(
                q=dict(zip(self.coordinates, e["q"])), exact=dict(zip(self.coordinates, e["exact"])),
                M=e["M"], K=e["K"], C=e["C"], G=e["G"], A=e["A"], B=e["B"], multipliers=list(e["multipliers"]),
                tangent=e["tangent"], modes=[NormalMode(w2, exact, np.array(shape)) for w2, exact, shape in e["modes"]],
                eigenvalues=np.array(e["eigenvalues"], dtype=complex), stability=e["stability"],
                growth_rate=e["growth_rate"], gyroscopic=e["gyroscopic"], damped=e["damped"]))

    def __iter__(self):
        return iter(self.equilibria)

    def __len__(self):
        return len(self.equilibria)

    def __getitem__(self, k):
        return self.equilibria[k]

    def __repr__(self):
        return "<eomgen.Modes: {} equilibria ({})>".format(
            len(self.equilibria), ", ".join(e.stability for e in self.equilibria))


class Ensemble:
    """An ensemble's members (Model.sweep, Model.sample), one row each in member order: the values it was given
    (`values`, declared units; `values_si`), whether it succeeded (`ok`; else `error`), where it ended (`t`, the
    event in `stopped_by` or None), its state there (`x`, `q`, `qdot`), h (`energy`) and the outputs there."""

    def __init__(self, model, names, table, r):
        self.model = model
        self.names = names
        self.values = {n: table[:, j] for j, n in enumerate(names)}
        self.values_si = {n: r["values_si"][:, j] for j, n in enumerate(names)}
        self.ok = r["ok"]
        self.t = r["t"]
        self.x = r["x"]
        n = len(model.coordinates)
        self.q = self.x[:, :n]
        self.qdot = self.x[:, n:]
        self.energy = r["energy"]
        self.outputs = {o: r["outputs"][:, k] for k, o in enumerate(model.outputs)}
        self.stopped_by = [s or None for s in r["stopped_by"]]
        self.error = [e or None for e in r["error"]]

    def __len__(self):
        return len(self.t)

    def __repr__(self):
        return "<eomgen.Ensemble of {}: {} members over {}, {} failed>".format(
            self.model.name, len(self.t), ", ".join(self.names), int(np.count_nonzero(~self.ok)))

    def to_structured(self):
        """One NumPy structured array: the values (a state's initial value as "psi(0)"), ok, t, the state, energy, the
        outputs, as the columns of the table `eomgen run --sweep` writes. The values in their declared units."""
        states = self.model.coordinates + [c + "_dot" for c in self.model.coordinates]
        varied = [n + "(0)" if n in states else n for n in self.names]
        fields = [(v, float) for v in varied] + [("ok", bool), ("t", float)]
        fields += [(s, float) for s in states] + [("energy", float)] + [(o, float) for o in self.model.outputs]
        a = np.empty(len(self.t), dtype=fields)
        for n, v in zip(self.names, varied):
            a[v] = self.values[n]
        a["ok"], a["t"], a["energy"] = self.ok, self.t, self.energy
        for k, s in enumerate(states):
            a[s] = self.x[:, k]
        for o in self.model.outputs:
            a[o] = self.outputs[o]
        return a

    def to_dataframe(self):
        """to_structured() as a pandas DataFrame, with stopped_by and error (needs pandas)."""
        import pandas as pd
        df = pd.DataFrame(self.to_structured())
        df["stopped_by"] = self.stopped_by
        df["error"] = self.error
        return df


@dataclass(frozen=True)
class EquationCheck:
    """One relation of a derivation and what eomgen found (docs/checker.md)."""
    verdict: str          # "agrees", "disagrees", "not comparable", "not read", "not judged"
    role: str             # what the row was taken for: "claim", "definition", "assumption", "condition", ...
    line: int
    column: int
    section: str
    equation: str         # as the text writes it (LaTeX)
    compared_with: str
    reason: str
    difference: str
    wrong_terms: list = field(default_factory=list)
    corrected: str = ""
    notes: list = field(default_factory=list)


class CheckResult:
    """A derivation checked against a model: its equations in order, with the report as `eomgen check` writes it."""

    def __init__(self, r):
        self.equations = [EquationCheck(**e) for e in r["equations"]]
        self.problems = [tuple(p) for p in r["problems"]]
        self.text = r["text"]
        self.markdown = r["markdown"]
        self.json = r["json"]

    @property
    def counts(self):
        """How many equations got each verdict."""
        out = {"agrees": 0, "disagrees": 0, "not comparable": 0, "not read": 0, "not judged": 0}
        for e in self.equations:
            out[e.verdict] += 1
        return out

    @property
    def disagreements(self):
        return [e for e in self.equations if e.verdict == "disagrees"]

    def __iter__(self):
        return iter(self.equations)

    def __len__(self):
        return len(self.equations)

    def __repr__(self):
        c = self.counts
        return "<eomgen.CheckResult: {} agree, {} disagree, {} not comparable, {} not read>".format(
            c["agrees"], c["disagrees"], c["not comparable"], c["not read"])

    def _repr_markdown_(self):
        return self.markdown


def check(model, derivation, path="<string>", sections=(), set=None):
    """Checks a derivation (Markdown with LaTeX, as `eomgen check` reads it) against `model` (a Model or the path
    of a model file), equation by equation. `derivation` is the text; `path` names it in the report. `sections`
    keeps only the sections whose headings contain one of these; `set` gives parameter values (SI) for the numbers
    the text works out. Returns a CheckResult."""
    if not isinstance(model, Model):
        model = load(model)
    if not isinstance(derivation, str):
        raise TypeError("check: the derivation's text (str), not " + type(derivation).__name__)
    if isinstance(sections, str):
        sections = [sections]
    return CheckResult(model._m.check(derivation, str(path), [str(s) for s in sections], _si_values(set, "set")))
