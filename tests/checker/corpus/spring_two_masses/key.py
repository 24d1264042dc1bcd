"""Answer key of spring_two_masses (SymPy only): the Physics Stack Exchange question on the potential energy of two
masses joined by three springs between walls."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, k = sp.symbols("m k", positive=True)
x1, x2 = coords("x1", "x2")
X1, X2 = sp.symbols("X1 X2")                # the displacements as plain symbols, for the integrals

# Own model: wall -k- m -k- m -k- wall, displacements from equilibrium; each spring stores k (stretch)^2 / 2.
T = m / 2 * (d(x1) ** 2 + d(x2) ** 2)
V = k / 2 * x1 ** 2 + k / 2 * (x2 - x1) ** 2 + k / 2 * x2 ** 2
mech = Mechanics(T - V, [x1, x2])
Vs = V.subs({x1: X1, x2: X2})
F1, F2 = -sp.diff(Vs, X1), -sp.diff(Vs, X2)  # the forces on the masses

_TEXT = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "derivation.md"), encoding="utf-8").read().split("\n")


def at(n, fragment):
    """Line n of derivation.md, checked to hold the fragment (so that a line number cannot silently drift)."""
    assert fragment in _TEXT[n - 1], (n, fragment, _TEXT[n - 1])
    return n


def up_to_constant(a, b, *variables):
    """a - b does not depend on the given variables."""
    diff = sp.expand(sp.sympify(a) - sp.sympify(b))
    return all(sp.simplify(sp.diff(diff, v)) == 0 for v in variables)


key = Key("https://physics.stackexchange.com/questions/583153/how-to-calculate-the-potential-energy-of-coupled-oscillators",
          "two masses and three springs between walls", "Q&A thread")

key.line(at(6, r"m \ddot{x_1} = -2kx_1 + kx_2"), r"m \ddot{x_1} = -2kx_1 + kx_2", "claim",
         mech.on_motion(m * d(x1, 2), -2 * k * x1 + k * x2), "Newton's law for the first mass (its two springs)")
key.line(at(8, r"m \ddot{x_2} = -2kx_2 + kx_1"), r"m \ddot{x_2} = -2kx_2 + kx_1", "claim",
         mech.on_motion(m * d(x2, 2), -2 * k * x2 + k * x1), "Newton's law for the second mass")
key.line(at(12, r"V(x) = - \int F(x)"), r"V(x) = - \int F(x) \hspace{.1cm} dx", "definition", None,
         "the general relation of a potential to a one-dimensional force, which the asker means to use")

# line 16: two relations, one in each display
c_, d_ = sp.symbols("c d")
I1 = -sp.integrate(-2 * k * X1 + k * X2, X1)
I2 = -sp.integrate(-2 * k * X2 + k * X1, X2)
assert same(-2 * k * X1 + k * X2, F1) and same(-2 * k * X2 + k * X1, F2)
key.line(at(16, r"dx_1= kx^{2}_1 - k x_1 x_2 + c"), r"- \int (- 2kx_1 + + kx_2) \hspace{.1cm} dx_1= kx^{2}_1 - k x_1 x_2 + c",
         "claim", up_to_constant(k * X1 ** 2 - k * X1 * X2 + c_, I1, X1),
         "an antiderivative in x_1 (the doubled '+ +' reads as one plus); c is constant in x_1 only, in truth a "
         "function of x_2")
key.line(at(16, r"dx_2= kx^{2}_2 - k x_2 x_1 + d."), r"- \int (- 2kx_2 + + kx_1) \hspace{.1cm} dx_2= kx^{2}_2 - k x_2 x_1 + d",
         "claim", up_to_constant(k * X2 ** 2 - k * X2 * X1 + d_, I2, X2),
         "an antiderivative in x_2; d is constant in x_2 only")

f_ = sp.symbols("f")
V_sum = k * X1 ** 2 + k * X2 ** 2 - 2 * k * X1 * X2 + f_
key.line(at(20, r"- 2 k x_1 x_2 + f."), r"V(x_1, x_2) = kx^{2}_1 + kx^{2}_2 + - 2 k x_1 x_2 + f", "claim",
         up_to_constant(V_sum, Vs, X1, X2),
         "adding the two partial integrals counts the middle spring's cross term -k x_1 x_2 twice (the asker's own "
         "suspicion): its gradient is not minus the forces",
         correct=r"V(x_1, x_2) = kx^{2}_1 + kx^{2}_2 - k x_1 x_2 + f")

V_book = k * X1 ** 2 + k * X2 ** 2 - k * X1 * X2
key.line(at(24, r"+ - k x_1 x_2$$"), r"V(x_1, x_2) = kx^{2}_1 + kx^{2}_2 + - k x_1 x_2", "claim", same(V_book, Vs),
         "the three springs' energies k x_1^2/2 + k (x_2 - x_1)^2/2 + k x_2^2/2 summed")

key.emit()
