"""Answer key: half hoop rolling on a floor, WSU Physics 521 notes "Phantom Torque". SymPy only."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, R, g, a = sp.symbols("m R g a", positive=True)
theta = coords("theta")
th, th0, phi = sp.symbols("th theta_0 phi", real=True)

# Own geometry: the half hoop is the arc of radius R about O, phi in (-pi/2, pi/2) from the downward vertical at
# theta = 0. Its centre of mass and moments:
a_val = sp.integrate(R * sp.cos(phi), (phi, -sp.pi / 2, sp.pi / 2)) / sp.pi      # mean distance of the arc below O
I_O = m * R**2                                                                    # every element is R from O
I_C = I_O - m * a**2                                                              # parallel axis
# Rolling: O moves by -R theta along the floor (O at height R); C is a from O, turned by theta.
x_C = a * sp.sin(th) - th * R
y_C = -a * sp.cos(th)                     # from the height of O
P = sp.Matrix([-R * th, -R])              # contact point, on the floor (R below O)
I_P = sp.simplify(I_C + m * ((x_C - P[0])**2 + (y_C - P[1])**2))
I_P0 = I_C + m * ((x_C + R * th0)**2 + (y_C + R)**2)                              # about the fixed floor point P_0

# The motion: T = 1/2 m v_C^2 + 1/2 I_C theta'^2, V = m g y_C (from the height of O).
def on(expr):
    return sp.sympify(expr).subs(th, theta)
T = sp.Rational(1, 2) * m * (sp.diff(on(x_C), t)**2 + sp.diff(on(y_C), t)**2) + sp.Rational(1, 2) * I_C * d(theta)**2
V = m * g * on(y_C)
mech = Mechanics(T - V, [theta])                           # general a
mech_hoop = Mechanics((T - V).subs(a, a_val), [theta])     # a = 2R/pi
assert same(T, sp.Rational(1, 2) * on(I_P) * d(theta)**2)

key = Key("https://github.com/WSU-Physics-Courses/physics-521-classical-mechanics/blob/68f7292de0318c8692da69f60913eda01884c197/Docs/ClassNotes/RigidBodies.md",
          "half hoop rolling without slipping on a floor (phantom torque)", "course notes (MyST, Jupyter book)")

key.line(8, r"\left. \diff{\vect{L}}{t}\right|_{\text{inertial}} = \vect{\Gamma}^{(e)} \tag{27.1}", "given", None,
         "the textbook's law (27.1), about a fixed origin or the centre of mass, quoted")
key.line(14, r"I_p'(\theta) \neq 0", "claim", not same(sp.diff(I_P, th), 0),
         "I_P(theta) = 2mR(R - a cos theta) depends on theta for the half hoop")
key.line(15, r"I_{p}(\theta) = I_{p}", "given", None, "said of a coin or a ball, not of this body")
key.line(21, r"a=2R/m", "claim", same(a_val, 2 * R / m),
         "the centre of mass of a half hoop is 2R/pi from the centre (a typo: m for pi; the solution says 2R/pi)",
         correct=r"a=2R/\pi")
key.line(21, r"g>0", "given", None, "sign convention for g")
key.line(27, r"\theta = 0", "definition", None, "fixes the zero of theta (O, C, P on one vertical)")
assert same(sp.diff(-m * g * a * sp.cos(th), th).subs(th, 0), 0)

key.line(30, r"a = 2R/\pi", "claim", same(a_val, 2 * R / sp.pi), "centroid of a semicircular arc")
key.line(32, r"I_{O} = mR^2 = I_{C} + ma^2", "claim", same(I_O, m * R**2) and same(m * R**2, I_C + m * a**2),
         "all the mass is R from O; parallel axis theorem (defines I_C)")
key.line(32, r"I_{P}(\theta) = I_{C} + m(R^2 + a^2 - 2aR\cos\theta)", "claim",
         same(I_P, I_C + m * (R**2 + a**2 - 2 * a * R * sp.cos(th))), "parallel axis with |CP|^2 = R^2 + a^2 - 2aR cos(theta)")
key.line(33, r"= 2mR(R-a\cos\theta)", "claim", same(I_C + m * (R**2 + a**2 - 2 * a * R * sp.cos(th)), 2 * m * R * (R - a * sp.cos(th))),
         "with I_C = mR^2 - ma^2")

key.line(37, r"L(\theta, \dot{\theta}) = mR(R-a\cos\theta)\dot{\theta}^2 + mga\cos\theta", "claim",
         same(m * R * (R - a * sp.cos(theta)) * d(theta)**2 + m * g * a * sp.cos(theta), mech.L),
         "T = I_P theta'^2/2, V = -m g a cos(theta) from the height of O")
key.line(38, r"\diff{}{t}\pdiff{L}{\dot{\theta}} = \pdiff{L}{\theta}", "claim",
         mech.on_motion(sp.diff(sp.diff(mech.L, d(theta)), t), sp.diff(mech.L, theta)), "Euler-Lagrange equation")
key.line(39, r"2mR(R-a\cos\theta)\ddot{\theta} = -mRa\sin\theta\dot{\theta}^2 - mga\sin\theta", "claim",
         mech.on_motion(2 * m * R * (R - a * sp.cos(theta)) * d(theta, 2),
                        -m * R * a * sp.sin(theta) * d(theta)**2 - m * g * a * sp.sin(theta)), "the equation of motion")
key.line(40, r"\left(1 - \frac{2}{\pi}\cos\theta\right)\ddot{\theta} = -\frac{\sin\theta}{\pi} \dot{\theta}^2 - \frac{\sin\theta}{\pi}\frac{g}{R}",
         "claim", mech_hoop.on_motion((1 - 2 / sp.pi * sp.cos(theta)) * d(theta, 2),
                                      -sp.sin(theta) / sp.pi * d(theta)**2 - sp.sin(theta) / sp.pi * g / R),
         "the same divided by 2mR^2, with a = 2R/pi")

# The general form about P, with I_p(theta) = I_P and V(theta) = -m g a cos(theta).
Ip, Vf = on(I_P), -m * g * a * sp.cos(theta)
Ipp = on(sp.diff(I_P, th))
Vp = on(sp.diff(-m * g * a * sp.cos(th), th))
key.line(50, r"L(\theta, \dot{\theta}) = \frac{1}{2}I_{p}(\theta)\dot{\theta}^2 - V(\theta)", "claim",
         same(sp.Rational(1, 2) * Ip * d(theta)**2 - Vf, mech.L), "rotation about the instantaneously fixed P")
key.line(51, r"p_\theta = L", "definition", None,
         "names the angular momentum about P L (the same letter as the Lagrangian): p_theta is that angular momentum")
key.line(51, r"L = \pdiff{L}{\dot{\theta}} = I_{p}(\theta)\dot{\theta}", "claim",
         same(mech.momentum(theta), Ip * d(theta)), "the momentum conjugate to theta is I_P theta' (the first L is the angular momentum)")
key.line(52, r"\dot{L} = \pdiff{L}{\theta}", "claim", mech.on_motion(sp.diff(mech.momentum(theta), t), sp.diff(mech.L, theta)),
         "Euler-Lagrange equation, dot L = d p_theta/dt")
key.line(55, r"\dot{L} = \partial L/\partial \theta", "claim", mech.on_motion(sp.diff(mech.momentum(theta), t), sp.diff(mech.L, theta)),
         "the same equation")
key.line(59, r"I_{p}'(\theta)\dot{\theta}^2 + I_{p}(\theta)\ddot{\theta} = \frac{1}{2}I'_{p}(\theta)\dot{\theta}^2 - V'(\theta)", "claim",
         mech.on_motion(Ipp * d(theta)**2 + Ip * d(theta, 2), Ipp / 2 * d(theta)**2 - Vp), "d/dt(I_P theta') = dL/dtheta written out")
key.line(61, r"I_{p}(\theta)\ddot{\theta} = - V'(\theta) + \frac{-I'_{p}(\theta)}{2}\dot{\theta}^2", "claim",
         mech.on_motion(Ip * d(theta, 2), -Vp - Ipp / 2 * d(theta)**2), "the same, rearranged")
key.line(66, r"F = ma", "given", None, "Newton's second law named (a here an acceleration)")
key.line(66, r"\Gamma = I \dot{\omega}", "claim", mech.on_motion(Ip * d(theta, 2), -Vp),
         "the naive form about P that the text says fails: with Gamma = -V' (gravity's torque about P) it misses the phantom torque -I_P' theta'^2/2",
         correct=r"\Gamma = I \dot{\omega} + \frac{1}{2}I'_{p}(\theta)\dot{\theta}^{2}")
# Gravity's torque about P is -V'(theta):
tau_P = ((on(x_C) - on(P[0])) * (-m * g) - (on(y_C) - on(P[1])) * 0)
assert same(tau_P, -Vp)
key.line(71, r"\diff{\vect{L}}{t} = \mat{I}\cdot \ddot{\vect{\theta}} + \dot{\mat{I}}\cdot \dot{\vect{\theta}}", "claim",
         same(sp.diff(Ip * d(theta), t), Ip * d(theta, 2) + sp.diff(Ip, t) * d(theta)),
         "product rule for L = I_P theta' (the misleading step the text shows)")
key.line(72, r"\mat{I}\cdot \ddot{\vect{\theta}} + \dot{\mat{I}}\cdot \dot{\vect{\theta}} = \vect{\Gamma}^{(e)}", "claim",
         mech.on_motion(Ip * d(theta, 2) + Ipp * d(theta)**2, -Vp),
         "the text's point: this finds a but not b; the motion has I_P theta'' + I_P' theta'^2/2 = Gamma",
         correct=r"\mat{I}\cdot \ddot{\vect{\theta}} + \frac{1}{2}\dot{\mat{I}}\cdot \dot{\vect{\theta}} = \vect{\Gamma}^{(e)}")

key.line(76, r"P_0=P", "definition", None, "names the fixed floor point that coincides with P at the instant considered")
key.line(79, r"\theta_0 = \theta", "condition", None, "the instant considered")
# The naive rate: the moment about the fixed point P_0 changes at dI_P0/dtheta theta' (theta_0 held), which is 0 at theta_0 = theta.
Idot_true = sp.simplify(sp.diff(I_P0, th).subs(th0, th))
key.line(80, r"\dot{I} = I_{P}'(\theta)\dot{\theta}", "claim", same(Idot_true, sp.diff(I_P, th)),
         "the naive rate the text calls the slip: about the fixed P_0 the moment changes at dI_P0/dtheta theta' = 0 here, not I_P' theta'")
rot = sp.Matrix([[sp.cos(th), -sp.sin(th)], [sp.sin(th), sp.cos(th)]])          # counterclockwise by theta
C_geo = sp.Matrix([-R * th, 0]) + rot * sp.Matrix([0, -a])                      # O rolled to -R theta, C = O + rotated (0, -a)
key.line(84, r"x_{C} = a\sin\theta - \theta R", "kinematics", same(C_geo[0], a * sp.sin(th) - th * R), "O rolls to -R theta, C is a from O turned by theta")
key.line(85, r"y_{C} = -a\cos\theta", "kinematics", same(C_geo[1], -a * sp.cos(th)), "measured from the height of O (R above the floor)")
# (own check of rolling: the material point at P is at rest)
vP = sp.Matrix([sp.diff(on(-R * th), t), 0]) + d(theta) * sp.Matrix([R, 0])     # v_O + omega x (P - O), P - O = (0, -R)
assert same(vP[0], 0)

text98 = I_C + m * (x_C + th0 * R)**2 + m * y_C**2
key.line(98, r"I_{P_0}(\theta, \theta_0) = I_{C} + m\Bigl(x_{C}(\theta) + \theta_0 R\Bigr)^2 + my_{C}^2(\theta)", "claim",
         same(I_P0, text98),
         "y_C is measured from O, but P_0 is on the floor, R below O: the vertical distance is y_C + R",
         correct=r"I_{P_0}(\theta, \theta_0) = I_{C} + m\Bigl(x_{C}(\theta) + \theta_0 R\Bigr)^2 + m\bigl(y_{C}(\theta) + R\bigr)^2")
text99 = I_P - 2 * m * R * x_C * (th - th0) - m * R**2 * (th**2 - th0**2)
assert same(text99, I_P0)     # the right side of line 99 is the correct I_P0 ...
key.line(99, r"= I_{P}(\theta) - 2mRx_{C}(\theta)(\theta - \theta_0) - mR^2(\theta^2 - \theta_0^2)", "claim",
         same(text98, text99),
         "this side is the correct I_P0 (with the true I_P), so it differs from the previous side: the slip is on line 98")
key.line(102, r"I_{P}(\theta_0) = I_{P_0}(\theta_0)", "claim", same(I_P.subs(th, th0), I_P0.subs(th, th0)),
         "at theta = theta_0 the fixed point is the contact point")
key.line(105, r"\dot{I} = \left.\diff{I_{P_0}}{t}\right|_{\text{inertial}}", "definition", None, "the rate of the moment about the fixed point")
key.line(105, r"\left.\diff{I_{P_0}}{t}\right|_{\text{inertial}} = \pdiff{I_{P_0}(\theta, \theta_0)}{\theta}\dot{\theta}", "claim",
         same(sp.diff(on(I_P0), t), on(sp.diff(I_P0, th)) * d(theta)), "theta_0 is fixed, so I_P0 changes only through theta (chain rule)")
text107 = (2 * m * (x_C + th0 * R) * sp.diff(x_C, th) + 2 * m * y_C * sp.diff(y_C, th)).subs(th, th0)
true107 = sp.diff(I_P0, th).subs(th, th0)
key.line(107, r"\left.\pdiff{I_{P_0}(\theta, \theta_0)}{\theta} \right|_{\theta=\theta_0}= 2m\bigl(x_{C}(\theta_0) + \theta_0R\bigr)x_{C}'(\theta_0) + 2my_{C}(\theta_0)y_{C}'(\theta_0)",
         "claim", same(true107, text107), "carries the slip of line 98: the y term is 2m(y_C + R) y_C'",
         correct=r"\left.\pdiff{I_{P_0}(\theta, \theta_0)}{\theta} \right|_{\theta=\theta_0}= 2m\bigl(x_{C}(\theta_0) + \theta_0R\bigr)x_{C}'(\theta_0) + 2m\bigl(y_{C}(\theta_0) + R\bigr)y_{C}'(\theta_0)")
text110 = (sp.diff(I_P, th) - 2 * m * R * (x_C + th * R)).subs(th, th0)
assert same(text110, true107)     # ... this side is the true derivative (= 0)
key.line(110, r"= I_{P}'(\theta_0) - 2mR\bigl(x_{C}(\theta_0) + \theta_0R\bigr)", "claim", same(text107, text110),
         "this side is the correct derivative (0: the distance to the contact point is stationary), so it differs from the previous side")
text114 = 2 * m * (x_C + th * R) * (sp.diff(x_C, th) + R) + 2 * m * y_C * sp.diff(y_C, th)
key.line(114, r"I_{P}'(\theta) = 2m\bigl(x_{C}(\theta) + \theta R\bigr)(x_{C}'(\theta) + R) + 2m y_{C}(\theta)y_{C}'(\theta)", "claim",
         same(sp.diff(I_P, th), text114),
         "the right side is identically 0 (y_C measured from O, not from the floor); I_P' = 2maR sin(theta)",
         correct=r"I_{P}'(\theta) = 2m\bigl(x_{C}(\theta) + \theta R\bigr)(x_{C}'(\theta) + R) + 2m \bigl(y_{C}(\theta) + R\bigr)y_{C}'(\theta)")

key.emit()
