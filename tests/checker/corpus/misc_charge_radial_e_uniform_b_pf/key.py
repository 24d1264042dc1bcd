"""Answer key: charge in E = E0/r r_hat and B = B0 z_hat (physicsforums thread 321338, opening post)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, e, E0, B0 = sp.symbols("m e E_0 B_0", positive=True)
r, th, z = coords("r", "theta", "z")

# Fields and potentials in cylindrical coordinates (R, TH, Z static symbols for the vector calculus).
R, TH, Z = sp.symbols("R Theta Z", positive=True)
phi_pot = -E0 * sp.log(R)                        # E = −∇φ = E0/R r_hat
A_th = B0 * R / 2                                # A = A_θ θ_hat
E_r = -sp.diff(phi_pot, R)
B_z = sp.diff(R * A_th, R) / R                   # (∇×A)_z in cylindrical coordinates
B_r = -sp.diff(A_th, Z)
assert sp.simplify(E_r - E0 / R) == 0

# Kinematics: position (r cos θ, r sin θ, z); velocity components v_r = ṙ, v_θ = r θ̇, v_z = ż.
x, y = r * sp.cos(th), r * sp.sin(th)
T = sp.simplify(m / 2 * (d(x) ** 2 + d(y) ** 2 + d(z) ** 2))
v_dot_A = (r * d(th)) * A_th.subs(R, r)
L = T - e * phi_pot.subs(R, r) + e * v_dot_A   # L = T − q φ + q v·A
mech = Mechanics(L, [r, th, z])

key = Key("https://www.physicsforums.com/threads/how-does-velocity-affect-potential-in-electromagnetic-fields.321338/",
          "charge in a radial electric field E0/r and a uniform magnetic field B0 (cylindrical r, θ, z)",
          "Q&A thread (homework help)")

key.line(6, r"\vec{E}=\frac{E_0}{r}\hat{r}", "given", None, "the electric field")
key.line(7, r"\vec{B}=B_0\hat{k}", "given", None, "the magnetic field")
key.line(8, r"\vec{A}=\frac{1}{2}B_0 r \hat{\theta}", "claim", sp.simplify(B_z - B0) == 0 and B_r == 0,
         "∇×A = (1/r) ∂(r A_θ)/∂r ẑ = B0 ẑ")
U_gen = e * phi_pot.subs(R, r) - e * v_dot_A   # the generalized potential
key.line(14, r"L=T-V", "claim", same(T - U_gen, L),
         "L = T − V with V the velocity-dependent potential e φ − e v·A (definition of the generalized potential)")
text14 = m / 2 * (d(r) ** 2 + d(th) ** 2 + d(z) ** 2) - e * phi_pot.subs(R, r) + e * v_dot_A
key.line(14, r"T-V=\frac{1}{2}m \left ( \dot{r}^2+\dot{\theta}^2+\dot{z}^2 \right) - e\phi + e\vec{v} \cdot \vec{A}",
         "claim", same(text14, L),
         "the kinetic energy in cylindrical coordinates has r² θ̇², not θ̇² (the first reply points at the units)",
         correct=r"T-V=\frac{1}{2}m \left ( \dot{r}^2+r^2\dot{\theta}^2+\dot{z}^2 \right) - e\phi + e\vec{v} \cdot \vec{A}")
text16 = m / 2 * (d(r) ** 2 + d(th) ** 2 + d(z) ** 2) - e * E0 * sp.log(r) + sp.Rational(1, 2) * e * d(th) * B0 * r
key.line(16, r"L = \frac{1}{2}m \left ( \dot{r}^2+\dot{\theta}^2+\dot{z}^2 \right) - eE_0\ln(r) + \frac{1}{2}e\dot{\theta}B_0r",
         "claim", same(text16, L),
         "three slips: θ̇² for r² θ̇²; −eφ = +eE0 ln r (φ = −E0 ln r since E = −∇φ = E0/r r̂), not −eE0 ln r; "
         "e v·A = e (r θ̇)(B0 r/2) = ½ e B0 r² θ̇, not ½ e B0 r θ̇",
         correct=r"L = \frac{1}{2}m \left ( \dot{r}^2+r^2\dot{\theta}^2+\dot{z}^2 \right) + eE_0\ln(r) + \frac{1}{2}e\dot{\theta}B_0r^2")
key.line(20, r"0 = m\ddot{r} + eE_0\frac{1}{r} - \frac{1}{2}e\dot{\theta}B_0", "claim",
         mech.on_motion(m * d(r, 2) + e * E0 / r - sp.Rational(1, 2) * e * d(th) * B0),
         "follows the wrong L of line 16: the true r equation has −m r θ̇² and −e E0/r (sign) and −e B0 r θ̇",
         correct=r"0 = m\ddot{r} - mr\dot{\theta}^2 - eE_0\frac{1}{r} - eB_0r\dot{\theta}")
key.line(22, r"0=m\ddot{\theta}", "claim", mech.on_motion(m * d(th, 2)),
         "wrong even from the text's own L (its ∂L/∂θ̇ = m θ̇ + ½ e B0 r gives m θ̈ + ½ e B0 ṙ); the true θ "
         "equation is the conservation of p_θ = m r² θ̇ + ½ e B0 r²",
         correct=r"0=\frac{d}{dt}\left(mr^2\dot{\theta}+\frac{1}{2}eB_0r^2\right)")
key.line(24, r"0=m\ddot{z}", "claim", mech.on_motion(m * d(z, 2)), "z is cyclic and free")
key.emit()
