"""Answer key: two spring-coupled pendulums of unequal masses and lengths (Oscillators.jl, AsymmetricPendula.ipynb)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


m1, m2, l1, l2, k, g, w = sp.symbols("m_1 m_2 l_1 l_2 k g omega", positive=True)

# Own derivation: the full pendulums in their angles, then the small-amplitude (quadratic) Lagrangian, then the
# bobs' horizontal displacements x_i = l_i theta_i (to first order). Pivots a spring's natural length apart; the
# spring's stretch is the change of the bobs' horizontal separation, l2 sin(th2) - l1 sin(th1).
th1, th2 = coords("th1", "th2")
eps = sp.Symbol("epsilon")
T_full = m1 / 2 * l1 ** 2 * d(th1) ** 2 + m2 / 2 * l2 ** 2 * d(th2) ** 2
V_full = (m1 * g * l1 * (1 - sp.cos(th1)) + m2 * g * l2 * (1 - sp.cos(th2))
          + k / 2 * (l2 * sp.sin(th2) - l1 * sp.sin(th1)) ** 2)
small = {th1: eps * th1, th2: eps * th2}
V2 = sp.series(V_full.subs(small), eps, 0, 3).removeO().subs(eps, 1)   # to second order in the angles
x1, x2 = coords("x1", "x2")
to_x = {th1: x1 / l1, th2: x2 / l2}
L = sp.expand((T_full - V2).subs({d(th1): d(x1) / l1, d(th2): d(x2) / l2}).subs(to_x))
mech = Mechanics(L, [x1, x2])
a1, a2 = mech.accelerations[d(x1, 2)], mech.accelerations[d(x2, 2)]

key = Key("https://github.com/KahaanGandhi/Oscillators.jl/blob/87a24e951f43b873cd465b4dde7643a82e42b540/AsymmetricPendula.ipynb",
          "two pendulums of unequal masses and lengths coupled by a spring (small oscillations, normal modes)",
          "Jupyter notebook")

ln1 = at(r"$$ m_1 \ddot{x_1} = \frac{-m_1 g}{l_1}x_1 + k(x_2 - x_1)")
key.line(ln1, r"m_1 \ddot{x_1} = \frac{-m_1 g}{l_1}x_1 + k(x_2 - x_1)", "claim",
         mech.on_motion(m1 * d(x1, 2), -m1 * g / l1 * x1 + k * (x2 - x1)),
         "Newton's law for bob 1 at small amplitude (gravity's restoring force m_1 g x_1 / l_1, the spring's k(x_2 - x_1))")
key.line(ln1, r"\ddot{x_1} = \frac{-g}{l_1}x_1 + \frac{k}{m_1}(x_2 - x_1)", "claim",
         mech.on_motion(d(x1, 2), -g / l1 * x1 + k / m1 * (x2 - x1)), "the same divided by m_1")

ln2 = at(r"$$ m_2 \ddot{x_2} = \frac{-m_2 g}{l_2}x_1 - k(x_2 - x_1)")
key.line(ln2, r"m_2 \ddot{x_2} = \frac{-m_2 g}{l_2}x_1 - k(x_2 - x_1)", "claim",
         mech.on_motion(m2 * d(x2, 2), -m2 * g / l2 * x1 - k * (x2 - x1)),
         "gravity's restoring force on bob 2 is -m_2 g x_2 / l_2: the text has x_1 for x_2 in that term",
         r"m_2 \ddot{x_2} = \frac{-m_2 g}{l_2}x_2 - k(x_2 - x_1)")
key.line(ln2, r"\ddot{x_2} = \frac{-g}{l_2}x_2 - \frac{k}{m_1}(x_2 - x_1)", "claim",
         mech.on_motion(d(x2, 2), -g / l2 * x2 - k / m1 * (x2 - x1)),
         "dividing bob 2's equation by m_2 gives k/m_2: the text has k/m_1 (the gravity term here has x_2 again, "
         "so this side does not follow from the left side either)",
         r"\ddot{x_2} = \frac{-g}{l_2}x_2 - \frac{k}{m_2}(x_2 - x_1)")

A = sp.Matrix([[k / m1 + g / l1, -k / m1], [-k / m2, k / m2 + g / l2]])
X = sp.Matrix([x1, x2])
rows = -A * X
ok = mech.on_motion(d(x1, 2), rows[0]) and mech.on_motion(d(x2, 2), rows[1])
key.line(at(r"= - "), r"\begin{bmatrix}\ddot{x}_1 \\ \ddot{x}_2\end{bmatrix} = - \begin{bmatrix}\frac{k}{m_1} + \frac{g}{l_1} & -\frac{k}{m_1} \\ -\frac{k}{m_2} & \frac{k}{m_2} + \frac{g}{l_2}\end{bmatrix}\begin{bmatrix}x_1 \\ x_2\end{bmatrix}",
         "claim", ok, "the equations of motion in matrix form (right: k/m_2 and x_2 in the second row)")

# Normal modes of the key's own equations: x = X e^{i omega t} gives (K - omega^2 M) X = 0 with M, K from L.
Mm = sp.Matrix(2, 2, lambda i, j: sp.diff(L, d([x1, x2][i]), d([x1, x2][j])))
Km = sp.Matrix(2, 2, lambda i, j: -sp.diff(L, [x1, x2][i], [x1, x2][j]))
char_own = sp.expand((Km - w ** 2 * Mm).det())
B = sp.Matrix([[k / m1 + g / l1 - w ** 2, -k / m1], [-k / m2, k / m2 + g / l2 - w ** 2]])
char_text = sp.expand(B.det())
key.line(at(r"\right) = 0"), r"\text{det}\left(\begin{bmatrix}\frac{k}{m_1} + \frac{g}{l_1} - \omega^2 & -\frac{k}{m_1} \\ -\frac{k}{m_2} & \frac{k}{m_2} + \frac{g}{l_2} - \omega^2\end{bmatrix}\right) = 0",
         "claim", same(char_text * m1 * m2, char_own),
         "the characteristic equation of the normal modes, det(K - omega^2 M) = 0 divided by m_1 m_2")
key.emit()
