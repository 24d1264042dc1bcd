"""Answer key of bead_helix (SymPy only): SICM exercise 1.17, a bead on a helical wire with a horizontal axis, as
worked in Thomas Antony's SICM workbook."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m, g, d_, h = sp.symbols("m g d h", positive=True)
s = coords("s")
r = d_ / 2                                   # the text's radius r (map.toml)

# Own kinematics: the helix's axis is the x-axis (horizontal), y is vertical (up), z horizontal across the axis; the
# angle around the helix after a length s along the axis is 2 pi h s (h turns per unit length).
phi = 2 * sp.pi * h * s
X, Y, Z = s, r * sp.cos(phi), r * sp.sin(phi)
T = m / 2 * (d(X) ** 2 + d(Y) ** 2 + d(Z) ** 2)
V = m * g * Y
mech = Mechanics(T - V, [s])

_TEXT = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "derivation.md"), encoding="utf-8").read().split("\n")


def at(n, fragment):
    """Line n of derivation.md, checked to hold the fragment (so that a line number cannot silently drift)."""
    assert fragment in _TEXT[n - 1], (n, fragment, _TEXT[n - 1])
    return n


key = Key("https://www.thomasantony.com/projects/sicm-workbook/sicm-exercise-1-17/",
          "bead on a helical wire with a horizontal axis (SICM 1.17)", "blog post")

S = sp.Symbol("S")                          # s as a plain symbol, for the point halfway along the first turn
half = {S: 1 / (2 * h)}
at_half = lambda e: sp.simplify(e.subs(s, S).subs(half))  # noqa: E731

key.line(at(6, r"\frac{2\pi}{1/h}s = 2\pi hs"), r"\frac{2\pi}{1/h}s = 2\pi hs", "kinematics",
         same(2 * sp.pi / (1 / h) * s, phi), "the angle around the helix after a length s: h s turns")
key.line(at(8, r"$s = 0$"), r"s = 0", "condition", None, "the bead at the start of the axis")
key.line(at(8, r"$x, y, z = 0, 0, 0$"), r"x, y, z = 0, 0, 0", "kinematics",
         all(sp.simplify(e.subs(s, 0)) == 0 for e in (X, Y, Z)),
         "at s = 0 the bead is on the wire, a radius r from the axis: (x, y, z) = (0, r, 0) with the text's own "
         "y = r cos(2πhs) of line 13 (0, 0, 0 is the point of the axis)",
         correct=r"x, y, z = 0, r, 0")

key.line(at(11, r"s = \frac{1}{2h}\\"), r"s = \frac{1}{2h}", "condition", None, "the point halfway along the first turn")
key.line(at(12, r"x = s = \frac{1}{2h},"), r"x = s = \frac{1}{2h}", "kinematics",
         same(X, s) and sp.simplify(at_half(X) - 1 / (2 * h)) == 0, "x is s along the axis, here 1/(2h)")
key.line(at(13, r"y = r \cos{\left(2\pi h \frac{1}{2h}\right)} = r\cos{\pi}"),
         r"y = r \cos{\left(2\pi h \frac{1}{2h}\right)} = r\cos{\pi}", "kinematics",
         sp.simplify(at_half(Y) - r * sp.cos(2 * sp.pi * h / (2 * h))) == 0 and sp.simplify(r * sp.cos(2 * sp.pi * h / (2 * h)) - r * sp.cos(sp.pi)) == 0,
         "the height of the bead halfway along the turn, -r")
key.line(at(14, r"y = r \sin{\left(2\pi h \frac{1}{2h}\right)}"), r"y = r \sin{\left(2\pi h \frac{1}{2h}\right)}",
         "kinematics", sp.simplify(at_half(Y) - r * sp.sin(2 * sp.pi * h / (2 * h))) == 0,
         "the second coordinate across the axis is z, not y (y was given on line 13): a label slip; y = -r there",
         correct=r"z = r \sin{\left(2\pi h \frac{1}{2h}\right)}")
key.line(at(14, r"= r\sin{\pi}"), r"r \sin{\left(2\pi h \frac{1}{2h}\right)} = r\sin{\pi}", "kinematics",
         sp.simplify(r * sp.sin(2 * sp.pi * h / (2 * h)) - r * sp.sin(sp.pi)) == 0, "2πh/(2h) = π")

key.line(at(21, r"x(t) &= s(t)"), r"x(t) = s(t)", "kinematics", same(X, s), "the position along the axis")
key.line(at(22, r"y(t) &= \frac{d}{2} \cos{2 \pi h s}"), r"y(t) = \frac{d}{2} \cos{2 \pi h s}", "kinematics",
         same(Y, d_ / 2 * sp.cos(phi)), "the height above the axis, radius d/2")
key.line(at(23, r"y(t) &= \frac{d}{2} \sin{2 \pi h s}"), r"y(t) = \frac{d}{2} \sin{2 \pi h s}", "kinematics",
         same(Y, d_ / 2 * sp.sin(phi)),
         "the third coordinate is z (the velocities below call it v_z); labelled y a second time",
         correct=r"z(t) = \frac{d}{2} \sin{2 \pi h s}")

key.line(at(31, r"v_x(t) &= \dot{s}"), r"v_x(t) = \dot{s}", "kinematics", same(d(X), d(s)), "d/dt of x")
key.line(at(32, r"v_y(t) &= -\pi d h"), r"v_y(t) = -\pi d h \dot{s} \sin{2 \pi h s}", "kinematics",
         same(d(Y), -sp.pi * d_ * h * d(s) * sp.sin(phi)), "d/dt of y = d/2 cos 2πhs")
key.line(at(33, r"v_z(t) &= \pi d h"), r"v_z(t) = \pi d h \dot{s} \cos{2 \pi h s}", "kinematics",
         same(d(Z), sp.pi * d_ * h * d(s) * sp.cos(phi)), "d/dt of z = d/2 sin 2πhs")

vx, vy, vz = d(X), d(Y), d(Z)
key.line(at(41, r"T(t,s,\dot{s}) &= \frac{1}{2} m"), r"T(t,s,\dot{s}) = \frac{1}{2} m \left({v_x}^2 + {v_y}^2 + {v_z}^2\right)",
         "claim", same(m / 2 * (vx ** 2 + vy ** 2 + vz ** 2), T), "the kinetic energy of the bead")
T2 = m / 2 * (d(s) ** 2 + (sp.pi ** 2 * d_ ** 2 * h ** 2 * d(s) ** 2) * (sp.sin(phi) ** 2 + sp.cos(phi) ** 2))
key.line(at(42, r"&= \frac{1}{2} m \left( \dot{s}^2 + \left( \pi^2 d^2 h^2"),
         r"= \frac{1}{2} m \left( \dot{s}^2 + \left( \pi^2 d^2 h^2 \dot{s}^2 \right) (\sin^2{2 \pi h s} + \cos^2{2 \pi h s}) \right)",
         "claim", same(T2, T), "the velocities of lines 31-33 squared")
T3 = m / 2 * d(s) ** 2 * (1 + sp.pi ** 2 * d_ ** 2 * h ** 2)
key.line(at(43, r"&= \frac{1}{2} m \dot{s}^2 \left( 1 + \pi^2 d^2 h^2 \right)"),
         r"= \frac{1}{2} m \dot{s}^2 \left( 1 + \pi^2 d^2 h^2 \right)", "claim", same(T3, T), "sin² + cos² = 1")

key.line(at(50, r"V(t,s,\dot{s}) = mgy(t) = m g \frac{d}{2} \cos{2 \pi h s}"),
         r"V(t,s,\dot{s}) = mgy(t) = m g \frac{d}{2} \cos{2 \pi h s}", "claim",
         same(m * g * Y, V) and same(m * g * d_ / 2 * sp.cos(phi), V), "gravity, with y the height (up)")

rhs_text = d_ * g * h * sp.pi * sp.sin(2 * sp.pi * h * s) / (d_ ** 2 + h ** 2 + sp.pi ** 2 + 1)
rhs_fix = d_ * g * h * sp.pi * sp.sin(2 * sp.pi * h * s) / (1 + sp.pi ** 2 * d_ ** 2 * h ** 2)
assert mech.on_motion(d(s, 2), rhs_fix)
key.line(at(60, r"\ddot{s} = \frac{dgh\pi"), r"\ddot{s} = \frac{dgh\pi \sin{\left( 2\pi h s \right)}} { d^2  + h^2  +  \pi^2 + 1 }",
         "claim", mech.on_motion(d(s, 2), rhs_text),
         "the denominator is the factor 1 + π² d² h² of T (line 43), not 1 + π² + d² + h²: the coded T summed the "
         "squares instead of multiplying them, and the printed equation of line 55 carries that",
         correct=r"\ddot{s} = \frac{dgh\pi \sin{\left( 2\pi h s \right)}} { 1 + \pi^2 d^2 h^2 }")

key.emit()
