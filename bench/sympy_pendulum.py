#!/usr/bin/env python3
"""The n-link planar pendulum through SymPy: LagrangesMethod + cse + ccode, timed, written as a C++ header.

Usage: sympy_pendulum.py N OUT_DIR
Writes OUT_DIR/sympy_pendulum_N.hpp (namespace sympy_pendulum_N, function
  dynamics(const double* q, const double* qd, const double* p, double* M, double* f)
with M column-major n x n and p in eomgen's parameter order m1..mn, l1..ln, g) and prints one JSON line:
  {"n", "sympy", "lagrange_s", "subs_s", "cse_s", "ccode_s", "total_s" (wall), "cpu_s", "peak_rss_kb"}
The model is the one `eomgen generate --family pendulum:n=N` writes (generator/model/families.cpp): point
masses m_i on links l_i, absolute angles theta_i from the downward vertical, T = sum m_i/2 (x_i'^2 + y_i'^2)
with x_i = sum_{k<=i} l_k sin(theta_k), y_i = -sum_{k<=i} l_k cos(theta_k), V = sum m_i g y_i.
The clock starts after `import sympy` (as eomgen's starts after the process is up).
"""
import json
import os
import resource
import sys
import time


def main():
    n = int(sys.argv[1])
    out_dir = sys.argv[2]
    import sympy as sp
    import sympy.physics.mechanics as me

    t0 = time.perf_counter()
    c0 = time.process_time()
    t = me.dynamicsymbols._t
    q = me.dynamicsymbols(" ".join(f"theta{i}" for i in range(1, n + 1)))
    q = list(q) if n > 1 else [q]
    m = sp.symbols(" ".join(f"m{i}" for i in range(1, n + 1)))
    m = list(m) if n > 1 else [m]
    l = sp.symbols(" ".join(f"l{i}" for i in range(1, n + 1)))
    l = list(l) if n > 1 else [l]
    g = sp.Symbol("g")
    T = 0
    V = 0
    x = 0
    y = 0
    for i in range(n):
        x += l[i] * sp.sin(q[i])
        y -= l[i] * sp.cos(q[i])
        T += m[i] / 2 * (x.diff(t) ** 2 + y.diff(t) ** 2)
        V += m[i] * g * y
    L = T - V
    lm = me.LagrangesMethod(L, q)
    lm.form_lagranges_equations()
    M = lm.mass_matrix
    F = lm.forcing
    t1 = time.perf_counter()

    # Plain symbols for q(t) and q'(t), derivatives first, so that ccode prints variables.
    qs = [sp.Symbol(f"theta{i + 1}") for i in range(n)]
    qds = [sp.Symbol(f"theta{i + 1}_dot") for i in range(n)]
    rep = {q[i].diff(t): qds[i] for i in range(n)}
    rep.update({q[i]: qs[i] for i in range(n)})
    outputs = [M[i, j].xreplace(rep) for j in range(n) for i in range(n)]  # column-major
    outputs += [F[i].xreplace(rep) for i in range(n)]
    t2 = time.perf_counter()

    replacements, reduced = sp.cse(outputs)
    t3 = time.perf_counter()

    lines = [f"const double {sym} = {sp.ccode(expr)};" for sym, expr in replacements]
    for k, expr in enumerate(reduced):
        target = f"M[{k}]" if k < n * n else f"f[{k - n * n}]"
        lines.append(f"{target} = {sp.ccode(expr)};")
    t4 = time.perf_counter()
    c4 = time.process_time()

    locals_ = [f"const double theta{i + 1} = q[{i}];" for i in range(n)]
    locals_ += [f"const double theta{i + 1}_dot = qd[{i}];" for i in range(n)]
    names = [f"m{i + 1}" for i in range(n)] + [f"l{i + 1}" for i in range(n)] + ["g"]
    locals_ += [f"const double {name} = p[{k}];" for k, name in enumerate(names)]
    body = "\n".join("    " + s for s in locals_ + lines)
    header = f"""// Written by bench/sympy_pendulum.py with SymPy {sp.__version__}: LagrangesMethod + cse + ccode, n = {n}.
#pragma once
#include <cmath>

namespace sympy_pendulum_{n} {{
// M (column-major {n}x{n}) and f of M q'' = f; p = m1..m{n}, l1..l{n}, g.
inline void dynamics(const double* q, const double* qd, const double* p, double* M, double* f) {{
    using std::sin; using std::cos; using std::pow; using std::sqrt;
    // BEGIN BODY
{body}
    // END BODY
    (void)q; (void)qd; (void)p;
}}
}}  // namespace sympy_pendulum_{n}
"""
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, f"sympy_pendulum_{n}.hpp")
    with open(path + ".tmp", "w") as fh:
        fh.write(header)
    os.replace(path + ".tmp", path)
    print(json.dumps({
        "n": n, "sympy": sp.__version__,
        "lagrange_s": t1 - t0, "subs_s": t2 - t1, "cse_s": t3 - t2, "ccode_s": t4 - t3, "total_s": t4 - t0,
        "cpu_s": c4 - c0,
        "peak_rss_kb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss,
    }), flush=True)


if __name__ == "__main__":
    main()
