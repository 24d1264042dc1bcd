"""Answer key: block on a sliding ramp (joshuaspiral.github.io blog post)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


X, q = coords("X", "q")
M, m, g, th = sp.symbols("M m g theta", positive=True)
s, c = sp.sin(th), sp.cos(th)
Xd, qd, Xdd, qdd = d(X), d(q), d(X, 2), d(q, 2)

# Own kinematics: the ramp at X; the block a distance q down the slope, moving against X as q grows
# (the text's kinetic energy has (Xdot - qdot cos theta)); height -q sin theta.
xb, yb = X - q * c, -q * s
T = M * Xd**2 / 2 + m * (sp.diff(xb, t) ** 2 + sp.diff(yb, t) ** 2) / 2
V = m * g * yb
L = T - V
mech = Mechanics(L, [X, q])
half = sp.Rational(1, 2)

key = Key("https://github.com/joshuaspiral/joshuaspiral.github.io/blob/074f078a88556908420cded48ed8ae801f336351/"
          "content/posts/intro-lagrangian-mechanics/index.md",
          "block sliding on a ramp that slides on a smooth floor", "blog post")

key.line(at(r"$$\Lagr = T - V$$"), r"\Lagr = T - V", "definition", None, "the Lagrangian as T - V")
key.line(at(r"S = \int"), r"S = \int_{t1}^{t2} \Lagr \, \mathrm{d}t", "definition", None,
         "defines the action S")
key.line(at(r"\frac{\partial \Lagr}{\partial q} - \frac{d}{dt}"),
         r"\frac{\partial \Lagr}{\partial q} - \frac{d}{dt} \frac{\partial \Lagr}{\partial \dot{q}} = 0",
         "definition", None,
         "the Euler-Lagrange equation stated for a generic coordinate q (the ramp problem later calls its "
         "coordinate q too; for that q it holds)")

rhs_x, rhs_y = X + q * c, -q * s
key.line(at(r"(X - x, y) = (X + q\cos{\theta}"), r"(X - x, y) = (X + q\cos{\theta}, -q\sin{\theta})",
         "kinematics", same(rhs_x, xb) and same(rhs_y, yb),
         "the block's horizontal position is X - q cos(theta): that is what the text's kinetic energy "
         "(Xdot - qdot cos theta)^2 and the rest of the derivation use (the block and the ramp move in "
         "opposite directions); the written X + q cos(theta) has the wrong sign. (The left side's X - x "
         "cannot tell: x is not defined further.)",
         r"(X - x, y) = (X - q\cos{\theta}, -q\sin{\theta})")

T1 = M * Xd**2 / 2 + m * ((Xd - qd * c) ** 2 + (-qd * s) ** 2) / 2
key.line(at(r"T = \frac{1}{2}M\dot{X}^2 + \frac{1}{2}m((\dot{X}-\dot{q}\cos{\theta})^2"),
         r"T = \frac{1}{2}M\dot{X}^2 + \frac{1}{2}m((\dot{X}-\dot{q}\cos{\theta})^2 + (-\dot{q}\sin{\theta})^2)",
         "claim", same(T1, T), "the kinetic energy of ramp and block")
T2 = M * Xd**2 / 2 + m * (Xd**2 - 2 * c * Xd * qd + qd**2 * c**2 + qd**2 * s**2) / 2
key.line(at(r"\dot{q}^2\cos^2{\theta}+\dot{q}^2\sin^2{\theta})$$"),
         r"T = \frac{1}{2}M\dot{X}^2 + \frac{1}{2}m(\dot{X}^2-2\cos{\theta}\dot{X}\dot{q}+\dot{q}^2\cos^2{\theta}+\dot{q}^2\sin^2{\theta})",
         "claim", same(T2, T), "the square expanded")
key.line(at(r"$\sin^2{\theta} + \cos^2{\theta} = 1$"), r"\sin^2{\theta} + \cos^2{\theta} = 1", "claim",
         same(s**2 + c**2, 1), "trigonometric identity")
T3 = M * Xd**2 / 2 + m * (Xd**2 - 2 * c * Xd * qd + qd**2) / 2
key.line(at(r"-2\cos{\theta}\dot{X}\dot{q}+\dot{q}^2)$$"),
         r"T = \frac{1}{2}M\dot{X}^2 + \frac{1}{2}m(\dot{X}^2-2\cos{\theta}\dot{X}\dot{q}+\dot{q}^2)",
         "claim", same(T3, T), "sin^2 + cos^2 = 1 used")
T4 = M * Xd**2 / 2 + m * Xd**2 / 2 - m * c * Xd * qd + m * qd**2 / 2
key.line(at(r"T = \frac{1}{2}M\dot{X}^2 + \frac{1}{2}m\dot{X}^2-m\cos"),
         r"T = \frac{1}{2}M\dot{X}^2 + \frac{1}{2}m\dot{X}^2-m\cos{\theta}\dot{X}\dot{q}+\frac{1}{2}m\dot{q}^2",
         "claim", same(T4, T), "multiplied out")
T5 = (M + m) * Xd**2 / 2 + m * qd**2 / 2 - m * c * Xd * qd
key.line(at(r"T = \frac{1}{2}(M + m)\dot{X}^2"),
         r"T = \frac{1}{2}(M + m)\dot{X}^2+\frac{1}{2}m\dot{q}^2-m\cos{\theta}\dot{X}\dot{q}",
         "claim", same(T5, T), "collected")
key.line(at(r"U = -mgq\sin{\theta}"), r"U = -mgq\sin{\theta}", "claim", same(-m * g * q * s, V),
         "the block's potential energy (height -q sin theta); the text calls it U")
L_text = (M + m) * Xd**2 / 2 + m * qd**2 / 2 - m * c * Xd * qd + m * g * q * s
key.line(at(r"\Lagr = \frac{1}{2}(M + m)"),
         r"\Lagr = \frac{1}{2}(M + m)\dot{X}^2+\frac{1}{2}m\dot{q}^2 - m\cos{\theta}\dot{X}\dot{q}+ mgq\sin{\theta}",
         "claim", same(L_text, L), "L = T - U")
key.line(at(r"\frac{\partial{\Lagr}}{\partial{\dot{X}}} = \frac{\partial{\Lagr}}{\partial{X}}"),
         r"\frac{d}{dt}\frac{\partial{\Lagr}}{\partial{\dot{X}}} = \frac{\partial{\Lagr}}{\partial{X}}", "claim",
         mech.on_motion(sp.diff(sp.diff(L, Xd), t), sp.diff(L, X)), "the Euler-Lagrange equation for X")
ok = mech.on_motion((M + m) * Xdd - m * c * qdd) and mech.on_motion(Xdd, m / (M + m) * c * qdd)
key.line(at(r"(M+m)\ddot{X}-m\cos{\theta}\ddot{q} = 0\implies"),
         r"(M+m)\ddot{X}-m\cos{\theta}\ddot{q} = 0\implies\ddot{X} = \frac{m}{M+m}\cos{\theta}\ddot{q}", "claim",
         ok, "the X equation (X is cyclic) and the same solved for Xddot")
key.line(at(r"\frac{\partial{\Lagr}}{\partial{\dot{q}}} = \frac{\partial{\Lagr}}{\partial{q}}"),
         r"\frac{d}{dt}\frac{\partial{\Lagr}}{\partial{\dot{q}}} = \frac{\partial{\Lagr}}{\partial{q}}", "claim",
         mech.on_motion(sp.diff(sp.diff(L, qd), t), sp.diff(L, q)), "the Euler-Lagrange equation for q")
key.line(at(r"\cancel{m}\ddot{q}-\cancel{m}\cos{\theta}\ddot{X}"),
         r"\cancel{m}\ddot{q}-\cancel{m}\cos{\theta}\ddot{X} = \cancel{m}g\sin{\theta}", "claim",
         mech.on_motion(m * qdd - m * c * Xdd, m * g * s),
         "the q equation (the cancel marks only say m divides out)")
ln = at(r"\ddot{q} +\left(\frac{m}{M+m}\cos{\theta}\ddot{q}\right)\cos{\theta} = g\sin{\theta}")
key.line(ln, r"\ddot{q} +\left(\frac{m}{M+m}\cos{\theta}\ddot{q}\right)\cos{\theta} = g\sin{\theta}", "claim",
         mech.on_motion(qdd + (m / (M + m) * c * qdd) * c, g * s),
         "sign slip: the q equation is qddot - cos(theta) Xddot = g sin(theta), so substituting "
         "Xddot = m cos(theta) qddot/(M+m) gives a minus sign before the bracket",
         r"\ddot{q} -\left(\frac{m}{M+m}\cos{\theta}\ddot{q}\right)\cos{\theta} = g\sin{\theta}")
key.line(ln, r"\ddot{q} = g\sin{\theta}\frac{M+m}{M+m\sin^2{\theta}}", "claim",
         mech.on_motion(qdd, g * s * (M + m) / (M + m * s**2)),
         "the correct qddot (it does not follow from the step before it, whose sign is wrong: that step would "
         "give (M+m)/(M+m+m cos^2 theta))")
Xdd_text = -m / (M + m) * c * (g * s * (M + m) / (M + m * s**2))
ok = mech.on_motion(Xdd, Xdd_text)
assert ok == mech.on_motion(Xdd, -g * c * s * m / (M + m * s**2))  # both links of the line alike
key.line(at(r"\ddot{X}=-\frac{m}{\cancel{M+m}}"),
         r"\ddot{X}=-\frac{m}{\cancel{M+m}}\cos{\theta}\left(g\sin{\theta}\frac{\cancel{M+m}}{M+m\sin^2{\theta}}\right) \implies \ddot{X}=-g\cos{\theta}\sin{\theta}\frac{m}{M+m\sin^2{\theta}}",
         "claim", ok,
         "sign slip: the X equation gave Xddot = +m cos(theta) qddot/(M+m); the minus sign put in here (the ramp "
         "'moves the other way') is already in the coordinates, so Xddot = +g m sin cos/(M + m sin^2) in them",
         r"\ddot{X}=g\cos{\theta}\sin{\theta}\frac{m}{M+m\sin^2{\theta}}")
key.emit()
