"""Answer key: solid cylinder rolling inside a hollow cylinder, small oscillations (cheenta.com). SymPy only."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, r, R, g = sp.symbols("m r R g", positive=True)
theta = coords("theta")
eps = sp.Symbol("epsilon", positive=True)

# Own kinematics: the axis of the small cylinder is at (R - r)(sin theta, -cos theta) from the axis of the big one;
# rolling without slipping inside: the contact point is at rest, so the spin is omega = (R - r) theta'/r.
axis = sp.Matrix([(R - r) * sp.sin(theta), -(R - r) * sp.cos(theta)])
vel = sp.diff(axis, t)
v2 = sp.simplify(vel.dot(vel))
spin = (R - r) * d(theta) / r
# (check: velocity of the material point at the contact, axis + r*(sin, -cos), is zero with this spin, taken clockwise)
contact_rel = r * sp.Matrix([sp.sin(theta), -sp.cos(theta)])
v_contact = vel + (-spin) * sp.Matrix([-contact_rel[1], contact_rel[0]])
assert same(v_contact[0], 0) and same(v_contact[1], 0)
s_ = sp.Symbol("s", positive=True)
I = sp.integrate(m / (sp.pi * r**2) * s_**2 * 2 * sp.pi * s_, (s_, 0, r))      # uniform solid cylinder
T = sp.Rational(1, 2) * m * v2 + sp.Rational(1, 2) * I * spin**2
V = m * g * (R - r) * (1 - sp.cos(theta))
mech = Mechanics(T - V, [theta])


def small(expr, order):
    """expr along the motion, expanded with theta, theta', theta'' all of order epsilon: zero through `order`."""
    e = sp.sympify(expr).subs(mech.accelerations)
    e = e.subs({d(theta): eps * sp.Symbol("w"), theta: eps * sp.Symbol("q")})
    ser = sp.series(e, eps, 0, order + 1).removeO()
    return same(ser, 0)


key = Key("https://www.cheenta.com/time-period-of-a-rolling-cylinder/",
          "solid cylinder rolling without slipping inside a fixed hollow cylinder, small oscillations",
          "tutorial / problem-solving site (worked solution)")

x = (R - r) * theta          # the text's x (line 21): arc moved by the axis
E_text = sp.Rational(1, 2) * m * ((R - r) * d(theta))**2 + sp.Rational(1, 2) * I * spin**2 + m * g * (R - r) * (1 - sp.cos(theta))
key.line(11, r"\frac{1}{2}mv^2+{\frac{1}{2}I\omega^2+mg(R-r)(1-cos\theta)}=C", "claim", mech.on_motion(sp.diff(E_text, t)),
         "energy conservation with v = (R-r) theta', omega = (R-r) theta'/r ('cos' written without its backslash)")
key.line(13, r"I=1/2mr^2", "claim", same(I, m * r**2 / 2), "uniform solid cylinder about its axis (read as (1/2) m r^2)")
E15 = sp.Rational(3, 4) * m * sp.diff(x, t)**2 + m * g * (R - r) * theta**2 / 2
key.line(15, r"3/4m(dx/dt)^2+mg(R-r)\theta^2/2=C", "approximation",
         small(E15 - E_text, 3) and small(sp.diff(E15, t), 3),
         "the energy to second order in theta (1 - cos theta ~ theta^2/2, T = 3/4 m x'^2 exactly); conserved to that order")
key.line(21, r"x=(R-r)\theta", "kinematics", same(sp.diff(x, t)**2, v2), "arc length moved by the axis of the small cylinder")
key.line(23, r"\frac{3}{2} d^2x/dt^2(R-r)d\theta/dt+gxd\theta/dt=0", "approximation",
         small(sp.Rational(3, 2) * sp.diff(x, t, 2) * (R - r) * d(theta) + g * x * d(theta), 3),
         "the time derivative of line 15 divided by m, with dx/dt = (R-r) dtheta/dt; holds to second order in theta")
key.line(27, r"\frac{d^2x}{dt^2}+\frac{2}{3}\frac{gx}{R-r}=0", "approximation",
         small(sp.diff(x, t, 2) + sp.Rational(2, 3) * g * x / (R - r), 2),
         "linearized equation of motion (3/2)(R-r) theta'' + g sin(theta) = 0")
# The frequency: theta'' = -omega^2 theta at first order.
lin = sp.series(mech.accelerations[d(theta, 2)].subs(theta, eps * sp.Symbol("q")), eps, 0, 2).removeO()
omega2 = sp.simplify(-lin / (eps * sp.Symbol("q")))
key.line(31, r"\omega^2=\frac{2}{3}\frac{g}{R-r}", "claim", same(omega2, sp.Rational(2, 3) * g / (R - r)),
         "frequency of the small oscillations (omega is now the oscillation's angular frequency)")
key.line(35, r"T=\frac{2\pi}{\omega}", "definition", None, "T is here the period, not the kinetic energy")
Dl = sp.Symbol("D", positive=True)        # R - r > 0
key.line(35, r"\frac{2\pi}{\omega}=2\pi\sqrt{\frac{3(R-r)}{2g}}", "claim",
         same((2 * sp.pi / sp.sqrt(omega2)).subs(R, r + Dl), (2 * sp.pi * sp.sqrt(3 * (R - r) / (2 * g))).subs(R, r + Dl)),
         "the period of the small oscillations")
key.emit()
