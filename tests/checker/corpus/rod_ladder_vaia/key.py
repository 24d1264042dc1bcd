"""Answer key of rod_ladder_vaia (SymPy only): a uniform ladder of mass M and length 2L sliding down a frictionless
wall on a frictionless floor, theta the angle between the ladder and the floor (Cline, Variational Principles in
Classical Mechanics, ch. 8, problem 15, as the vaia.com solution works it)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


M, L, g, I = sp.symbols("M L g I", positive=True)
th = coords("theta")
dth = d(th)
s, c = sp.sin, sp.cos

# Own mechanics: wall along the vertical axis, floor along the horizontal one; the feet at (2L cos(theta), 0), the
# top at (0, 2L sin(theta)), so the centre of mass is at (L cos(theta), L sin(theta)) and the ladder turns at the
# rate theta'. The moment of inertia of the uniform rod about its midpoint, by integration along it.
u = sp.Symbol("u", real=True)
I_mid = sp.integrate(M / (2 * L) * u**2, (u, -L, L))
xc, yc = L * c(th), L * s(th)
T = sp.trigsimp(sp.expand(M / 2 * (sp.diff(xc, t)**2 + sp.diff(yc, t)**2) + I_mid / 2 * dth**2))
V = M * g * yc
Lag = T - V
mech = Mechanics(Lag, [th])
H = sp.trigsimp(mech.energy())                      # h = theta' dL/dtheta' - L (= T + V here)

key = Key("https://www.vaia.com/en-us/textbooks/physics/variational-principles-in-classical-mechanics-2018-edition/chapter-8/problem-15-a-uniform-ladder-of-mass-m-and-length-2-l-is-lean",
          "uniform ladder sliding down a frictionless wall on a frictionless floor", "textbook solutions site")

key.line(at(r"\(\theta_{0}=60^{\circ}\)"), r"\theta_{0}=60^{\circ}", "condition", None,
         "the release angle to the floor (the ladder starts at rest)")
key.line(at(r"\(g=9.81 \mathrm{~m} / \mathrm{s}^{2}\)"), r"g=9.81 \mathrm{~m} / \mathrm{s}^{2}", "given", None,
         "the problem's value of g")
assert same(sp.Rational(1, 3) * M * L**2, I_mid)     # the problem's I is the rod's, so the given is no contradiction
key.line(at(r"\(I=\frac{1}{3} M L^{2}\)"), r"I=\frac{1}{3} M L^{2}", "given", None,
         "the problem's moment of inertia about the midpoint (it is the uniform rod's, M (2L)^2/12)")

T_text = sp.Rational(1, 6) * M * L**2 * dth**2
V_text = M * g * L * s(th)
L_text = T_text - V_text
H_text = T_text + V_text
ok = same(L_text, Lag)
key.line(at(r"(b) \(\mathcal{L} = "), r"\mathcal{L} = \frac{1}{6} M L^2 \dot{\theta}^2 - M g L \sin\theta", "claim", ok,
         "T - V" if ok else
         f"T leaves out the motion of the centre of mass (speed L theta'): L = {sp.sstr(T).replace('(t)', '')} - M g L sin(theta), "
         "not 1/6 M L^2 theta'^2",
         None if ok else r"\mathcal{L} = \frac{2}{3} M L^2 \dot{\theta}^2 - M g L \sin\theta")
ok = same(H_text, H)
key.line(at(r"(c) \(H = "), r"H = \frac{1}{6} M L^2 \dot{\theta}^2 + M g L \sin\theta", "claim", ok,
         "H = theta' dL/dtheta' - L = T + V" if ok else
         f"H = theta' dL/dtheta' - L = {sp.sstr(H).replace('(t)', '')}: the same missing translational energy as (b)",
         None if ok else r"H = \frac{2}{3} M L^2 \dot{\theta}^2 + M g L \sin\theta")

l25 = at(r"\( T = \frac{1}{2} I \dot{\theta}^2 = ")
ok = same(sp.Rational(1, 2) * I_mid * dth**2, T)
key.line(l25, r"T = \frac{1}{2} I \dot{\theta}^2", "claim", ok,
         "the kinetic energy" if ok else
         "the ladder does not turn about a fixed midpoint: its centre of mass moves on a circle of radius L (speed L "
         "theta'), so T = M L^2 theta'^2/2 + I theta'^2/2",
         None if ok else r"T = \frac{1}{2} M L^2 \dot{\theta}^2 + \frac{1}{2} I \dot{\theta}^2")
key.line(l25, r"\frac{1}{2} I \dot{\theta}^2 = \frac{1}{6} M L^2 \dot{\theta}^2", "claim",
         same(sp.Rational(1, 2) * I_mid * dth**2, T_text), "I = M L^2/3 put in (the arithmetic of this step is right)")
key.line(at(r"\( V = M g L \sin\theta \)"), r"V = M g L \sin\theta", "claim", same(V_text, V),
         "the centre of mass at height L sin(theta), zero at the floor")
l31 = at(r"\( \mathcal{L} = T - V = ")
key.line(l31, r"\mathcal{L} = T - V", "definition", None, "the Lagrangian")
ok = same(L_text, Lag)
key.line(l31, r"T - V = \frac{1}{6} M L^2 \dot{\theta}^2 - M g L \sin\theta", "claim", ok,
         "T - V" if ok else "T - V of the text's own T and V, but that T lacks M L^2 theta'^2/2 (step 2), so the "
         "Lagrangian of the ladder is 2/3 M L^2 theta'^2 - M g L sin(theta)",
         None if ok else r"\mathcal{L} = T - V = \frac{2}{3} M L^2 \dot{\theta}^2 - M g L \sin\theta")
key.emit()
