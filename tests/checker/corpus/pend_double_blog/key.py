"""Answer key of pend_double_blog (SymPy only): the plane double pendulum of the Ars Numerandi post."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

m1, m2, l1, l2, g = sp.symbols("m_1 m_2 l_1 l_2 g", positive=True)
th1, th2 = coords("theta1", "theta2")
s, c = sp.sin, sp.cos

# Own kinematics: pivot at the origin, y upward, angles from the downward vertical.
X1, Y1 = l1 * s(th1), -l1 * c(th1)
X2, Y2 = X1 + l2 * s(th2), Y1 - l2 * c(th2)
T = m1 / 2 * (d(X1) ** 2 + d(Y1) ** 2) + m2 / 2 * (d(X2) ** 2 + d(Y2) ** 2)
V = m1 * g * Y1 + m2 * g * Y2
L = T - V
mech = Mechanics(L, [th1, th2])

key = Key("http://arsnumerandi.com/post/11/", "plane double pendulum (point masses)", "blog post")

# line 7: x_1, y_1
key.line(7, r"x_1=l_1\sin\left(\theta_1\right)", "kinematics", same(l1 * s(th1), X1), "the upper mass, pivot at the origin")
key.line(7, r"y_1=-l_1\cos\left(\theta_1\right)", "kinematics", same(-l1 * c(th1), Y1), "y upward, θ₁ from the downward vertical")
# line 9: x_2, y_2
key.line(9, r"x_2=l_2\sin\left(\theta_2\right)+l_1\sin\left(\theta_1\right)", "kinematics",
         same(l2 * s(th2) + l1 * s(th1), X2), "the lower mass hangs from the upper one")
key.line(9, r"y_2=-l_2\cos\left(\theta_2\right)-l_1\cos\left(\theta_1\right)", "kinematics",
         same(-l2 * c(th2) - l1 * c(th1), Y2), "the lower mass hangs from the upper one")

# line 13: L in the Cartesian velocities (with the kinematics of lines 7 and 9)
xt1, yt1 = l1 * s(th1), -l1 * c(th1)
xt2, yt2 = l2 * s(th2) + l1 * s(th1), -l2 * c(th2) - l1 * c(th1)
L_cart = (m1 * (d(xt1) ** 2 + d(yt1) ** 2) / 2 + m2 * (d(xt2) ** 2 + d(yt2) ** 2) / 2 - m1 * g * yt1 - m2 * g * yt2)
key.line(13, r"L\left(\theta_1,\dot{\theta}_1,\theta_2,\dot{\theta}_2\right)=\frac{m_1(\dot{x}_1^2+\dot{y}_1^2)}{2}+\frac{m_2(\dot{x}_2^2+\dot{y}_2^2)}{2}-m_1gy_1-m_2gy_2",
         "claim", same(L_cart, L), "T − V with the positions of lines 7 and 9")

# lines 13-15: the chain continued over three displays ("=$$ $$=" is one relation; its right side starts on line 14)
L_text = (m1 * l1 ** 2 * d(th1) ** 2 / 2
          + m2 * (l1 ** 2 * d(th1) ** 2 + l2 ** 2 * d(th2) ** 2 + 2 * l1 * l2 * c(th2 - th1) * d(th1) * d(th2)) / 2
          + (m1 + m2) * g * l1 * c(th1) + m2 * l2 * c(th2))
L_fix = L_text - m2 * l2 * c(th2) + m2 * g * l2 * c(th2)
assert same(L_fix, L)
key.line(14, r"=\frac{m_1l_1^2\dot{\theta}_1^2}{2}+\frac{m_2\left(l_1^2\dot{\theta}_1^2+l_2^2\dot{\theta}_2^2+2l_1l_2\cos\left(\theta_2-\theta_1\right)\dot{\theta}_1\dot{\theta}_2\right)}{2}+\left(m_1+m_2\right)gl_1\cos\left(\theta_1\right)+m_2l_2\cos\left(\theta_2\right)",
         "claim", same(L_text, L),
         "the last term m₂ l₂ cos θ₂ lacks g (the potential of the lower mass is −m₂ g l₂ cos θ₂); the kinetic part is right. "
         "The relation's '=' stands both at the end of line 13 and at the start of line 14; the claimed side is on lines 14-15",
         correct=r"=\frac{m_1l_1^2\dot{\theta}_1^2}{2}+\frac{m_2\left(l_1^2\dot{\theta}_1^2+l_2^2\dot{\theta}_2^2+2l_1l_2\cos\left(\theta_2-\theta_1\right)\dot{\theta}_1\dot{\theta}_2\right)}{2}+\left(m_1+m_2\right)gl_1\cos\left(\theta_1\right)+m_2gl_2\cos\left(\theta_2\right)")

# line 18: Lagrange's equation for theta_1 (of the system's L)
el1 = sp.diff(sp.diff(L, d(th1)), t) - sp.diff(L, th1)
key.line(18, r"\frac{d}{dt}\left(\frac{\partial L}{\partial{\dot{\theta}_1}}\right)-\frac{\partial L}{\partial\theta_1}=0", "claim",
         mech.on_motion(el1), "Lagrange's equation for θ₁ of the system's L (the slip of line 14 does not enter: the text's "
         "next line is derived with g in place)")
# line 19
eq1 = ((m1 + m2) * l1 ** 2 * d(th1, 2) + m2 * l1 * l2 * (-d(th2) ** 2 * s(th2 - th1) + d(th2, 2) * c(th2 - th1))
       + (m1 + m2) * g * l1 * s(th1))
key.line(19, r"(m_1+m_2)l_1^2\ddot{\theta}_1+m_2l_1l_2\left(-\dot{\theta}_2^2\sin\left(\theta_2-\theta_1\right)+\ddot{\theta}_2\cos\left(\theta_2-\theta_1\right)\right)+(m_1+m_2)gl_1\sin(\theta_1)=0",
         "claim", mech.on_motion(eq1), "the Euler–Lagrange equation for θ₁")
# line 21
el2 = sp.diff(sp.diff(L, d(th2)), t) - sp.diff(L, th2)
key.line(21, r"\frac{d}{dt}\left(\frac{\partial L}{\partial{\dot{\theta}_2}}\right)-\frac{\partial L}{\partial\theta_2}=0", "claim",
         mech.on_motion(el2), "Lagrange's equation for θ₂ of the system's L")
# line 22
eq2 = m2 * l2 * (l2 * d(th2, 2) + l1 * d(th2) ** 2 * s(th2 - th1) + l1 * d(th1, 2) * c(th2 - th1) + g * s(th2))
eq2_fix = m2 * l2 * (l2 * d(th2, 2) + l1 * d(th1) ** 2 * s(th2 - th1) + l1 * d(th1, 2) * c(th2 - th1) + g * s(th2))
assert mech.on_motion(eq2_fix)
key.line(22, r"m_2l_2\left(l_2\ddot{\theta}_2+l_1\dot{\theta}_2^2\sin\left(\theta_2-\theta_1\right)+l_1\ddot{\theta}_1\cos\left(\theta_2-\theta_1\right)+g\sin\left(\theta_2\right)\right)=0",
         "claim", mech.on_motion(eq2),
         "the centripetal term of the θ₂ equation has the upper rod's rate: l₁ θ̇₁² sin(θ₂−θ₁), not θ̇₂²",
         correct=r"m_2l_2\left(l_2\ddot{\theta}_2+l_1\dot{\theta}_1^2\sin\left(\theta_2-\theta_1\right)+l_1\ddot{\theta}_1\cos\left(\theta_2-\theta_1\right)+g\sin\left(\theta_2\right)\right)=0")

key.emit()
