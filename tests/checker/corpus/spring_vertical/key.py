"""Answer key of spring_vertical (SymPy only): the CVUT notebook's mass on a spring with a damper, in gravity."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, k, c, g = sp.symbols("m k c g", positive=True)
y = coords("y")

# Own kinematics: y is measured DOWNWARD from the unstretched spring (the notebook's definition), so the height of
# the mass is -y and its potential energy in gravity is m g (-y).
height = -y
T = m / 2 * d(y) ** 2
V = k / 2 * y ** 2 + m * g * height
L = T - V
Qd = -c * d(y)                      # the damper's generalized force, -dR/dy' with R = c y'^2/2
mech = Mechanics(L, [y], forces=[Qd])

_TEXT = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "derivation.md"), encoding="utf-8").read().split("\n")


def at(n, fragment):
    """Line n of derivation.md, checked to hold the fragment (so that a line number cannot silently drift)."""
    assert fragment in _TEXT[n - 1], (n, fragment, _TEXT[n - 1])
    return n


key = Key("https://github.com/CVUT-FS-12110/Python-for-Scientific-Computations-and-Control/blob/"
          "2d74f772d0c00cd8e3eadb5e6d88193d1e997ed2/courses/E375004/lagrange2eom/"
          "lagrangian_mass_spring_damper_gravity.ipynb",
          "mass on a vertical spring with a damper, in gravity", "notebook")

T_text = m / 2 * d(y) ** 2
key.line(at(11, r"T = \frac{1}{2} m \dot{y}^2"), r"T = \frac{1}{2} m \dot{y}^2", "claim", same(T_text, T), "the kinetic energy of the mass")

V_text = k / 2 * y ** 2 + m * g * y
key.line(at(19, r"V = \frac{1}{2} k y^2 + m g y"), r"V = \frac{1}{2} k y^2 + m g y", "claim", same(V_text, V),
         "y is measured downward (the text's own definition), so gravity's part is -m g y, not +m g y",
         correct=r"V = \frac{1}{2} k y^2 - m g y")

key.line(at(22, r"L = T - V"), r"L = T - V", "definition", None, "the Lagrangian, in the heading")

L_text = m / 2 * d(y) ** 2 - (k / 2 * y ** 2 + m * g * y)
key.line(at(25, r"L = \frac{1}{2} m"), r"L = \frac{1}{2} m \dot{y}^2 - \left( \frac{1}{2} k y^2 + m g y \right)", "claim", same(L_text, L),
         "carries the sign slip of V (line 19): the gravity term of L is +m g y",
         correct=r"L = \frac{1}{2} m \dot{y}^2 - \left( \frac{1}{2} k y^2 - m g y \right)")

el = sp.diff(sp.diff(L, d(y)), t) - sp.diff(L, y)
key.line(at(31, r"= Q"), r"\frac{d}{dt} \left( \frac{\partial L}{\partial \dot{y}} \right) - \frac{\partial L}{\partial y} = Q", "claim",
         mech.on_motion(el, Qd),
         "Lagrange's equation with the damper's generalized force, for the system's L (a statement of the law; the "
         "slip of lines 19 and 25 enters only once the text's L is put in)")

key.line(at(37, r"Q = -c"), r"Q = -c \dot{y}", "given", None, "the damping force, the problem's viscous damper")

eom_text = m * d(y, 2) + c * d(y) + k * y + m * g
eom_fix = m * d(y, 2) + c * d(y) + k * y - m * g
assert mech.on_motion(eom_fix)
key.line(at(45, r"+ m g = 0"), r"m \ddot{y} + c \dot{y} + k y + m g = 0", "claim", mech.on_motion(eom_text),
         "the gravity term follows the sign slip of V: with y downward gravity pulls along +y, so it enters as -m g",
         correct=r"m \ddot{y} + c \dot{y} + k y - m g = 0")

key.emit()
