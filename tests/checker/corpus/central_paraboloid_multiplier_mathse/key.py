"""Answer key: particle inside the paraboloid x^2 + y^2 = a z, with a multiplier (math.stackexchange 958377)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, g, a = sp.symbols("m g a", positive=True)
rho, ph = coords("rho", "phi")

# Kinematics on the surface: z = ρ²/a; Cartesian x = ρ cos φ, y = ρ sin φ.
z = rho ** 2 / a
x, y = rho * sp.cos(ph), rho * sp.sin(ph)
T = sp.simplify(m / 2 * (d(x) ** 2 + d(y) ** 2 + d(z) ** 2))
V = m * g * z
mech = Mechanics(T - V, [rho, ph])          # the motion, from the Lagrangian on the surface

# The multiplier of d/dt ∂L/∂q̇ − ∂L/∂q = λ ∂f/∂q with f = ρ² − a z, read off the z equation (∂f/∂z = −a).
lam = -(m * sp.diff(z, t, 2) + m * g) / a
c0 = rho ** 2 * d(ph)                        # the text's constant c0 = ρ² φ̇

key = Key("https://math.stackexchange.com/questions/958377/how-to-solve-the-system-of-differential-equations-for-this-particle",
          "particle on the inner surface of the paraboloid x² + y² = a z, Lagrange multiplier (ρ, z, φ)",
          "Q&A thread (question)")

key.line(5, r"x^2+y^2=az", "given", None, "the surface")
# The unconstrained L in ρ, z, φ; with z = ρ²/a it must be the L on the surface.
zf = coords("zf")
L_text = m / 2 * (d(rho) ** 2 + rho ** 2 * d(ph) ** 2 + d(zf) ** 2) - m * g * zf
key.line(7, r"L=\frac 1 2m\left(\dot\rho^2+\rho^2\dot\varphi^2+\dot z^2\right)-mgz", "claim",
         same(L_text.subs(d(zf), d(z)).subs(zf, z), T - V), "T − V in cylindrical coordinates (z free before the constraint)")
key.line(7, r"\ddot q\equiv\frac {d\dot q} {dt}\equiv\frac{d^2 q}{dt^2}", "definition", None, "notation")
key.line(7, r"f=\rho^2-az=0", "definition", None, "the constraint function f, zero on the surface")
key.line(7, r"\frac d{dt}\left(\frac{\partial L}{\partial \dot q_i} \right)-\frac{\partial L}{\partial q_i}=\lambda\frac{\partial f}{\partial q_i}",
         "definition", None, "Lagrange's equations with a multiplier: introduces λ (fixed by the constraint)")
key.line(8, r"q_1=\rho", "definition", None, "names the coordinates")
key.line(8, r"q_2=z", "definition", None, "names the coordinates")
key.line(8, r"q_3=\varphi", "definition", None, "names the coordinates")
key.line(9, r"m\ddot\rho-m\rho\dot \varphi^2=2\rho\lambda", "claim",
         mech.on_motion(m * d(rho, 2) - m * rho * d(ph) ** 2, 2 * rho * lam),
         "the ρ equation with ∂f/∂ρ = 2ρ (λ from the z equation, on the motion)")
key.line(10, r"m\ddot z+mg=-a\lambda", "claim",
         mech.on_motion(m * sp.diff(z, t, 2) + m * g, -a * lam), "the z equation, ∂f/∂z = −a (defines λ on the motion)")
key.line(11, r"\frac{d}{dt}\left(\rho^2\dot\varphi\right)=0", "claim", mech.on_motion(sp.diff(c0, t)),
         "the φ equation divided by m (∂f/∂φ = 0)")
key.line(12, r"\rho^2-az=0", "given", None, "the constraint")
key.line(13, r"\rho\in[0,+\infty),\quad\varphi\in[0,2\pi),\quad z\in(-\infty,+\infty)", "given", None,
         "ranges of the coordinates")
key.line(17, r"\rho^2\dot\varphi=c_0", "claim", mech.on_motion(sp.diff(c0, t)),
         "integral of line 11, c0 its constant")
key.line(18, r"m\ddot\rho-m\frac{c_0^2}{\rho^3}=2\rho\lambda", "claim",
         mech.on_motion(m * d(rho, 2) - m * c0 ** 2 / rho ** 3, 2 * rho * lam), "line 9 with φ̇ = c0/ρ²")
key.line(19, r"az\dot\varphi=c_0", "claim", same(a * z * d(ph), c0), "ρ² = a z on the surface")
key.line(20, r"\dot z\dot\varphi+z\ddot\varphi=0", "claim", mech.on_motion(sp.diff(z, t) * d(ph) + z * d(ph, 2)),
         "d/dt of line 19, divided by a")
key.line(24, r"m\ddot y=2y\lambda", "claim", mech.on_motion(m * sp.diff(y, t, 2), 2 * y * lam),
         "the y equation, ∂f/∂y = 2y for f = x² + y² − a z")
key.line(25, r"m\ddot x=2x\lambda", "claim", mech.on_motion(m * sp.diff(x, t, 2), 2 * x * lam), "the x equation")
key.line(26, r"m\ddot z+mg=-a\lambda", "claim",
         mech.on_motion(m * sp.diff(z, t, 2) + m * g, -a * lam), "the z equation, as line 10")
key.line(27, r"x^2+y^2-az=0", "given", None, "the constraint in Cartesian coordinates")
key.emit()
