"""Answer key of atwood_swinging_blog (SymPy only): the swinging Atwood machine of the "Dynamical System Modeling"
blog post (Tclack88/blog): its Lagrangian and the two equations of motion."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

M, m, g, l, dd = sp.symbols("M m g l d", positive=True)
r, th = coords("r", "theta")

# Own kinematics: the pulleys at (0, 0) and (d, 0), y up. M hangs below the first pulley on the rope's first part,
# of length l - d - r; m hangs from the second pulley on a part of length r at the angle theta from the downward
# vertical.
xM, yM = sp.Integer(0), -(l - dd - r)
xm, ym = dd + r * sp.sin(th), -r * sp.cos(th)
T = sp.simplify(M / 2 * (d(xM) ** 2 + d(yM) ** 2) + m / 2 * (d(xm) ** 2 + d(ym) ** 2))
V = M * g * yM + m * g * ym
L = sp.expand(T - V)
mech = Mechanics(L, [r, th])

_TEXT = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "derivation.md"), encoding="utf-8").read().split("\n")


def at(n, fragment):
    """Line n of derivation.md, checked to hold the fragment (so that a line number cannot silently drift)."""
    assert fragment in _TEXT[n - 1], (n, fragment, _TEXT[n - 1])
    return n


key = Key("https://github.com/Tclack88/blog/blob/0f3e8b263c6416f9bdb3369465a339cdfbdbc238/_posts/"
          "2022-07-29-dynamical_system_modeling.md",
          "swinging Atwood machine (one mass swings as a pendulum of variable length, the other hangs straight down)",
          "personal blog")

# Line 8: the post writes \dot{r^2} and \dot{\theta^2} for the squared velocities (the dot over the whole power, as
# in all its formulas); read so, the line is T - V.
Lt = M / 2 * d(r) ** 2 + m / 2 * (d(r) ** 2 + r ** 2 * d(th) ** 2) - M * g * (r + dd - l) + m * g * r * sp.cos(th)
key.line(at(8, r"$$ L = \frac{M}{2}\dot{r^2} + \frac{m}{2}(\dot{r^2}+r^2\dot{\theta^2}) - Mg(r+d-l)+mgr\cos\theta $$"),
         r"L = \frac{M}{2}\dot{r^2} + \frac{m}{2}(\dot{r^2}+r^2\dot{\theta^2}) - Mg(r+d-l)+mgr\cos\theta", "claim",
         same(Lt, L),
         "T - V, heights from the pulleys (M at depth l - d - r, m at depth r cos(theta)); \\dot{r^2} and "
         "\\dot{\\theta^2} are the post's way of writing the squared velocities r'^2 and theta'^2")
# Line 13: the r equation, d/dt((M+m) r') = m r theta'^2 - M g + m g cos(theta).
key.line(at(13, r"(M+m)\ddot{r} = mr\dot{\theta^2} + g(m\cos\theta-M)\\"),
         r"(M+m)\ddot{r} = mr\dot{\theta^2} + g(m\cos\theta-M)", "claim",
         mech.on_motion((M + m) * d(r, 2), m * r * d(th) ** 2 + g * (m * sp.cos(th) - M)),
         "Lagrange's equation for r (\\dot{\\theta^2} read as theta'^2)")
# Line 14: the theta equation is d/dt(m r^2 theta') = -m g r sin(theta), i.e. 2 r' theta' + r theta'' = -g sin(theta)
# after division by m r. The post has an extra factor r on the first term and theta'' squared; neither reading of
# the square (theta''^2 or a stray exponent on theta'') makes it hold.
as_written = 2 * r * d(r) * d(th) + r * d(th, 2) ** 2
stray_exponent = 2 * r * d(r) * d(th) + r * d(th, 2)
right = 2 * d(r) * d(th) + r * d(th, 2)
assert mech.on_motion(right, -g * sp.sin(th))
assert not mech.on_motion(stray_exponent, -g * sp.sin(th))
key.line(at(14, r"2r\dot r\dot\theta + r\ddot\theta^2 = -g\sin\theta"),
         r"2r\dot r\dot\theta + r\ddot\theta^2 = -g\sin\theta", "claim",
         mech.on_motion(as_written, -g * sp.sin(th)),
         "Lagrange's equation for theta is m r^2 theta'' + 2 m r r' theta' = -m g r sin(theta); divided by m r it is "
         "2 r' theta' + r theta'' = -g sin(theta): the text has 2 r r' theta' (an r too many) and theta'' squared",
         correct=r"2\dot r\dot\theta + r\ddot\theta = -g\sin\theta")

key.emit()
