"""Answer key: Atwood machine (Jupyter notebook, MuhammadHamzaAsif1/Physics-and-Mathematics Problem-3)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


y1 = coords("y1")
m1, m2, g, c1 = sp.symbols("m_1 m_2 g c_1", positive=True)
y1d = d(y1)

# Own kinematics: heights y1, y2 of the two masses; the string over the fixed pulley keeps y1 + y2 = c1.
y2 = c1 - y1
T = m1 * y1d**2 / 2 + m2 * sp.diff(y2, t) ** 2 / 2
V = m1 * g * y1 + m2 * g * y2
L = T - V
mech = Mechanics(L, [y1])

key = Key("https://github.com/MuhammadHamzaAsif1/Physics-and-Mathematics/blob/"
          "df0d3e56dbb81d9a1080ac10105f247243a5ec2e/Lagrangian%20Mechanics/Problem-3.ipynb",
          "Atwood machine (massless pulley)", "Jupyter notebook")

T_text = m1 * y1**2 / 2 + m2 * y2**2 / 2
key.line(at(r"T = \frac{1}{2}m_1y_1^{2}"), r"T = \frac{1}{2}m_1y_1^{2} + \frac{1}{2}m_2y_2^{2}", "claim",
         same(T_text, T), "the dots are missing: the kinetic energy has the velocities squared, not the heights "
         "(the notebook's code squares the velocities)",
         r"T = \frac{1}{2}m_1\dot{y_1}^{2} + \frac{1}{2}m_2\dot{y_2}^{2}")
key.line(at(r"V = m_1gy_1 + m_2gy_2"), r"V = m_1gy_1 + m_2gy_2", "claim", same(m1 * g * y1 + m2 * g * y2, V),
         "potential energy with y the heights")
key.line(at(r"\frac{\partial{L}}{\partial{q}} - \frac{d}{dt}"),
         r"\frac{\partial{L}}{\partial{q}} - \frac{d}{dt} \frac{\partial{L}}{\partial{\dot{q}}} = 0", "definition",
         None, "the Euler-Lagrange equation stated for a generic coordinate q")

lk = at(r"$$ y_1 + y_2 = c_1 $$")
key.line(lk, r"y_1 + y_2 = c_1", "kinematics", same(y1 + y2, c1), "the string's constraint (heights)")
key.line(lk, r"y_2 = c_1 - y_1", "kinematics", same(y2, c1 - y1), "the constraint solved for y_2")
key.line(lk, r"\dot{y_2} = \dot{-y_1}", "kinematics", same(sp.diff(y2, t), -y1d),
         "the derivative: ydot_2 = -ydot_1 (written with the dot over -y_1)")
key.line(lk, r"\dot{y_2}^{2} = \dot{y_1}^{2}", "kinematics", same(sp.diff(y2, t) ** 2, y1d**2), "squared")
key.line(at(r"Hence $$ \dot{y_2}^{2} = \dot{y_1}^{2} $$"), r"\dot{y_2}^{2} = \dot{y_1}^{2}", "kinematics",
         same(sp.diff(y2, t) ** 2, y1d**2), "repeated")
key.line(at(r"\frac{\partial{L}}{\partial{y_1}} - \frac{d}{dt}"),
         r"\frac{\partial{L}}{\partial{y_1}} - \frac{d}{dt} \frac{\partial{L}}{\partial{\dot{y_1}}} = 0", "claim",
         mech.on_motion(sp.diff(L, y1) - sp.diff(sp.diff(L, y1d), t)), "the Euler-Lagrange equation for y_1")
key.emit()
