"""Answer key of spring_ring (SymPy only): Goldstein 6.10 (a), three masses on a circle joined by arc springs, as
asked on Physics Stack Exchange."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, k, R = sp.symbols("m k R", positive=True)
w2 = sp.Symbol("omega2")
th = coords("theta1", "theta2", "theta3")

# Own kinematics: mass i sits at arc position s_i = R (phi_i0 + theta_i) on the circle; the spring between masses i
# and j spans the arc s_j - s_i (+ 2 pi R for the one that closes the ring), so its change of length is R (theta_j -
# theta_i) whatever the constant, and its energy is k/2 times the square of that change (the problem's springs).
s_pos = [R * (sp.Rational(2 * i, 3) * sp.pi + th[i]) for i in range(3)]
arcs = [s_pos[1] - s_pos[0], s_pos[2] - s_pos[1], s_pos[0] + 2 * sp.pi * R - s_pos[2]]
rest = [arc.subs({q: 0 for q in th}) for arc in arcs]
V = sum(k / 2 * (arc - a0) ** 2 for arc, a0 in zip(arcs, rest))
T = sum(m / 2 * d(si) ** 2 for si in s_pos)
mech = Mechanics(T - V, list(th))

q = sp.symbols("q1:4")
qd = sp.symbols("qd1:4")
sub_q = {th[i]: q[i] for i in range(3)}
sub_qd = {d(th[i]): qd[i] for i in range(3)}
Vq = sp.expand(V.subs(sub_q))
Tq = sp.expand(T.subs(sub_qd))
Vmat = sp.hessian(Vq, q)
Tmat = sp.hessian(Tq, qd)

_TEXT = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "derivation.md"), encoding="utf-8").read().split("\n")


def at(n, fragment):
    """Line n of derivation.md, checked to hold the fragment (so that a line number cannot silently drift)."""
    assert fragment in _TEXT[n - 1], (n, fragment, _TEXT[n - 1])
    return n


key = Key("https://physics.stackexchange.com/q/830674", "three masses on a ring joined by arc springs (Goldstein 6.10)",
          "Q&A thread")

t1, t2, t3 = th
V_text = k / 2 * (R * t2 - R * t1) ** 2 + k / 2 * (R * t3 - R * t2) ** 2 + k / 2 * (R * t3 - R * t1) ** 2
key.line(at(8, r"V = \frac{k}{2}\left[R\theta_{2}"), r"V = \frac{k}{2}\left[R\theta_{2}-R\theta_{1}\right]^{2} + "
         r"\frac{k}{2}\left[R\theta_{3}-R\theta_{2}\right]^{2} + \frac{k}{2}\left[R\theta_{3}-R\theta_{1}\right]^{2}",
         "claim", same(V_text, V),
         "the three arc springs; the ring-closing spring's stretch is R(θ₁ − θ₃), which the text writes with the "
         "opposite sign inside a square")

T_text = m * R ** 2 / 2 * (d(t1) ** 2 + d(t2) ** 2 + d(t3) ** 2)
key.line(at(12, r"T = \frac{mR^{2}}{2}"), r"T = \frac{mR^{2}}{2}\left(\dot{\theta}_{1}^{2}+\dot{\theta}_{2}^{2}+"
         r"\dot{\theta}_{3}^{2}\right)", "claim", same(T_text, T), "each mass moves at R θ̇ᵢ along the circle")

Vm_text = sp.Matrix([[2 * k * R ** 2, -k * R ** 2, -k * R ** 2], [-k * R ** 2, 2 * k * R ** 2, -k * R ** 2],
                     [-k * R ** 2, -k * R ** 2, 2 * k * R ** 2]])
Tm_text = sp.diag(m * R ** 2, m * R ** 2, m * R ** 2)
secular = sp.factor((Vmat - w2 * Tmat).det())
roots = set(sp.solve(secular, w2))
key.line(at(16, r"\left|\mathbf{V}-\omega^{2}\mathbf{T}\right| = 0"), r"\left|\mathbf{V}-\omega^{2}\mathbf{T}\right| = 0",
         "claim", (Vm_text - Vmat).is_zero_matrix and (Tm_text - Tmat).is_zero_matrix,
         "the secular equation of the system, with its V and T matrices (those of line 20): det = -m R^6 ω² (3k - m ω²)²")
key.line(at(16, r"\omega^{2}\in \left\{0,\frac{3k}{m}\right\}"), r"\omega^{2}\in \left\{0,\frac{3k}{m}\right\}", "claim",
         roots == {0, 3 * k / m},
         "the roots of the secular equation: 0 (the rigid rotation) and 3k/m, a double root, so the two vibrations the "
         "asker expects are degenerate, not missing")
key.line(at(20, r"\mathbf{V} = \left(\begin{array}{ccc} 2kR^{2}"), r"\mathbf{V} = \left(\begin{array}{ccc} 2kR^{2} & "
         r"-kR^{2} & -kR^{2}\\ \dots \end{array}\right)", "claim", (Vm_text - Vmat).is_zero_matrix,
         "the Hessian of V in the θᵢ")
key.line(at(20, r"\mathbf{T} = \left(\begin{array}{ccc} mR^{2}"), r"\mathbf{T} = \left(\begin{array}{ccc} mR^{2} & 0 & "
         r"0\\ \dots \end{array}\right)", "claim", (Tm_text - Tmat).is_zero_matrix, "the kinetic matrix in the θ̇ᵢ")

assert sp.simplify(secular + m * R ** 6 * w2 * (3 * k - m * w2) ** 2) == 0
key.emit()
