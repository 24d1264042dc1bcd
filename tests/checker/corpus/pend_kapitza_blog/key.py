"""Answer key of pend_kapitza_blog (SymPy only): the pendulum with a vertically oscillating pivot (Kapitza)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, Lr, A, w, g = sp.symbols("m L A omega g", positive=True)
ph = coords("phi")
s, c = sp.sin, sp.cos

# Own kinematics: pivot at height -A cos(omega t) (the phase of the post's second equation), phi from the downward
# vertical, y upward.
yp = -A * c(w * t)
X, Y = Lr * s(ph), yp - Lr * c(ph)
T = m / 2 * (d(X) ** 2 + d(Y) ** 2)
V = m * g * Y
mech = Mechanics(T - V, [ph])

key = Key("https://github.com/lorenzifrancesco/blog/blob/909107423c78bc9c46d53df4fa45e6fdeb1d7648/lorenziblog/content/post/classical/kapitza.md",
          "pendulum with a vertically oscillating pivot (Kapitza pendulum)", "blog post")

key.line(7, r"\phi = \pi", "condition", None, "the inverted position")
key.line(7, r"\phi = 0", "condition", None, "the hanging position (the text calls it 'upright', though φ = 0 is the downward vertical by its own definition)")
key.line(9, r"\phi=0", "condition", None, "the ordinary pendulum's stable position")
key.line(9, r"\phi=\pi", "condition", None, "the ordinary pendulum's unstable position")

lhs13 = m * Lr * d(ph, 2)
rhs13 = m * g * s(ph) - A * m * w ** 2 * c(w * t) * s(ph)
rhs13_fix = -m * g * s(ph) - A * m * w ** 2 * c(w * t) * s(ph)
assert mech.on_motion(lhs13, rhs13_fix)
key.line(13, r"mL\ddot{\phi} = mg\sin\phi - Am\omega^2 \cos(\omega t) \sin \phi", "claim", mech.on_motion(lhs13, rhs13),
         "gravity's torque has the wrong sign for φ measured from the downward vertical (it must restore: −m g sin φ); "
         "the drive term is that of the next line. No phase of the pivot makes it hold with φ from below "
         "(it is the equation for the angle from the upward vertical with the pivot at +A cos ωt)",
         correct=r"mL\ddot{\phi} = -mg\sin\phi - Am\omega^2 \cos(\omega t) \sin \phi")

rhs17 = -(g + A * w ** 2 * c(w * t)) * s(ph) / Lr
key.line(17, r"\ddot{\phi} = -\frac{1}{L}(g+A\omega^2\cos(\omega t))\sin \phi", "claim", mech.on_motion(d(ph, 2), rhs17),
         "the equation of motion with the pivot at height −A cos ωt (the phase 'our case' fixes)")

key.line(21, r"\phi = \phi_0 + \tilde{\phi}", "definition", None, "splits φ into φ₀ and φ̃")

# line 25: the equation of line 17 linearized in phi~ about a constant phi0 (the Mathieu reading the text names)
p0, pt, eps = sp.symbols("phi0 phitilde epsilon")
exact = -(g + A * w ** 2 * c(w * t)) * s(p0 + eps * pt) / Lr
first_order = sp.series(exact, eps, 0, 2).removeO().subs(eps, 1)
linear_part = sp.expand(first_order - first_order.subs(pt, 0))  # the term in phi~ (phi0 an equilibrium: sin phi0 = 0)
text25 = -(g + A * w ** 2 * c(w * t)) * s(p0) * pt / Lr
fix25 = -(g + A * w ** 2 * c(w * t)) * c(p0) * pt / Lr
assert same(linear_part, fix25)
key.line(25, r"\ddot{\tilde{\phi}} = -\frac{1}{L}(g+A\omega^2\cos(\omega t))\sin\phi_0 \tilde{\phi}", "approximation",
         same(text25, linear_part) and same(text25, first_order),
         "linearizing sin(φ₀ + φ̃) gives sin φ₀ + cos φ₀ φ̃: the coefficient of φ̃ is cos φ₀ (about φ₀ = 0 or π, where "
         "sin φ₀ = 0, the Mathieu equation the text names); with sin φ₀ it vanishes at both equilibria. Read as Kapitza's "
         "fast equation instead, the fast part is driven by −(Aω²/L) cos ωt sin φ₀ with no factor φ̃, so the line fails "
         "either way",
         correct=r"\ddot{\tilde{\phi}} = -\frac{1}{L}(g+A\omega^2\cos(\omega t))\cos\phi_0 \tilde{\phi}")

key.emit()
