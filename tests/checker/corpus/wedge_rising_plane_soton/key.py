"""Answer key: particle on a plane tilted up at a constant rate (Southampton edshare question)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


r = coords("r")
m, g, a, r0, A, B = sp.symbols("m g alpha r_0 A B", positive=True)
rd, rdd = d(r), d(r, 2)
phi = a * t                      # the plane's incline, raised at the constant rate alpha

# Own kinematics: polar coordinates (r, phi) in the vertical plane, origin at the foot of the plane.
x, y = r * sp.cos(phi), r * sp.sin(phi)
T = m * (sp.diff(x, t) ** 2 + sp.diff(y, t) ** 2) / 2
V = m * g * y
L = T - V
mech = Mechanics(L, [r])


def solves(expr):
    """r(t) = expr satisfies the Euler-Lagrange equation identically in t."""
    res = mech.el[0].subs(r, expr).doit()
    return sp.simplify(res) == 0


key = Key("http://edshare.soton.ac.uk/id/document/5585",
          "particle on a smooth plane tilted up at a constant rate (moving incline)", "course notes (question with answer)")

key.line(at(r"rate $\alpha$ ($\phi ="), r"\phi = 0", "given", None,
         "the plane starts horizontal (phi = alpha t vanishes at t = 0)")
key.line(at(r"0$ at $t = 0$"), r"t = 0", "condition", None, "the instant the statement refers to")
key.line(at(r"$\phi=\alpha t$"), r"\phi=\alpha t", "given", None, "the plane's motion: incline alpha t")

lL = at(r"\ds L = K.E. - P.E.")
key.line(lL, r"L = K.E. - P.E.", "definition", None, "the Lagrangian as kinetic minus potential energy")
L_text = m * (rd**2 - r**2 * a**2) / 2 - m * g * r * sp.sin(a * t)
key.line(lL, r"L = \frac{1}{2}m(\dot r^2 - r^2 \dot \phi^2) - mgr\sin\alpha t", "claim", same(L_text, L),
         "sign slip: the kinetic energy in polar coordinates is (m/2)(rdot^2 + r^2 phidot^2); the minus sign "
         "before r^2 phidot^2 is wrong (phidot = alpha)",
         r"L = \frac{1}{2}m(\dot r^2 + r^2 \dot \phi^2) - mgr\sin\alpha t")

el_text = sp.diff(sp.diff(L, rd), t) - sp.diff(L, r)
ok1 = mech.on_motion(el_text)
ok2 = mech.on_motion(rdd - a**2 * r, -g * sp.sin(a * t))
assert ok1 == ok2
key.line(at(r"\frac{\pl L}{\pl r} = 0 \Rightarrow"),
         r"\frac{d}{dt} \left(\frac{\pl L}{\pl \dot r}\right) - \frac{\pl L}{\pl r} = 0 \Rightarrow \ddot r - \alpha^2 r = -g \sin \alpha t",
         "claim", ok1,
         "the Euler-Lagrange equation and the correct equation of motion (it does not follow from the line "
         "above as written: that L would give rddot + alpha^2 r; the sign slip there is a typo)")

r_gen = A * sp.exp(a * t) + B * sp.exp(-a * t) + g / (2 * a**2) * sp.sin(a * t)
key.line(at(r"Its solution is $\ds r(t) = Ae^{\alpha t}"),
         r"r(t) = Ae^{\alpha t}+ Be^{-\alpha t} + \frac{g}{2\alpha^2} \sin \alpha t", "claim", solves(r_gen),
         "the general solution of the equation of motion (A, B free)")

lic = at(r"$r(0) = r_0$, $\dot r(0) = 0$")
key.line(lic, r"r(0) = r_0", "condition", None, "initial position")
key.line(lic, r"\dot r(0) = 0", "condition", None, "released at rest (relative to the plane)")

r_fin = (r0 - g / (2 * a**2)) * sp.exp(a * t) / 2 + (r0 + g / (2 * a**2)) * sp.exp(-a * t) / 2 \
    + g / (2 * a**2) * sp.sin(a * t)
ok = solves(r_fin) and same(r_fin.subs(t, 0), r0) and same(sp.diff(r_fin, t).subs(t, 0), 0)
key.line(at(r"Thus $\ds r(t) = \frac{1}{2} \left[ r_0"),
         r"r(t) = \frac{1}{2} \left[ r_0 - \frac{g}{2 \alpha^2} \right]e^{\alpha t} + \frac{1}{2} \left[ r_0 + \frac{g}{2 \alpha^2}\right]e^{-\alpha t} + \frac{g}{2\alpha^2} \sin \alpha t",
         "claim", ok, "solves the equation of motion with r(0) = r_0 and rdot(0) = 0")
key.emit()
