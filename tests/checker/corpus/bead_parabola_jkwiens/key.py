"""Answer key of bead_parabola_jkwiens (SymPy only): a bead on a smooth parabolic wire z = c r^2 turning at the
constant rate omega about its vertical axis; the jkwiens.com blog post (Lagrangian set up, Euler-Lagrange equation
and dL/dr; the stored copy ends there)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, c, w, g = sp.symbols("m c omega g", positive=True)
r = coords("r")

# Own kinematics: z up, the wire in a vertical plane through the z-axis that turns at the rate omega; the bead at
# distance r from the axis, on the wire: (r cos wt, r sin wt, c r^2).
X = r * sp.cos(w * t)
Y = r * sp.sin(w * t)
Z = c * r ** 2
v2 = sp.simplify(d(X) ** 2 + d(Y) ** 2 + d(Z) ** 2)
T = m / 2 * v2
V = m * g * Z                                # zero at the vertex
L = sp.expand(T - V)
mech = Mechanics(L, [r])

_TEXT = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "derivation.md"), encoding="utf-8").read().split("\n")


def at(n, fragment):
    """Line n of derivation.md, checked to hold the fragment (so that a line number cannot silently drift)."""
    assert fragment in _TEXT[n - 1], (n, fragment, _TEXT[n - 1])
    return n


key = Key("http://www.jkwiens.com/2007/12/13/question-a-bead-sliding-on-a-rotating-parabola-2/",
          "bead on a parabolic wire z = c r^2 turning about its vertical axis at a constant rate", "personal blog")

key.line(at(6, r"parabola $z = cr^2$"), r"z = cr^2", "given", None, "the shape of the wire (z the height, r the distance from the axis)")

# Line 10: L = K + P = 1/2 m |v|^2 - mgz. K the kinetic energy, P the potential (the text's words: "the Kinetic
# Energy + Potential"); with P the potential energy mgz, K + P is the energy (what the post calls the
# Hamiltonian), not the Lagrangian K - P; the last member is K - P.
K, P = T, V
key.line(at(10, r"$$L = K + P = \frac{1}{2} m \arrowvert \vec{v} \arrowvert ^{2} -mgz$$"),
         r"L = K + P = \frac{1}{2} m \arrowvert \vec{v} \arrowvert ^{2} -mgz", "claim",
         same(K + P, L) and same(K + P, m / 2 * v2 - m * g * Z),
         "with K the kinetic energy and P the potential energy mgz (the text: 'the Kinetic Energy + Potential'), "
         "K + P is the energy, not the Lagrangian; the last member 1/2 m|v|^2 - mgz is K - P, the Lagrangian",
         correct=r"L = K - P = \frac{1}{2} m \arrowvert \vec{v} \arrowvert ^{2} -mgz")
assert same(K - P, L) and same(m / 2 * v2 - m * g * Z, L)

key.line(at(12, r"and $z = cr^2$, so"), r"z = cr^2", "given", None, "the wire's shape again, used to eliminate z")

# Line 14: the speed squared as the dot product of the cylindrical velocity with itself, theta' and z' not yet
# replaced: r'^2 + r^2 theta'^2 + z'^2 with theta' = omega and z' = d(c r^2)/dt.
thd, zd = sp.symbols("thetadot zdot")
L14 = m / 2 * (d(r) ** 2 + r ** 2 * thd ** 2 + zd ** 2) - m * g * c * r ** 2
key.line(at(14, r"\cdot(\dot{r}\hat{r} + r \dot{\theta}\hat{\theta} + \dot{z}\hat{k}) -mgcr^2$$"),
         r"L = \frac{1}{2} m (\dot{r}\hat{r} + r \dot{\theta}\hat{\theta} + \dot{z}\hat{k})\cdot(\dot{r}\hat{r} + r "
         r"\dot{\theta}\hat{\theta} + \dot{z}\hat{k}) -mgcr^2", "claim",
         same(L14.subs({thd: w, zd: d(Z)}), L),
         "the unit vectors are orthonormal: 1/2 m (r'^2 + r^2 theta'^2 + z'^2) - mgcr^2, the Lagrangian once "
         "theta' = omega and z' = 2crr'")
key.line(at(16, r"$\dot{\theta}=\omega$"), r"\dot{\theta}=\omega", "given", None,
         "the wire (and the bead's azimuth theta) turns at the constant rate omega")
key.line(at(16, r"$\dot{z}=\frac{d}{dt}(cr^2) = 2 c r \dot{r}$"), r"\dot{z}=\frac{d}{dt}(cr^2) = 2 c r \dot{r}",
         "kinematics", same(d(Z), 2 * c * r * d(r)), "z = c r^2 differentiated")
L18 = m / 2 * (d(r) ** 2 + r ** 2 * w ** 2 + 4 * c ** 2 * r ** 2 * d(r) ** 2) - m * g * c * r ** 2
key.line(at(18, r"$$L = \frac{1}{2} m (\dot{r}^2 + r^2\omega^2 + 4c^2r^2\dot{r}^2) -mgcr^2$$"),
         r"L = \frac{1}{2} m (\dot{r}^2 + r^2\omega^2 + 4c^2r^2\dot{r}^2) -mgcr^2", "claim", same(L18, L),
         "T - V in the one coordinate r")
el = sp.diff(L, r) - sp.diff(sp.diff(L, d(r)), t)
key.line(at(22, r"$$\frac{\partial L}{\partial r} -\frac{\partial}{\partial t}"),
         r"\frac{\partial L}{\partial r} -\frac{\partial}{\partial t}(\frac{\partial L}{\partial \dot{r}}) = 0", "claim",
         mech.on_motion(el),
         "Lagrange's equation for r (the partial sign on t written for the total derivative d/dt)")
key.line(at(26, r"$$\frac{\partial L}{\partial r} = m ( 4c^2r\dot{r}^2 + r \omega ^2) -2mgcr$$"),
         r"\frac{\partial L}{\partial r} = m ( 4c^2r\dot{r}^2 + r \omega ^2) -2mgcr", "claim",
         same(sp.diff(L, r), m * (4 * c ** 2 * r * d(r) ** 2 + r * w ** 2) - 2 * m * g * c * r), "dL/dr")

key.emit()
