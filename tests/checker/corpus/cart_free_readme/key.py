"""Answer key: pendulum on a freely sliding support (mcbosch/Pendulum-with-free-frictionless-support README)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


x, th = coords("x", "theta")
M1, M2, l, g, m = sp.symbols("M_1 M_2 l g m", positive=True)
xd, thd, xdd, thdd = d(x), d(th), d(x, 2), d(th, 2)
s, c = sp.sin(th), sp.cos(th)

# Own kinematics: support at (x, 0), bob at (x + l sin theta, -l cos theta).
X1, Y1 = x, sp.Integer(0)
X2, Y2 = x + l * s, -l * c
T = M1 * (sp.diff(X1, t) ** 2 + sp.diff(Y1, t) ** 2) / 2 + M2 * (sp.diff(X2, t) ** 2 + sp.diff(Y2, t) ** 2) / 2
V = M2 * g * Y2
L = T - V
mech = Mechanics(L, [x, th])
NOTE = " (cos and sin are written without a backslash throughout the README)"

key = Key("https://github.com/mcbosch/Pendulum-with-free-frictionless-support/blob/"
          "d44b974a188161367d21613d761e569f58f11528/README.md",
          "pendulum hanging from a support that slides freely (pendulum on a free cart)", "project README")

l1 = at(r"x_1 =  x & y_1 =  0")
key.line(l1, r"x_1 = x", "kinematics", same(X1, x), "the support's position")
key.line(l1, r"y_1 = 0", "kinematics", same(Y1, 0), "the support stays on the x-axis")
l2 = at(r"x_2 =  x + lsin(\theta)")
key.line(l2, r"x_2 = x + lsin(\theta)", "kinematics", same(X2, x + l * s), "the bob's position" + NOTE)
key.line(l2, r"y_2 = -lcos(\theta)", "kinematics", same(Y2, -l * c), "the bob hangs below the support")

key.line(at(r"L &= T - U = (T_1 + T_2) - (U_1 + U_2)"), r"L = T - U = (T_1 + T_2) - (U_1 + U_2)", "definition",
         None, "L as T - U, split into the two bodies' parts")
L_text = (M1 + M2) * xd**2 / 2 + M2 * l * thd * xd * c + M2 * l**2 * thd**2 / 2 + m * g * l * c
key.line(at(r"+ mglcos(\theta)"),
         r"L = \frac{1}{2}(M_1+M_2)\dot{x}^2 + M_2l\dot{\theta}\dot{x}cos(\theta) + \frac{1}{2}M_2l^2\dot{\theta}^2 + mglcos(\theta)",
         "claim", same(L_text, L),
         "m where M_2 belongs in the gravity term: the masses are M_1 and M_2, m is not defined (the README's "
         "own code uses m2 there)" + NOTE,
         r"L = \frac{1}{2}(M_1+M_2)\dot{x}^2 + M_2l\dot{\theta}\dot{x}\cos(\theta) + \frac{1}{2}M_2l^2\dot{\theta}^2 + M_2gl\cos(\theta)")

lel = at(r"The Euler-Lagrange equations $$\frac{d}{dt}")
key.line(lel, r"\frac{d}{dt}\frac{\partial L}{\partial\dot{x}} - \frac{\partial L}{\partial x} = 0", "claim",
         mech.on_motion(sp.diff(sp.diff(L, xd), t) - sp.diff(L, x)), "the Euler-Lagrange equation for x")
key.line(lel, r"\frac{d}{dt}\frac{\partial L}{\partial\dot{\theta}} - \frac{\partial L}{\partial \theta} = 0", "claim",
         mech.on_motion(sp.diff(sp.diff(L, thd), t) - sp.diff(L, th)), "the Euler-Lagrange equation for theta")

E1 = (M1 + M2) * xdd / 2 + M2 * l * thdd * c - M2 * l * thd**2 * s
key.line(at(r"(E_1):&"),
         r"(E_1): \frac{1}{2}(M_1 + M_2)\ddot{x} + M_2l\ddot{\theta}cos(\theta) - M_2l\dot{\theta}^2sin(\theta) = 0",
         "claim", mech.on_motion(E1),
         "a spurious factor 1/2 on (M_1 + M_2) xddot: d/dt of dL/dxdot = (M_1+M_2) xdot + ... has none (the "
         "README's code uses M_1 + M_2 - M_2 cos^2 as the denominator, i.e. without the 1/2)" + NOTE,
         r"(E_1): (M_1 + M_2)\ddot{x} + M_2l\ddot{\theta}\cos(\theta) - M_2l\dot{\theta}^2\sin(\theta) = 0")
E2 = l * thdd + xdd * c + g * s
key.line(at(r"(E_2): &"), r"(E_2): l\ddot{\theta} + \ddot{x}cos(\theta) + gsin(\theta) = 0", "claim",
         mech.on_motion(E2), "the theta equation divided by M_2 l" + NOTE)

ld = at(r"$v:= \dot{x}$")
key.line(ld, r"v:= \dot{x}", "definition", None, "names the velocity v")
key.line(ld, r"w:=\dot{\theta}", "definition", None, "names the angular velocity w")
li = at(r"$x = -7.5; \theta = 120º; v = 1; w = 0$")
for rel, why in ((r"x = -7.5", "initial position of the support"), (r"\theta = 120º", "initial angle (degrees)"),
                 (r"v = 1", "initial velocity of the support"), (r"w = 0", "initial angular velocity")):
    key.line(li, rel, "condition", None, why)
key.emit()
