"""Answer key of pend_simple_blog (SymPy only): the simple pendulum."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, l, g = sp.symbols("m l g", positive=True)
ph = coords("phi")
s, c = sp.sin, sp.cos

# Own kinematics: pivot at the origin, y upward, phi from the downward vertical.
X, Y = l * s(ph), -l * c(ph)
T = m / 2 * (d(X) ** 2 + d(Y) ** 2)
U = m * g * Y
L = T - U
mech = Mechanics(L, [ph])
dp = d(ph)

key = Key("https://github.com/jsdelivrbot/phyposts.github.io/blob/12aa742824c2cd28e22a48cd612baf44eb5d8611/_posts/2018-08-22-simple-pendulum.markdown",
          "simple pendulum", "blog post")

key.line(10, r"x = \ell\sin\phi", "kinematics", same(l * s(ph), X), "the bob, pivot at the origin")
key.line(11, r"y = -\ell\cos\phi", "kinematics", same(-l * c(ph), Y), "y upward, φ from the downward vertical")
key.line(20, r"T = \frac{1}{2}m[(\ell\dot{\phi}\cos\phi)^2 + (\ell\dot{\phi}\sin\phi)^2] = \frac{1}{2} m \ell^2 \dot{\phi}^2", "claim",
         same(m / 2 * ((l * dp * c(ph)) ** 2 + (l * dp * s(ph)) ** 2), T) and same(m / 2 * l ** 2 * dp ** 2, T),
         "½ m (ẋ² + ẏ²), then cos² + sin² = 1")
key.line(28, r"U = -mg\ell\cos\phi", "claim", same(-m * g * l * c(ph), U), "the potential energy (the text's U)")
key.line(36, r"L = \frac{1}{2} m \ell^2 \dot{\phi}^2 + mg\ell\cos\phi", "claim",
         same(m / 2 * l ** 2 * dp ** 2 + m * g * l * c(ph), L), "T − U")
key.line(44, r"\frac{\partial L}{\partial \dot{\phi}} = m\ell^2 \dot{\phi}", "claim", same(mech.momentum(ph), m * l ** 2 * dp),
         "the momentum of φ")
key.line(45, r"\frac{d}{dt} \frac{\partial L}{\partial \dot{\phi}} = m \ell^2 \ddot{\phi}", "claim",
         same(sp.diff(mech.momentum(ph), t), m * l ** 2 * d(ph, 2)), "its time derivative")
key.line(46, r"\frac{\partial L}{\partial \phi} = -mg\ell\sin\phi", "claim", same(sp.diff(L, ph), -m * g * l * s(ph)), "∂L/∂φ")
key.line(54, r"\ell\ddot{\phi} + g \sin\phi = 0", "claim", mech.on_motion(l * d(ph, 2) + g * s(ph)),
         "the Euler–Lagrange equation divided by m ℓ")

key.emit()
