/** @file not_equal.cpp  `a \neq b`: a claim that two expressions differ. It holds where they are not identically
 * equal (`I_{p}'(\theta) \neq 0` for the half hoop, whose moment about the contact point changes with θ), and is
 * false where they are one expression written twice. A name against a number (`\theta \neq 0`) is a condition, as
 * for the other inequalities (compare_link.cpp). */
#include "checker/checker_internals.hpp"

namespace eomgen::checker::detail {

void Checker::check_not_equal(const PSide& L, const PSide& R, EquationCheck& r) {
    const Prepared a = prepare(L), b = prepare(R);
    if (!a.ok || !b.ok) {
        r.reason = !a.ok ? a.problem : b.problem;
        return;
    }
    if (!a.comparable() || !b.comparable()) {
        std::string names;
        for (const Prepared* p : {&a, &b})
            for (const FreeName* f : p->unknown.empty() ? p->vectors : p->unknown)
                if (names.find(m(f->name)) == std::string::npos) names += (names.empty() ? "" : ", ") + m(f->name);
        r.reason = "a relation \\neq between sides that use " + names + ", which the model does not know, is not compared";
        return;
    }
    for (const Prepared* p : {&a, &b}) r.notes.insert(r.notes.end(), p->notes.begin(), p->notes.end());
    const double tol = std::max(1e-9, L.side->rounding + R.side->rounding);
    switch (equal(a.value, b.value, tol)) {
    case Tri::No:
        r.verdict = Verdict::Agrees;
        r.compared_with = "the two sides";
        r.reason = "they are not identically equal, as the text says";
        return;
    case Tri::Yes:
        r.verdict = Verdict::Disagrees;
        r.compared_with = "the two sides";
        r.reason = "they are identically equal, so \\neq does not hold";
        r.wrong_terms = {"the two sides are the same expression: " + m(latex(a.value)) + " on either"};
        return;
    case Tri::Unknown:
        r.reason = "could not decide whether the two sides are identically equal";
        return;
    }
}

}  // namespace eomgen::checker::detail
