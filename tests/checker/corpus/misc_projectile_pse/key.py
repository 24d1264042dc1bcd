"""Answer key of misc_projectile_pse (SymPy only): a particle moving in a vertical plane under uniform gravity,
Lagrange's equations in Cartesian coordinates, as asked on Physics Stack Exchange (question 19963)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


x, y = coords("x", "y")
m, g = sp.symbols("m g", positive=True)
xd, yd, xdd, ydd = d(x), d(y), d(x, 2), d(y, 2)

# Own kinematics: the particle at (x, y), y upward (the text's potential is m g y); its speed squared is
# xdot^2 + ydot^2, the only force is gravity, -m g along y.
T = m * (xd**2 + yd**2) / 2
V = m * g * y
L = T - V
mech = Mechanics(L, [x, y])
assert same(mech.accelerations[xdd], 0) and same(mech.accelerations[ydd], -g)

# The text's quantities.
L_text = m * (xd + yd) ** 2 / 2 - m * g * y
ax, ay = xdd, ydd                      # the text's a_x = xddot, a_y = yddot (line 25)

key = Key("https://physics.stackexchange.com/questions/19963/how-can-we-represent-the-motion-of-a-particle-in-2d-space-using-lagranges-equat",
          "particle moving in a vertical plane under uniform gravity (Cartesian coordinates)", "Q&A thread")

# v = xdot + ydot: the speed is sqrt(xdot^2 + ydot^2); the text's v is the same as the true speed only where one
# of the rates vanishes. Compared as squares (v >= 0 is not at issue: (xdot + ydot)^2 != xdot^2 + ydot^2).
key.line(at(r"$v=\dot{x}+\dot{y}$"), r"v=\dot{x}+\dot{y}", "kinematics",
         same((xd + yd) ** 2, xd**2 + yd**2),
         "the speed is not the sum of the velocity's components: v^2 = xdot^2 + ydot^2 (the cross term 2 xdot ydot "
         "is extra); the slip the question asks about",
         r"v^2=\dot{x}^2+\dot{y}^2")
key.line(at(r"$L=\frac{1}{2}m(\dot{x}+\dot{y})^2-mgy$"), r"L=\frac{1}{2}m(\dot{x}+\dot{y})^2-mgy", "claim",
         same(L_text, L),
         "built on v = xdot + ydot: the kinetic energy has an extra m xdot ydot; L = m(xdot^2 + ydot^2)/2 - m g y",
         r"L=\frac{1}{2}m(\dot{x}^2+\dot{y}^2)-mgy")
key.line(at(r"$\frac{{\partial}{L}}{\partial{y}}=-mg$"), r"\frac{{\partial}{L}}{\partial{y}}=-mg", "claim",
         same(sp.diff(L, y), -m * g),
         "∂L/∂y = -m g: the wrong kinetic energy does not depend on y, so this derivative is right")
key.line(at(r"$\frac{{\partial}{L}}{\partial{\dot{y}}}=m(\dot{x}+\dot{y})$"),
         r"\frac{{\partial}{L}}{\partial{\dot{y}}}=m(\dot{x}+\dot{y})", "claim",
         same(sp.diff(L, yd), m * (xd + yd)),
         "∂L/∂ẏ of the true L is m ydot; m(xdot + ydot) is that of the text's wrong L (right from it)",
         r"\frac{{\partial}{L}}{\partial{\dot{y}}}=m\dot{y}")
# Line 23: d t/d t ( ... ) is read as the d/dt of the Euler-Lagrange equation, as meant (literally dt/dt = 1);
# its middle member dL/dydot is a slip for its time derivative. Both links are false: one entry.
dt_dLdyd = sp.diff(sp.diff(L, yd), t)
assert not same(dt_dLdyd, sp.diff(L, yd))
key.line(at(r"=\frac{{\partial}{L}}{\partial{\dot{y}}}=m(\ddot{x}+\ddot{y})$"),
         r"\frac {\mathrm d t}{\mathrm d t}(\frac{{\partial}{L}}{\partial{\dot{y}}})=\frac{{\partial}{L}}{\partial{\dot{y}}}=m(\ddot{x}+\ddot{y})",
         "claim", same(dt_dLdyd, m * (xdd + ydd)),
         "d/dt ∂L/∂ẏ (typeset d t/d t) of the true L is m yddot, not m(xddot + yddot), which is that of the text's "
         "wrong L; and the middle member ∂L/∂ẏ is not its own time derivative (a slip for d/dt ∂L/∂ẏ)",
         r"\frac{d}{dt}(\frac{{\partial}{L}}{\partial{\dot{y}}})=m\ddot{y}")
lv = at(r"$\ddot{x}=a_x$")
key.line(lv, r"\ddot{x}=a_x", "definition", None, "names the x component of the acceleration a_x")
key.line(lv, r"\ddot{y}=a_y", "definition", None, "names the y component of the acceleration a_y")
key.line(at(r"=m(a_x+a_y)$ ---(2)"), r"\frac {\mathrm d t}{\mathrm d t}(\frac{{\partial}{L}}{\partial{\dot{y}}})=m(a_x+a_y)",
         "claim", same(dt_dLdyd, m * (ax + ay)),
         "line 23 in the names a_x, a_y: d/dt ∂L/∂ẏ = m a_y for the true L; the extra m a_x comes from the wrong L",
         r"\frac{d}{dt}(\frac{{\partial}{L}}{\partial{\dot{y}}})=m a_y")
# -mg = m(a_x + a_y): obtained from the wrong L as the y equation, but it holds on every motion of the particle
# (a_x = 0, a_y = -g): it is the sum of the two true equations m xddot = 0 and m yddot = -m g.
key.line(at(r"=> $-mg=m(a_x+a_y)$"), r"-mg=m(a_x+a_y)", "claim", mech.on_motion(-m * g, m * (ax + ay)),
         "holds on every motion (a_x = 0, a_y = -g): it is the sum of the true equations m xddot = 0 and "
         "m yddot = -m g, though the text reaches it from the wrong L as the y equation alone, and it does not "
         "determine the motion")
key.line(at(r"$-g=a_x+a_y$"), r"-g=a_x+a_y", "claim", mech.on_motion(-g, ax + ay),
         "the same divided by m: true on every motion, not the y equation")
key.line(at(r"$a_y=-g$"), r"a_y=-g", "claim", mech.on_motion(ay, -g),
         "the y equation of the correct L (the asker's update): yddot = -g")
key.emit()
