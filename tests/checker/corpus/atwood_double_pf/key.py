"""Answer key: double Atwood machine, two pulleys and three masses (Physics Forums thread, post by erobz)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from keylib import *  # noqa: E402,F401,F403

TEXT = derivation_lines(HERE)
at = locator(TEXT)


l1, l2 = coords("l_1", "l_2")
m1, m2, M, g, Lr, S = sp.symbols("m_1 m_2 M g L S", positive=True)
l1d, l2d, l1dd, l2dd = d(l1), d(l2), d(l1, 2), d(l2, 2)

# Own kinematics (depths below the fixed pulley): m1 at l1; movable pulley at Lr - l1; m2 at (Lr - l1) + l2;
# M at (Lr - l1) + (S - l2).
z1, zp = l1, Lr - l1
z2, zM = zp + l2, zp + S - l2
T = (m1 * sp.diff(z1, t) ** 2 + m2 * sp.diff(z2, t) ** 2 + M * sp.diff(zM, t) ** 2) / 2
U = -g * (m1 * z1 + m2 * z2 + M * zM)
Lag = T - U
mech = Mechanics(Lag, [l1, l2])
mech0 = Mechanics(Lag.subs(m1, 0), [l1, l2])    # the limit m_1 = 0 the post looks at

key = Key("https://www.physicsforums.com/threads/problem-with-two-pulleys-and-three-masses.1046233/page-4",
          "double Atwood machine (massless pulleys)", "Q&A thread (forum)")

key.line(at(r"$$\mathcal{L} = T - U $$"), r"\mathcal{L} = T - U", "definition", None, "the Lagrangian")
L_text = (m1 * l1d**2 + m2 * (l2d - l1d) ** 2 + M * (l1d + l2d) ** 2) / 2 \
    + m1 * g * l1 + m2 * g * (Lr - l1 + l2) + M * g * (Lr - l1 + S - l2)
key.line(at(r"$$ \mathcal{L} = \frac{1}{2} m_1 { \dot l_1 }^2"),
         r"\mathcal{L} = \frac{1}{2} m_1 { \dot l_1 }^2+ \frac{1}{2} m_2 \left( { \dot l_2}- {\dot l_1 } \right)^2 + \frac{1}{2} M \left( {\dot l_1}+ {\dot l_2} \right) ^2 + m_1 g l_1 + m_2 g ( L - l_1 + l_2) + M g ( L - l_1 + S - l_2 )",
         "claim", same(L_text, Lag), "T - U with depths measured downward")
key.line(at(r"\frac{ \partial \mathcal{L} }{ \partial l_1 } ="),
         r"\frac{ \partial \mathcal{L} }{ \partial l_1 } = \frac{d}{dt} \frac{ \partial \mathcal{L} }{ \partial \dot{l_1} }",
         "claim", mech.on_motion(sp.diff(Lag, l1), sp.diff(sp.diff(Lag, l1d), t)), "the Euler-Lagrange equation for l_1")
key.line(at(r"$$ ( m_1 - m_2 -M ) g ="),
         r"( m_1 - m_2 -M ) g = \left ( m_1 + m_2+M \right) \ddot {l_1} + \left( M - m_2\right) \ddot {l_2}", "claim",
         mech.on_motion((m1 - m2 - M) * g, (m1 + m2 + M) * l1dd + (M - m2) * l2dd), "the l_1 equation worked out")
key.line(at(r"\ddot{l_1} = \frac{(m_1 -m_2 -M)g"),
         r"\ddot{l_1} = \frac{(m_1 -m_2 -M)g - (M-m_2) \ddot{l_2}}{m_1 + m_2 + M} \tag{1}", "claim",
         mech.on_motion(l1dd, ((m1 - m2 - M) * g - (M - m2) * l2dd) / (m1 + m2 + M)), "solved for lddot_1")
key.line(at(r"\frac{ \partial \mathcal{L} }{ \partial l_2 } ="),
         r"\frac{ \partial \mathcal{L} }{ \partial l_2 } = \frac{d}{dt} \frac{ \partial \mathcal{L} }{ \partial \dot{l_2} }",
         "claim", mech.on_motion(sp.diff(Lag, l2), sp.diff(sp.diff(Lag, l2d), t)), "the Euler-Lagrange equation for l_2")
key.line(at(r"$$( m_2 -M ) g ="),
         r"( m_2 -M ) g = \left( M - m_2 \right) \ddot{l_1} + \left( M+m_2 \right) \ddot{l_2} \tag{2}", "claim",
         mech.on_motion((m2 - M) * g, (M - m2) * l1dd + (M + m2) * l2dd), "the l_2 equation worked out")
l2dd_text = 2 * m1 * (m2 - M) / (m1 * M + m1 * m2 + 2 * M * m2) * g
ok3 = mech.on_motion(l2dd, l2dd_text)
l2dd_true = sp.factor(mech.accelerations[l2dd])
key.line(at(r"$$\ddot{l_2} = \frac{ 2m_1(m_2 - M) }"),
         r"\ddot{l_2} = \frac{ 2m_1(m_2 - M) }{m_1M + m_1 m_2 + 2 M m_2}g \tag{3}", "claim", ok3,
         "(1) put into (2)" if ok3 else
         f"(1) put into (2) gives lddot_2 = {sp.sstr(l2dd_true)}: the denominator is m_1 M + m_1 m_2 + 4 M m_2, "
         "not 2 M m_2 (an algebra slip in the reduction; the m_1 = 0 limit below is unaffected)",
         None if ok3 else r"\ddot{l_2} = \frac{ 2m_1(m_2 - M) }{m_1M + m_1 m_2 + 4 M m_2}g")
ll = at(r"For ##m_1 = 0 ##")
key.line(ll, r"m_1 = 0", "condition", None, "the limiting case examined")
key.line(ll, r"\ddot {l_2} = 0g", "limit", mech0.on_motion(l2dd, 0), "with m_1 = 0 the movable pulley's rope does not move relative to it")
key.line(ll, r"\ddot{l_1} = -g", "limit", mech0.on_motion(l1dd, -g), "with m_1 = 0 the lower system falls freely")
key.emit()
