"""Answer key: free particle seen from a rotating frame (jrekier blog post, 2016-05-06-rotatin-frames.md)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, w = sp.symbols("m omega", positive=True)
x, y = coords("x", "y")

# Kinematics: rotating basis e_x = (cos ωt, sin ωt), e_y = (−sin ωt, cos ωt) in inertial axes (frame turning at
# +ω about z); the particle at x e_x + y e_y; L = ½ m |inertial velocity|², no force.
ex = sp.Matrix([sp.cos(w * t), sp.sin(w * t)])
ey = sp.Matrix([-sp.sin(w * t), sp.cos(w * t)])
r_in = x * ex + y * ey
T = sp.simplify(m / 2 * d(r_in).dot(d(r_in)))
L = T
mech = Mechanics(L, [x, y])

with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "derivation.md"), encoding="utf-8") as fh:
    TEXT = fh.read().split("\n")

key = Key("https://github.com/jrekier/minimal-mistakes/blob/1b06a5d17cfb029e84216ec64f35716a7553041a/_posts/2016-05-06-rotatin-frames.md",
          "free particle in a frame rotating at ω about z (rotating-frame x, y)", "blog post")

# Line 12: ½ m |ṙ + ω × r|² with rotating-frame components, ω = ω ẑ.
om = sp.Matrix([0, 0, w])
rv = sp.Matrix([x, y, 0])
v_in = d(rv) + om.cross(rv)
key.line(12, r"L = \frac{1}{2}m\left|~\dot{\vec{r}}+\vec{\omega}\times\vec{r}~\right|^2", "claim",
         same(m / 2 * v_in.dot(v_in), L), "the inertial velocity in rotating components is ṙ + ω × r")
# Line 13: a vector identity, for any 3-vectors ω, r, ṙ.
W = sp.Matrix(sp.symbols("w1:4", real=True))
Rv = sp.Matrix(sp.symbols("r1:4", real=True))
Vv = sp.Matrix(sp.symbols("v1:4", real=True))
lhs13 = m / 2 * (Vv + W.cross(Rv)).dot(Vv + W.cross(Rv))
rhs13 = m / 2 * Vv.dot(Vv) + m * W.dot(Rv.cross(Vv)) + m / 2 * (W.dot(W) * Rv.dot(Rv) - W.dot(Rv) ** 2)
key.line(13, r"= \frac{1}{2}m\left|\dot{\vec{r}}\right|^2+m~\vec{\omega}\cdot\left(\vec{r}\times\dot{\vec{r}}\right)+\frac{1}{2}m\left[\omega^2r^2-(\vec{\omega}\cdot\vec{r})^2\right]",
         "claim", same(lhs13, rhs13), "|a + b|² expanded; (ω × r)·ṙ = ω·(r × ṙ) and |ω × r|² = ω² r² − (ω·r)²")
key.line(17, r"\vec{\omega}^{T}=\left(0,0,\omega\right)", "given", None, "rotation about z")
text20 = sp.Rational(1, 2) * (d(x) ** 2 + d(y) ** 2) + m * w * (x * d(y) - y * d(x)) + sp.Rational(1, 2) * w ** 2 * (x ** 2 + y ** 2)
key.line(20, r"L = \frac{1}{2}\left(\dot{x}^2+\dot{y}^2\right)+m\omega(x\dot{y}-y\dot{x})+\frac{1}{2}\omega^2(x^2+y^2)",
         "claim", same(text20, L),
         "the mass m is dropped from the first and last terms but kept in the middle one (line 13 has m in all "
         "three); right only for m = 1",
         correct=r"L = \frac{1}{2}m\left(\dot{x}^2+\dot{y}^2\right)+m\omega(x\dot{y}-y\dot{x})+\frac{1}{2}m\omega^2(x^2+y^2)")
A = sp.Matrix([[0, 1, 0, 0], [w ** 2, 0, 0, 2 * w], [0, 0, 0, 1], [0, -2 * w, w ** 2, 0]])
Xs = sp.Matrix([x, d(x), y, d(y)])
key.line(27, TEXT[26].strip(), "claim",
         all(mech.on_motion(a, b) for a, b in zip(d(Xs), A * Xs)),
         "ẍ = ω² x + 2ω ẏ, ÿ = −2ω ẋ + ω² y: the Euler–Lagrange equations (m cancels)")
# The propagator: the text's matrix, checked by E' = A E and E(0) = 1 (which makes it e^{At}).
c, s = sp.cos(t * w), sp.sin(t * w)
E_text = sp.Matrix([
    [c + t * w * s, t * c, s - t * w * c, t * s],
    [t * w ** 2 * c, c - t * w * s, t * w ** 2 * s, t * w * c + s],
    [t * w * c - s, -t * s, c + t * w * s, t * c],
    [-t * w ** 2 * s, -t * w * c - s, t * w ** 2 * c, c - t * w * s]])
is_propagator = sp.simplify(E_text.diff(t) - A * E_text) == sp.zeros(4, 4) and E_text.subs(t, 0) == sp.eye(4)
key.line(33, r"X(t)=e^{A[\omega]t}\cdot X(0)", "claim", is_propagator and not A.has(t),
         "the solution of the linear system with constant A (line 27)")
key.line(39, " ".join(l.strip() for l in TEXT[38:54]), "claim", is_propagator,
         "solves E' = A E with E(0) = 1, so it is e^{At}")
key.line(57, r"X(0)^T=(0,1,0,0)", "condition", None, "initial state: at the centre, unit velocity along x")
key.line(58, r"\omega=1", "given", None, "value for the plot")
key.line(58, r"t=0", "condition", None, "start of the plotted interval")
key.line(58, r"t=20", "condition", None, "end of the plotted interval")
# Initial velocity that reaches the centre at t_c from (x0, y0).
x0, y0, tc, vx, vy = sp.symbols("x_0 y_0 t_c v_x v_y", real=True)
state_tc = E_text.subs(t, tc) * sp.Matrix([x0, vx, y0, vy])
sol = sp.solve([state_tc[0], state_tc[2]], [vx, vy], dict=True)[0]
key.line(67, r"v_x^0=-\frac{x_0-y_0\omega t_c}{t_c}", "claim", same(sol[vx], -(x0 - y0 * w * tc) / tc),
         "x(t_c) = y(t_c) = 0 solved for the initial velocity")
key.line(68, r"v_y^0=-\frac{y_0+x_0\omega t_c}{t_c}", "claim", same(sol[vy], -(y0 + x0 * w * tc) / tc),
         "x(t_c) = y(t_c) = 0 solved for the initial velocity")
key.line(72, r"y_0=0", "given", None, "a start on the x axis")
key.line(76, r"v_x^0=-\frac{x_0}{t_c}", "claim", same(sol[vx].subs(y0, 0), -x0 / tc), "line 67 with y0 = 0")
key.line(77, r"v_y^0=-\omega x_0", "claim", same(sol[vy].subs(y0, 0), -w * x0), "line 68 with y0 = 0")
key.line(81, r"t=t_c", "condition", None, "the arrival time")
key.line(84, r"x_0=1", "given", None, "start at distance 1")
traj = E_text * sp.Matrix([1, sol[vx], 0, sol[vy]]).subs({x0: 1, y0: 0})
key.line(88, r"\vec{r}=(1-\frac{t}{t_c})\cos \omega t~\vec{e}_x - (1-\frac{t}{t_c})\sin \omega t~\vec{e}_y", "claim",
         same(traj[0], (1 - t / tc) * sp.cos(w * t)) and same(traj[2], -(1 - t / tc) * sp.sin(w * t)),
         "the propagator applied to (1, v_x^0, 0, v_y^0)")
# The basis of line 97 is the one under which the rotating-frame equations describe free motion.
free = all(mech.on_motion(comp) for comp in sp.diff(r_in, t, 2))
key.line(97, r"\begin{pmatrix}\vec{e}_x\\\vec{e}_y\end{pmatrix}=\begin{pmatrix}\cos\omega t & \sin\omega t\\ -\sin\omega t & \cos\omega t \end{pmatrix}\begin{pmatrix}\vec{X}\\\vec{Y}\end{pmatrix}",
         "kinematics", free and same(ex[0], sp.cos(w * t)) and same(ex[1], sp.sin(w * t)),
         "the frame turns at +ω about z; with this basis x e_x + y e_y has zero acceleration on every motion")
r_inertial = traj[0] * ex + traj[2] * ey
vx0 = sol[vx].subs({x0: 1, y0: 0})
key.line(104, r"\vec{r}=\left(1+v_x^0t\right)\vec{X}", "claim",
         same(r_inertial[0], 1 + vx0 * t) and same(r_inertial[1], 0), "line 88 in the inertial basis, v_x^0 = −1/t_c")
key.emit()
