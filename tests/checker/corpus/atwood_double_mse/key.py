"""Answer key: double Atwood machine (imathworks mirror of a Mathematics Stack Exchange question)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


y1, y2 = coords("y1", "y2")
m1, m2, m3, mm, g, h, l1, l2 = sp.symbols("m_1 m_2 m_3 m g h l_1 l_2", positive=True)
y1d, y2d, y1dd, y2dd = d(y1), d(y2), d(y1, 2), d(y2, 2)

# Own kinematics (depths below the reference at height h): big wheel at depth 0, rope l2 over it carries m3
# at depth y3 and the small wheel at depth yp = l2 - y3; rope l1 over the small wheel: (y1 - yp) + (y2 - yp) = l1.
yp = (y1 + y2 - l1) / 2
y3 = l2 - yp
T = (m1 * y1d**2 + m2 * y2d**2 + m3 * sp.diff(y3, t) ** 2) / 2
V = m1 * g * (h - y1) + m2 * g * (h - y2) + m3 * g * (h - y3)
L = T - V
mech = Mechanics(L, [y1, y2])
# the asker's particular case m1 = m2 = m
eq = {m1: mm, m2: mm}
mech_eq = Mechanics(L.subs(eq), [y1, y2])

key = Key("https://imathworks.com/math/math-equilibrium-of-double-atwood-machine-via-lagrangian",
          "double Atwood machine", "Q&A thread")

lc = at(r"Their constraint: $\frac{1}{2}(y_1+y_2) = l_2-y_3$")
key.line(lc, r"\frac{1}{2}(y_1+y_2) = l_2-y_3", "kinematics",
         same(sp.diff((y1 + y2) / 2 - (l2 - y3), t), 0),
         "the ropes' constraint; true for the velocities, and for the positions up to the constant l_1/2 of the "
         "small wheel's rope, which only shifts V by a constant (ambiguous: the asker's l_2 may include it)")
key.line(lc, r"y_3 = l_2 - \frac{1}{2} (y_1 - y_2)", "kinematics",
         same(sp.diff(l2 - (y1 - y2) / 2, t), sp.diff(y3, t)),
         "sign slip solving the line before for y_3: it is y_3 = l_2 - (y_1 + y_2)/2",
         r"y_3 = l_2 - \frac{1}{2} (y_1 + y_2)")

y3d = -(y1d + y2d) / 2       # d/dt of y3
T_a = (m1 * y1d + m2 * y2d + m3 * y3d) / 2
T_b = ((m1 + m3 / 4) * y1d + (m2 + m3 / 4) * y2d - m3 / 2 * y1d * y2d) / 2
assert same(T_a, T) == same(T_b, T)  # both sides of the chain alike
key.line(at(r"T = \frac{1}{2} \left( m_1\dot{y_1} + m_2 \dot{y_2}"),
         r"T = \frac{1}{2} \left( m_1\dot{y_1} + m_2 \dot{y_2} + m_3 \dot{y_3} \right) = \frac{1}{2} \left( \left( m_1 + \frac{m_3}{4}\right)\dot{y_1} + \left(m_2 + \frac{m_3}{4} \right) \dot{y_2} - \frac{m_3}{2} \dot{y_1}\dot{y_2}\right)",
         "claim", same(T_b, T),
         "the velocities are not squared in either expression, and the cross term follows the wrong constraint "
         "y_3 = l_2 - (y_1 - y_2)/2: with ydot_3 = -(ydot_1 + ydot_2)/2 it is +m_3/2 ydot_1 ydot_2",
         r"T = \frac{1}{2} \left( \left( m_1 + \frac{m_3}{4}\right)\dot{y_1}^2 + \left(m_2 + \frac{m_3}{4} \right) \dot{y_2}^2 + \frac{m_3}{2} \dot{y_1}\dot{y_2}\right)")

lV = at(r"V = mg(h-y_1)")
V_a = mm * g * (h - y1) + m2 * g * (h - y2) + m3 * g * (h - y3)
key.line(lV, r"V = mg(h-y_1) + m_2g(h-y_2) + m_3g(h-y_3)", "claim", same(V_a, V),
         "m where m_1 belongs in the first term (a typo: the next expression has m_1)",
         r"V = m_1g(h-y_1) + m_2g(h-y_2) + m_3g(h-y_3)")
V_b = (m3 / 2 - m1) * y1 * g + (m3 / 2 - m2) * y2 * g
key.line(lV, r"V = \left( \frac{m_3}{2} - m_1\right)y_1g + \left( \frac{m_3}{2} - m_2\right) y_2g + const.",
         "claim", same(sp.diff(V_b - V, y1), 0) and same(sp.diff(V_b - V, y2), 0),
         "V up to a constant, with the correct constraint y_3 = l_2 - (y_1 + y_2)/2")

EL1 = sp.diff(sp.diff(L, y1d), t) - sp.diff(L, y1)
EL2 = sp.diff(sp.diff(L, y2d), t) - sp.diff(L, y2)
E1 = (m1 + m3 / 4) * y1dd - m3 / 4 * y2dd + (m3 / 2 - m1) * g
E2 = (m2 + m3 / 4) * y2dd - m3 / 4 * y1dd + (m3 / 2 - m2) * g
assert same(EL1, E1) == mech.on_motion(E1)
key.line(at(r"\frac{d}{dt} \frac{\partial L}{\partial \dot{y_1}} - \frac{\partial L}{\partial y_1} ="),
         r"\frac{d}{dt} \frac{\partial L}{\partial \dot{y_1}} - \frac{\partial L}{\partial y_1} = \left( m_1 + \frac{m_3}{4}\right)\ddot{y_1} - \frac{m_3}{4}\ddot{y_2} + \left(\frac{m_3}{2} - m_1\right) g = 0",
         "claim", same(EL1, E1),
         "the yddot_2 term has the wrong sign (it comes from the wrong cross term of T): the equation for y_1 "
         "is (m_1 + m_3/4) yddot_1 + (m_3/4) yddot_2 + (m_3/2 - m_1) g = 0",
         r"\frac{d}{dt} \frac{\partial L}{\partial \dot{y_1}} - \frac{\partial L}{\partial y_1} = \left( m_1 + \frac{m_3}{4}\right)\ddot{y_1} + \frac{m_3}{4}\ddot{y_2} + \left(\frac{m_3}{2} - m_1\right) g = 0")
assert same(EL2, E2) == mech.on_motion(E2)
key.line(at(r"\frac{d}{dt}\frac{\partial L}{\partial \dot{y_2}} - \frac{\partial L}{\partial y_2} ="),
         r"\frac{d}{dt}\frac{\partial L}{\partial \dot{y_2}} - \frac{\partial L}{\partial y_2} = \left( m_2 + \frac{m_3}{4} \right) \ddot{y_2} - \frac{m_3}{4}\ddot{y_1} + \left( \frac{m_3}{2} - m_2 \right)g = 0",
         "claim", same(EL2, E2), "the yddot_1 term has the wrong sign, as in (i)",
         r"\frac{d}{dt}\frac{\partial L}{\partial \dot{y_2}} - \frac{\partial L}{\partial y_2} = \left( m_2 + \frac{m_3}{4} \right) \ddot{y_2} + \frac{m_3}{4}\ddot{y_1} + \left( \frac{m_3}{2} - m_2 \right)g = 0")

key.line(at(r"$m_1 = m_2 \Rightarrow$"), r"m_1 = m_2", "given", None, "the case the asker examines")

lc = at(r"(i) - (ii) = m_1\ddot{y_1}")
comb = m1 * y1dd - m2 * y2dd + m3 / 4 * (y1dd - y2dd) + (m2 - m1) * g
key.line(lc, r"(i) - (ii) = m_1\ddot{y_1} - m_2\ddot{y_2} + \frac{m_3}{4} \left( \ddot{y_1} - \ddot{y_2}\right) + (m_2 - m_1) g",
         "combination", same(EL1 - EL2, comb),
         "the difference of the true equations has no m_3 term (m_3 yddot_1/4 + m_3 yddot_2/4 appears in both); "
         "of the asker's own (i) and (ii) it would be m_3/2, not m_3/4",
         r"(i) - (ii) = m_1\ddot{y_1} - m_2\ddot{y_2} + (m_2 - m_1) g = 0")
key.line(lc, r"m_1\ddot{y_1} - m_2\ddot{y_2} + \frac{m_3}{4} \left( \ddot{y_1} - \ddot{y_2}\right) + (m_2 - m_1) g = 0",
         "claim", mech_eq.on_motion(comb.subs(eq)),
         "holds on the motion in the case m_1 = m_2 the asker assumed just before ('m_1 = m_2 =>'; then yddot_1 = "
         "yddot_2 and every term vanishes); it would not hold for m_1 != m_2 (ambiguous: the line still writes "
         "m_1 and m_2 apart and sets them equal only on the next line)")

key.line(at(r"with $m_1 = m_2 = m$"), r"m_1 = m_2 = m", "given", None, "names the common mass m")
e1 = mm * y1dd - mm * y2dd + m3 / 4 * (y1dd - y2dd)
key.line(at(r"\Rightarrow m \ddot{y_1} - m \ddot{y_2}"),
         r"m \ddot{y_1} - m \ddot{y_2} + \frac{m_3}{4} ( \ddot{y_1} - \ddot{y_2}) = 0", "claim",
         mech_eq.on_motion(e1), "with m_1 = m_2 = m the motion has yddot_1 = yddot_2, so this holds")
key.line(at(r"\Rightarrow m(\ddot{y_1} - \ddot{y_2}) ="),
         r"m(\ddot{y_1} - \ddot{y_2}) = -\frac{m_3}{4} ( \ddot{y_1} - \ddot{y_2})", "claim",
         mech_eq.on_motion(mm * (y1dd - y2dd), -m3 / 4 * (y1dd - y2dd)), "both sides vanish on the motion")
key.line(at(r"\Rightarrow m = -\frac{m_3}{4}"), r"m = -\frac{m_3}{4}", "claim", same(mm, -m3 / 4),
         "divides by yddot_1 - yddot_2, which is zero on the motion when m_1 = m_2; the line before only says "
         "yddot_1 = yddot_2 (nothing about m)",
         r"\ddot{y_1} = \ddot{y_2}")
key.emit()
