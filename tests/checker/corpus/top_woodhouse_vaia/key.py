"""Answer key: Woodhouse's heavy top on a pivot (vaia problem page). SymPy only."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, a, A, C, g = sp.symbols("m a A C g", positive=True)
phi, theta, psi = coords("phi", "theta", "psi")

# Own kinematics: body angular velocity in z-x-z Euler angles (Goldstein 4.87), pivot at the origin, centre of mass at
# distance a on the symmetry axis, z up; A, A, C are the moments about the pivot.
w1 = d(phi) * sp.sin(theta) * sp.sin(psi) + d(theta) * sp.cos(psi)
w2 = d(phi) * sp.sin(theta) * sp.cos(psi) - d(theta) * sp.sin(psi)
w3 = d(phi) * sp.cos(theta) + d(psi)
T = sp.Rational(1, 2) * A * (w1**2 + w2**2) + sp.Rational(1, 2) * C * w3**2
V = m * g * a * sp.cos(theta)
mech = Mechanics(T - V, [phi, theta, psi])

key = Key("https://www.vaia-test.com/en-us/textbooks/physics/introduction-to-analytical-dynamics-1-edition/chapter-5/"
          "problem-3-dagger-show-that-the-principal-moments-of-inertia-",
          "heavy symmetric top on a pivot (Euler angles), a motion started at theta = pi/3", "solutions site (textbook problem)")

# Line 8: the Lagrangian.
L_text = (sp.Rational(1, 2) * A * (d(theta)**2 + d(phi)**2 * sp.sin(theta)**2)
          + sp.Rational(1, 2) * C * (d(psi) + d(phi) * sp.cos(theta))**2 - m * g * a * sp.cos(theta))
key.line(8, r"L=\frac{1}{2} A\left(\dot{\theta}^{2}+\dot{\varphi}^{2} \sin ^{2}\theta\right)+\frac{1}{2} C(\dot{\psi}+\dot{\varphi} \cos \theta)^{2}-m g a\cos \theta",
         "claim", same(L_text, mech.L), "T - V of the top with the moments A, A, C about the pivot")

# Line 12: n and k, and that they are conserved (checked here, though the lines themselves are definitions).
n_expr = d(psi) + d(phi) * sp.cos(theta)
k_expr = A * d(phi) * sp.sin(theta)**2 + C * n_expr * sp.cos(theta)
assert mech.on_motion(sp.diff(n_expr, t)) and mech.on_motion(sp.diff(k_expr, t))
assert same(C * n_expr, mech.momentum(psi)) and same(k_expr, mech.momentum(phi))
key.line(12, r"n=\dot{\psi}+\dot{\varphi} \cos \theta", "definition", None,
         "defines n (= p_psi/C; conserved: checked)")
key.line(12, r"k=A \dot{\varphi} \sin^{2} \theta+C n \cos \theta", "definition", None,
         "defines k (= p_phi; conserved: checked)")

# Lines 18-19: the initial conditions, with gamma = sqrt(m g a / A) (line 21).
gam = sp.sqrt(m * g * a / A)
key.line(18, r"\theta=\frac{\pi}{3}", "condition", None, "initial angle")
key.line(18, r"\dot{\theta}=0", "condition", None, "initial nutation rate")
key.line(18, r"\dot{\varphi}=\frac{2\gamma}{\sqrt{3}}", "condition", None, "initial precession rate")
key.line(19, r"\dot{\psi}=\frac{(3 A-C) \gamma}{C \sqrt{3}}", "condition", None, "initial spin rate")
key.line(21, r"\gamma=\sqrt{m g a / A}", "definition", None, "defines gamma")

# The constants of the motion at the start, then theta' and u' = -sin(theta) theta' at any theta along the motion.
th, thd, phd, psd = sp.symbols("th thd phd psd", real=True)
state0 = {theta: sp.pi / 3, d(theta): 0, d(phi): 2 * gam / sp.sqrt(3), d(psi): (3 * A - C) * gam / (C * sp.sqrt(3))}
def at(expr, sub):
    return sp.simplify(expr.subs({d(theta): sub[d(theta)], d(phi): sub[d(phi)], d(psi): sub[d(psi)]}).subs(theta, sub[theta]))
n0, k0, E0 = at(n_expr, state0), at(k_expr, state0), at(mech.energy(), state0)
assert same(k0, sp.sqrt(3) * A * gam) and same(C * n0, sp.sqrt(3) * A * gam)
# Along the motion: n = n0, k = k0 give phi', psi' as functions of theta; the energy gives theta'^2.
sol = sp.solve([n_expr.subs({d(phi): phd, d(psi): psd, theta: th}) - n0,
                k_expr.subs({d(phi): phd, d(psi): psd, theta: th}) - k0], [phd, psd], dict=True)[0]
E_th = mech.energy().subs({d(phi): sol[phd], d(psi): sol[psd], d(theta): thd}).subs(theta, th)
X = sp.Symbol("X")
thd2 = sp.solve(sp.Eq(E_th.subs(thd**2, X), E0), X)[0]          # theta'^2 on the motion
u = sp.Symbol("u")
udot2 = sp.simplify((sp.sin(th)**2 * thd2).rewrite(sp.cos).subs(sp.cos(th), u))   # u' = -sin(theta) theta'
text_rhs = gam**2 * (1 - u)**2 * (2 * u - 1)
key.line(23, r"\left(\frac{\mathrm{d} u}{\mathrm{~d} t}\right)^{2}=\gamma^{2}(1-u)^{2}(2 u-1)", "claim",
         same(udot2, text_rhs), "from the conserved energy with k = C n = sqrt(3) A gamma on this motion (u = cos theta)")
key.line(25, r"u=\cos \theta", "definition", None, "defines u")

# Line 27: u(t) = 1/(1 + sech(gamma t)) solves it with u(0) = 1/2 on the branch the equations of motion choose
# (u'' > 0 at t = 0: theta'' < 0 there).
tt = sp.Symbol("tt", real=True)
u_t = 1 / (1 + 1 / sp.cosh(gam * tt))
ode_ok = same(sp.diff(u_t, tt)**2, text_rhs.subs(u, u_t))
start_ok = same(u_t.subs(tt, 0), sp.Rational(1, 2))
thdd0 = at(mech.accelerations[d(theta, 2)], state0)
udd0 = -sp.sin(sp.pi / 3) * thdd0          # u'' = -sin(theta) theta'' - cos(theta) theta'^2, theta' = 0
branch_ok = same(udd0, sp.diff(u_t, tt, 2).subs(tt, 0))
key.line(27, r"\frac{1}{u}=1+\frac{1}{\cosh (\gamma t)}", "claim", ode_ok and start_ok and branch_ok,
         "solves the u equation with u(0) = 1/2 and the u''(0) of the equations of motion")

key.emit()
