"""Answer key: particle inside an upside-down cone (dannycab/phy415msu notebook, commit 171ca41)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, g, al = sp.symbols("m g alpha", positive=True)
r, th = coords("r", "theta")

# Kinematics: on the cone z = r/tan(α) (the text's own z(t) = r(t)/tan α), cylindrical r, θ.
z = r / sp.tan(al)
x, y = r * sp.cos(th), r * sp.sin(th)
T = sp.simplify(m / 2 * (d(x) ** 2 + d(y) ** 2 + d(z) ** 2))
V = m * g * z
L = T - V
mech = Mechanics(L, [r, th])
assert same(T, m / 2 * (d(r) ** 2 / sp.sin(al) ** 2 + r ** 2 * d(th) ** 2))

# The text's names of the first order system: v = ṙ, ω = θ̇ (so v̇ = r̈, ω̇ = θ̈).
v, w = d(r), d(th)

key = Key("https://github.com/dannycab/phy415msu/blob/171ca418054b023c20d4214f5fd62bf5d47de6ad/MMIPbook/content/2_oscillations/activity-Lagrange-with-constraints-analysis.ipynb",
          "particle on the inside of a cone of half-angle α (cylindrical r, θ)", "Jupyter notebook (course activity)")

text_r = (m * r ** 2 * d(th) - m * g * sp.cot(al)) * sp.cos(al) ** 2
why_r = ("two slips: the centrifugal term is m r θ̇², not m r² θ̇ (not even an acceleration's dimension), and with "
         "z = r/tan α the factor is sin²α: (m/sin²α) r̈ = m r θ̇² − m g cot α")
correct_r = r"m\ddot{r} = (mr\dot{\theta}^2-mg\cot\alpha)\sin^2\alpha"
key.line(11, r"m\ddot{r} = (mr^2\dot{\theta}-mg\cot\alpha)\cos^2\alpha", "claim",
         mech.on_motion(m * d(r, 2), text_r), why_r, correct=correct_r)
key.line(13, r"\dfrac{d}{dt}\left(mr^2\dot{\theta}\right) = 0", "claim",
         mech.on_motion(sp.diff(m * r ** 2 * d(th), t)), "the θ equation: θ is cyclic, p_θ = m r² θ̇")
key.line(19, r"m\ddot{r} = (mr^2\dot{\theta}-mg\cot\alpha)\cos^2\alpha", "claim",
         mech.on_motion(m * d(r, 2), text_r), "the same line repeated: " + why_r, correct=correct_r)
key.line(21, r"2mr\dot{r}\dot{\theta}+mr^2\ddot{\theta} = 0", "claim",
         mech.on_motion(2 * m * r * d(r) * d(th) + m * r ** 2 * d(th, 2)), "d/dt(m r² θ̇) = 0 expanded")
key.line(23, r"v=\dot{r}", "definition", None, "names the radial velocity v")
key.line(23, r"\omega=\dot{\theta}", "definition", None, "names the angular velocity ω")
key.line(25, r"\dot{v} = \left(r^2\omega-g\cot\alpha\right)\cos^2\alpha", "claim",
         mech.on_motion(sp.diff(v, t), (r ** 2 * w - g * sp.cot(al)) * sp.cos(al) ** 2),
         "the r equation of line 11 divided by m, with its two slips (r² ω for r ω², cos²α for sin²α)",
         correct=r"\dot{v} = \left(r\omega^2-g\cot\alpha\right)\sin^2\alpha")
key.line(27, r"\dot{r} = v", "definition", None, "restates the definition of v")
key.line(29, r"\dot{\omega} = -2\dfrac{v\omega}{r}", "claim",
         mech.on_motion(sp.diff(w, t), -2 * v * w / r), "line 21 divided by m r²")
key.line(31, r"\dot{\theta} = \omega", "definition", None, "restates the definition of ω")
key.line(36, r"z(t) = \dfrac{r(t)}{\tan\alpha}", "kinematics", same(z, r / sp.tan(al)),
         "the height on the cone (the constraint), α the half-angle between the surface and the axis")
key.emit()
