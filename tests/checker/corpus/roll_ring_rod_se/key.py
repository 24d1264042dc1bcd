"""Answer key: point mass on a rod inside a rolling massless ring (physics.stackexchange 433777). SymPy only."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, R, g = sp.symbols("m R g", positive=True)
lam = sp.Symbol("lambda")
x, theta = coords("x", "theta")

# Own kinematics: the mass sits at the centre of the ring plus (R/2)(cos theta, sin theta); the centre is at (x, R).
xm = x + R / 2 * sp.cos(theta)
ym = R + R / 2 * sp.sin(theta)
T = sp.Rational(1, 2) * m * (d(xm)**2 + d(ym)**2)
V = m * g * ym
L = sp.expand(T - V)
f = x + R * theta                      # rolling: the ring turns counterclockwise by theta, the centre moves by -R theta

# Lagrange's equations with the multiplier in the text's convention: d/dt dL/dq' - dL/dq - lambda df/dq = 0.
EL = {q: sp.diff(sp.diff(L, d(q)), t) - sp.diff(L, q) - lam * sp.diff(f, q) for q in (x, theta)}
sol = sp.solve([EL[x], EL[theta], sp.diff(f, t, 2)], [d(x, 2), d(theta, 2), lam], dict=True)[0]
on_constraint = {d(x): -R * d(theta), x: -R * theta}


def holds(expr):
    """expr = 0 along every motion (accelerations and lambda from the constrained equations, on the constraint)."""
    r = sp.sympify(expr).subs(sol).subs(on_constraint)
    return same(r, 0)


# The reduced motion (x = -R theta eliminated) for the one-coordinate lines.
red = Mechanics(L.subs({d(x): -R * d(theta), x: -R * theta}), [theta])
assert holds(sp.diff(f, t, 2)) and same(sol[d(theta, 2)].subs(on_constraint), red.accelerations[d(theta, 2)])

key = Key("https://physics.stackexchange.com/questions/433777/lagrangian-of-point-mass-on-rod-inside-ring-with-holonomic-constraint",
          "point mass on a rod inside a massless ring rolling on a plane (constraint x + R theta = 0, multiplier)",
          "Q&A thread (the question: where is my mistake)")

key.line(12, r"f(x,\theta) = x + R\theta", "definition", None, "names the constraint function")
key.line(12, r"x + R\theta = 0", "kinematics", same(sp.diff(f, t).subs(d(x), -R * d(theta)), 0),
         "rolling: the ring turns counterclockwise by theta while its centre moves by -R theta")

L_text = (sp.Rational(1, 2) * m * d(x)**2 + sp.Rational(1, 2) * m * R**2 / 4 * d(theta)**2
          - m * g * (R / 2 * sp.sin(theta) + R))
key.line(14, r"L = \frac{1}{2} m \dot{x}^{2} + \frac{1}{2} m \frac{R^2}{4}\dot{\theta}^{2} - mg(\frac{R}{2}\sin{\theta} + R)",
         "claim", same(L_text, L),
         "T misses the cross term -(1/2) m R sin(theta) x' theta' of the mass's velocity (x' + R/2 d(cos theta)/dt)",
         correct=r"L = \frac{1}{2} m \dot{x}^{2} - \frac{1}{2} m R\sin{\theta}\,\dot{x}\dot{\theta} + \frac{1}{2} m \frac{R^2}{4}\dot{\theta}^{2} - mg(\frac{R}{2}\sin{\theta} + R)")

key.line(18, r"\frac{d}{dt}\frac{\partial L}{\partial \dot{x}} - \frac{\partial L}{\partial x} - \lambda\frac{\partial f}{\partial x} = 0",
         "claim", holds(EL[x]), "Lagrange's equation for x with the multiplier (the text's sign convention for lambda)")
key.line(20, r"\frac{d}{dt}\frac{\partial L}{\partial \dot{\theta}} - \frac{\partial L}{\partial \theta} - \lambda\frac{\partial f}{\partial \theta} = 0",
         "claim", holds(EL[theta]), "Lagrange's equation for theta with the multiplier")

key.line(24, r"m\ddot{x} - \lambda = 0", "claim", holds(m * d(x, 2) - lam),
         "misses -(mR/2)(theta'' sin theta + theta'^2 cos theta) from the cross term of T",
         correct=r"m\ddot{x} - \frac{mR}{2}(\ddot{\theta}\sin{\theta} + \dot{\theta}^{2}\cos{\theta}) - \lambda = 0")
key.line(26, r"m\frac{R^{2}}{4} \ddot{\theta} -mg\frac{R}{2}\cos{\theta}- \lambda R = 0", "claim",
         holds(m * R**2 / 4 * d(theta, 2) - m * g * R / 2 * sp.cos(theta) - lam * R),
         "sign of the gravity term (dL/dtheta = -mg(R/2)cos theta even with the text's L) and the missing -(mR/2) sin(theta) x'' term",
         correct=r"m\frac{R^{2}}{4} \ddot{\theta} - \frac{mR}{2}\sin{\theta}\,\ddot{x} + mg\frac{R}{2}\cos{\theta} - \lambda R = 0")
key.line(30, r"\lambda = m\ddot{x}", "claim", holds(lam - m * d(x, 2)),
         "follows from the wrong x equation",
         correct=r"\lambda = m\ddot{x} - \frac{mR}{2}(\ddot{\theta}\sin{\theta} + \dot{\theta}^{2}\cos{\theta})")
key.line(32, r"\ddot{x} = -R\ddot{\theta}", "kinematics", holds(d(x, 2) + R * d(theta, 2)),
         "the rolling constraint differentiated twice")
key.line(36, r"m\frac{R^{2}}{4} \ddot{\theta} -mg\frac{R}{2}\cos{\theta} + m \ddot{\theta} R^{2} = 0", "claim",
         red.on_motion(m * R**2 / 4 * d(theta, 2) - m * g * R / 2 * sp.cos(theta) + m * d(theta, 2) * R**2),
         "the theta equation on the constraint is m R^2 (5/4 + sin theta) theta'' + (m R^2/2) cos(theta) theta'^2 + mg(R/2) cos theta = 0",
         correct=r"mR^{2}\left(\frac{5}{4} + \sin{\theta}\right)\ddot{\theta} + \frac{mR^{2}}{2}\cos{\theta}\,\dot{\theta}^{2} + mg\frac{R}{2}\cos{\theta} = 0")
key.line(40, r"\ddot{\theta} = \frac{2g\cos{\theta}}{5R}", "claim",
         red.on_motion(d(theta, 2) - 2 * g * sp.cos(theta) / (5 * R)),
         "sign, the theta'^2 term and the sin(theta) in the effective inertia are wrong",
         correct=r"\ddot{\theta} = -\frac{2\cos{\theta}\,(R\dot{\theta}^{2} + g)}{R(5 + 4\sin{\theta})}")

# The corrections are themselves right:
assert red.on_motion(m * R**2 * (sp.Rational(5, 4) + sp.sin(theta)) * d(theta, 2)
                     + m * R**2 / 2 * sp.cos(theta) * d(theta)**2 + m * g * R / 2 * sp.cos(theta))
assert red.on_motion(d(theta, 2) + 2 * sp.cos(theta) * (R * d(theta)**2 + g) / (R * (5 + 4 * sp.sin(theta))))
assert holds(m * d(x, 2) - m * R / 2 * (d(theta, 2) * sp.sin(theta) + d(theta)**2 * sp.cos(theta)) - lam)
assert holds(m * R**2 / 4 * d(theta, 2) - m * R / 2 * sp.sin(theta) * d(x, 2) + m * g * R / 2 * sp.cos(theta) - lam * R)

key.emit()
