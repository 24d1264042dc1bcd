"""Answer key of roll_disk_glued_mass_pf (SymPy only): a uniform disk rolling without slipping with a point mass
glued at the distance a from its centre, small oscillations, as asked on Physics Forums."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


ph = coords("phi")
M, m, R, a, g = sp.symbols("M m R a g", positive=True)
phd, phdd = d(ph), d(ph, 2)
s, c = sp.sin(ph), sp.cos(ph)

# Own kinematics: the disk rolls without slipping on the floor y = 0, turning by phi (clockwise) as its centre moves
# by R phi along +x; the point mass, straight below the centre at phi = 0, turns with the disk.
xc, yc = R * ph, R
xp, yp = xc - a * s, yc - a * c
Idisk = M * R**2 / 2                              # uniform solid disk about its axis
Kcm = M * (d(xc) ** 2 + sp.diff(yc, t) ** 2) / 2 + Idisk * phd**2 / 2
Kp = m * (d(xp) ** 2 + d(yp) ** 2) / 2           # a point mass: translation only
T = Kcm + Kp
Udisk = M * g * yc
Up = m * g * yp
V = Udisk + Up
L = T - V
mech = Mechanics(L, [ph])
assert same(Kp, m * (R**2 + a**2 - 2 * a * R * c) * phd**2 / 2)

# Small oscillations about phi = 0: the linearised equation phi'' + w2 phi = 0.
Meff = sp.diff(T, phd, 2).subs(ph, 0)
Keff = sp.diff(V, ph, 2).subs(ph, 0)
w2 = sp.simplify(Keff / Meff)
assert same(w2, m * g * a / (sp.Rational(3, 2) * M * R**2 + m * (R - a) ** 2))

key = Key("https://www.physicsforums.com/threads/lagrangian-rigid-body-problem.784753/post-4928218",
          "uniform disk rolling without slipping with a point mass glued off its centre", "Q&A thread")

l10 = at(r"$\frac{\partial L}{\partial q} - \frac{d}{dt}\frac{\partial L}{\partial {\dot q}}=0$")
key.line(l10, r"\frac{\partial L}{\partial q} - \frac{d}{dt}\frac{\partial L}{\partial {\dot q}}=0", "definition", None,
         "the Euler-Lagrange equation stated for a generic coordinate q")
key.line(l10, r"I=I_{cm}+ MR^2", "given", None,
         "the parallel axis theorem as the asker quotes it, for the second way (the disk about its contact point, "
         "R from its centre); the post never reaches the second way")
key.line(at(r" x_{cm}=R\varphi \\"), r"x_{cm}=R\varphi", "kinematics", same(xc, R * ph),
         "rolling without slipping: the centre moves by R phi")
key.line(at(r" y_{cm}=R"), r"y_{cm}=R", "kinematics", same(yc, R), "the centre stays at the height R")
key.line(at(r" x_{p}=x_{cm} - a\sin(\varphi)"), r"x_{p}=x_{cm} - a\sin(\varphi)=R\varphi - a\sin(\varphi)",
         "kinematics", same(xp, R * ph - a * s), "the point mass, a from the centre, turned with the disk")
key.line(at(r" y_{p}=y_{cm} - a\cos(\varphi)"), r"y_{p}=y_{cm} - a\cos(\varphi) =R - a\cos(\varphi)",
         "kinematics", same(yp, R - a * c), "its height")
l26 = at(r"$K=K_{cm}+K_{p}$")
key.line(l26, r"K=K_{cm}+K_{p}", "definition", None, "splits the kinetic energy K into the disk's and the point mass's")
key.line(l26, r"U=U_{cm}+U_{p}", "definition", None,
         "splits the potential energy U into the disk's (written U_{disk} on line 36) and the point mass's")
key.line(at(r"$$K_{cm}=\frac{1}{2} M{v^2}_{cm}"),
         r"K_{cm}=\frac{1}{2} M{v^2}_{cm} +\frac{1}{2}I_{disk}\dot{\varphi}^2 = \frac{3}{4}MR^2\dot{\varphi}^2", "claim",
         same(Kcm, sp.Rational(3, 4) * M * R**2 * phd**2),
         "the disk's translation (v_cm = R phidot) and its rotation about its centre")
key.line(at(r"using $I_{disk}=\frac{1}{2}MR^2$"), r"I_{disk}=\frac{1}{2}MR^2", "claim", same(Idisk, M * R**2 / 2),
         "uniform solid disk about its axis")
Ip = m * a**2
Kp_text_1 = m * (d(xp) ** 2 + d(yp) ** 2) / 2 + Ip * phd**2 / 2
Kp_text_2 = m * R**2 / 2 + m * a**2 / 2 - m * a * R * c + m * a**2 * phd**2 / 2
assert not same(Kp_text_1, Kp) and not same(Kp_text_1, Kp_text_2)
key.line(at(r"$$K_{p}=\frac{1}{2} m({\dot{x}^2}_{p}"),
         r"K_{p}=\frac{1}{2} m({\dot{x}^2}_{p}+{\dot{y}^2}_{p} )+\frac{1}{2}I_{p}\dot{\varphi}^2 = \frac{1}{2}mR^2 + \frac{1}{2}ma^2 -maR\cos(\varphi) + \frac{1}{2}ma^2\dot{\varphi}^2",
         "claim", same(Kp_text_1, Kp) and same(Kp_text_2, Kp),
         "both links are wrong: a point mass has no energy of rotation besides its translation, so the term "
         "(1/2) I_p phidot^2 = (1/2) m a^2 phidot^2 counts its motion twice; and the translation "
         "(1/2) m (xdot_p^2 + ydot_p^2) = (1/2) m (R^2 + a^2 - 2aR cos phi) phidot^2 has lost its factor phidot^2",
         r"K_{p}=\frac{1}{2} m({\dot{x}^2}_{p}+{\dot{y}^2}_{p} ) = \frac{1}{2}m(R^2 + a^2 - 2aR\cos(\varphi))\dot{\varphi}^2")
key.line(at(r"using $I_{p}=ma^2$"), r"I_{p}=ma^2", "claim", same(Ip, m * a**2),
         "the moment of inertia of the point mass about the disk's centre (true as such; the slip is adding "
         "(1/2) I_p phidot^2 to the point's translational energy on line 32)")
key.line(at(r"$$U_{disk}=MgR$$"), r"U_{disk}=MgR", "claim", same(Udisk, M * g * R), "the disk's centre at the height R")
key.line(at(r"$$U_{p}=mg(R-a\cos(\varphi))$$"), r"U_{p}=mg(R-a\cos(\varphi))", "claim",
         same(Up, m * g * (R - a * c)), "the point mass at the height R - a cos phi")
L_text = (m * R**2 / 2 + m * a**2 / 2 - m * a * R * c + m * a**2 * phd**2 / 2 + sp.Rational(3, 4) * M * R**2 * ph
          - M * g * R - m * g * (R - a * c))
key.line(at(r"$$L=\frac{1}{2}mR^2"),
         r"L=\frac{1}{2}mR^2 + \frac{1}{2}ma^2 -maR\cos(\varphi) + \frac{1}{2}ma^2\dot{\varphi}^2 +\frac{3}{4}MR^2\varphi -MgR - mg(R-a\cos(\varphi))",
         "claim", same(L_text, L),
         "carries K_p of line 32 (the point's translation without phidot^2, and the extra (1/2) m a^2 phidot^2), "
         "and the disk's (3/4) M R^2 phidot^2 of line 28 is written (3/4) M R^2 phi",
         r"L=\frac{1}{2}m(R^2 + a^2 -2aR\cos(\varphi))\dot{\varphi}^2 +\frac{3}{4}MR^2\dot{\varphi}^2 -MgR - mg(R-a\cos(\varphi))")
_u = sp.Symbol("u")                               # phi as a plain symbol for the series
key.line(at(r"$sin(\varphi)=\varphi$"), r"sin(\varphi)=\varphi", "approximation",
         same(sp.series(sp.sin(_u), _u, 0, 2).removeO(), _u),
         "sin phi = phi to first order in phi (small oscillations)")
k_text = (m * R * a + m * g * a) / (sp.Rational(3, 2) * M * R**2 + m * a**2)
key.line(at(r"$$\ddot{\varphi}+{\varphi}[\frac{mRa + mga}"),
         r"\ddot{\varphi}+{\varphi}[\frac{mRa + mga}{\frac{3}{2}MR^2 +ma^2}]=0", "approximation",
         same(k_text, w2),
         "the linearised equation is [(3/2) M R^2 + m (R - a)^2] phiddot + m g a phi = 0: the moment of inertia "
         "about the contact point is (3/2) M R^2 + m (R - a)^2 (not + m a^2), and only gravity restores, m g a "
         "(the term m R a is not even of the dimension of m g a)",
         r"\ddot{\varphi}+{\varphi}[\frac{mga}{\frac{3}{2}MR^2 +m(R-a)^2}]=0")
key.emit()
