"""Answer key of cart_pole_hoani (SymPy only): the damped pendulum on a cart of hoani.github.io's guide."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


x, th = coords("x", "theta")
Mc, Mp, Lp, g, dc, dp, F = sp.symbols("M_c M_p L g d_c d_p F", positive=True)
s, c = sp.sin(th), sp.cos(th)
xd, thd, xdd, thdd = d(x), d(th), d(x, 2), d(th, 2)

# Own kinematics: the cart at (x, 0); the pendulum (point mass M_p, rod L) at angle theta from the upward
# vertical, on the side that makes the text's kinetic energy (-M_p L xdot thetadot cos theta) and its code
# (xp = pos - sin(theta)): (x - L sin theta, L cos theta).
xp, yp = x - Lp * s, Lp * c
T = Mc * xd**2 / 2 + Mp * (sp.diff(xp, t) ** 2 + sp.diff(yp, t) ** 2) / 2
V = g * Mp * yp
L = T - V
Fx = F - dc * xd          # the text's F(t), taken constant by the model
Fth = -dp * thd
mech = Mechanics(L, [x, th], forces=[Fx, Fth])
half = sp.Rational(1, 2)

key = Key("https://github.com/hoani/hoani.github.io/blob/a120a8934eba490b297426257478ef192d580784/_posts/guides/"
          "engineering/mathematics/2020-09-12-pendulumOnCart.md",
          "inverted pendulum on a cart, with a force on the cart and damping of cart and pivot", "blog post")

key.line(at(r"$$ L = T - V $$"), r"L = T - V", "definition", None, "the Lagrangian as T - V")
key.line(at(r"- \frac{\partial L}{\partial q_i} = Q_i $$"),
         r"\frac{d}{dt}\left(\frac{\partial L}{\partial \dot{q_i}}\right) - \frac{\partial L}{\partial q_i} = Q_i",
         "definition", None, "Lagrange's equations with generalized forces Q_i, stated in general")
key.line(at(r"$$ \dot{y} = y = 0 $$"), r"\dot{y} = y = 0", "given", None,
         "the cart stays on the level track (its own y, not a coordinate)")

# The pendulum's position: the text's x_p = x + L sin(theta) is on the other side from the rest of the text.
key.line(at(r"$$ x_p = x + L \sin{\theta} $$"), r"x_p = x + L \sin{\theta}", "kinematics",
         same(x + Lp * s, xp),
         "the pendulum is at x - L sin(theta): that is what the text's kinetic energy (-M_p L xdot thetadot "
         "cos theta), its equations of motion and its code (xp = pos - sin(theta)) use; with x + L sin(theta) "
         "the cross term of T would be +M_p L xdot thetadot cos theta",
         r"x_p = x - L \sin{\theta}")
key.line(at(r"$$ \dot{x_p} = \dot{x} + L \cos{\theta} $$"), r"\dot{x_p} = \dot{x} + L \cos{\theta}", "kinematics",
         same(xd + Lp * c, sp.diff(xp, t)),
         "the factor thetadot of the chain rule is missing (and the sign follows x_p = x - L sin theta): "
         "xdot_p = xdot - L thetadot cos theta (even from the text's own x_p it would be xdot + L thetadot cos theta)",
         r"\dot{x_p} = \dot{x} - L \dot{\theta} \cos{\theta}")
key.line(at(r"$$ y_p = L \cos{\theta} $$"), r"y_p = L \cos{\theta}", "kinematics", same(Lp * c, yp),
         "the pendulum's height")
key.line(at(r"$$ \dot{y_p} = - L \sin{\theta} $$"), r"\dot{y_p} = - L \sin{\theta}", "kinematics",
         same(-Lp * s, sp.diff(yp, t)),
         "the factor thetadot of the chain rule is missing: ydot_p = -L thetadot sin theta",
         r"\dot{y_p} = - L \dot{\theta} \sin{\theta}")

# T: both links of the chain (one line) hold, the first with the pendulum's true velocity components.
T1 = Mc * xd**2 / 2 + Mp * (sp.diff(xp, t) ** 2 + sp.diff(yp, t) ** 2) / 2
T2 = xd**2 * (Mc + Mp) / 2 - Mp * Lp * xd * thd * c + Lp**2 * thd**2 * Mp / 2
assert same(T1, T) and same(T2, T)
key.line(at(r"$$ \begin{aligned} T &= \frac{1}{2} M_c"),
         r"T = \frac{1}{2} M_c \dot{x}^2 + \frac{1}{2} M_p (\dot{x_p}^2 + \dot{y_p}^2) = \frac{1}{2}\dot{x}^2(M_c + M_p) - M_p L \dot{x}\dot{\theta}\cos{\theta} + \frac{1}{2} L^2 \dot{\theta}^2 M_p",
         "claim", same(T1, T) and same(T2, T),
         "the kinetic energy of cart and pendulum (the first link with the pendulum's true velocity components, "
         "not the text's wrong ones above; the second is T of the model)")
key.line(at(r"$$ \begin{aligned} V &= g M_p y_p"), r"V = g M_p y_p = g M_p L \cos{\theta}", "claim",
         same(g * Mp * yp, V) and same(g * Mp * Lp * c, V), "the potential energy of the pendulum")

L_text = xd**2 * (Mc + Mp) / 2 - Mp * Lp * xd * thd * c + Lp**2 * thd**2 * Mp / 2 - g * Mp * Lp * c
L_line = r"L = \frac{1}{2}\dot{x}^2(M_c + M_p) - M_p L \dot{x}\dot{\theta}\cos{\theta} + \frac{1}{2} L^2 \dot{\theta}^2 M_p - g M_p L \cos{\theta}"
key.line(at(r"$$ L = \frac{1}{2}\dot{x}^2(M_c + M_p)", 1), L_line, "claim", same(L_text, L),
         "L = T - V (the text's L is both the Lagrangian and the pendulum's length)")

key.line(at(r"$$ F_x = F(t) - d_c \dot{x} $$"), r"F_x = F(t) - d_c \dot{x}", "definition", None,
         "the generalized force on x: the push F(t) and the cart's damping")
key.line(at(r"$$ F_{\theta} = - d_p \dot{\theta} $$"), r"F_{\theta} = - d_p \dot{\theta}", "definition", None,
         "the generalized force on theta: the pivot's damping")
key.line(at(r"- \frac{\partial L}{\partial q_i} = Q_i $$", 2),
         r"\frac{d}{dt}\left(\frac{\partial L}{\partial \dot{q_i}}\right) - \frac{\partial L}{\partial q_i} = Q_i",
         "definition", None, "Lagrange's equations with generalized forces, stated again in general")
key.line(at(r"$$ (q_1, q_2) = (x, \theta) $$"), r"(q_1, q_2) = (x, \theta)", "definition", None,
         "names the coordinates")
key.line(at(r"$$ (Q_1, Q_2) = (F_x, F_{\theta}) $$"), r"(Q_1, Q_2) = (F_x, F_{\theta})", "definition", None,
         "names the generalized forces")

key.line(at(r"$$ L = \frac{1}{2}\dot{x}^2(M_c + M_p)", 2), L_line, "claim", same(L_text, L),
         "the Lagrangian repeated")
dLdxd = sp.diff(L, xd)
el_x = sp.diff(dLdxd, t) - sp.diff(L, x)
key.line(at(r"- \frac{\partial L}{\partial x} = F_x $$"),
         r"\frac{d}{dt}\left(\frac{\partial L}{\partial \dot{x}}\right) - \frac{\partial L}{\partial x} = F_x",
         "claim", mech.on_motion(el_x, Fx), "Lagrange's equation for x with its generalized force")
key.line(at(r"\frac{\partial L}{\partial \dot{x}} &= (M_c + M_p)\dot{x}"),
         r"\frac{\partial L}{\partial \dot{x}} = (M_c + M_p)\dot{x} - M_p L \dot{\theta} \cos{\theta}", "claim",
         same((Mc + Mp) * xd - Mp * Lp * thd * c, dLdxd), "the x momentum")
key.line(at(r"\frac{d}{dt}\left(\frac{\partial L}{\partial \dot{x}}\right) &="),
         r"\frac{d}{dt}\left(\frac{\partial L}{\partial \dot{x}}\right) = (M_c + M_p)\ddot{x} - M_p L \ddot{\theta} \cos{\theta} + M_p L \dot{\theta}^2 \sin{\theta}",
         "claim", same((Mc + Mp) * xdd - Mp * Lp * thdd * c + Mp * Lp * thd**2 * s, sp.diff(dLdxd, t)),
         "its time derivative")
key.line(at(r"\frac{\partial L}{\partial x} &= 0"), r"\frac{\partial L}{\partial x} = 0", "claim",
         same(0, sp.diff(L, x)), "x is cyclic")
eom_x_lhs = (Mc + Mp) * xdd - Mp * Lp * thdd * c + Mp * Lp * thd**2 * s
eom_x = r"(M_c + M_p)\ddot{x} - M_p L \ddot{\theta} \cos{\theta} + M_p L \dot{\theta}^2 \sin{\theta} = F(t) - d_c \dot{x}"
key.line(at(r"$$ (M_c + M_p)\ddot{x} - M_p L \ddot{\theta}", 1), eom_x, "claim", mech.on_motion(eom_x_lhs, Fx),
         "the x equation of motion (F(t) the push on the cart)")

key.line(at(r"$$ L = \frac{1}{2}\dot{x}^2(M_c + M_p)", 3), L_line, "claim", same(L_text, L),
         "the Lagrangian repeated")
dLdthd = sp.diff(L, thd)
el_th = sp.diff(dLdthd, t) - sp.diff(L, th)
key.line(at(r"- \frac{\partial L}{\partial \theta} = F_{\theta} $$"),
         r"\frac{d}{dt}\left(\frac{\partial L}{\partial \dot{\theta}}\right) - \frac{\partial L}{\partial \theta} = F_{\theta}",
         "claim", mech.on_motion(el_th, Fth), "Lagrange's equation for theta with its generalized force")
key.line(at(r"\frac{\partial L}{\partial \dot{\theta}} &= -M_p L"),
         r"\frac{\partial L}{\partial \dot{\theta}} = -M_p L \dot{x} \cos{\theta} + L^2 \dot{\theta} M_p", "claim",
         same(-Mp * Lp * xd * c + Lp**2 * thd * Mp, dLdthd), "the theta momentum")
key.line(at(r"\frac{d}{dt}\left(\frac{\partial L}{\partial \dot{\theta}}\right) &="),
         r"\frac{d}{dt}\left(\frac{\partial L}{\partial \dot{\theta}}\right) = -M_p L (\ddot{x} \cos{\theta} - \dot{x}\dot{\theta}\sin{\theta}) + L^2 \ddot{\theta} M_p",
         "claim", same(-Mp * Lp * (xdd * c - xd * thd * s) + Lp**2 * thdd * Mp, sp.diff(dLdthd, t)),
         "its time derivative")
key.line(at(r"\frac{\partial L}{\partial \theta} &= \dot{x}"),
         r"\frac{\partial L}{\partial \theta} = \dot{x} \dot{\theta} M_p L \sin{\theta} + g M_p L \sin{\theta}", "claim",
         same(xd * thd * Mp * Lp * s + g * Mp * Lp * s, sp.diff(L, th)), "dL/dtheta")
eom_th = r"L \ddot{\theta} - \ddot{x}\cos{\theta} - g\sin{\theta} = -\dot{\theta}\frac{d_p}{M_p L}"
eom_th_ok = mech.on_motion(Lp * thdd - xdd * c - g * s, -thd * dp / (Mp * Lp))
key.line(at(r"$$ L \ddot{\theta} - \ddot{x}\cos{\theta}", 1), eom_th, "claim", eom_th_ok,
         "the theta equation of motion divided by M_p L")

key.line(at(r"$$ (M_c + M_p)\ddot{x} - M_p L \ddot{\theta}", 2), eom_x, "claim", mech.on_motion(eom_x_lhs, Fx),
         "the x equation repeated")
key.line(at(r"$$ L \ddot{\theta} - \ddot{x}\cos{\theta}", 2), eom_th, "claim", eom_th_ok,
         "the theta equation repeated")
D = Mc + Mp - Mp * c**2
xdd_text = (F - xd * dc - thd**2 * Mp * Lp * s - thd * dp / Lp * c + g * Mp * c * s) / D
thdd_text = ((F - xd * dc - thd**2 * Mp * Lp * s) * c - thd * dp * (Mc + Mp) / (Mp * Lp) + g * (Mc + Mp) * s) / (Lp * D)
key.line(at(r"\ddot{x} &= \frac{F(t)"),
         r"\ddot{x} = \frac{F(t) - \dot{x} d_c - \dot{\theta}^2 M_p L \sin{\theta} - \dot{\theta}\frac{d_p}{L}\cos{\theta} + g M_p \cos{\theta}\sin{\theta}}{M_c + M_p - M_p\cos^2{\theta}}",
         "claim", mech.on_motion(xdd, xdd_text), "the two equations solved for xddot")
key.line(at(r"\ddot{\theta} &= \frac{1}{L}"),
         r"\ddot{\theta} = \frac{1}{L}\frac{(F(t) - \dot{x} d_c - \dot{\theta}^2 M_p L \sin{\theta})\cos{\theta} - \dot{\theta} d_p \frac{M_c + M_p}{M_p L} + g (M_c + M_p) \sin{\theta}}{M_c + M_p - M_p\cos^2{\theta}}",
         "claim", mech.on_motion(thdd, thdd_text), "the two equations solved for thetaddot")
key.emit()
