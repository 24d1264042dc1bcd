"""Answer key: falling yo-yo (helpwithphysics.com). SymPy only.

The page's math was pasted from a word processor: "(x^2 ) \u0307" is its x-dot squared (the dot of the time derivative
is a combining character after a space), "x \u0307" is x-dot, "x \u0308" is x-double-dot; "frac{..}{..}" lacks its
backslash. The key reads them as the author meant them and says so where it matters.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F403

m, R0, R, k, g = sp.symbols("m R_0 R k g", positive=True)
x = coords("x")

# Own kinematics: the centre falls x; the string unwinds from the axle, so omega = x'/R0; I = m k^2 (k the radius of
# gyration, a length).
I = m * k**2
v, omega = d(x), d(x) / R0
T = sp.Rational(1, 2) * m * v**2 + sp.Rational(1, 2) * I * omega**2
V = -m * g * x
mech = Mechanics(T - V, [x])
acc = mech.accelerations[d(x, 2)]

key = Key("https://www.helpwithphysics.com/2016/03/yo-yo-physics.html", "yo-yo falling as its string unwinds from the axle",
          "tutorial blog post (math pasted from a word processor)")
key.line(8, r"L=T-U", "definition", None, "the Lagrangian")
key.line(10, r"T=T_{rotation}+T_{translation}=(I\omega^2)/2+(m v^2)/2=I/(2(R_0)^2 )*\dot{x}^2+m/2*\dot{x}^2", "claim",
         same(I * omega**2 / 2 + m * v**2 / 2, T) and same(I / (2 * R0**2) * d(x)**2 + m / 2 * d(x)**2, T),
         "rotation about the centre plus translation, omega = x'/R_0; '(x^2 ) \u0307' read as x-dot squared (a dot over x^2)")
key.line(12, r"\dot{x}=dx/dt(=v=\omega R_0)", "kinematics", same(d(x), omega * R0),
         "the string unwinds from the axle without slipping")
key.line(13, r"U=+mgh=-mgx", "claim", same(-m * g * x, V), "h = -x is the height (x is the distance fallen)")
key.line(15, r"L(x,\dot{x},t)=(I/(2R_0^2 )+m/2)*\dot{x}^2+mgx", "claim",
         same((I / (2 * R0**2) + m / 2) * d(x)**2 + m * g * x, mech.L), "T - U")
key.line(17, r"(d/dt) (\partial L/(\partial \dot{x} )=\partial L/\partial x", "claim",
         mech.on_motion(sp.diff(sp.diff(mech.L, d(x)), t), sp.diff(mech.L, x)),
         "Euler-Lagrange equation (one parenthesis is not closed on the page)")
key.line(18, r"(d/dt) [(I/(R_0^2 )+m) \dot{x} ]=mg", "claim",
         mech.on_motion(sp.diff((I / R0**2 + m) * d(x), t), m * g), "the equation of motion, with I = m k^2")
key.line(19, r"a=\ddot{x}=\frac{mg}{m+I/(R_0^2 )}", "claim", same(acc, m * g / (m + I / R0**2)),
         "a = x'' solved from the equation of motion ('frac' without its backslash on the page)")
key.line(19, r"\frac{mg}{m+I/(R_0^2 )}=\frac{mg}{(m+(k^2 mR^2)/(R_0^2 )}", "claim",
         same(m * g / (m + I / R0**2), m * g / (m + k**2 * m * R**2 / R0**2)),
         "uses I = m(kR)^2; with k the radius of gyration (a length, as the problem says) I = m k^2",
         correct=r"\frac{mg}{m+I/(R_0^2 )}=\frac{mg}{m+(k^2 m)/(R_0^2 )}")
key.line(19, r"\frac{mg}{(m+(k^2 mR^2)/(R_0^2 )}=\frac{g}{1+(kR/R_0 )^2}", "claim",
         same(m * g / (m + k**2 * m * R**2 / R0**2), g / (1 + (k * R / R0)**2)),
         "algebra of the previous side (right); the result carries its slip: a = g/(1 + (k/R_0)^2)")
key.line(20, r"I=m(kR)^2", "definition", same(I, m * (k * R)**2),
         "contradicts the problem: the radius of gyration k is defined by I = m k^2 (k a length); I = m(kR)^2 treats k as a fraction of R",
         correct=r"I=mk^2")
key.emit()
