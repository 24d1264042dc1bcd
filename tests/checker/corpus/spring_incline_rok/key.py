"""Answer key of spring_incline_rok (SymPy only): a cart on an incline held by a spring (rok.50webs.com)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


x = coords("x")
m, k, x0, g, th, A, phi, w = sp.symbols("m k x_0 g theta A phi omega", positive=True)
s = sp.sin(th)
xd, xdd = d(x), d(x, 2)

# Own mechanics: x is the spring's length, the cart's distance down the slope from the spring's fixed end at the
# top; the cart sinks x sin(theta) as x grows.
T = m * xd**2 / 2
V = k * (x - x0) ** 2 / 2 + m * g * (-x * s)
L = T - V
mech = Mechanics(L, [x])

key = Key("http://rok.50webs.com/courseware/mechanics/ap6_Lagrangians_10.html",
          "cart (block) on a smooth incline held by a spring", "course notes")

# The text writes "sin\theta" without the backslash of \sin: the key reads it as sin(theta), as its reader does.
key.line(at(r"\( K.E. = "), r"K.E. = \dfrac {1}{2} m\dot x^2", "claim", same(m * xd**2 / 2, T),
         "the kinetic energy (K.E. is the text's name for T)")
key.line(at(r"\( P.E. = "), r"P.E. = \dfrac {1}{2} k(x-x_0)^2 - mgx sin\theta", "claim",
         same(k * (x - x0) ** 2 / 2 - m * g * x * s, V),
         "the spring's and gravity's potential energy (P.E. is the text's name for V; 'sin' typed without its "
         "backslash)")
key.line(at(r"\( \mathscr L = "), r"\mathscr L = \dfrac {1}{2} m\dot x^2 - \dfrac {1}{2} k(x-x_0)^2 + mgx sin\theta",
         "claim", same(m * xd**2 / 2 - k * (x - x0) ** 2 / 2 + m * g * x * s, L), "L = T - V")
key.line(at(r"\( \dfrac{\partial \mathscr L}{\partial \dot x} = m\dot x \)"),
         r"\dfrac{\partial \mathscr L}{\partial \dot x} = m\dot x", "claim", same(m * xd, sp.diff(L, xd)),
         "the momentum")
key.line(at(r"\( \dfrac {d}{dt} \dfrac{\partial \mathscr L}{\partial \dot x} = m\ddot x \)"),
         r"\dfrac {d}{dt} \dfrac{\partial \mathscr L}{\partial \dot x} = m\ddot x", "claim",
         same(m * xdd, sp.diff(sp.diff(L, xd), t)), "its time derivative")
key.line(at(r"\( \dfrac{\partial \mathscr L}{\partial x} = "),
         r"\dfrac{\partial \mathscr L}{\partial x} = - k(x-x_0) + mg sin\theta", "claim",
         same(-k * (x - x0) + m * g * s, sp.diff(L, x)), "dL/dx")
key.line(at(r"\( m\ddot x =- k(x-x_0) + mg sin\theta \)"), r"m\ddot x =- k(x-x_0) + mg sin\theta", "claim",
         mech.on_motion(m * xdd, -k * (x - x0) + m * g * s), "the equation of motion")
key.line(at(r"\( m\ddot x =- k(x-(x_0 + mgsin\theta/k)) \)"), r"m\ddot x =- k(x-(x_0 + mgsin\theta/k))", "claim",
         mech.on_motion(m * xdd, -k * (x - (x0 + m * g * s / k))), "the same about the shifted equilibrium")
# The solution: x0 + m g sin(theta)/k + A cos(omega t + phi) satisfies the equation of motion for every A, phi
# exactly when omega = sqrt(k/m) (the text's "where" on the next lines).
xsol = x0 + m * g * s / k + A * sp.cos(w * t + phi)
resid = m * sp.diff(xsol, t, 2) + k * (xsol - x0) - m * g * s
ok_sol = sp.simplify(resid.subs(w, sp.sqrt(k / m))) == 0
assert sp.simplify(resid) != 0  # it needs that omega
key.line(at(r"\( x = x_0 + mgsin\theta/k + Acos(\omega t + \phi) \)"),
         r"x = x_0 + mgsin\theta/k + Acos(\omega t + \phi)", "claim", ok_sol,
         "the general solution of the equation of motion, with omega = sqrt(k/m) as the text gives below "
         "('Acos' is A cos, typed without the backslash)")
# x = A cos(omega t + phi) in m xddot + k x = 0: (k - m omega^2) x = 0, so omega^2 = k/m.
ws = sp.solve(sp.cancel((m * sp.diff(sp.cos(w * t), t, 2) + k * sp.cos(w * t)) / sp.cos(w * t)), w)
key.line(at(r"\( \omega = \sqrt {\dfrac{k}{m}} \)"), r"\omega = \sqrt {\dfrac{k}{m}}", "claim",
         any(same(r, sp.sqrt(k / m)) for r in ws),
         "the angular frequency of the oscillation (introduced with 'where', but its value is the mechanics': "
         "the solution above holds only for it)")
key.emit()
