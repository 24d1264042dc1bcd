"""Answer key: cylinder rolling down an incline with a Lagrange multiplier (blebon.com). SymPy only."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, r, alpha, Z, g = sp.symbols("m r alpha Z g", positive=True)
lam = sp.Symbol("lambda")
x, theta = coords("x", "theta")

# Own kinematics: centre at distance x down the slope from the top, r off the slope; the cylinder turns by theta.
I = sp.Rational(1, 2) * m * r**2
height = (Z - x) * sp.sin(alpha) + r * sp.cos(alpha)
T = sp.Rational(1, 2) * m * d(x)**2 + sp.Rational(1, 2) * I * d(theta)**2
V = m * g * height
L = T - V
f = x - r * theta
# The text's convention: d/dt dL/dq' - dL/dq = lambda df/dq.
EL = {q: sp.diff(sp.diff(L, d(q)), t) - sp.diff(L, q) - lam * sp.diff(f, q) for q in (x, theta)}
sol = sp.solve([EL[x], EL[theta], sp.diff(f, t, 2)], [d(x, 2), d(theta, 2), lam], dict=True)[0]


def holds(expr):
    return same(sp.sympify(expr).subs(sol).subs(d(x), r * d(theta)), 0)


key = Key("http://www.blebon.com/physics-examples/51-classical-mechanics/55-cylinder-rolling-down-an-incline-without-slipping",
          "uniform cylinder rolling down a fixed incline (rolling constraint with a multiplier)", "personal blog (worked example)")

Lt = sp.Rational(1, 2) * m * d(x)**2 + sp.Rational(1, 2) * I * d(theta)**2 - m * g * (Z - x + r) * sp.sin(alpha)
diff_L = sp.simplify(Lt - L)
key.line(10, r"L = \frac{1}{2}m\dot{x}^{2} + \frac{1}{2}I\omega^{2} - mg\left(Z - x + r\right)\sin\alpha", "claim",
         not diff_L.has(x, theta, d(x), d(theta)),
         "T - V up to an additive constant: the centre is (Z - x) sin(alpha) + r cos(alpha) high, the text has r sin(alpha), a constant that does not change the motion")
key.line(14, r"f = x - r\theta", "definition", None, "names the constraint function")
key.line(14, r"x - r\theta = 0", "kinematics", same(sp.diff(f, t).subs(d(x), r * d(theta)), 0) and holds(sp.diff(f, t, 2)),
         "rolling without slipping (x and theta both 0 at the start)")
key.line(18, r"m\ddot{x} - mg\sin\alpha = \lambda", "claim", holds(m * d(x, 2) - m * g * sp.sin(alpha) - lam),
         "Lagrange's equation for x with the multiplier (d/dt dL/dq' - dL/dq = lambda df/dq)")
key.line(20, r"I\ddot{\theta} = -\lambda r", "claim", holds(I * d(theta, 2) + lam * r), "the same for theta (df/dtheta = -r)")
key.line(24, r"\ddot{x} = r\ddot{\theta}", "kinematics", holds(d(x, 2) - r * d(theta, 2)), "f differentiated twice")
key.line(28, r"-\frac{mr^{2}}{I}\lambda - mg\sin\alpha = \lambda", "claim",
         holds(-m * r**2 / I * lam - m * g * sp.sin(alpha) - lam), "the three equations combined")
s_ = sp.Symbol("s", positive=True)
I_disk = sp.integrate(m / (sp.pi * r**2) * s_**2 * 2 * sp.pi * s_, (s_, 0, r))      # uniform disk about its axis
key.line(32, r"I = \frac{1}{2}mr^{2}", "claim", same(I_disk, m * r**2 / 2),
         "uniform solid cylinder about its axis")
key.line(34, r"\lambda = \frac{mg\sin\alpha}{3}", "claim", holds(lam - m * g * sp.sin(alpha) / 3),
         "sign: -2 lambda - mg sin(alpha) = lambda gives lambda = -mg sin(alpha)/3 (the friction force points up the slope)",
         correct=r"\lambda = -\frac{mg\sin\alpha}{3}")
key.line(38, r"\ddot{x} = \frac{2}{3}g\sin\alpha", "claim", holds(d(x, 2) - sp.Rational(2, 3) * g * sp.sin(alpha)),
         "mx'' = mg sin(alpha) + lambda with the right lambda")
key.line(40, r"f = 0", "condition", None, "the rolling condition, which fails once the cylinder slips")
assert holds(lam + m * g * sp.sin(alpha) / 3)
key.emit()
