"""Answer key: small mass sliding on a dome, with a Lagrange multiplier (physics.stackexchange 713655)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


M, g, r = sp.symbols("M g r", positive=True)  # r: the dome's radius (the text's r; the mass stays at r)
th = coords("theta")
thd, thdd = d(th), d(th, 2)

# Own kinematics: the mass at (r sin(theta), r cos(theta)) from the dome's centre, theta from the top.
X, Y = r * sp.sin(th), r * sp.cos(th)
T = M / 2 * (d(X) ** 2 + d(Y) ** 2)
V = M * g * Y
L = sp.simplify(T - V)
mech = Mechanics(L, [th])  # the motion on the dome: theta'' = (g/r) sin(theta)

# The multiplier. With the radial coordinate rho free and the constraint f = rho - r = 0, Lagrange's equations with
# a multiplier d/dt dL/d(rho') - dL/d(rho) = lambda df/d(rho) give, for rho = r (rho' = rho'' = 0):
# M g cos(theta) - M r theta'^2 = lambda, the normal force (the text's convention: its first equation).
rho = coords("rho")
L_free = M / 2 * (d(rho) ** 2 + rho ** 2 * thd ** 2) - M * g * rho * sp.cos(th)
EL_rho = sp.diff(sp.diff(L_free, d(rho)), t) - sp.diff(L_free, rho)
lam = sp.expand(EL_rho.subs({d(rho, 2): 0, d(rho): 0}).subs(rho, r))   # = lambda * df/drho = lambda
assert same(lam, M * g * sp.cos(th) - M * r * thd ** 2)
lam_dot = sp.diff(lam, t)                               # lambda changes along the motion
E = sp.expand(T + V)                                    # total energy, conserved
assert mech.on_motion(sp.diff(E, t))
# lambda as a function of theta along a motion of energy E: lambda = 3 M g cos(theta) - 2E/r (checked below);
# its derivative with respect to theta (E fixed):
Es = sp.Symbol("E")
lam_of_theta = 3 * M * g * sp.cos(th) - 2 * Es / r
lam_p = sp.diff(lam_of_theta, th)

key = Key("https://physics.stackexchange.com/questions/713655/small-mass-on-a-dome-problems-with-derivatives",
          "small mass sliding on a frictionless dome (sphere), the normal force as a Lagrange multiplier",
          "Q&A thread (question and answer)")

L_text = M / 2 * (r * thd) ** 2 - M * g * r * sp.cos(th)
key.line(at(r"$$L=\frac{1}{2}M\left(r\,\dot{\theta}\right)^2-Mgr\cos\theta$$"),
         r"L=\frac{1}{2}M\left(r\,\dot{\theta}\right)^2-Mgr\cos\theta", "claim", same(L_text, L),
         "T - V of the mass on the dome (height r cos(theta) above the centre; r fixed, so no r-dot term)")

key.line(at(r"$$Mr\dot{\theta}^2-Mg\cos\theta+\lambda=0$$"), r"Mr\dot{\theta}^2-Mg\cos\theta+\lambda=0", "claim",
         same(M * r * thd ** 2 - M * g * sp.cos(th) + lam, 0),
         "the radial Lagrange equation with the multiplier of the constraint r = const (L + lambda (rho - r)), "
         "at rho'' = 0: lambda = M g cos(theta) - M r theta-dot^2, the normal force; this equation is where the "
         "text's lambda gets its sign")

key.line(at(r"$$Mr^2\ddot{\theta}-Mgr\sin\theta=0$$"), r"Mr^2\ddot{\theta}-Mgr\sin\theta=0", "claim",
         mech.on_motion(M * r ** 2 * thdd - M * g * r * sp.sin(th)), "the theta equation (df/dtheta = 0)")

root = sp.sqrt(g / r * sp.cos(th) - lam / (M * r))
key.line(at(r"$\dot{\theta}=\sqrt{\frac{g}{r}\cos\theta-\frac{\lambda}{Mr}}$"),
         r"\dot{\theta}=\sqrt{\frac{g}{r}\cos\theta-\frac{\lambda}{Mr}}", "claim",
         same(thd ** 2, g / r * sp.cos(th) - lam / (M * r)),
         "the first equation solved for theta-dot (the root taken positive: theta-dot >= 0)")

ln = at(r"$$\ddot{\theta}=\frac{-\frac{g}{r}\sin\theta\,\dot{\theta}}{2\sqrt{")
# The derivative of the root, lambda held fixed: what the text writes.
rhs1 = (-g / r * sp.sin(th) * thd) / (2 * root)
# Along the motion the root is theta-dot (theta-dot > 0): compare with the root replaced by theta-dot.
rhs1_m = (-g / r * sp.sin(th) * thd) / (2 * thd)
ok1 = mech.on_motion(thdd, rhs1_m)
key.line(ln, r"\ddot{\theta}=\frac{-\frac{g}{r}\sin\theta\,\dot{\theta}}{2\sqrt{\frac{g}{r}\cos\theta-\frac{\lambda}{Mr}}}",
         "claim", ok1,
         "the time derivative of the root misses the term of lambda-dot: lambda = M g cos(theta) - M r theta-dot^2 "
         "changes along the motion (lambda-dot = -3 M g sin(theta) theta-dot); the right side is -(g/2r) sin(theta), "
         "not theta-ddot = (g/r) sin(theta)",
         r"\ddot{\theta}=\frac{-\frac{g}{r}\sin\theta\,\dot{\theta}-\frac{\dot\lambda}{Mr}}{2\sqrt{\frac{g}{r}\cos\theta-\frac{\lambda}{Mr}}}")
key.line(ln, r"\frac{-\frac{g}{r}\sin\theta\,\dot{\theta}}{2\sqrt{\frac{g}{r}\cos\theta-\frac{\lambda}{Mr}}}=\frac{-\frac{g}{r}\sin\theta\,\dot{\theta}}{2\dot{\theta}}",
         "claim", same(root ** 2, thd ** 2),
         "the root is theta-dot (the text's previous line), so the two fractions are equal")
key.line(ln, r"\frac{-\frac{g}{r}\sin\theta\,\dot{\theta}}{2\dot{\theta}}=-\frac{g}{2r}\sin\theta", "claim",
         same(rhs1_m, -g / (2 * r) * sp.sin(th)), "theta-dot cancelled")

key.line(at(r"$$\ddot{\theta}=\frac{g}{r}\sin\theta$$"), r"\ddot{\theta}=\frac{g}{r}\sin\theta", "claim",
         mech.on_motion(thdd, g / r * sp.sin(th)), "the theta equation divided by M r^2")

# The answer's chain: lambda-dot = lambda' theta-dot, and the root is theta-dot.
ans1 = -(g / r * sp.sin(th) * thd + lam_dot / (M * r)) / (2 * thd)
lam_p_motion = sp.simplify(lam_dot.subs(mech.accelerations) / thd)  # d(lambda)/d(theta) on the motion
ans2 = -(g / r * sp.sin(th) + lam_p_motion / (M * r)) / (2 * thd) * thd
ans3 = -sp.Rational(1, 2) * (g / r * sp.sin(th) + lam_p_motion / (M * r))
ok = mech.on_motion(thdd, ans1) and mech.on_motion(thdd, ans2) and mech.on_motion(thdd, ans3)
key.line(at(r"$$ \ddot \theta = -\frac{\frac{g}{r}\sin\theta\dot \theta+\frac{1}{Mr}\dot\lambda}"),
         r"\ddot \theta = -\frac{\frac{g}{r}\sin\theta\dot \theta+\frac{1}{Mr}\dot\lambda}{2\sqrt{\frac{g}{r}\cos\theta-\frac{1}{Mr}\lambda} }\\ =-\frac{\frac{g}{r}\sin\theta+\frac{1}{Mr}\lambda'}{2\sqrt{\frac{g}{r}\cos\theta-\frac{1}{Mr}\lambda}} \dot \theta\\ = -\frac{1}{2}\left(\frac{g}{r}\sin\theta+\frac{1}{Mr}\lambda'\right)",
         "claim", ok,
         "the derivative of the root with lambda's time dependence (lambda-dot = lambda' theta-dot, lambda' = "
         "d lambda/d theta), then the root replaced by theta-dot; each side is theta-ddot on the motion")

lam_E = lam_of_theta.subs(Es, E)
key.line(at(r"$\lambda = 3Mg\cos\theta-\frac{2E}{r}$"), r"\lambda = 3Mg\cos\theta-\frac{2E}{r}", "claim",
         same(lam, lam_E), "lambda = M g cos(theta) - M r theta-dot^2 with M r^2 theta-dot^2 = 2(E - M g r cos(theta))")
key.line(at(r"$\lambda' = -3Mg\sin\theta$"), r"\lambda' = -3Mg\sin\theta", "claim",
         same(lam_p, -3 * M * g * sp.sin(th)) and same(lam_p_motion, -3 * M * g * sp.sin(th)),
         "d lambda/d theta at fixed E (also lambda-dot/theta-dot on the motion)")

key.line(at(r"$$ \ddot \theta = \frac{g}{r}\sin\theta $$"), r"\ddot \theta = \frac{g}{r}\sin\theta", "claim",
         mech.on_motion(thdd, g / r * sp.sin(th)) and same(ans3.subs(lam_p_motion, lam_p), g / r * sp.sin(th)),
         "the previous line with lambda' = -3 M g sin(theta)")
key.emit()
