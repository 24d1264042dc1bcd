"""Answer key: planar Kepler problem (leuraph/kepler-geocache, readme.md at commit 128dc85)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, k_, G, M = sp.symbols("m k G M", positive=True)
r, th = coords("r", "theta")

# Kinematics: the mass at (r cos θ, r sin θ); the potential of the text, V(r) = -k/r.
x, y = r * sp.cos(th), r * sp.sin(th)
T = sp.simplify(m / 2 * (d(x) ** 2 + d(y) ** 2))
V = -k_ / r
L = T - V
mech = Mechanics(L, [r, th])

ell = m * r ** 2 * d(th)                                   # the text's ℓ := m r² θ̇
E = m / 2 * d(r) ** 2 + ell ** 2 / (2 * m * r ** 2) + V    # the text's E (ℓ substituted)
V_eff = V + ell ** 2 / (2 * m * r ** 2)

key = Key("https://github.com/leuraph/kepler-geocache/blob/128dc85ca419c8c45dc6205569e30c83773ad28c/readme.md",
          "planar Kepler problem, V = -k/r (polar r, θ)", "README of a public repository (Markdown)")

key.line(9, r"L := \frac{m}{2}\left(\dot r^2 + r^2 \dot \theta^2\right) - V(r)", "claim",
         same(m / 2 * (d(r) ** 2 + r ** 2 * d(th) ** 2) - V, L), "T − V in polar coordinates")
key.line(20, r"V(r) = - \frac{k}{r}", "given", None, "the potential of gravity, the model's V")
key.line(26, r"k := GMm", "definition", None, "names the strength k of the attraction")
key.line(37, r"\frac{\mathrm d}{\mathrm d t}\left(m r^2 \dot \theta\right) = 0", "claim",
         mech.on_motion(sp.diff(m * r ** 2 * d(th), t)), "the Euler–Lagrange equation for θ (θ cyclic)")
text_r = m * d(r, 2) - m * r * d(th) ** 2 - sp.diff(V, r)
key.line(38, r"m \ddot r - mr \dot \theta^2 - \frac{\partial V}{\partial r} = 0", "claim", mech.on_motion(text_r),
         "sign of ∂V/∂r: d/dt ∂L/∂ṙ − ∂L/∂r = m r̈ − m r θ̇² + ∂V/∂r (with V = −k/r the text's line has −k/r², "
         "a repulsive force)",
         correct=r"m \ddot r - mr \dot \theta^2 + \frac{\partial V}{\partial r} = 0")
key.line(45, r"\ell := m r^2 \dot \theta", "definition", None, "names the angular momentum ℓ = p_θ")
assert same(mech.momentum(th), ell)
key.line(45, r"m r^2 \dot \theta \equiv \mathrm{const}", "claim", mech.on_motion(sp.diff(ell, t)),
         "p_θ is conserved (θ cyclic)")
key.line(52, r"E := \frac{1}{2} m \dot r^2 + \frac{\ell^2}{2mr^2} + V(r)", "definition", None,
         "names the energy E; with ℓ = m r² θ̇ it is T + V")
assert same(E, T + V)
key.line(54, r"\frac{1}{2} m \dot r^2 + \frac{\ell^2}{2mr^2} + V(r) \equiv \mathrm{const}", "claim",
         mech.on_motion(sp.diff(E, t)), "the energy is conserved (L has no explicit t)")
key.line(64, r"\dot \theta = \frac{\ell}{m r^2}", "claim", same(d(th), ell / (m * r ** 2)),
         "the definition of ℓ solved for θ̇")
# ṙ from the energy: the root of ṙ² is |ṙ|, not ṙ.
root = sp.sqrt(sp.simplify(2 / m * (E - V - ell ** 2 / (2 * m * r ** 2))))


def holds_for_any_sign(lhs, rhs):
    """lhs = rhs for every state: test also a state with ṙ < 0 (the root is never negative)."""
    pt = {d(r): -sp.Rational(3, 2), d(th): sp.Rational(1, 3), r: 2, m: 1, k_: 1}
    return same(lhs, rhs) and sp.simplify((lhs - rhs).subs(pt)) == 0
key.line(67, r"\dot r = \sqrt{\frac{2}{m}\left(E - V(r) - \frac{\ell^2}{2mr^2}\right)}", "claim",
         holds_for_any_sign(d(r), root),
         "drops the sign of the root: the right side is |ṙ|, so the line holds only while r grows (ṙ ≥ 0); "
         "on the inward half of an orbit ṙ is the negative root, and this first-order system cannot turn at a "
         "turning point (debatable as a slip: some texts take the outgoing branch tacitly, but the text offers this "
         "system as equivalent to the Euler–Lagrange equations)",
         correct=r"\dot r = \pm\sqrt{\frac{2}{m}\left(E - V(r) - \frac{\ell^2}{2mr^2}\right)}")
key.line(82, r"V_{\text{eff}} := V(r) + \frac{\ell^2}{2mr^2}", "definition", None, "names the effective potential")
key.line(92, r"\dot \theta = \frac{\ell}{m r^2}", "claim", same(d(th), ell / (m * r ** 2)),
         "the definition of ℓ solved for θ̇")
key.line(95, r"\dot r = \sqrt{\frac{2}{m}\left(E - V_{\text{eff}}\right)}", "claim",
         holds_for_any_sign(d(r), sp.sqrt(sp.simplify(2 / m * (E - V_eff)))),
         "as line 67: the right side is |ṙ|; the sign of ṙ is lost",
         correct=r"\dot r = \pm\sqrt{\frac{2}{m}\left(E - V_{\text{eff}}\right)}")
key.emit()
