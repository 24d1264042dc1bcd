"""Answer key of pend_circle_pivot_notes (SymPy only): a pendulum whose support goes uniformly round a vertical
circle (Landau & Lifshitz §5 problem 3a), the counter-clockwise case of the notes."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, l, a, gm, g = sp.symbols("m l a gamma g", positive=True)
ph = coords("phi")
s, c = sp.sin, sp.cos
gt = gm * t

# Own kinematics: support at (a cos(gamma t), a sin(gamma t)), y upward, phi from the downward vertical.
X0, Y0 = a * c(gt), a * s(gt)
X, Y = X0 + l * s(ph), Y0 - l * c(ph)
T = m / 2 * (d(X) ** 2 + d(Y) ** 2)
U = m * g * Y
L = T - U
mech = Mechanics(L, [ph])
dp, ddp = d(ph), d(ph, 2)


def same_motion(L2):
    """L2 gives the same Euler-Lagrange expression as the system's L (an equivalent Lagrangian)."""
    el = lambda LL: sp.diff(sp.diff(LL, dp), t) - sp.diff(LL, ph)  # noqa: E731
    return same(el(L2), el(L))


key = Key("https://github.com/smat1957/pendulum_python/blob/4a9290ccc3d59a78102cc6371e168c0b52e9152f/readme/TeX/chap4.tex",
          "pendulum whose support moves uniformly round a vertical circle", "personal notes (LaTeX, Japanese)")

key.line(7, r"\gamma<0", "definition", None, "the sign convention: γ < 0 turns clockwise")
key.line(7, r"\gamma>0", "definition", None, "the sign convention: γ > 0 turns counter-clockwise")
ts = sp.Symbol("tau")
key.line(9, r"sin(-\gamma t)  = -sin(\gamma t)", "claim", same(s(-gm * ts), -s(gm * ts)),
         "sine is odd (typeset with a bare 'sin')")

key.line(14, r"x=a\cos\gamma t + l\sin\varphi", "kinematics", same(a * c(gt) + l * s(ph), X), "support on the circle plus the rod")
key.line(15, r"y=a\sin\gamma t - l\cos\varphi", "kinematics", same(a * s(gt) - l * c(ph), Y), "counter-clockwise support, y upward")
xd = -a * gm * s(gt) + l * dp * c(ph)
yd = a * gm * c(gt) + l * dp * s(ph)
key.line(21, r"\dot{x}=-a\gamma\sin\gamma t + l\dot{\varphi}\cos\varphi", "kinematics", same(xd, d(X)), "d/dt of x")
key.line(22, r"\dot{y}=a\gamma\cos\gamma t + l\dot{\varphi}\sin\varphi", "kinematics", same(yd, d(Y)), "d/dt of y")
key.line(23, r"\dot{x}^2=a^2\gamma^2\sin^2\gamma t + l^2\dot{\varphi}^2\cos^2\varphi - 2al\gamma\dot{\varphi}\sin\gamma t\cos\varphi",
         "kinematics", same(a ** 2 * gm ** 2 * s(gt) ** 2 + l ** 2 * dp ** 2 * c(ph) ** 2 - 2 * a * l * gm * dp * s(gt) * c(ph), d(X) ** 2),
         "the square of ẋ")
key.line(24, r"\dot{y}^2=a^2\gamma^2\cos^2\gamma t + l^2\dot{\varphi}^2\sin^2\varphi + 2al\gamma\dot{\varphi}\sin\varphi\cos\gamma t",
         "kinematics", same(a ** 2 * gm ** 2 * c(gt) ** 2 + l ** 2 * dp ** 2 * s(ph) ** 2 + 2 * a * l * gm * dp * s(ph) * c(gt), d(Y) ** 2),
         "the square of ẏ")

key.line(27, r"U=mgy", "claim", same(m * g * Y, U), "the potential energy of the bob, y upward")
key.line(30, r"T=\displaystyle\frac{m}{2}\left(\dot{x}^2+\dot{y}^2\right)", "claim", same(m / 2 * (xd ** 2 + yd ** 2), T),
         "the kinetic energy of the bob")
