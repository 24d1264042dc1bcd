"""Answer key: effective potential of a heavy symmetric top, stability of the sleeping top (numerade problem). SymPy only."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, l, I1, I3, g = sp.symbols("m l I_1 I_3 g", positive=True)
phi, theta, psi = coords("phi", "theta", "psi")

# Own kinematics: z-x-z Euler angles, body angular velocity (Goldstein 4.87); moments about the fixed point.
w1 = d(phi) * sp.sin(theta) * sp.sin(psi) + d(theta) * sp.cos(psi)
w2 = d(phi) * sp.sin(theta) * sp.cos(psi) - d(theta) * sp.sin(psi)
w3 = d(phi) * sp.cos(theta) + d(psi)
T = sp.Rational(1, 2) * I1 * (w1**2 + w2**2) + sp.Rational(1, 2) * I3 * w3**2
V = m * g * l * sp.cos(theta)
mech = Mechanics(T - V, [phi, theta, psi])
Mz, M3 = mech.momentum(phi), mech.momentum(psi)      # conserved: phi and psi are cyclic
assert mech.on_motion(sp.diff(Mz, t)) and mech.on_motion(sp.diff(M3, t))

key = Key("https://www.numerade.com/student-profile/martin-marquez-6770/",
          "heavy symmetric top with its lowest point fixed: effective potential and the sleeping top",
          "homework problem statement (homework-help site)")

# U_eff: E = 1/2 I1 theta'^2 + U_eff(theta) + M3^2/(2 I3), with M_z, M_3 the conserved momenta.
U_text = (Mz - M3 * sp.cos(theta))**2 / (2 * I1 * sp.sin(theta)**2) + m * g * l * sp.cos(theta)
key.line(6, r"U_{eff} = \frac{(M_z - M_3 \cos \theta)^2}{2I_1 \sin^2 \theta} + mgl \cos \theta", "claim",
         same(mech.energy() - sp.Rational(1, 2) * I1 * d(theta)**2 - M3**2 / (2 * I3), U_text),
         "energy = I1 theta'^2/2 + U_eff + M_3^2/(2 I3) with M_z = p_phi, M_3 = p_psi (the constant M_3^2/2I3 left out)")
key.line(12, r"\theta = 0", "condition", None, "the vertical (sleeping) rotation")
key.line(12, r"\theta = 0", "condition", None, "the same axis, in the hint")
key.line(13, r"M_3 = M_z", "claim", same((Mz - M3).subs(theta, 0), 0), "at theta = 0: p_phi = I3 (psi' + phi' cos theta) cos theta = p_psi")
key.line(13, r"\theta = 0", "condition", None, "the point whose stability is asked")
q = sp.Symbol("q")
key.line(14, r"\sin \theta \approx \theta", "approximation", same(sp.series(sp.sin(q), q, 0, 2).removeO(), q), "to first order")
key.line(14, r"\cos \theta \approx 1 - \theta^2/2", "approximation", same(sp.series(sp.cos(q), q, 0, 3).removeO(), 1 - q**2 / 2),
         "to second order")
key.emit()
