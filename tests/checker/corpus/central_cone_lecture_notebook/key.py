"""Answer key: particle on a cone standing on its tip (mhjensen/Physics321 lecture notes, chapter8.ipynb)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, g, al = sp.symbols("m g alpha", positive=True)
r, th = coords("r", "theta")

# Kinematics: cylindrical r, θ (the text's azimuth, called φ in its words); on the cone z = r cot α.
x, y, z = r * sp.cos(th), r * sp.sin(th), r / sp.tan(al)
T = sp.simplify(m / 2 * (d(x) ** 2 + d(y) ** 2 + d(z) ** 2))
V = m * g * z
L = T - V
mech = Mechanics(L, [r, th])
Lmom = m * r ** 2 * d(th)            # the text's L (angular momentum), not the Lagrangian

key = Key("https://github.com/mhjensen/Physics321/blob/fabd5b06d71071d1126fa76a9ce42424955968ed/doc/LectureNotes/chapter8.ipynb",
          "particle on a cone of half angle α standing on its tip (cylindrical r, θ)",
          "Jupyter notebook (lecture notes)")

key.line(10, r"r=\sqrt{x^2+y^2}=z\tan \alpha", "kinematics",
         same(sp.sqrt(sp.trigsimp(x ** 2 + y ** 2)).subs(sp.Abs(r), r), r) and same(z * sp.tan(al), r),
         "the cylindrical radius (r ≥ 0) and the cone's surface (both links hold)")
key.line(20, r"T=\frac{1}{2}mr^2\dot{\theta}^2+\frac{1}{2}m(\dot{r}^2+\dot{z}^2)", "claim",
         same(m / 2 * r ** 2 * d(th) ** 2 + m / 2 * (d(r) ** 2 + d(z) ** 2), T),
         "T in cylindrical coordinates, ż = ṙ cot α on the cone")
key.line(21, r"=\frac{1}{2}mr^2\dot{\theta}^2+\frac{1}{2}m\dot{r}^2\left(1+\cot^2\alpha\right)", "claim",
         same(m / 2 * r ** 2 * d(th) ** 2 + m / 2 * d(r) ** 2 * (1 + sp.cot(al) ** 2), T), "ż = ṙ cot α")
key.line(22, r"=\frac{1}{2}mr^2\dot{\theta}^2+\frac{1}{2}m\dot{r}^2\csc^2\alpha", "claim",
         same(m / 2 * r ** 2 * d(th) ** 2 + m / 2 * d(r) ** 2 * sp.csc(al) ** 2, T), "1 + cot²α = csc²α")
key.line(29, r"U=mgr\cot\alpha", "claim", same(m * g * r * sp.cot(al), V), "V = m g z with z = r cot α")
key.line(36, r"\frac{d}{dt}\left(mr^2\dot{\theta}\right)=0", "claim",
         mech.on_motion(sp.diff(m * r ** 2 * d(th), t)), "the θ equation (θ cyclic)")
key.line(37, r"\frac{d}{dt}\left(m\csc^2\alpha \dot{r}\right)=mr\dot{\theta}^2-mg\cot\alpha", "claim",
         mech.on_motion(sp.diff(m * sp.csc(al) ** 2 * d(r), t), m * r * d(th) ** 2 - m * g * sp.cot(al)),
         "the r equation")
key.line(38, r"\ddot{r}=r\dot{\theta}^2\sin^2\alpha-g\cos\alpha\sin\alpha", "claim",
         mech.on_motion(d(r, 2), r * d(th) ** 2 * sp.sin(al) ** 2 - g * sp.cos(al) * sp.sin(al)),
         "the r equation times sin²α/m")
key.line(42, r"L=mr^2\dot{\theta}", "definition", None,
         "names the angular momentum L = p_θ (the letter of the Lagrangian, here the angular momentum)")
assert same(mech.momentum(th), Lmom)
key.line(46, r"\ddot{r}=\frac{L^2\sin^2\alpha}{m^2r^3}-g\sin\alpha\cos\alpha", "claim",
         mech.on_motion(d(r, 2), Lmom ** 2 * sp.sin(al) ** 2 / (m ** 2 * r ** 3) - g * sp.sin(al) * sp.cos(al)),
         "line 38 with θ̇ = L/(m r²)")
key.emit()
