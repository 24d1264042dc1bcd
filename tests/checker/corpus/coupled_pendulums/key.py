"""Answer key of coupled_pendulums (SymPy only): two pendulums joined by a spring, the energies of the Physics Stack
Exchange question on the spring's potential energy."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, l, k, g, D = sp.symbols("m l k g D", positive=True)
th1, th2 = coords("theta1", "theta2")

# Own kinematics: pivots at (0, 0) and (D, 0), y up, bobs at l from them at angles from the downward vertical. The
# spring's stretch is the change of the bobs' horizontal separation (the question's x_i = l sin(theta_i); the spring
# kept horizontal), its rest length D.
P1 = (l * sp.sin(th1), -l * sp.cos(th1))
P2 = (D + l * sp.sin(th2), -l * sp.cos(th2))
T = m / 2 * (d(P1[0]) ** 2 + d(P1[1]) ** 2) + m / 2 * (d(P2[0]) ** 2 + d(P2[1]) ** 2)
stretch = (P2[0] - P1[0]) - D
V = m * g * (P1[1] + l) + m * g * (P2[1] + l) + k / 2 * stretch ** 2
mech = Mechanics(T - V, [th1, th2])
v1sq = d(P1[0]) ** 2 + d(P1[1]) ** 2
v2sq = d(P2[0]) ** 2 + d(P2[1]) ** 2

_TEXT = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "derivation.md"), encoding="utf-8").read().split("\n")


def at(n, fragment):
    """Line n of derivation.md, checked to hold the fragment (so that a line number cannot silently drift)."""
    assert fragment in _TEXT[n - 1], (n, fragment, _TEXT[n - 1])
    return n


key = Key("https://physics.stackexchange.com/questions/580587/expression-for-total-potential-energy-in-coupled-systems",
          "two pendulums coupled by a spring", "Q&A thread")

T_text = m * l ** 2 / 2 * (d(th1) ** 2 + d(th2) ** 2)
key.line(at(6, r"T = \frac{1}{2}mv_1^2+\frac{1}{2}mv_2^2=\frac{1}{2}ml^2"),
         r"T = \frac{1}{2}mv_1^2+\frac{1}{2}mv_2^2=\frac{1}{2}ml^2(\dot{\theta_1}^2+\dot{\theta_2}^2)", "claim",
         same(m / 2 * v1sq + m / 2 * v2sq, T) and same(T_text, T), "each bob moves at l θ̇ᵢ")
U_text = m * g * l * (1 - sp.cos(th1)) + m * g * l * (1 - sp.cos(th2)) + k / 2 * (l * sp.sin(th2) - l * sp.sin(th1)) ** 2
key.line(at(10, r"U = mgl(1-\cos \theta_1)"),
         r"U = mgl(1-\cos \theta_1) + mgl(1-\cos \theta_2)+ \frac{1}{2}k(l\sin \theta_2- l\sin \theta_1)^2", "claim",
         same(U_text, V), "gravity of each bob from its lowest point, and the spring stretched by the change of the "
                          "bobs' horizontal separation")
key.line(at(12, r"$x_i= l\sin \theta_i$"), r"x_i= l\sin \theta_i", "kinematics", same(P1[0], l * sp.sin(th1))
         and same(P2[0] - D, l * sp.sin(th2)), "each bob's horizontal position from below its pivot")
key.line(at(12, r"$L=T-U$"), r"L=T-U", "definition", None, "the Lagrangian")
x1s, x2s = sp.symbols("x_1 x_2")
key.line(at(20, r"=k(x_2-x_1)^2$$"), r"\frac{1}{2}k(x_2-x_1)^2+\frac{1}{2}k(x_1-x_2)^2 =k(x_2-x_1)^2", "claim",
         same(k / 2 * (x2s - x1s) ** 2 + k / 2 * (x1s - x2s) ** 2, k * (x2s - x1s) ** 2),
         "an algebraic identity, true; the left side is not the spring's energy (that is k(x₂ − x₁)²/2, the spring "
         "counted once), which is the asker's question, not a claim of this line")

key.emit()
