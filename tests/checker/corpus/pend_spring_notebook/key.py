"""Answer key of pend_spring_notebook (SymPy only): the spring pendulum of the Uniandes notebook."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, l, k, g, w = sp.symbols("m l k g omega", positive=True)
r, th = coords("r", "theta")
s, c = sp.sin, sp.cos

# Own kinematics: pivot at the origin, y upward, the spring l + r long at angle theta from the downward vertical.
X, Y = (l + r) * s(th), -(l + r) * c(th)
T = m / 2 * (d(X) ** 2 + d(Y) ** 2)
V = m * g * Y + k / 2 * r ** 2
L = T - V
mech = Mechanics(L, [r, th])

key = Key("https://github.com/ComputoCienciasUniandes/Demonstrations/blob/8973a22227f750dab151424473e97bc2c0b067d1/SpringPendulum/Spring%20Pendulum.ipynb",
          "elastic (spring) pendulum", "Jupyter notebook")

key.line(12, r"L = T-V", "claim", same(T - V, L), "the Lagrangian")
V_text = -m * g * c(l + r) * c(th) + k / 2 * r ** 2
T_text = m / 2 * (d(r) ** 2 + (l + r) ** 2 * d(th) ** 2)
assert same(T_text, T)
key.line(12, r"T-V = \left(\frac{1}{2}m(\dot r^2 + (l+r)^2\dot\theta^2)\right) - \left(-mg\cos(l+r)\cos\theta + \frac{1}{2}kr^2\right)",
         "claim", same(T_text - V_text, L),
         "the gravitational potential is −m g (l + r) cos θ: the text writes cos(l + r), the cosine of a length, for the "
         "factor (l + r); T and the spring term are right (the equations of motion below use the right potential)",
         correct=r"T-V = \left(\frac{1}{2}m(\dot r^2 + (l+r)^2\dot\theta^2)\right) - \left(-mg(l+r)\cos\theta + \frac{1}{2}kr^2\right)")

el = [sp.diff(sp.diff(L, d(q)), t) - sp.diff(L, q) for q in (r, th)]
key.line(17, r"\dfrac{d}{dt}\dfrac{\partial L}{\partial \dot{q}} - \dfrac{\partial L}{\partial q} = 0", "claim",
         all(mech.on_motion(e) for e in el), "Lagrange's equation, for each coordinate q = r, θ")

rdd = (l + r) * d(th) ** 2 + g * c(th) - w ** 2 * r
key.line(21, r"\ddot r = (l+r)\dot\theta^2 + g\cos\theta - \omega^2 r", "claim",
         mech.on_motion(d(r, 2), rdd.subs(w, sp.sqrt(k / m))), "the r equation with ω² = k/m (defined on the same line)")
key.line(21, r"\omega^2 = k/m", "definition", None, "defines ω (inside \\text{donde …})")
thdd = -(2 * d(r) * d(th) + g * s(th)) / (l + r)
key.line(25, r"\ddot \theta = - \dfrac{1}{l+r}\left(2\dot{r}\dot{\theta} + g\sin\theta\right)", "claim",
         mech.on_motion(d(th, 2), thdd), "the θ equation divided by m (l + r)²")

key.emit()
