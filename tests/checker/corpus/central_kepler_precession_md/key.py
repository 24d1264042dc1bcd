"""Answer key: planar Kepler orbit (codiphy-org/precession, newtonian.md at commit da18bd4)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, M, G = sp.symbols("m M G", positive=True)
r, th = coords("r", "theta")

# Kinematics: m at (r cos θ, r sin θ), M fixed at the origin (M >> m).
x, y = r * sp.cos(th), r * sp.sin(th)
T = sp.simplify((d(x) ** 2 + d(y) ** 2) * m / 2)
V = -G * M * m / r
L = T - V
mech = Mechanics(L, [r, th])


def pd(expr, var):
    """Partial derivative with respect to a coordinate or a velocity (functions of t)."""
    s = sp.Dummy()
    return sp.diff(expr.subs(var, s), s).subs(s, var)


def proportional(a, b):
    """a = c b for a nonzero constant c (no coordinate in c): equal as equations '... = 0'."""
    ratio = sp.simplify(sp.sympify(a) / sp.sympify(b))
    return ratio != 0 and not ratio.has(t) and all(not isinstance(f, sp.Function) for f in ratio.atoms(sp.Function))


EL_r = pd(L, r) - sp.diff(pd(L, d(r)), t)          # ∂L/∂r − d/dt ∂L/∂ṙ
EL_th = pd(L, th) - sp.diff(pd(L, d(th)), t)       # ∂L/∂θ − d/dt ∂L/∂θ̇
text_r = r * d(th) ** 2 - G * M / r ** 2 - d(r, 2)

k = Key("https://github.com/codiphy-org/precession/blob/da18bd4bfb756c9c63b5aa28da9a9f317e4b56ae/newtonian.md",
        "planar Kepler orbit about a fixed mass M (polar r, θ)", "notes in a public repository (Markdown)")

text_L = sp.Rational(1, 2) * (m * d(r) ** 2 + m * r ** 2 * d(th) ** 2) + G * M * m / r
k.line(8, r"\mathscr{L} = \frac{1}{2}(m \dot{r}^2 + m r^2 \dot{\theta}^2) + \frac{GMm}{r}", "claim",
       same(text_L, L), "T − V with V = −GMm/r")
k.line(14, r"\frac{\partial \mathscr{L}}{\partial r} = m r \dot{\theta}^2 - \frac{GMm}{r^2}", "claim",
       same(pd(L, r), m * r * d(th) ** 2 - G * M * m / r ** 2), "∂L/∂r")
k.line(18, r"\frac{\partial \mathscr{L}}{\partial \dot{r}} = m \dot{r}", "claim",
       same(pd(L, d(r)), m * d(r)), "∂L/∂ṙ")
k.line(22, r"\frac{\partial \mathscr{L}}{\partial \theta} = 0", "claim", same(pd(L, th), 0), "θ is cyclic")
k.line(26, r"\frac{\partial \mathscr{L}}{\partial \dot{\theta}} = m r^2 \dot{\theta}", "claim",
       same(pd(L, d(th)), m * r ** 2 * d(th)), "∂L/∂θ̇")
k.line(32, r"0 = \frac{\partial \mathscr{L}}{\partial r} - \frac{d}{dt}(\frac{\partial \mathscr{L}}{\partial \dot{r}})",
       "claim", mech.on_motion(EL_r), "the Euler–Lagrange equation for r")
k.line(33, r"\frac{\partial \mathscr{L}}{\partial r} - \frac{d}{dt}(\frac{\partial \mathscr{L}}{\partial \dot{r}}) = r \dot{\theta}^2 - \frac{GM}{r^2} -\ddot{r}",
       "claim", proportional(EL_r, text_r) and mech.on_motion(text_r),
       "the r expression divided by m, allowed since the chain sets it to 0 (literally it is m times the right side)")
k.line(38, r"\ddot{r} = r \dot{\theta}^2 - \frac{GM}{r^2}", "claim",
       mech.on_motion(d(r, 2), r * d(th) ** 2 - G * M / r ** 2), "the r equation solved for r̈")
k.line(44, r"0 = \frac{\partial \mathscr{L}}{\partial \theta} - \frac{d}{dt}(\frac{\partial \mathscr{L}}{\partial \dot{\theta}})",
       "claim", mech.on_motion(EL_th), "the Euler–Lagrange equation for θ")
k.line(45, r"\frac{\partial \mathscr{L}}{\partial \theta} - \frac{d}{dt}(\frac{\partial \mathscr{L}}{\partial \dot{\theta}}) = r \dot{\theta}^2 - \frac{GM}{r^2} -\ddot{r}",
       "claim", proportional(EL_th, text_r),
       "the r equation copied into the θ line: the θ expression is −d/dt(m r² θ̇) = −(2 m r ṙ θ̇ + m r² θ̈), not a multiple "
       "of r θ̇² − GM/r² − r̈ (both vanish on a motion, but this is not the θ equation; the author replaced it by "
       "d/dt(m r² θ̇) in a later commit)",
       correct=r"0 = \frac{\partial \mathscr{L}}{\partial \theta} - \frac{d}{dt}(\frac{\partial \mathscr{L}}{\partial \dot{\theta}}) = -\frac{d}{dt}(m r^2 \dot{\theta})")
k.line(50, r"L = m r^2 \dot{\theta}", "definition", None,
       "names the angular momentum L (the text's Lagrangian is \\mathscr{L}); it equals p_θ = ∂\\mathscr{L}/∂θ̇")
assert same(mech.momentum(th), m * r ** 2 * d(th))
k.emit()
