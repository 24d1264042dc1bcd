"""Answer key: kinetic energy of a rod whose lower end rests on a smooth floor (physicsforums 290217). SymPy only."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, a, g = sp.symbols("m a g", positive=True)
x, theta = coords("x", "theta")

# Own kinematics: centre at (x, a cos theta) (lower end on the floor), rod turning at theta'.
s_ = sp.Symbol("s", real=True)
I_cm = sp.integrate(m / (2 * a) * s_**2, (s_, -a, a))        # uniform rod of length 2a about its centre
I_end = sp.integrate(m / (2 * a) * s_**2, (s_, 0, 2 * a))     # about an end
T = sp.Rational(1, 2) * m * (d(x)**2 + sp.diff(a * sp.cos(theta), t)**2) + sp.Rational(1, 2) * I_cm * d(theta)**2
V = m * g * a * sp.cos(theta)
mech = Mechanics(T - V, [x, theta])

key = Key("https://www.physicsforums.com/threads/kinetic-energy-of-rod-with-lower-end-in-contact-with-smooth-surface.290217/",
          "uniform rod with its lower end on a smooth horizontal floor", "Q&A forum thread (homework help)")
KE_text = sp.Rational(1, 2) * m * d(x)**2 + sp.Rational(1, 2) * (sp.Rational(1, 3) * m * (2 * a)**2) * d(theta)**2
assert same(sp.Rational(1, 3) * m * (2 * a)**2, I_end)
key.line(10, r"KE = \frac{1}{2}m\dot{x}^2 + \frac{1}{2}I\dot{\theta}^2 = \frac{1}{2}m\dot{x}^2 + \frac{1}{2}(\frac{1}{3}m(2a)^2)\dot{\theta}^2",
         "claim", same(KE_text, T),
         "the centre also moves vertically (a sin(theta) theta') and the rotation is about the centre, I = m(2a)^2/12; "
         "the moment about the end would do only if the end were fixed",
         correct=r"KE = \frac{1}{2}m\dot{x}^2 + \frac{1}{2}ma^2\sin^2\theta\,\dot{\theta}^2 + \frac{1}{2}(\frac{1}{12}m(2a)^2)\dot{\theta}^2")
key.line(10, r"\frac{1}{2}m\dot{x}^2 + \frac{1}{2}(\frac{1}{3}m(2a)^2)\dot{\theta}^2 = \frac{1}{2}m\dot{x}^2 + \frac{2}{3}ma^2\dot{\theta}^2",
         "claim", same(KE_text, sp.Rational(1, 2) * m * d(x)**2 + sp.Rational(2, 3) * m * a**2 * d(theta)**2),
         "the arithmetic of this step is right")
key.emit()
