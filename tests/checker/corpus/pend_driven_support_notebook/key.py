"""Answer key of pend_driven_support_notebook (SymPy only): a pendulum whose support moves along a horizontal line
as x = A cos(omega t) (Morin problem 6.3, as worked in the vhvitro/Moving-Pendulum notebook)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


m, l, A, w, g = sp.symbols("m l A omega g", positive=True)
th = coords("theta")
s, c = sp.sin, sp.cos
dth, ddth = d(th), d(th, 2)

# Own kinematics: the support at (A cos(omega t), 0), Y upward, theta from the downward vertical.
xs = A * c(w * t)
X, Y = xs + l * s(th), -l * c(th)
T = sp.expand(m / 2 * (sp.diff(X, t) ** 2 + sp.diff(Y, t) ** 2))
V = m * g * Y
L = T - V
mech = Mechanics(L, [th])
xd, xdd = sp.diff(xs, t), sp.diff(xs, t, 2)

key = Key("https://github.com/vhvitro/Moving-Pendulum/blob/8578d86b70b33a806d4a98b1e594a15ef3d3248b/Moving%20Pendulum.ipynb",
          "simple pendulum whose point of support moves horizontally as A cos(ωt)", "Jupyter notebook")

l11 = at(r"$(X, Y) = (x + l\sin(\theta), -l\cos(\theta))$")
key.line(l11, r"(X, Y) = (x + l\sin(\theta), -l\cos(\theta))", "kinematics",
         same(xs + l * s(th), X) and same(-l * c(th), Y), "the bob, x being the support's abscissa")
key.line(l11, r"x = A\cos(\omega t)", "given", None, "the law of the support's motion")
key.line(at(r"$\dot{X} = "), r"\dot{X} = \dot{x}+l\dot{\theta}\cos(\theta)", "kinematics",
         same(xd + l * dth * c(th), sp.diff(X, t)), "d/dt of X")
key.line(at(r"$\dot{Y} = "), r"\dot{Y} = l\dot{\theta}\sin(\theta)", "kinematics",
         same(l * dth * s(th), sp.diff(Y, t)), "d/dt of Y")
l21 = at(r"$V^2 = \dot{X}^2+\dot{Y}^2$")
key.line(l21, r"V^2 = \dot{X}^2+\dot{Y}^2", "definition", None,
         "introduces V as the bob's speed (not the potential energy, which the text calls U)")
V2 = xd ** 2 + l ** 2 * dth ** 2 * c(th) ** 2 + 2 * xd * dth * l * c(th) + l ** 2 * dth ** 2 * s(th) ** 2
key.line(l21, r"V^2 = \dot{x}^2 + l^2\dot{\theta}^2\cos^2\theta+2\dot{x}\dot{\theta}l\cos\theta+l^2\dot{\theta}^2\sin^2\theta",
         "kinematics", same(V2, sp.diff(X, t) ** 2 + sp.diff(Y, t) ** 2), "the bob's speed squared, Ẋ² + Ẏ² expanded")
T_text = m / 2 * (xd ** 2 + l ** 2 * dth ** 2 + 2 * xd * dth * l * c(th))
key.line(at(r"$T = \frac{1}{2}m("), r"T = \frac{1}{2}m(\dot{x}^2+l^2\dot{\theta}^2 + 2\dot{x}\dot{\theta}l\cos\theta)",
         "claim", same(T_text, T), "the kinetic energy of the bob")
key.line(at(r"$U = -mgl\cos\theta$"), r"U = -mgl\cos\theta", "claim", same(-m * g * l * c(th), V),
         "the potential energy, zero at the support's height")
L_text = T_text + m * g * l * c(th)
key.line(at(r"$\lgr = \frac{1}{2}m("), r"\lgr = \frac{1}{2}m(\dot{x}^2+l^2\dot{\theta}^2 + 2\dot{x}\dot{\theta}l\cos\theta) + mgl\cos\theta",
         "claim", same(L_text, L), "T - U (\\lgr is \\mathcal{L}, the notebook's \\newcommand)")
key.line(at(r"$\frac{\partial \lgr}{\partial \theta} = "),
         r"\frac{\partial \lgr}{\partial \theta} = \frac{d}{dt}(\frac{\partial \lgr}{\partial \dot{\theta}})", "claim",
         mech.on_motion(sp.diff(L, th), sp.diff(sp.diff(L, dth), t)), "the Euler-Lagrange equation for θ")
lhs = -m * g * l * s(th) - m * xd * dth * l * s(th)
key.line(at(r"= \frac{d}{dt}(ml^2\dot{\theta}+m\dot{x}l\cos\theta)$"),
         r"-mgl\sin\theta -m\dot{x}\dot{\theta}l\sin\theta = \frac{d}{dt}(ml^2\dot{\theta}+m\dot{x}l\cos\theta)", "claim",
         same(lhs, sp.diff(L, th)) and same(m * l ** 2 * dth + m * xd * l * c(th), sp.diff(L, dth))
         and mech.on_motion(lhs, sp.diff(m * l ** 2 * dth + m * xd * l * c(th), t)),
         "∂L/∂θ and ∂L/∂θ̇ put in (ẋ = d/dt of A cos ωt)")
key.line(at(r"= ml^2\ddot{\theta} +ml\ddot{x}\cos\theta -ml\dot{x}\dot{\theta}\sin\theta$"),
         r"-mgl\sin\theta -m\dot{x}\dot{\theta}l\sin\theta = ml^2\ddot{\theta} +ml\ddot{x}\cos\theta -ml\dot{x}\dot{\theta}\sin\theta",
         "claim", mech.on_motion(lhs, m * l ** 2 * ddth + m * l * xdd * c(th) - m * l * xd * dth * s(th)),
         "the time derivative taken")
key.line(at(r"$-g\sin\theta = l\ddot{\theta} + \ddot{x}\cos\theta$"), r"-g\sin\theta = l\ddot{\theta} + \ddot{x}\cos\theta",
         "claim", mech.on_motion(-g * s(th), l * ddth + xdd * c(th)), "divided by m l, the ẋθ̇ terms cancelled")
key.line(at(r"$x = A\cos(\omega t):$"), r"x = A\cos(\omega t):", "given", None, "the support's law again, put in")
key.line(at(r"+ \frac{g}{l}\sin\theta = 0$"),
         r"\ddot{\theta}-\frac{A}{l}\omega^2\cos(\omega t )\cos\theta + \frac{g}{l}\sin\theta = 0", "claim",
         mech.on_motion(ddth - A / l * w ** 2 * c(w * t) * c(th) + g / l * s(th)), "ẍ = −Aω² cos ωt put in")

# Small angles: first order in theta.
eps = sp.Symbol("epsilon")
l47 = at(r"$\cos\theta \approx 1, \sin\theta \approx \theta$")
key.line(l47, r"\cos\theta \approx 1", "approximation", same(sp.series(c(eps), eps, 0, 2).removeO(), 1),
         "to first order in θ")
key.line(l47, r"\sin\theta \approx \theta", "approximation", same(sp.series(s(eps), eps, 0, 2).removeO(), eps),
         "to first order in θ")
acc = mech.accelerations[ddth]                      # theta'' on the motion
lin = sp.series(acc.subs(th, eps), eps, 0, 2).removeO().subs(eps, th)
key.line(at(r"$$\ddot{\theta}+\frac{g}{l}\theta  - \frac{A}{l}\omega^2\cos(\omega t) = 0$$"),
         r"\ddot{\theta}+\frac{g}{l}\theta  - \frac{A}{l}\omega^2\cos(\omega t) = 0", "approximation",
         same(lin, -g / l * th + A / l * w ** 2 * c(w * t)), "the equation of motion to first order in θ")
l49 = at(r"Let $a = \frac{A}{l}, \mu = \sqrt{\frac{g}{l}}$:")
key.line(l49, r"a = \frac{A}{l}", "definition", None, "names A/l")
key.line(l49, r"\mu = \sqrt{\frac{g}{l}}", "definition", None, "names the natural angular frequency")

# The general solution of the linearised equation (a = A/l, mu^2 = g/l), C and phi arbitrary.
C, ph = sp.symbols("C phi")
a, mu = A / l, sp.sqrt(g / l)
sol = C * c(mu * t + ph) + a * w ** 2 * c(w * t) / (mu ** 2 - w ** 2)
resid = sp.diff(sol, t, 2) + g / l * sol - A / l * w ** 2 * c(w * t)
key.line(at(r"$$\theta(t) = C\cos(\mu t + \phi)"),
         r"\theta(t) = C\cos(\mu t + \phi) + \dfrac{a\omega^2\cos(\omega t)}{\mu^2-\omega^2}", "approximation", same(resid, 0),
         "the general solution (two constants C, φ) of the small-angle equation, for ω ≠ μ")
key.line(at(r"$$\theta(0) = 0$$"), r"\theta(0) = 0", "condition", None, "the initial angle")
key.line(at(r"$$\dfrac{d}{dt}\theta(0) = 0$$"), r"\dfrac{d}{dt}\theta(0) = 0", "condition", None,
         "the initial angular velocity")
key.emit()
