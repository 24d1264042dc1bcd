#!/usr/bin/env python3
"""The n-link planar pendulum from Python the way SymPy users do it, start to finish: LagrangesMethod for M and f,
lambdify (the backend PyDy's System uses by default; PyDy itself is not packaged in Debian) and SciPy's solve_ivp
with RK45 (Dormand-Prince 5(4), as eomgen's dopri5), x'' from numpy.linalg.solve(M, f) at each step. The model and
the initial state are those of bench/python_api.py's eomgen side: `eomgen.family("pendulum:n=N")` with its defaults
(every m_i = 1 kg, l_i = 1 m, g = 9.81; generator/model/families.cpp) and theta1(0) = 0.1, the other angles and every
rate 0 (small oscillations, so that two integrators' results can be compared at the end).

Usage: sympy_python_pendulum.py N T_END RTOL ATOL
Prints one JSON line: {"n", "sympy", "derive_s", "lambdify_s", "integrate_s", "total_s" (wall, from before
`import sympy`), "rhs_calls", "x_end"}.
"""
import json
import sys
import time


def main():
    n, t_end, rtol, atol = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
    start = time.perf_counter()
    import numpy as np
    import scipy.integrate
    import sympy as sp
    import sympy.physics.mechanics as me

    t = me.dynamicsymbols._t
    q = me.dynamicsymbols(" ".join(f"theta{i}" for i in range(1, n + 1)))
    q = list(q) if n > 1 else [q]
    m = list(sp.symbols(" ".join(f"m{i}" for i in range(1, n + 1)) + ",", seq=True))
    l = list(sp.symbols(" ".join(f"l{i}" for i in range(1, n + 1)) + ",", seq=True))
    g = sp.Symbol("g")
    T = V = x = y = 0
    for i in range(n):
        x += l[i] * sp.sin(q[i])
        y -= l[i] * sp.cos(q[i])
        T += m[i] / 2 * (x.diff(t) ** 2 + y.diff(t) ** 2)
        V += m[i] * g * y
    lm = me.LagrangesMethod(T - V, q)
    lm.form_lagranges_equations()
    M, F = lm.mass_matrix, lm.forcing
    derived = time.perf_counter()

    qs = [sp.Symbol(f"q{i}") for i in range(n)]
    us = [sp.Symbol(f"u{i}") for i in range(n)]
    rep = {q[i].diff(t): us[i] for i in range(n)}
    rep.update({q[i]: qs[i] for i in range(n)})
    args = qs + us + m + l + [g]
    mass = sp.lambdify(args, M.xreplace(rep), modules="numpy", cse=True)
    forcing = sp.lambdify(args, F.xreplace(rep), modules="numpy", cse=True)
    lambdified = time.perf_counter()

    params = [1.0] * n + [1.0] * n + [9.81]  # the family's defaults (generator/model/families.cpp)
    calls = [0]

    def rhs(_t, state):
        calls[0] += 1
        a = list(state) + params
        qdd = np.linalg.solve(np.asarray(mass(*a), dtype=float), np.asarray(forcing(*a), dtype=float).ravel())
        return np.concatenate([state[n:], qdd])

    x0 = np.zeros(2 * n)
    x0[0] = 0.1
    sol = scipy.integrate.solve_ivp(rhs, (0.0, t_end), x0, method="RK45", rtol=rtol, atol=atol)
    if sol.status != 0:
        raise RuntimeError(sol.message)
    done = time.perf_counter()
    print(json.dumps({"n": n, "sympy": sp.__version__, "derive_s": derived - start, "lambdify_s": lambdified - derived,
                      "integrate_s": done - lambdified, "total_s": done - start, "rhs_calls": calls[0],
                      "x_end": [float(v) for v in sol.y[:, -1]]}), flush=True)


if __name__ == "__main__":
    main()
