"""Answer key of atwood_pulley_inertia_farside (SymPy only): an Atwood machine whose pulley (radius a, moment of
inertia I) turns with the cord, which does not slip (Fitzpatrick, Newtonian Dynamics, "Atwood Machines")."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


m1, m2, I, a, l, g = sp.symbols("m_1 m_2 I a l g", positive=True)
x = coords("x")
xd, xdd = d(x), d(x, 2)

# Own mechanics: heights measured upward from the pulley's axle; m_1 hangs at depth x, m_2 at depth l - x (the cord's
# length, the bit wrapped on the small pulley left out as the text does with a << l). The pulley's angle phi turns
# with the cord: a phi' is the cord's speed x' (no slipping).
y1, y2 = -x, -(l - x)
phid = xd / a
T = m1 / 2 * sp.diff(y1, t)**2 + m2 / 2 * sp.diff(y2, t)**2 + I / 2 * phid**2
V = m1 * g * y1 + m2 * g * y2
Lag = T - V
mech = Mechanics(Lag, [x])

key = Key("http://farside.ph.utexas.edu/teaching/336k/lectures/node93.html",
          "Atwood machine with a pulley of moment of inertia I (cord not slipping)", "lecture notes")

# "$a\ll l$" (line 5), the pulley small beside the cord, is an assumption written with \ll, which score.py's relation
# pattern does not know (it would move the entry to the "-->" of line 1): no entry.
K_text = m1 / 2 * xd**2 + m2 / 2 * xd**2 + I / 2 * xd**2 / a**2
key.line(at(r"K = \frac{1}{2}\,m_1"), r"K = \frac{1}{2}\,m_1\,\dot{x}^{\,2} + \frac{1}{2}\,m_2\,\dot{x}^{\,2} + \frac{1}{2}\,I\, \frac {\dot{x}^{\,2}}{a^2}",
         "claim", same(K_text, T), "the two weights at speed x' and the pulley turning at x'/a")
U_text = -m1 * g * x - m2 * g * (l - x)
key.line(at(r"U = -m_1\,g\,x"), r"U = -m_1\,g\,x - m_2\,g\,(l-x)", "claim", same(U_text, V),
         "depths x and l - x below the axle")
C = sp.Symbol("C")                                    # the text's "const"
L_text = sp.Rational(1, 2) * (m1 + m2 + I / a**2) * xd**2 + g * (m1 - m2) * x + C
diffL = sp.expand(Lag - L_text)
ok = all(same(sp.diff(diffL, v), 0) for v in (x, xd, t))
key.line(at(r"L=\frac{1}{2}\left(m_1+ m_2"), r"L=\frac{1}{2}\left(m_1+ m_2+\frac{I}{a^2}\right)\dot{x}^{\,2} + g\,(m_1-m_2)\,x + {\rm const}",
         "claim", ok, "K - U up to the constant m_2 g l")
key.line(at(r"\frac{d}{dt}\!\left(\frac{\partial L}{\partial\dot{x}}\right)"),
         r"\frac{d}{dt}\!\left(\frac{\partial L}{\partial\dot{x}}\right) - \frac{\partial L}{\partial x} = 0", "claim",
         mech.on_motion(sp.diff(sp.diff(Lag, xd), t) - sp.diff(Lag, x)), "the Euler-Lagrange equation for x")
key.line(at(r"\ddot{x} - g\,(m_1-m_2) = 0"), r"\left(m_1+ m_2+\frac{I}{a^2}\right)\ddot{x} - g\,(m_1-m_2) = 0", "claim",
         mech.on_motion((m1 + m2 + I / a**2) * xdd - g * (m1 - m2)), "the Euler-Lagrange equation worked out")
key.line(at(r"\ddot{x} = \frac{g\,(m_1-m_2)}"), r"\ddot{x} = \frac{g\,(m_1-m_2)}{m_1+m_2 + I/a^2}", "claim",
         mech.on_motion(xdd, g * (m1 - m2) / (m1 + m2 + I / a**2)), "solved for the acceleration")
key.emit()