T31 = m / 2 * (a ** 2 * gm ** 2 + l ** 2 * dp ** 2 + 2 * a * l * gm * dp * (s(ph) * c(gt) - c(ph) * s(gt)))
key.line(31, r"=\frac{m}{2}\{a^2\gamma^2 + l^2\dot{\varphi}^2 + 2al\gamma\dot{\varphi}\left(\sin\varphi\cos\gamma t - \cos\varphi\sin\gamma t\right)\}",
         "claim", same(T31, T), "the sum of the squares of lines 23-24")
T32 = m / 2 * (a ** 2 * gm ** 2 + l ** 2 * dp ** 2 + 2 * a * l * gm * dp * s(ph - gt))
key.line(32, r"=\frac{m}{2}\{a^2\gamma^2 + l^2\dot{\varphi}^2 + 2al\gamma\dot{\varphi}\sin(\varphi-\gamma t)\}", "claim", same(T32, T),
         "sin φ cos γt − cos φ sin γt = sin(φ − γt)")
key.line(33, r"U=mgy=mga\sin\gamma t - mgl\cos\varphi", "claim", same(m * g * a * s(gt) - m * g * l * c(ph), U),
         "m g times the height of line 15")
key.line(36, r"L=T-U", "claim", same(T - U, L), "the Lagrangian (the text's U is the potential energy)")
key.line(39, r"L=T-U", "claim", same(T - U, L), "the Lagrangian")
L40 = m / 2 * a ** 2 * gm ** 2 + m / 2 * l ** 2 * dp ** 2 + a * l * m * gm * dp * s(ph - gt) - m * g * a * s(gt) + m * g * l * c(ph)
key.line(40, r"=\displaystyle\frac{m}{2}a^2\gamma^2 + \frac{m}{2}l^2\dot{\varphi}^2 + alm\gamma\dot{\varphi}\sin(\varphi-\gamma t) - mga\sin\gamma t + mgl\cos\varphi",
         "claim", same(L40, L), "T of line 32 minus U of line 33")
L41 = m / 2 * l ** 2 * dp ** 2 + a * l * m * gm * dp * s(ph - gt) + m * g * l * c(ph) + (m / 2 * a ** 2 * gm ** 2 - m * g * a * s(gt))
key.line(41, r"=\frac{m}{2}l^2\dot{\varphi}^2 + alm\gamma\dot{\varphi}\sin(\varphi-\gamma t) + mgl\cos\varphi +\left(\frac{m}{2}a^2\gamma^2 - mga\sin\gamma t\right)",
         "claim", same(L41, L), "the same terms regrouped")

f = m / 2 * a ** 2 * gm ** 2 * t + m * g * a / gm * c(gt)
key.line(46, r"f(t)=\displaystyle\frac{m}{2}a^2\gamma^2t + mga\frac{1}{\gamma}\cos\gamma t", "definition", None, "defines f(t)")
key.line(46, r"\frac{df(t)}{dt}=\frac{m}{2}a^2\gamma^2-mga\sin\gamma t", "claim",
         same(sp.diff(f, t), m / 2 * a ** 2 * gm ** 2 - m * g * a * s(gt)), "the derivative of f: the bracket of line 41")

L52 = m / 2 * l ** 2 * dp ** 2 + a * l * m * gm * dp * s(ph - gt) + m * g * l * c(ph)
assert same(L - L52, sp.diff(f, t))
key.line(52, r"\therefore L=\displaystyle\frac{m}{2}l^2\dot{\varphi}^2 + alm\gamma\dot{\varphi}\sin(\varphi-\gamma t)+mgl\cos\varphi",
         "claim", same_motion(L52),
         "T − U less df/dt of line 46, a function of t alone: an equivalent Lagrangian with the same Euler–Lagrange "
         "equation, as the text says (it is not T − U itself)")

key.line(56, r"\frac{\partial L}{\partial\dot{\varphi}}=ml^2\dot{\varphi} + alm\gamma\sin(\varphi-\gamma t)", "claim",
         same(sp.diff(L52, dp), m * l ** 2 * dp + a * l * m * gm * s(ph - gt)) and same(sp.diff(L, dp), sp.diff(L52, dp)),
         "∂L/∂φ̇ (the same for T − U and the L of line 52)")
