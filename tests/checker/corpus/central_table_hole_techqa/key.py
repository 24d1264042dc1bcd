"""Answer key of central_table_hole_techqa (SymPy only): a particle on a smooth table tied by a string through a
hole to a particle of equal mass that hangs and moves vertically (math.techqa.club copy of a math.stackexchange
question, its hint answer)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


m, l, g = sp.symbols("m l g", positive=True)
r, th = coords("r", "theta")
s, c = sp.sin, sp.cos

# Own kinematics: the hole at the origin, z up; the particle on the table at (r cos theta, r sin theta, 0), the
# hanging one at (0, 0, -(l - r)).
P_table = sp.Matrix([r * c(th), r * s(th)])
z_hang = -(l - r)
T_table = m / 2 * (sp.diff(P_table, t).dot(sp.diff(P_table, t)))
T_hang = m / 2 * sp.diff(z_hang, t) ** 2
V_table, V_hang = 0, m * g * z_hang
T = T_table + T_hang
V = V_table + V_hang
L = T - V
mech = Mechanics(L, [r, th])                       # (only to be sure the model is a proper Lagrangian system)

# The hint's names: rho_2 = r on the table, rho_1 = l - r the hanging particle's depth, rho_0 = l the string's
# length; m_1 = m_2 = m ("a particle of equal mass").
rho1, rho2, rho0 = l - r, r, l
m1 = m2 = m

key = Key("https://math.techqa.club/classical-mechanics-kinetic-energy-string-4087742",
          "particle on a smooth table tied by a string through a hole to a hanging particle of equal mass",
          "Q&A thread (copy of a math.stackexchange question and its answer)")

U_text = m * g * r
key.line(at(r"$U=mgr$"), r"U=mgr", "claim",
         not sp.simplify(U_text - V).has(r, th),
         "the potential energy up to an additive constant: the hanging particle is l − r below the table, "
         "V = −m g (l − r) = m g r − m g l")

l19 = at(r"$$ p = \rho(\cos\theta,\sin\theta)")
key.line(l19, r"p = \rho(\cos\theta,\sin\theta)", "kinematics", same((P_table - r * sp.Matrix([c(th), s(th)])).norm(), 0),
         "the position of the particle on the table, ρ its distance from the hole")
pd_text = d(r) * sp.Matrix([c(th), s(th)]) + r * sp.Matrix([-s(th), c(th)]) * d(th)
key.line(l19, r"\dot p = \dot\rho(\cos\theta,\sin\theta)+\rho(-\sin\theta,\cos\theta)\dot\theta", "kinematics",
         all(same(a_, b_) for a_, b_ in zip(pd_text, sp.diff(P_table, t))), "its velocity")
key.line(l19, r"\|\dot p\|^2=\dot \rho^2+\rho^2\dot\theta^2", "kinematics",
         same(d(r) ** 2 + r ** 2 * d(th) ** 2, sp.diff(P_table, t).dot(sp.diff(P_table, t))), "its speed squared")

l23 = at(r"T_1 = \frac 12 m_1 \dot\rho_1^2")
key.line(l23, r"T_1 = \frac 12 m_1 \dot\rho_1^2", "claim", same(m1 / 2 * sp.diff(rho1, t) ** 2, T_hang),
         "the hanging particle's kinetic energy, ρ_1 its depth below the table")
key.line(l23, r"U_1 = -\rho_1 m _1 g", "claim", same(-rho1 * m1 * g, V_hang),
         "its potential energy, zero at the table's height (ρ_1 measured downward)")
l27 = at(r"T_2 = \frac 12m_2(\dot \rho_2^2+\rho_2^2\dot\theta^2)")
key.line(l27, r"T_2 = \frac 12m_2(\dot \rho_2^2+\rho_2^2\dot\theta^2)", "claim",
         same(m2 / 2 * (sp.diff(rho2, t) ** 2 + rho2 ** 2 * d(th) ** 2), T_table),
         "the kinetic energy of the particle on the table, ρ_2 = r")
key.line(l27, r"U_2 = 0", "claim", same(V_table, 0), "the table is the level of zero potential energy")
key.line(at(r"$$ \rho_1 + \rho_2 = \rho_0 $$"), r"\rho_1 + \rho_2 = \rho_0", "kinematics",
         same(rho1 + rho2, rho0) and same(sp.diff(rho1 + rho2, t), 0),
         "the string's length ρ_0 is constant: the hanging part and the part on the table add up to it")
key.emit()
