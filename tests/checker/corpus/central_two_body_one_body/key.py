"""Answer key: the two-body problem reduced to one body (rprador/rprador, mechanics/one-body.md, commit 0abf83f)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m1, m2 = sp.symbols("m_1 m_2", positive=True)
Mt = m1 + m2
mu = m1 * m2 / Mt
Vf = sp.Function("V")                     # the text's general central potential V(r)
X, Y, r, th = coords("X", "Y", "r", "theta")

# Kinematics in the plane of the motion: R = (X, Y) the centre of mass, rel = r2 - r1 = r (cos θ, sin θ).
R = sp.Matrix([X, Y])
rel = sp.Matrix([r * sp.cos(th), r * sp.sin(th)])
r1 = R - m2 / Mt * rel                     # solves R = (m1 r1 + m2 r2)/M with r2 - r1 = rel
r2 = R + m1 / Mt * rel
assert sp.simplify((m1 * r1 + m2 * r2) / Mt - R) == sp.zeros(2, 1) and sp.simplify(r2 - r1 - rel) == sp.zeros(2, 1)


def sq(v):
    return sp.simplify(v.dot(v))


T = sp.simplify(m1 / 2 * sq(d(r1)) + m2 / 2 * sq(d(r2)))
V = Vf(r)
L = T - V
mech = Mechanics(L, [X, Y, r, th])

key = Key("https://github.com/rprador/rprador/blob/0abf83f8e472f36d80888af6618202c12ec6d40a/mechanics/one-body.md",
          "two-body problem with a central interaction, reduced to one body (CM X, Y; relative r, θ)",
          "course notes (personal site, Markdown)")

key.line(8, r"\textbf{r}=\textbf{r}\_2 - \textbf{r}\_1", "definition", None, "names the relative vector")
key.line(10, r"\textbf{R} = \frac{1}{M}\sum_{i}m_{i}\textbf{r}_{i} = \frac{m_1 \textbf{r}_1 + m_2 \textbf{r}_2}{m_1 + m_2}",
         "definition", None, "the centre of mass")

# T depends on the velocities only (relative part in Cartesian components x, y of r).
xr, yr = coords("x", "y")
T_cart = sp.simplify(m1 / 2 * sq(d(R - m2 / Mt * sp.Matrix([xr, yr]))) + m2 / 2 * sq(d(R + m1 / Mt * sp.Matrix([xr, yr]))))
key.line(16, r"L = T(\dot{\textbf{R}}, \dot{\textbf{r}}) - U(\textbf{r}, \dot{\textbf{r}}, \dots)", "claim",
         all(sp.diff(T_cart, q) == 0 for q in (X, Y, xr, yr)),
         "T depends on Ṙ and ṙ only (in Cartesian components of r no coordinate appears in T)")

r1p, r2p = r1 - R, r2 - R                  # positions from the CM
key.line(20, r"T = \frac{1}{2}(m_{1} + m_{2})\dot{\textbf{R}}^{2} + \frac{1}{2}m_{1}\dot{\textbf{r}}_{1}^{'2} + \frac{1}{2}m_{2}\dot{\textbf{r}}_{2}^{'2}",
         "claim", same(Mt / 2 * sq(d(R)) + m1 / 2 * sq(d(r1p)) + m2 / 2 * sq(d(r2p)), T),
         "König: motion of the CM plus motion about it (the cross terms vanish)")
key.line(24, r"\textbf{r}_{1}^{'} = -\frac{m_{2}}{m_{1}+m_{2}}\textbf{r}", "kinematics",
         sp.simplify(r1p + m2 / Mt * rel) == sp.zeros(2, 1), "r1 − R with r = r2 − r1")
key.line(24, r"\textbf{r}_{2}^{'} = -\frac{m_{1}}{m_{1}+m_{2}}\textbf{r}", "kinematics",
         sp.simplify(r2p + m1 / Mt * rel) == sp.zeros(2, 1),
         "sign: r2 − R = +m1 r/(m1 + m2) (mass 2 is on the side r points to); harmless in T, where it is squared",
         correct=r"\textbf{r}_{2}^{'} = \frac{m_{1}}{m_{1}+m_{2}}\textbf{r}")
vr2 = sq(d(rel))
middle = Mt / 2 * sq(d(R)) + m1 / 2 * (m2 / Mt) ** 2 * vr2 + m1 / 2 * (m1 / Mt) ** 2 * vr2
last = Mt / 2 * sq(d(R)) + sp.Rational(1, 2) * m1 * m2 / Mt * vr2
assert same(last, T) and not same(middle, T) and not same(middle, last)
key.line(28, r"T = \frac{1}{2}(m_{1} + m_{2})\dot{\textbf{R}}^{2} + \frac{1}{2}m_{1} \left(\frac{m_{2}}{m_{1}+m_{2}}\right)^{2} \dot{\textbf{r}}^{2} + \frac{1}{2}m_{1} \left(\frac{m_{1}}{m_{1}+m_{2}}\right)^{2} \dot{\textbf{r}}^{2} = \frac{1}{2}(m_{1} + m_{2})\dot{\textbf{R}}^{2} + \frac{1}{2}\frac{m_{1}m_{2}}{m_{1}+m_{2}}\dot{\textbf{r}}^{2}",
         "claim", same(middle, T) and same(middle, last),
         "the middle step has m1 where m2 belongs in its last term (½ m2 (m1/M)² ṙ²), so T = middle and "
         "middle = last are both false; the final expression, T = ½ M Ṙ² + ½ μ ṙ², is right",
         correct=r"T = \frac{1}{2}(m_{1} + m_{2})\dot{\textbf{R}}^{2} + \frac{1}{2}m_{1} \left(\frac{m_{2}}{m_{1}+m_{2}}\right)^{2} \dot{\textbf{r}}^{2} + \frac{1}{2}m_{2} \left(\frac{m_{1}}{m_{1}+m_{2}}\right)^{2} \dot{\textbf{r}}^{2} = \frac{1}{2}(m_{1} + m_{2})\dot{\textbf{R}}^{2} + \frac{1}{2}\frac{m_{1}m_{2}}{m_{1}+m_{2}}\dot{\textbf{r}}^{2}")
key.line(32, r"\mu = \frac{m_1 m_2}{m_1 + m_2 \,. }", "definition", None, "the reduced mass")
key.line(36, r"L = \frac{1}{2}(m_{1} + m_{2})\dot{\textbf{R}}^{2} + \frac{1}{2}\mu\dot{\textbf{r}}^{2} - U(\textbf{r}, \dot{\textbf{r}}, \dots)",
         "claim", same(Mt / 2 * sq(d(R)) + mu / 2 * vr2 - V, L), "T of line 28 with μ, minus the interaction")
key.line(38, r"M=m\_1 + m\_2", "definition", None, "the total mass")
# R is cyclic: d/dt (M Ṙ) = 0, i.e. Ṙ is constant, not zero.
key.line(47, r"m\dot{\textbf{R}}=0", "claim", mech.on_motion(Mt * d(X)) and mech.on_motion(Mt * d(Y)),
         "R cyclic makes its momentum M Ṙ constant, not zero (the CM moves uniformly, as the same sentence says)",
         correct=r"M\dot{\textbf{R}}=\text{const}")
Lz = mu * (rel[0] * d(rel[1]) - rel[1] * d(rel[0]))          # (r × μ ṙ)_z, the only component in the plane
key.line(50, r"\textbf{L} = \textbf{r} \times \textbf{p}", "definition", None,
         "the angular momentum of the relative motion (p = μ ṙ)")
key.line(50, r"\textbf{r} \times \textbf{p} = \text{constant}", "claim", mech.on_motion(sp.diff(Lz, t)),
         "conserved for a central interaction: μ r² θ̇ is constant")
# The single particle of mass m is the reduced mass: L of the relative motion (the CM part separates).
m_single = mu
L_rel = L - Mt / 2 * sq(d(R))
key.line(56, r"L = \frac{1}{2}m(\dot{r}^{2} + r^{2}\dot{\theta}^{2}) - V(r)", "claim",
         same(m_single / 2 * (d(r) ** 2 + r ** 2 * d(th) ** 2) - V, L_rel),
         "read as the Lagrangian of the one-body problem the text has just announced (m the reduced mass μ; the CM "
         "part ½ M Ṙ² separates); as the Lagrangian of the whole system it would lack ½ M Ṙ²")
l_ = m_single * r ** 2 * d(th)
key.line(60, r"p_\theta = \frac{\partial L}{\partial \dot{\theta}} = mr^{2}\dot{\theta}", "claim",
         same(mech.momentum(th), l_), "p_θ")
key.line(60, r"mr^{2}\dot{\theta} = l", "definition", None, "names l")
key.line(60, r"l = \text{const.}", "claim", mech.on_motion(sp.diff(l_, t)), "θ is cyclic")
key.line(64, r"mr^{2}\dot{\theta} = l", "definition", None, "restates the definition of l")
key.line(70, r"m\ddot{r} - mr\dot{\theta}^{2} + \frac{\partial V}{\partial r} = 0", "claim",
         mech.on_motion(m_single * d(r, 2) - m_single * r * d(th) ** 2 + sp.diff(Vf(r), r)),
         "the Euler–Lagrange equation for r")
key.line(72, r"\dot{\theta}=\frac{l}{mr^{2}}", "claim", same(d(th), l_ / (m_single * r ** 2)), "the definition of l solved for θ̇")
key.line(74, r"m\ddot{r} - \frac{l^{2}}{mr^{3}} = -\frac{\partial V}{\partial r}", "claim",
         mech.on_motion(m_single * d(r, 2) - l_ ** 2 / (m_single * r ** 3), -sp.diff(Vf(r), r)),
         "line 70 with θ̇ = l/(m r²)")
key.emit()
