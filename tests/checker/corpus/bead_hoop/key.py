"""Answer key of bead_hoop (SymPy only): a bead on a hoop spinning about its vertical diameter, the PHYS 501
computing-assignment notebook."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, R, w, g = sp.symbols("m R omega g", positive=True)
th = coords("theta")

# Own kinematics: hoop centre at the origin, z up, the hoop turning about the z-axis at the rate omega; theta from the
# bottom of the hoop. Bead at (R sin th cos wt, R sin th sin wt, -R cos th).
X = R * sp.sin(th) * sp.cos(w * t)
Y = R * sp.sin(th) * sp.sin(w * t)
Z = -R * sp.cos(th)
T = sp.simplify(m / 2 * (d(X) ** 2 + d(Y) ** 2 + d(Z) ** 2))
V = m * g * (Z + R)                          # zero at the bottom of the hoop, as the text takes it
L = T - V
mech = Mechanics(L, [th])
theta_dd = mech.accelerations[d(th, 2)]

_TEXT = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "derivation.md"), encoding="utf-8").read().split("\n")


def at(n, fragment):
    """Line n of derivation.md, checked to hold the fragment (so that a line number cannot silently drift)."""
    assert fragment in _TEXT[n - 1], (n, fragment, _TEXT[n - 1])
    return n


key = Key("https://github.com/jakeb245/phys501/blob/221401437050c2b52ecf14d8e1d5aaf1f6fce877/homework/"
          "ComputationAssignment.ipynb", "bead on a hoop spinning about its vertical diameter", "notebook")

key.line(at(10, r"$\mathcal{L}=T-U$"), r"\mathcal{L}=T-U", "definition", None, "the Lagrangian")
key.line(at(14, r"$T=\frac{1}{2}mv^2$"), r"T=\frac{1}{2}mv^2", "definition", None,
         "the general form of the kinetic energy, v the speed")
speed_sq = sp.simplify(d(X) ** 2 + d(Y) ** 2 + d(Z) ** 2)
v_wire = R * d(th)
rho = sp.sqrt(X ** 2 + Y ** 2)
v_rot = sp.simplify(rho * w)
assert same(speed_sq, v_wire ** 2 + v_rot ** 2)     # the two parts are perpendicular
key.line(at(16, r"$v=R\dot{\theta}$"), r"v=R\dot{\theta}", "kinematics",
         same(sp.sqrt(d(X.subs(w, 0)) ** 2 + d(Z) ** 2) ** 2, v_wire ** 2), "the speed along the hoop")
rvec, wvec = sp.Matrix([X, Y, 0]), sp.Matrix([0, 0, w])      # r: from the axis to the bead, perpendicular to it
cross_sq = sp.simplify(sum(c ** 2 for c in rvec.cross(wvec)))
key.line(at(16, r"$v=r\times \omega$"), r"v=r\times \omega", "kinematics", same(cross_sq, v_rot ** 2),
         "read as magnitudes (the text writes no vectors): the spin gives a speed ω times the distance from the axis. "
         "As vectors the order is ω × r; r × ω points the other way")
key.line(at(16, r"$\rho=R\sin{\theta}$"), r"\rho=R\sin{\theta}", "kinematics",
         same(rho ** 2, (R * sp.sin(th)) ** 2), "the bead's distance from the spin axis (for 0 ≤ θ ≤ π)")
key.line(at(16, r"$v=\rho\omega=R\omega\sin{\theta}$"), r"v=\rho\omega=R\omega\sin{\theta}", "kinematics",
         same(v_rot ** 2, (R * w * sp.sin(th)) ** 2), "the speed from the spin")
key.line(at(18, r"$T=\frac{1}{2}mR^2(\dot{\theta}^2+\omega^2\sin^2{\theta})$"),
         r"T=\frac{1}{2}mR^2(\dot{\theta}^2+\omega^2\sin^2{\theta})", "claim",
         same(m * R ** 2 / 2 * (d(th) ** 2 + w ** 2 * sp.sin(th) ** 2), T), "the two perpendicular parts squared")
key.line(at(20, r"$U=mgh$"), r"U=mgh", "definition", None, "gravity's potential energy, h the height")
key.line(at(20, r"$h=R(1-\cos{\theta})$"), r"h=R(1-\cos{\theta})", "kinematics", same(R * (1 - sp.cos(th)), Z + R),
         "the height above the bottom of the hoop (it runs from 0 to 2R, not to R as the prose says)")
key.line(at(22, r"$U=mgR(1-\cos{\theta})$"), r"U=mgR(1-\cos{\theta})", "claim", same(m * g * R * (1 - sp.cos(th)), V),
         "zero at the bottom")
L_text = m * R ** 2 / 2 * (d(th) ** 2 + w ** 2 * sp.sin(th) ** 2) - m * g * R * (1 - sp.cos(th))
key.line(at(26, r"$$\mathcal{L}=\frac{1}{2}mR^2"), r"\mathcal{L}=\frac{1}{2}mR^2(\dot{\theta}^2+\omega^2\sin^2{\theta})"
         r"-mgR(1-\cos{\theta})", "claim", same(L_text, L), "T − U")
el = sp.diff(sp.diff(L, d(th)), t) - sp.diff(L, th)
key.line(at(30, r"$$\frac{\delta \mathcal{L}}{\delta \theta}=\frac{d}{dt}"),
         r"\frac{\delta \mathcal{L}}{\delta \theta}=\frac{d}{dt}\left(\frac{\delta \mathcal{L}}{\delta \dot{\theta}}\right)",
         "claim", mech.on_motion(el), "Lagrange's equation (δ written for the partial derivative ∂)")
key.line(at(34, r"mR^2\omega^2\sin{\theta}\cos{\theta}-mgR\sin{\theta}.$$"),
         r"\frac{\delta \mathcal{L}}{\delta \theta}=mR^2\omega^2\sin{\theta}\cos{\theta}-mgR\sin{\theta}", "claim",
         same(sp.diff(L, th), m * R ** 2 * w ** 2 * sp.sin(th) * sp.cos(th) - m * g * R * sp.sin(th)), "∂L/∂θ")
key.line(at(38, r"=\frac{d}{dt}\left(mR^2\dot{\theta}\right)=mR^2\ddot{\theta}"),
         r"\frac{d}{dt}\left(\frac{\delta \mathcal{L}}{\delta \dot{\theta}}\right)=\frac{d}{dt}\left(mR^2\dot{\theta}\right)"
         r"=mR^2\ddot{\theta}", "claim",
         same(sp.diff(L, d(th)), m * R ** 2 * d(th)) and same(sp.diff(sp.diff(L, d(th)), t), m * R ** 2 * d(th, 2)),
         "∂L/∂θ̇ and its time derivative")
key.line(at(42, r"$$mR^2\ddot{\theta}=mR^2\omega^2"), r"mR^2\ddot{\theta}=mR^2\omega^2\sin{\theta}\cos{\theta}-mgR\sin{\theta}",
         "claim", mech.on_motion(m * R ** 2 * d(th, 2), m * R ** 2 * w ** 2 * sp.sin(th) * sp.cos(th) - m * g * R * sp.sin(th)),
         "the equation of motion")
key.line(at(46, r"$$\ddot{\theta}=\omega^2\sin{\theta}\cos{\theta}-\frac{g}{R}\sin{\theta}.$$"),
         r"\ddot{\theta}=\omega^2\sin{\theta}\cos{\theta}-\frac{g}{R}\sin{\theta}", "claim",
         mech.on_motion(d(th, 2), w ** 2 * sp.sin(th) * sp.cos(th) - g / R * sp.sin(th)), "divided by mR²")

# Part IIa: small oscillations about the off-centre equilibrium cos(theta_0) = g/(omega^2 R) (it exists for
# omega^2 R > g).
A, dl, Wp = sp.symbols("A delta Omega_p", positive=True)
th0 = sp.acos(g / (w ** 2 * R))
Wp_text = sp.sqrt(w ** 2 - (g / (w * R)) ** 2)
f = theta_dd.subs(d(th), 0)                               # theta'' = f(theta), no velocity terms
assert same(f.subs(th, th0), 0) and same(f.subs(th, -th0), 0)
fprime = sp.diff(f, th).subs(th, th0)
assert same(-fprime, Wp_text ** 2)
trial = th0 + A * sp.cos(Wp_text * t - dl)
resid = sp.diff(trial, t, 2) - f.subs(th, trial)
first_order = sp.diff(resid, A).subs(A, 0)                # the residual's term linear in A
key.line(at(52, r"$$\theta(t)=\theta_0+A\cos\left(\Omega't-\delta\right)$$"),
         r"\theta(t)=\theta_0+A\cos\left(\Omega't-\delta\right)", "approximation",
         same(resid.subs(A, 0), 0) and same(first_order, 0),
         "solves the equation of motion to first order in A about the equilibrium θ₀ (Taylor's small oscillations)")
key.line(at(56, r"$$\Omega'=\sqrt{\omega^2-\left(\frac{g}{\omega R}\right)^2}$$"),
         r"\Omega'=\sqrt{\omega^2-\left(\frac{g}{\omega R}\right)^2}", "claim", same(-fprime, Wp_text ** 2),
         "the frequency of small oscillations about θ₀: Ω'² = ω² sin²θ₀ = ω² − g²/(ω²R²)")
key.line(at(60, r"$$\theta_0=\pm \arccos\left(\frac{g}{\omega^2 R}\right).$$"),
         r"\theta_0=\pm \arccos\left(\frac{g}{\omega^2 R}\right)", "claim",
         same(f.subs(th, th0), 0) and same(f.subs(th, -th0), 0),
         "the two equilibria off the bottom, where ω² cos θ₀ = g/R (they exist for ω² R > g)")

key.emit()
