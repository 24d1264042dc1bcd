"""Answer key: cart on a spring with a pendulum (NextZtepS/SpringedCart_and_Pendulum report.tex)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


x, th = coords("x", "theta")
M, m, k, dd, l, g = sp.symbols("M m k d l g", positive=True)
Ts, Ls = sp.symbols("T_s L_s", positive=True)      # the text's time scale T and length scale L
xd, thd, xdd, thdd = d(x), d(th), d(x, 2), d(th, 2)
s, c = sp.sin(th), sp.cos(th)

# Own kinematics: cart at (x, 0), bob at (x + l sin theta, -l cos theta); spring energy k (x - d)^2 / 2.
rM = sp.Matrix([x, 0])
rm = sp.Matrix([x + l * s, -l * c])
T = M * rM.diff(t).dot(rM.diff(t)) / 2 + m * rm.diff(t).dot(rm.diff(t)) / 2
V = k * (x - dd) ** 2 / 2 + m * g * rm[1]
L = T - V
mech = Mechanics(L, [x, th])

key = Key("https://github.com/NextZtepS/SpringedCart_and_Pendulum/blob/a712672c990714ee56f85e55943bf3f2bc574299/report.tex",
          "pendulum on a cart tied to a wall by a spring", "student project report (LaTeX)")

key.line(at(r"\Vec{r_M} &= x \hat{x}"), r"\Vec{r_M} = x \hat{x}", "kinematics",
         same(rM[0], x) and same(rM[1], 0), "the cart moves along x")
key.line(at(r"\Vec{r_m} &= (x + l\sin{\theta}) \hat{x}"),
         r"\Vec{r_m} = (x + l\sin{\theta}) \hat{x} + (-l\cos{\theta}) \hat{y}", "kinematics",
         same(rm[0], x + l * s) and same(rm[1], -l * c), "the bob hangs l below the cart at angle theta")

lU = at(r"U &= U_{spring} + U_{gravity}")
key.line(lU, r"U = U_{spring} + U_{gravity}", "definition", None, "names the two parts of the potential energy")
key.line(lU, r"U = \frac{1}{2}k(x-d)^2 + (-mgl\cos{\theta})", "claim",
         same(k * (x - dd) ** 2 / 2 - m * g * l * c, V), "spring plus gravity")
lT = at(r"T &= T_{cart} + T_{pendulum}")
key.line(lT, r"T = T_{cart} + T_{pendulum}", "definition", None, "names the two parts of the kinetic energy")
T_b = ((M + m) * xd**2 + m * (l**2 * thd**2 + 2 * l * xd * thd * c)) / 2
key.line(lT, r"T = \frac{1}{2}M(\dot{\Vec{r_M}})^2 + \frac{1}{2}m(\dot{\Vec{r_m}})^2 = \frac{1}{2} \big[ (M+m)\dot{x}^2 + m(l^2\dot{\theta}^2 + 2l\dot{x}\dot{\theta}\cos{\theta}) \big]",
         "claim", same(T_b, T), "the kinetic energy of cart and bob")
lL = at(r"L &= T - U =")
key.line(lL, r"L = T - U", "definition", None, "the Lagrangian")
L_b = ((M + m) * xd**2 + m * l**2 * thd**2 + 2 * m * l * c * xd * thd) / 2 - (k * (x - dd) ** 2 - 2 * m * g * l * c) / 2
key.line(lL, r"L = \frac{1}{2} \big[ (M+m)\dot{x}^2 + ml^2\dot{\theta}^2 + 2ml\cos{\theta}\dot{x}\dot{\theta}\big] - \frac{1}{2} \big[ k(x-d)^2 - 2mgl\cos{\theta} \big]",
         "claim", same(L_b, L), "T - U written out")

key.line(at(r"follow from $\frac{d}{dt} (\frac{\partial L}{\partial \dot{p}})"),
         r"\frac{d}{dt} (\frac{\partial L}{\partial \dot{p}}) = \frac{\partial L}{\partial p}", "definition", None,
         "the Euler-Lagrange equation stated for a generic coordinate p")
key.line(at(r"\frac{d}{dt} (\frac{\partial L}{\partial \dot{x}}) &="),
         r"\frac{d}{dt} (\frac{\partial L}{\partial \dot{x}}) = \frac{\partial L}{\partial x}", "claim",
         mech.on_motion(sp.diff(sp.diff(L, xd), t), sp.diff(L, x)), "the Euler-Lagrange equation for x")
key.line(at(r"(M+m)\Ddot{x} + ml\cos{\theta}\Ddot{\theta}"),
         r"(M+m)\Ddot{x} + ml\cos{\theta}\Ddot{\theta} - ml\sin{\theta}\dot{\theta}^2 = -k(x-d)", "claim",
         mech.on_motion((M + m) * xdd + m * l * c * thdd - m * l * s * thd**2, -k * (x - dd)),
         "the x equation (\\Ddot is amsmath's double-dot accent)")
key.line(at(r"\frac{d}{dt} (\frac{\partial L}{\partial \dot{\theta}}) &="),
         r"\frac{d}{dt} (\frac{\partial L}{\partial \dot{\theta}}) = \frac{\partial L}{\partial \theta}", "claim",
         mech.on_motion(sp.diff(sp.diff(L, thd), t), sp.diff(L, th)), "the Euler-Lagrange equation for theta")
key.line(at(r"ml^2\Ddot{\theta}^2 + ml\cos{\theta}"),
         r"ml^2\Ddot{\theta}^2 + ml\cos{\theta} = -mgl\sin{\theta}", "claim",
         mech.on_motion(m * l**2 * thdd**2 + m * l * c, -m * g * l * s),
         "the theta equation is m l^2 thetaddot + m l cos(theta) xddot = -m g l sin(theta): thetaddot is squared "
         "and the factor xddot is missing (the dimensionless form below is derived from the correct one)",
         r"ml^2\Ddot{\theta} + ml\cos{\theta}\Ddot{x} = -mgl\sin{\theta}")

key.line(at(r"\tau &= \frac{t}{T}"), r"\tau = \frac{t}{T}", "definition", None, "dimensionless time, T a time scale")
key.line(at(r"X &= \frac{x-d}{L}"), r"X = \frac{x-d}{L}", "definition", None,
         "dimensionless displacement, L a length scale")
f = sp.Function("f")
ld = at(r"Then $\frac{d}{dt} = \frac{1}{T} \frac{d}{d\tau}$")
tau = sp.Symbol("tau")
F = f(t / Ts)
fp = sp.diff(f(tau), tau).subs(tau, t / Ts)
fpp = sp.diff(f(tau), tau, 2).subs(tau, t / Ts)
key.line(ld, r"\frac{d}{dt} = \frac{1}{T} \frac{d}{d\tau}", "claim", same(sp.diff(F, t), fp / Ts),
         "chain rule with tau = t/T")
key.line(ld, r"\frac{d^2}{dt^2} = \frac{1}{T^2} \frac{d^2}{d\tau^2}", "claim", same(sp.diff(F, t, 2), fpp / Ts**2),
         "chain rule twice")

# x = d + L X(tau), theta = Theta(tau): the tau-derivatives in terms of the t-derivatives.
Xv, Xpp = (x - dd) / Ls, Ts**2 * xdd / Ls
thp, thpp = Ts * thd, Ts**2 * thdd
nond_X = Xpp - (-m * l * c * thpp + m * l * s * thp**2 - k * Ls * Ts**2 * Xv) / ((M + m) * Ls)
key.line(at(r"\frac{d^2X}{d\tau^2} &= \frac{1}{(M+m)L}"),
         r"\frac{d^2X}{d\tau^2} = \frac{1}{(M+m)L} \big[ -ml\cos{\theta} \frac{d^2\theta}{d\tau^2} + ml\sin{\theta}(\frac{d\theta}{d\tau})^2 - kLT^2X \big]",
         "claim", mech.on_motion(nond_X), "the x equation in tau and X (multiplied by T^2/L)")
nond_th = thpp - (-Ls * c * Xpp - g * Ts**2 * s) / l
key.line(at(r"\frac{d^2\theta}{d\tau^2} &= \frac{1}{l}"),
         r"\frac{d^2\theta}{d\tau^2} = \frac{1}{l} \big[ -L\cos{\theta}\frac{d^2X}{d\tau^2} - gT^2\sin{\theta} \big]",
         "claim", mech.on_motion(nond_th),
         "the correct theta equation in tau and X (it does not follow from the wrong line above)")

key.line(at(r"r_{mass} &= \frac{M}{m}"), r"r_{mass} = \frac{M}{m}", "definition", None, "mass ratio")
key.line(at(r"f_{msp} &="), r"f_{msp} = \frac{1}{2\pi}\sqrt{\frac{k}{M+m}}", "definition", None,
         "the name for the mass-spring frequency (of cart and bob together on the spring)")
key.line(at(r"f_{pen} &="), r"f_{pen} = \frac{1}{2\pi}\sqrt{\frac{g}{l}}", "definition", None,
         "the name for the pendulum's frequency")
lp = at(r"$l = 1$ m, the unit of time $T = 1$")
key.line(lp, r"l = 1", "given", None, "pendulum length 1 m in the runs")
key.line(lp, r"T = 1", "given", None, "the time scale T of the dimensionless variables (not the kinetic energy)")
key.line(lp, r"L = 1", "given", None, "the length scale L of the dimensionless variables (not the Lagrangian)")
key.emit()