key.line(57, r"\frac{\partial L}{\partial\varphi}=alm\gamma\dot{\varphi}\cos(\varphi-\gamma t)- mgl\sin\varphi", "claim",
         same(sp.diff(L52, ph), a * l * m * gm * dp * c(ph - gt) - m * g * l * s(ph)) and same(sp.diff(L, ph), sp.diff(L52, ph)),
         "∂L/∂φ")

dtp = sp.diff(sp.diff(L52, dp), t)
text62 = m * l ** 2 * ddp - a * l * m * gm ** 2 * c(ph - gt)
fix62 = m * l ** 2 * ddp + a * l * m * gm * dp * c(ph - gt) - a * l * m * gm ** 2 * c(ph - gt)
assert same(dtp, fix62)
key.line(62, r"\frac{d}{dt}\frac{\partial L}{\partial\dot{\varphi}}=ml^2\ddot{\varphi}-alm\gamma^2\cos(\varphi-\gamma t)", "claim",
         same(dtp, text62),
         "d/dt of sin(φ − γt) is (φ̇ − γ) cos(φ − γt): the term alm γ φ̇ cos(φ − γt) is missing",
         correct=r"\frac{d}{dt}\frac{\partial L}{\partial\dot{\varphi}}=ml^2\ddot{\varphi}+alm\gamma\dot{\varphi}\cos(\varphi-\gamma t)-alm\gamma^2\cos(\varphi-\gamma t)")

key.line(66, r"\frac{d}{dt}\frac{\partial L}{\partial\dot{\varphi}}-\frac{\partial L}{\partial\varphi}=0", "claim",
         mech.on_motion(sp.diff(sp.diff(L, dp), t) - sp.diff(L, ph)), "Lagrange's equation")

acc_text = a * gm ** 2 / l * c(ph - gt) + a * gm / l * dp * c(ph - gt) - g / l * s(ph)
acc_fix = a * gm ** 2 / l * c(ph - gt) - g / l * s(ph)
assert mech.on_motion(ddp, acc_fix)
key.line(70, r"\therefore \ddot{\varphi}=\frac{a\gamma^2}{l}\cos(\varphi-\gamma t)+\frac{a\gamma}{l}\dot{\varphi}\cos(\varphi-\gamma t)-\frac{g}{l}\sin\varphi",
         "claim", mech.on_motion(ddp, acc_text),
         "the φ̇ cos(φ − γt) terms of d/dt ∂L/∂φ̇ and of ∂L/∂φ cancel; the extra term comes from the slip of line 62",
         correct=r"\therefore \ddot{\varphi}=\frac{a\gamma^2}{l}\cos(\varphi-\gamma t)-\frac{g}{l}\sin\varphi")

key.line(77, r"\frac{\mathrm{d}\varphi}{\mathrm{d}t}=\dot{\varphi}", "claim", same(sp.diff(ph, t), dp),
         "the first-order form: φ̇ is the rate of φ")
key.line(78, r"\frac{\mathrm{d}\dot{\varphi}}{\mathrm{d}t}=\frac{a\gamma^2}{l}\cos(\varphi-\gamma t) +\frac{a\gamma}{l}\dot{\varphi}\cos(\varphi-\gamma t)- \frac{g}{l}\sin\varphi",
         "claim", mech.on_motion(ddp, acc_text), "line 70 again, with its extra φ̇ term",
         correct=r"\frac{\mathrm{d}\dot{\varphi}}{\mathrm{d}t}=\frac{a\gamma^2}{l}\cos(\varphi-\gamma t)- \frac{g}{l}\sin\varphi")

key.line(83, r"x_0=a\cos\gamma t", "kinematics", same(a * c(gt), X0), "the support")
key.line(83, r"y_0=a\sin\gamma t", "kinematics", same(a * s(gt), Y0), "the support, counter-clockwise")
key.line(87, r"x=x_0 + l\sin\varphi", "kinematics", same(X0 + l * s(ph), X), "the bob")
key.line(87, r"y=y_0 - l\cos\varphi", "kinematics", same(Y0 - l * c(ph), Y), "the bob")

key.emit()
