"""Answer key of coupled_triatomic (SymPy only): the linear triatomic molecule (CO2) of the Oscillators.jl notebook,
its equations of motion, characteristic equation, frequencies and normal modes."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from keylib import *  # noqa: E402,F401,F403

M, m, k, w = sp.symbols("M m k omega", positive=True)
W2 = sp.Symbol("W2")                              # omega^2 as an unknown of the characteristic equation
x1, x2, x3 = xs = coords("x1", "x2", "x3")
A1, A2, A3 = A = sp.symbols("A1:4")

# Own model: O (mass M) - C (mass m) - O (mass M) on a line, two bonds k; displacements from the rest places.
masses = [M, m, M]
T = sum(mi / 2 * d(xi) ** 2 for mi, xi in zip(masses, xs))
V = k / 2 * (x2 - x1) ** 2 + k / 2 * (x3 - x2) ** 2
mech = Mechanics(T - V, list(xs))
q = sp.symbols("q1:4")
Kmat = sp.hessian(V.subs(dict(zip(xs, q))), q)
Mmat = sp.diag(*masses)
D = lambda om2: Kmat - om2 * Mmat  # noqa: E731  the dynamical matrix at omega^2
charpoly = sp.expand(D(W2).det())
roots = sp.solve(charpoly, W2)
w1s, w2s, w3s = 0, k / M, k * (1 + 2 * M / m) / M
assert set(sp.simplify(r) for r in roots) == {0, sp.simplify(w2s), sp.simplify(w3s)}

_TEXT = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "derivation.md"), encoding="utf-8").read().split("\n")


def at(n, fragment):
    """Line n of derivation.md, checked to hold the fragment (so that a line number cannot silently drift)."""
    assert fragment in _TEXT[n - 1], (n, fragment, _TEXT[n - 1])
    return n


def proportional(a, b):
    """The linear forms a and b (in the amplitudes) are the same equation a = 0, b = 0: a = c b, c free of A."""
    a, b = sp.expand(a), sp.expand(b)
    if b == 0:
        return a == 0
    ratio = sp.simplify(a / b)
    return ratio != 0 and not ratio.has(*A)


def row_of(om2, j):
    """Row j of the dynamical matrix times the amplitudes: the j-th equation of the mode at omega^2."""
    return sum(D(om2)[j, i] * A[i] for i in range(3))


def is_mode(om2, vec):
    return all(sp.simplify(e) == 0 for e in D(om2) * sp.Matrix(vec))


key = Key("https://github.com/KahaanGandhi/Oscillators.jl/blob/18e30e6e04afd7892baf2352edac786a5731fe72/"
          "mass-systems/3-TriatomicMolecule.ipynb", "linear triatomic molecule (CO2), normal modes", "notebook")

# Newton's law, lines 9-11 (m_1 = m_3 = M, m_2 = m: the text's own renaming of line 48)
key.line(at(9, r"m_1 \ddot{x_1} &= k(x_2 - x_1)"), r"m_1 \ddot{x_1} = k(x_2 - x_1)", "claim",
         mech.on_motion(M * d(x1, 2), k * (x2 - x1)), "the left oxygen, pulled by the left bond")
key.line(at(10, r"m_2 \ddot{x_2} &= k(x_3 - x_2) - k(x_2 - x_1)"), r"m_2 \ddot{x_2} = k(x_3 - x_2) - k(x_2 - x_1)", "claim",
         mech.on_motion(m * d(x2, 2), k * (x3 - x2) - k * (x2 - x1)), "the carbon, between the two bonds")
key.line(at(11, r"m_3 \ddot{x_3} &= -k(x_3 - x_2)"), r"m_3 \ddot{x_3} = -k(x_3 - x_2)", "claim",
         mech.on_motion(M * d(x3, 2), -k * (x3 - x2)), "the right oxygen")

key.line(at(14, r"$ x_j = A_j e^{i \omega t}$"), r"x_j = A_j e^{i \omega t}", "trial", None, "the normal-mode ansatz")
key.line(at(14, r"$j = (1,2,3)$"), r"j = (1,2,3)", "definition", None, "the mass index")

E = sp.exp(sp.I * w * t)
key.line(at(17, r"x_j &= A_j e^{i \omega t}"), r"x_j = A_j e^{i \omega t}", "trial", None, "the ansatz again")
key.line(at(18, r"\dot{x_j} &= i \omega A_j e^{i \omega t}"), r"\dot{x_j} = i \omega A_j e^{i \omega t}", "claim",
         same(sp.diff(A1 * E, t), sp.I * w * A1 * E), "d/dt of the ansatz")
key.line(at(19, r"\ddot{x_j}&= -\omega^2 A_j e^{i \omega t}"), r"\ddot{x_j} = -\omega^2 A_j e^{i \omega t}", "claim",
         same(sp.diff(A1 * E, t, 2), -w ** 2 * A1 * E), "d²/dt² of the ansatz")

# lines 25-27: the ansatz put into the equations of motion (the text's w in e^{iwt} is its omega)
trial = {x1: A1 * E, x2: A2 * E, x3: A3 * E}
eom = [M * d(x1, 2) - k * (x2 - x1), m * d(x2, 2) - k * (x3 - x2) + k * (x2 - x1), M * d(x3, 2) + k * (x3 - x2)]
subst = [sp.expand(e.subs({d(xi, 2): sp.diff(v, t, 2) for xi, v in trial.items()}).subs(trial).doit()) for e in eom]
text25 = M * (-w ** 2 * A1 * E) - k * (A2 * E - A1 * E)
text26 = m * (-w ** 2 * A2 * E) - (k * (A3 * E - A2 * E) - k * (A2 * E - A1 * E))
text27 = M * (-w ** 3 * A3 * E) - (-k * (A3 * E - A2 * E))
key.line(at(25, r"m_1(-\omega^2 A_1 e^{iwt})"), r"m_1(-\omega^2 A_1 e^{iwt}) = k (A_2 e^{iwt} - A_1 e^{iwt})", "claim",
         same(text25, subst[0]), "the first equation with the ansatz (e^{iwt} is the text's e^{iωt})")
key.line(at(26, r"m_2(-\omega^2 A_2 e^{iwt})"),
         r"m_2(-\omega^2 A_2 e^{iwt}) = k (A_3 e^{iwt} - A_2 e^{iwt}) - k (A_2 e^{iwt} - A_1 e^{iwt})", "claim",
         same(text26, subst[1]), "the second equation with the ansatz")
key.line(at(27, r"m_3(-\omega^3 A_3 e^{iwt})"), r"m_3(-\omega^3 A_3 e^{iwt}) = -k (A_3 e^{iwt} - A_2 e^{iwt})", "claim",
         same(text27, subst[2]), "ω³ where ẍ₃ gives ω² (line 19): a typo",
         correct=r"m_3(-\omega^2 A_3 e^{iwt}) = -k (A_3 e^{iwt} - A_2 e^{iwt})")

# lines 33-35: the amplitude equations (rows of (K - omega^2 M) A = 0)
W = w ** 2
key.line(at(33, r"(-m_1 \omega^2 + k)A_1 - kA_2 + 0 \cdot A_3 &= 0"), r"(-m_1 \omega^2 + k)A_1 - kA_2 + 0 \cdot A_3 = 0",
         "claim", proportional((-M * W + k) * A1 - k * A2, row_of(W, 0)), "the first row")
key.line(at(34, r"kA_1 + (-m_2 \omega^2 + 2k)A_2 - kA_3 &= 0"), r"kA_1 + (-m_2 \omega^2 + 2k)A_2 - kA_3 = 0", "claim",
         proportional(k * A1 + (-m * W + 2 * k) * A2 - k * A3, row_of(W, 1)),
         "the A₁ term has the wrong sign: the middle equation of line 26 gives −k A₁ after collecting (the matrix of "
         "line 42 has it right)",
         correct=r"-kA_1 + (-m_2 \omega^2 + 2k)A_2 - kA_3 = 0")
key.line(at(35, r"0 \cdot A_1 - kA_2 + (-m_3 \omega^2 + k) &= 0"), r"0 \cdot A_1 - kA_2 + (-m_3 \omega^2 + k) = 0",
         "claim", proportional(-k * A2 + (-M * W + k), row_of(W, 2)),
         "the factor A₃ of the last term is missing",
         correct=r"0 \cdot A_1 - kA_2 + (-m_3 \omega^2 + k)A_3 = 0")

Mtext = sp.Matrix([[-M * W + k, -k, 0], [-k, -m * W + 2 * k, -k], [0, -k, -M * W + k]])
key.line(at(46, r"\end{bmatrix} = 0"), r"\begin{bmatrix} -m_1\omega^2+k & -k & 0 \\ \dots \end{bmatrix} "
         r"\begin{bmatrix} A_1 \\ A_2 \\ A_3 \end{bmatrix} = 0", "claim", (Mtext - D(W)).is_zero_matrix,
         "the dynamical matrix K − ω² M (with the right sign of the A₁ entry of row 2)")

key.line(at(48, r"$m_1 = m_3 = M$"), r"m_1 = m_3 = M", "given", None, "the oxygen masses")
key.line(at(48, r"$m_2 = m$"), r"m_2 = m", "given", None, "the carbon mass")

key.line(at(54, r"\end{bmatrix} \right) = 0"), r"det\left(\begin{bmatrix} -M\omega^2+k & -k & 0 \\ \dots \end{bmatrix} "
         r"\right) = 0", "claim", (Mtext - D(W)).is_zero_matrix, "the characteristic equation")
exp57 = (-M * W + k) * ((-m * W + 2 * k) * (-M * W + k) - k ** 2) + k * (-k * (-M * W + k))
key.line(at(57, r"(-M\omega^2 + k)\left( (-m\omega^2 + 2k)"),
         r"(-M\omega^2 + k)\left( (-m\omega^2 + 2k)(-M\omega^2 + k) - k^2\right)+k\left( -k(-M\omega^2 + k \right)) = 0",
         "claim", same(exp57, D(W).det()),
         "the determinant expanded along the first row (a parenthesis misplaced in the typesetting: "
         "k(−k(−Mω² + k)) is meant)")
fac60 = (-m * W) * (-M * W + k) * (-M * W + k * (1 + 2 * M / m))
key.line(at(60, r"(-m\omega^2)(-M\omega^2 + k)"),
         r"(-m\omega^2)(-M\omega^2 + k)\left(-M\omega^2 + k\left(1+\frac{2M}{m}\right)\right) = 0", "claim",
         same(fac60, D(W).det()), "the determinant factored")

key.line(at(64, r"\omega_1^2 = 0,"), r"\omega_1^2 = 0", "claim", 0 in roots, "the translation of the whole molecule")
key.line(at(64, r"\omega_2^2 = \frac{k}{M}"), r"\omega_2^2 = \frac{k}{M}", "claim",
         any(same(r, w2s) for r in roots), "a root of the characteristic equation")
key.line(at(64, r"\omega_3^2 = \frac{k(1 + \frac{2M}{m}}{M}"), r"\omega_3^2 = \frac{k(1 + \frac{2M}{m})}{M}", "claim",
         any(same(r, w3s) for r in roots), "a root of the characteristic equation (a parenthesis unclosed in the typesetting)")
key.line(at(67, r"\omega_1 = 0,"), r"\omega_1 = 0", "claim", 0 in roots, "the square root of ω₁²")
key.line(at(67, r"\omega_2 = \sqrt{\frac{k}{M}}"), r"\omega_2 = \sqrt{\frac{k}{M}}", "claim",
         any(same(r, sp.sqrt(k / M) ** 2) for r in roots), "the square root of ω₂²")
key.line(at(67, r"\omega_3 = \sqrt{\frac{k \left(1 + \frac{2M}{m}\right)}{M}}"),
         r"\omega_3 = \sqrt{\frac{k \left(1 + \frac{2M}{m}\right)}{M}}", "claim",
         any(same(r, w3s) for r in roots), "the square root of ω₃²")

# mode 1
key.line(at(69, r"$\omega_1^2 = 0$"), r"\omega_1^2 = 0", "condition", None, "the first mode")
M1 = sp.Matrix([[k, -k, 0], [-k, 2 * k, -k], [0, -k, k]])
key.line(at(76, r"A_1 \\ A_2 \\ A_3 \end{bmatrix} = 0"), r"\begin{bmatrix} k & -k & 0 \\ -k & 2k & -k \\ 0 & -k & k "
         r"\end{bmatrix}\begin{bmatrix} A_1 \\ A_2 \\ A_3 \end{bmatrix} = 0", "claim", (M1 - D(0)).is_zero_matrix,
         "the dynamical matrix at ω² = 0 (the stiffness matrix)")
key.line(at(80, r"kA_1 - kA_2 &= 0 \quad (1)"), r"kA_1 - kA_2 = 0", "claim", proportional(k * A1 - k * A2, row_of(0, 0)), "row 1")
key.line(at(81, r"-kA_1 + 2kA_2 - kA_3 &= 0 \quad (2)"), r"-kA_1 + 2kA_2 - kA_3 = 0", "claim",
         proportional(-k * A1 + 2 * k * A2 - k * A3, row_of(0, 1)), "row 2")
key.line(at(82, r"-kA_2 + kA_3 &= 0 \quad (3)"), r"-kA_2 + kA_3 = 0", "claim", proportional(-k * A2 + k * A3, row_of(0, 2)), "row 3")
key.line(at(83, r"e_1 = \begin{bmatrix} 1 \\ 1 \\1 \end{bmatrix}"), r"e_1 = \begin{bmatrix} 1 \\ 1 \\1 \end{bmatrix}",
         "claim", is_mode(0, [1, 1, 1]), "the null vector of the stiffness matrix: a rigid translation")
e1 = {A1: 1, A2: 1, A3: 1}
key.line(at(85, r"$A_1 = A_2$"), r"A_1 = A_2", "claim", e1[A1] == e1[A2], "from row 1 of mode 1")
key.line(at(85, r"$A_2 = A_3$"), r"A_2 = A_3", "claim", e1[A2] == e1[A3], "from row 3 of mode 1")
key.line(at(85, r"$A_1 = A_2 = A_3$"), r"A_1 = A_2 = A_3", "claim", is_mode(0, [1, 1, 1]), "the first mode's amplitudes")

# mode 2
key.line(at(87, r"$\omega_2^2 = \frac{k}{M}$"), r"\omega_2^2 = \frac{k}{M}", "condition", None, "the second mode")
M2a = sp.Matrix([[-M * (k / M) + k, -k, 0], [-k, -m * (k / M) + 2 * k, -k], [0, -k, -M * (k / M) + k]])
M2b = sp.Matrix([[0, -k, 0], [-k, k * (2 - m / M), -k], [0, -k, 0]])
key.line(at(97, r"= \begin{bmatrix}"), r"\begin{bmatrix} -M\left(\frac{k}{M}\right)+k & \dots \end{bmatrix} "
         r"\begin{bmatrix} A_1 \\ A_2 \\ A_3 \end{bmatrix} = \begin{bmatrix} 0 & -k & 0 \\ \dots \end{bmatrix} "
         r"\begin{bmatrix} A_1 \\ A_2 \\ A_3 \end{bmatrix}", "claim", sp.simplify(M2a - M2b).is_zero_matrix,
         "the entries simplified")
key.line(at(104, r"\end{bmatrix} = 0"), r"\begin{bmatrix} 0 & -k & 0 \\ -k & k\left(2 - \frac{m}{M}\right) & -k \\ "
         r"0 & -k & 0 \end{bmatrix} \begin{bmatrix} A_1 \\ A_2 \\ A_3 \end{bmatrix} = 0", "claim",
         sp.simplify(M2b - D(w2s)).is_zero_matrix, "the dynamical matrix at ω² = k/M")
key.line(at(108, r"-kA_2 &= 0 \quad (1)"), r"-kA_2 = 0", "claim", proportional(-k * A2, row_of(w2s, 0)), "row 1")
key.line(at(109, r"-kA_1 + k\left(2 - \frac{m}{M}\right)A_2 - kA_3 &= 0"), r"-kA_1 + k\left(2 - \frac{m}{M}\right)A_2 - kA_3 = 0",
         "claim", proportional(-k * A1 + k * (2 - m / M) * A2 - k * A3, row_of(w2s, 1)), "row 2")
key.line(at(110, r"-kA_2 &= 0 \quad (3)"), r"-kA_2 = 0", "claim", proportional(-k * A2, row_of(w2s, 2)), "row 3")
key.line(at(111, r"e_2 = \begin{bmatrix} 1 \\ 0 \\ -1 \end{bmatrix}"), r"e_2 = \begin{bmatrix} 1 \\ 0 \\ -1 \end{bmatrix}",
         "claim", is_mode(w2s, [1, 0, -1]), "the oxygens against each other, the carbon at rest")
key.line(at(113, r"$A_2 = 0$"), r"A_2 = 0", "claim", is_mode(w2s, [1, 0, -1]), "from rows 1 and 3 of mode 2")
key.line(at(113, r"$-kA_1 - kA_3 = 0$"), r"-kA_1 - kA_3 = 0", "claim",
         proportional(-k * A1 - k * A3, row_of(w2s, 1).subs(A2, 0)), "row 2 with A₂ = 0")
key.line(at(113, r"$A_1 = -A_3$"), r"A_1 = -A_3", "claim", is_mode(w2s, [1, 0, -1]), "the second mode's amplitudes")

# mode 3
key.line(at(116, r"$\omega_3^2 = \frac{k(1 + \frac{2M}{m})}{M}$"), r"\omega_3^2 = \frac{k(1 + \frac{2M}{m})}{M}", "condition",
         None, "the third mode")
M3 = sp.Matrix([[-k * (1 + 2 * M / m), -k, 0], [-k, -k * (1 + 2 * M / m), -k], [0, -k, -k * (1 + 2 * M / m)]])
assert sp.simplify(D(w3s) - sp.Matrix([[-2 * k * M / m, -k, 0], [-k, -k * m / M, -k], [0, -k, -2 * k * M / m]])).is_zero_matrix
key.line(at(127, r"= 0"), r"\begin{bmatrix} -k(1+\frac{2M}{m}) & -k & 0 \\ -k & -k(1+\frac{2M}{m}) & -k \\ 0 & -k & "
         r"-k(1+\frac{2M}{m}) \end{bmatrix} \begin{bmatrix} A_1 \\ A_2 \\ A_3 \end{bmatrix} = 0", "claim",
         sp.simplify(M3 - D(w3s)).is_zero_matrix,
         "the diagonal entries are −k(1 + 2M/m) = −M ω₃² throughout, but they are −M ω₃² + k = −2kM/m (the +k dropped) "
         "and, in the middle, −m ω₃² + 2k = −km/M",
         correct=r"\begin{bmatrix} -\frac{2kM}{m} & -k & 0 \\ -k & -\frac{km}{M} & -k \\ 0 & -k & -\frac{2kM}{m} "
         r"\end{bmatrix} \begin{bmatrix} A_1 \\ A_2 \\ A_3 \end{bmatrix} = 0")
c3 = 1 + 2 * M / m
key.line(at(131, r"-k\left(1+\frac{2M}{m}\right)A_1 - kA_2 &= 0"), r"-k\left(1+\frac{2M}{m}\right)A_1 - kA_2 = 0", "claim",
         proportional(-k * c3 * A1 - k * A2, row_of(w3s, 0)), "row 1 of the wrong matrix of line 127",
         correct=r"-\frac{2kM}{m}A_1 - kA_2 = 0")
key.line(at(132, r"-kA_1 - k\left(1+\frac{2M}{m}\right)A_2 - kA_3 &= 0"),
         r"-kA_1 - k\left(1+\frac{2M}{m}\right)A_2 - kA_3 = 0", "claim",
         proportional(-k * A1 - k * c3 * A2 - k * A3, row_of(w3s, 1)), "row 2 of the wrong matrix of line 127",
         correct=r"-kA_1 - \frac{km}{M}A_2 - kA_3 = 0")
key.line(at(133, r"-kA_2 - k\left(1+\frac{2M}{m}\right)A_3 &= 0"), r"-kA_2 - k\left(1+\frac{2M}{m}\right)A_3 = 0", "claim",
         proportional(-k * A2 - k * c3 * A3, row_of(w3s, 2)), "row 3 of the wrong matrix of line 127",
         correct=r"-kA_2 - \frac{2kM}{m}A_3 = 0")
e3_text = [-1 / c3, 1, -1 / c3]
assert is_mode(w3s, [-m / (2 * M), 1, -m / (2 * M)])
key.line(at(134, r"\rightarrow e_3 = \begin{bmatrix}"), r"e_3 = \begin{bmatrix} -\frac{1}{1+\frac{2M}{m}} \\ 1 \\ "
         r"-\frac{1}{1+\frac{2M}{m}} \end{bmatrix}", "claim", is_mode(w3s, e3_text),
         "follows the wrong matrix: the outer amplitudes are −m/(2M) of the middle one (momentum: 2M A₁ + m A₂ = 0), "
         "not −m/(m + 2M); numerically −0.375, not the −0.2725 the notebook prints",
         correct=r"e_3 = \begin{bmatrix} -\frac{m}{2M} \\ 1 \\ -\frac{m}{2M} \end{bmatrix}")
key.line(at(141, r"$A_1 = -\frac{1}{1+\frac{2M}{m}} A_2$"), r"A_1 = -\frac{1}{1+\frac{2M}{m}} A_2", "claim",
         is_mode(w3s, e3_text), "from the wrong row 1 of line 131", correct=r"A_1 = -\frac{m}{2M} A_2")
key.line(at(141, r"$A_3 = -\frac{1}{1+\frac{2M}{m}} A_2$"), r"A_3 = -\frac{1}{1+\frac{2M}{m}} A_2", "claim",
         is_mode(w3s, e3_text), "from the wrong row 3 of line 133", correct=r"A_3 = -\frac{m}{2M} A_2")

key.line(at(143, r"$m = 1.993 \cdot 10^{-26} kg$"), r"m = 1.993 \cdot 10^{-26} kg", "given", None, "the carbon-12 mass")
key.line(at(143, r"$M = 2.66\cdot 10^{-26}kg$"), r"M = 2.66\cdot 10^{-26}kg", "given", None, "the oxygen-16 mass")
key.line(at(143, r"$k=3628 N/m$"), r"k=3628 N/m", "given", None, "the bond stiffness")

key.emit()
