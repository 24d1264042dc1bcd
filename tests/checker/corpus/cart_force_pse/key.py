"""Answer key: inverted physical pendulum on a forced cart (imathworks mirror of a Physics SE question)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


x, th = coords("x", "theta")
M, m, l, I, g, F = sp.symbols("M m l I g F", positive=True)
xd, thd, xdd, thdd = d(x), d(th), d(x, 2), d(th, 2)
s, c = sp.sin(th), sp.cos(th)
IG = I - m * l**2                     # moment of inertia about the centre of mass (I is about the pivot)

# Own kinematics: cart at x; the pendulum's centre of mass at (x + l sin theta, l cos theta), theta from the
# upward vertical. T of a rigid body in plane motion: translation of the centre of mass + rotation about it.
xG, yG = x + l * s, l * c
T = M * xd**2 / 2 + m * (sp.diff(xG, t) ** 2 + sp.diff(yG, t) ** 2) / 2 + IG * thd**2 / 2
V = m * g * yG
L = T - V
mech = Mechanics(L, [x, th], forces=[F, 0])     # the force F(t) acts on the cart along x

CONV = (" (the sign of the coupling terms depends on the sense in which theta is counted from the upward "
        "vertical, which the text does not say; the key counts it so that the centre of mass is at x + l sin theta)")

key = Key("https://imathworks.com/physics/physics-lagrangian-of-an-inverted-pendulum-on-a-moving-cart",
          "inverted physical pendulum on a cart pushed by a force", "Q&A thread")

key.line(at(r"$$ T = T_C + T_P $$"), r"T = T_C + T_P", "definition", None,
         "names the cart's and the pendulum's kinetic energy")
key.line(at(r"$T_C = 1/2 M \dot{x}^2$"), r"T_C = 1/2 M \dot{x}^2", "claim", same(T.subs(m, 0).subs(I, 0), M * xd**2 / 2),
         "the cart's kinetic energy (1/2 M read as M/2, as meant)")
lp = at(r"$T_{pivot}=1/2 m \dot{x}^2$")
key.line(lp, r"T_{pivot}=1/2 m \dot{x}^2", "definition", None,
         "names the energy of the pendulum's mass moving with the pivot (the asker's first term)")
key.line(lp, r"T_{rot} = 1/2 I \dot{\theta}^2", "definition", None,
         "names the rotational energy about the pivot (the asker's second term); the slip is in adding the two, "
         "which leaves out m l xdot thetadot cos(theta)")
L_text = (M + m) * xd**2 / 2 + I * thd**2 / 2 - m * g * l * c
key.line(at(r"\mathcal{L} = \frac{1}{2}(M+m) \dot{x}^2"),
         r"\mathcal{L} = \frac{1}{2}(M+m) \dot{x}^2 + \frac{1}{2} I \dot{\theta}^2 - mgl\cos\theta", "claim",
         same(L_text, L),
         "the coupling term m l xdot thetadot cos(theta) is missing: the pendulum's kinetic energy is not the "
         "pivot's translation plus the rotation about the pivot; it is the centre of mass's translation plus the "
         "rotation about the centre of mass" + CONV,
         r"\mathcal{L} = \frac{1}{2}(M+m) \dot{x}^2 + ml\dot{x}\dot{\theta}\cos\theta + \frac{1}{2} I \dot{\theta}^2 - mgl\cos\theta")
key.line(at(r"$$ (M+m) \ddot{x} = F(t) $$"), r"(M+m) \ddot{x} = F(t)", "claim",
         mech.on_motion((M + m) * xdd, F),
         "follows from the wrong L; the x equation has the pendulum's terms m l thetaddot cos(theta) - m l "
         "thetadot^2 sin(theta)" + CONV,
         r"(M+m) \ddot{x} + ml\ddot{\theta}\cos\theta - ml\dot{\theta}^2\sin\theta = F(t)")
key.line(at(r"$$ I \ddot{\theta} - mgl \sin\theta = 0 $$"), r"I \ddot{\theta} - mgl \sin\theta = 0", "claim",
         mech.on_motion(I * thdd - m * g * l * s),
         "follows from the wrong L; the theta equation has the cart's acceleration term m l xddot cos(theta)" + CONV,
         r"I \ddot{\theta} + ml\ddot{x}\cos\theta - mgl \sin\theta = 0")
key.emit()
