"""Answer key of pend_spherical_qa (SymPy only): the spherical pendulum of physics.stackexchange question 545374."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, l, g = sp.symbols("m l g", positive=True)
th, ph = coords("theta", "phi")
s, c = sp.sin, sp.cos

# Own kinematics: pivot at the origin, theta from the -z axis.
X = l * s(th) * c(ph)
Y = l * s(th) * s(ph)
Z = -l * c(th)
T = m / 2 * (d(X) ** 2 + d(Y) ** 2 + d(Z) ** 2)
V = m * g * Z
L = T - V
mech = Mechanics(L, [th, ph])

key = Key("https://wiki.weaverden.uk/content/physics.stackexchange.com_en_all_2025-07/questions/545374/"
          "rewriting-the-lagrangian-in-terms-of-the-constant-s-of-motion-doesn-t-work-why",
          "spherical pendulum", "Q&A thread")

L_text = m / 2 * (l * d(th)) ** 2 + m / 2 * (l * s(th) * d(ph)) ** 2 - (-m * g * l * c(th))
key.line(6, r"L=T-V=\frac{1}{2}m\left(l\dot\theta\right)^2+\frac{1}{2}m\left(l\sin\theta\dot\phi\right)^2-\left(-mgl\cos\theta\right)",
         "claim", same(L_text, L), "T − V of the bob, θ from the downward vertical")

J_text = m * l ** 2 * d(ph) * s(th) ** 2
key.line(13, r"J=\dfrac{\partial L}{\partial \dot{\phi}}", "definition", None, "names the momentum of φ J")
key.line(13, r"\dfrac{\partial L}{\partial \dot{\phi}}=ml^2\dot{\phi}sin^2\theta", "claim",
         same(J_text, mech.momentum(ph)), "the momentum of φ ('sin' is typeset as a bare word); it is conserved, φ being cyclic")

lhs = m * l ** 2 * d(th, 2)
rhs_text = m * l ** 2 * d(ph) * s(th) * c(th) - m * g * l * s(th)
rhs_fix = m * l ** 2 * d(ph) ** 2 * s(th) * c(th) - m * g * l * s(th)
assert mech.on_motion(lhs, rhs_fix)
key.line(15, r"ml^2\ddot{\theta}=ml^2\dot{\phi}sin\theta cos\theta-mglsin\theta", "claim", mech.on_motion(lhs, rhs_text),
         "the centrifugal term has φ̇², not φ̇ (∂L/∂θ = m l² φ̇² sin θ cos θ − m g l sin θ)",
         correct=r"ml^2\ddot{\theta}=ml^2\dot{\phi}^2sin\theta cos\theta-mglsin\theta")

# line 17 with V_eff of line 21, differentiated at fixed J, then J = m l^2 sin^2(theta) phi' (line 13)
Jsym, thv = sp.symbols("J thv")
Veff = -g / l * c(thv) + Jsym ** 2 / (2 * m ** 2 * l ** 4) / s(thv) ** 2
minus_dV = (-sp.diff(Veff, thv)).subs({thv: th, Jsym: mech.momentum(ph)})
key.line(17, r"\ddot{\theta} = -\frac{\partial V_{eff}}{\partial \theta}", "claim", mech.on_motion(d(th, 2), minus_dV),
         "with V_eff of line 21 differentiated at fixed J and J = m l² sin²θ φ̇, −∂V_eff/∂θ = φ̇² sin θ cos θ − (g/l) sin θ: "
         "the θ equation of motion (the correct one, not line 15's)")
key.line(21, r"V_{eff}(\theta) = -\frac{g}{l}cos\theta + \frac{J^2}{2m^2l^4}\frac{1}{sin^2\theta}", "definition", None,
         "defines the effective potential (per unit m l², in terms of the constant J)")

key.emit()
