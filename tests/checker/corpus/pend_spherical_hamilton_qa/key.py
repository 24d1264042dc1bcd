"""Answer key of pend_spherical_hamilton_qa (SymPy only): the spherical pendulum in Hamilton's form."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, b, g = sp.symbols("m b g", positive=True)
th, ph = coords("theta", "phi")
s, c = sp.sin, sp.cos

# Own kinematics: pivot at the origin, z upward, theta from the downward vertical.
X, Y, Z = b * s(th) * c(ph), b * s(th) * s(ph), -b * c(th)
T = m / 2 * (d(X) ** 2 + d(Y) ** 2 + d(Z) ** 2)
V = m * g * Z
L = T - V
mech = Mechanics(L, [th, ph])
pth_q, pph_q = mech.momentum(th), mech.momentum(ph)

# Own Hamiltonian by the Legendre transform, in canonical variables (q, p).
q1, q2, P1, P2, v1, v2 = sp.symbols("q1 q2 P1 P2 v1 v2")
Lv = L.subs({d(th): v1, d(ph): v2}).subs({th: q1, ph: q2})
sol = sp.solve([sp.diff(Lv, v1) - P1, sp.diff(Lv, v2) - P2], [v1, v2], dict=True)[0]
Hc = sp.simplify((P1 * v1 + P2 * v2 - Lv).subs(sol))
back = {q1: th, q2: ph, P1: pth_q, P2: pph_q}  # p = p(q, qdot) along a motion


def on_state(expr_canonical):
    return expr_canonical.subs(back)


key = Key("https://math.techqa.club/how-to-derive-directly-from-hamilton-equations-to-the-euler-lagrange-equations-4346559",
          "spherical pendulum (Hamilton's equations)", "Q&A thread")

key.line(5, r"L(\theta, \phi, \dot{\theta}, \dot\phi)=\frac{mb^2}{2}(\dot{\theta}^2+\sin^2(\theta)\dot{\phi}^2)+mbg\cos(\theta)", "claim",
         same(m * b ** 2 / 2 * (d(th) ** 2 + s(th) ** 2 * d(ph) ** 2) + m * b * g * c(th), L), "T − V, θ from the downward vertical")

E = T + V
assert same(mech.energy(), E)
key.line(7, r"H=T+V", "claim", same(on_state(Hc), E), "L has no t and T is quadratic in the velocities: H = T + V")
mid = sp.Rational(1, 2) * m * b ** 2 * d(th) ** 2 + sp.Rational(1, 2) * m * g ** 2 * s(th) ** 2 * d(ph) ** 2 + (-m * b * g * c(th))
key.line(7, r"T+V=\frac{1}{2}mb^2 \dot{\theta}^2+\frac{1}{2}mg^2sin^2(\theta)\dot{\phi}^2+(-mbg cos(\theta))", "claim", same(mid, E),
         "the φ̇² term of T is ½ m b² sin²θ φ̇²: the text writes m g² for m b²",
         correct=r"T+V=\frac{1}{2}mb^2 \dot{\theta}^2+\frac{1}{2}mb^2sin^2(\theta)\dot{\phi}^2+(-mbg cos(\theta))")
Hp = P1 ** 2 / (2 * m * b ** 2) + P2 ** 2 / (2 * m * b ** 2 * s(q1) ** 2) - m * g * b * c(q1)
assert same(Hp, Hc)
key.line(7, r"\frac{1}{2}mb^2 \dot{\theta}^2+\frac{1}{2}mg^2sin^2(\theta)\dot{\phi}^2+(-mbg cos(\theta))=\frac{p_{\theta}^2}{2mb^2}+\frac{p_{\phi}^2}{2mb^2 sin^2(\theta)}-mgb cos(\theta)",
         "claim", same(mid, on_state(Hp)),
         "the right-hand side is the Hamiltonian in the momenta (so H = … of the right side holds), but it is not the "
         "middle side, which has m g² for m b²",
         correct=r"\frac{1}{2}mb^2 \dot{\theta}^2+\frac{1}{2}mb^2sin^2(\theta)\dot{\phi}^2+(-mbg cos(\theta))=\frac{p_{\theta}^2}{2mb^2}+\frac{p_{\phi}^2}{2mb^2 sin^2(\theta)}-mgb cos(\theta)")

key.line(8, r"\dot{p_{\phi}}=-\frac{\partial H}{\partial \phi} = 0", "claim",
         mech.on_motion(sp.diff(pph_q, t), on_state(-sp.diff(Hc, q2))) and same(sp.diff(Hc, q2), 0),
         "φ is cyclic: p_φ is conserved")
dHdth = sp.diff(Hc, q1)
step = -(-P2 ** 2 * 2 * c(q1) / (2 * m * b ** 2 * s(q1) ** 3) - (m * g * b * (-s(q1))))
last = P2 ** 2 * c(q1) / (m * b ** 2 * s(q1) ** 3) - m * g * b * s(q1)
key.line(9, r"\dot{p_{\theta}}=-\frac{\partial H}{\partial \theta} =- (-\frac{p_{\phi}^2 2cos(\theta)}{2mb^2 sin^3(\theta)}-(mgb(-sin(\theta))))= \frac{p_{\phi}^2 cos(\theta)}{mb^2 sin^3(\theta)}-mgbsin(\theta)",
         "claim", mech.on_motion(sp.diff(pth_q, t), on_state(-dHdth)) and same(-dHdth, step) and same(step, last),
         "Hamilton's equation for p_θ, worked out correctly")
key.line(10, r"\dot{\theta}=\frac{\partial H}{\partial p_{\theta}} =\frac{2 p_{\theta}}{2mb^2}=\frac{p_{\theta}}{mb^2}", "claim",
         same(on_state(sp.diff(Hc, P1)), d(th)) and same(sp.diff(Hc, P1), 2 * P1 / (2 * m * b ** 2)) and same(sp.diff(Hc, P1), P1 / (m * b ** 2)),
         "Hamilton's equation for θ")
key.line(11, r"\dot{\phi}=\frac{\partial H}{\partial p_{\phi}} =\frac{2p_{\phi}}{2mb^2 sin^2(\theta)}=\frac{p_{\phi}}{mb^2 sin^2(\theta)}", "claim",
         same(on_state(sp.diff(Hc, P2)), d(ph)) and same(sp.diff(Hc, P2), P2 / (m * b ** 2 * s(q1) ** 2)),
         "Hamilton's equation for φ")

key.emit()
