"""Answer key of pend_vertical_support_lean (SymPy only): a pendulum whose support oscillates vertically
(Landau & Lifshitz §5 problem 3c, as worked in PhysLean's documentation)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, l, a, gm, g = sp.symbols("m l a gamma g", positive=True)
ph = coords("phi")
s, c = sp.sin, sp.cos
gt = gm * t
dp = d(ph)

# Own kinematics: support at (0, a cos(gamma t)), y upward, phi from the downward vertical.
Yp = a * c(gt)
X, Y = l * s(ph), Yp - l * c(ph)
T = m / 2 * (d(X) ** 2 + d(Y) ** 2)
V = m * g * Y
L = T - V
mech = Mechanics(L, [ph])
dropped = m / 2 * a ** 2 * gm ** 2 * s(gt) ** 2 - m * g * a * c(gt)  # functions of t alone, dropped by the text
L_red = L - dropped


def el(LL):
    return sp.diff(sp.diff(LL, dp), t) - sp.diff(LL, ph)


key = Key("https://github.com/HEPLean/PhysLean/blob/12fe5b99bb8046dd4f5d5f87b8c931f572c0c3ec/PhysLean/ClassicalMechanics/Pendulum/MiscellaneousPendulumPivotMotions.lean",
          "pendulum with a vertically oscillating point of support", "library documentation (worked textbook problem)")

key.line(7, r"y = a\cos(\gamma t)", "given", None, "the law of the support's motion (its height)")
key.line(13, r"x = l\sin\phi", "kinematics", same(l * s(ph), X), "the bob")
key.line(14, r"y = a\cos(\gamma t) - l\cos\phi", "kinematics", same(a * c(gt) - l * c(ph), Y), "the bob, below the moving support")
key.line(18, r"L = T - V", "claim", same(T - V, L), "the Lagrangian")
key.line(21, r"T = \tfrac{1}{2}m(\dot{x}^2 + \dot{y}^2)", "claim",
         same(m / 2 * (d(l * s(ph)) ** 2 + d(a * c(gt) - l * c(ph)) ** 2), T), "the kinetic energy of the bob")
T22 = m / 2 * (l ** 2 * dp ** 2 + a ** 2 * gm ** 2 * s(gt) ** 2 - 2 * a * l * gm * s(gt) * dp * s(ph))
key.line(22, r"= \tfrac{1}{2}m\bigl(l^2\dot{\phi}^2 + a^2\gamma^2\sin^2(\gamma t) - 2 a l \gamma\sin(\gamma t)\dot{\phi}\sin\phi\bigr)",
         "claim", same(T22, T), "ẋ = l φ̇ cos φ, ẏ = −aγ sin γt + l φ̇ sin φ")
key.line(24, r"V = m g y = m g\bigl(a\cos(\gamma t) - l\cos\phi\bigr)", "claim", same(m * g * (a * c(gt) - l * c(ph)), V),
         "m g times the height of line 14")

F = c(ph) * s(gt)
key.line(34, r"\frac{d}{dt}\bigl[\cos\phi\sin(\gamma t)\bigr] = -\dot{\phi}\sin\phi\sin(\gamma t) + \gamma\cos\phi\cos(\gamma t)",
         "claim", same(sp.diff(F, t), -dp * s(ph) * s(gt) + gm * c(ph) * c(gt)), "the product rule")

L38 = (m / 2 * l ** 2 * dp ** 2 + m * g * l * c(ph) - m * a * l * gm ** 2 * c(ph) * c(gt)
       + m * a * l * gm * sp.diff(c(ph) * c(gt), t))
L38_fix = (m / 2 * l ** 2 * dp ** 2 + m * g * l * c(ph) - m * a * l * gm ** 2 * c(ph) * c(gt)
           + m * a * l * gm * sp.diff(c(ph) * s(gt), t))
assert same(L38_fix, L_red)
key.line(38, r"L = \tfrac{1}{2} m l^2\dot{\phi}^2 + m g l \cos\phi - m a l \gamma^2 \cos\phi\cos(\gamma t) + m a l \gamma\frac{d}{dt}\bigl[\cos\phi\cos(\gamma t)\bigr]",
         "claim", same(L38, L_red) or same(L38, L),
         "the derivative just worked out is of cos φ sin(γt): inside d/dt the text writes cos(γt), so the line is not the "
         "Lagrangian (T − V, with or without the dropped functions of t; it differs by the φ-dependent m a l γ "
         "d/dt[cos φ (cos γt − sin γt)]). Being a total derivative either way, the slip does not reach the final L",
         correct=r"L = \tfrac{1}{2} m l^2\dot{\phi}^2 + m g l \cos\phi - m a l \gamma^2 \cos\phi\cos(\gamma t) + m a l \gamma\frac{d}{dt}\bigl[\cos\phi\sin(\gamma t)\bigr]")

L44 = m / 2 * l ** 2 * dp ** 2 + m * g * l * c(ph) - m * a * l * gm ** 2 * c(ph) * c(gt)
key.line(44, r"L = \tfrac{1}{2} m l^2\dot{\phi}^2 + m g l \cos\phi - m a l \gamma^2 \cos\phi\cos(\gamma t)", "claim",
         same(el(L44), el(L)),
         "T − V less functions of t alone and the total derivative m a l γ d/dt[cos φ sin γt]: an equivalent Lagrangian "
         "with the same Euler–Lagrange equation, m l² φ̈ + m l (g − aγ² cos γt) sin φ = 0, as the text says (not T − V itself)")

key.emit()
