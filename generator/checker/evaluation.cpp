/** @file evaluation.cpp  Sides made ready for comparison (labels, d/dt and ∂ evaluated, the text's definitions),
 * equality at random points, and whether an equation is a consequence of the Euler–Lagrange equations. */
#include "checker/checker_internals.hpp"

#include <stdexcept>

namespace eomgen::checker::detail {

// ------------------------------------------------------------------------------------------- evaluation

GiNaC::ex Checker::with_dotted_definitions(const GiNaC::ex& e) const {
    std::vector<std::string> notes;
    const GiNaC::ex v = dotted_definitions(definitions_, e, current_offset_, ctx_, model_, notes);
    for (const std::string& n : notes) add_note_once(operator_notes_, n);
    return v;
}

GiNaC::ex Checker::resolve_operators(const GiNaC::ex& e) const {
    // A name inside a derivative is its definition in the text, or the derivative cannot be evaluated.
    if (is_ex_the_function(e, ddt)) {
        // (ẋ of a name the text defines, x = A cos ωt, inside it: the derivative of its definition.)
        const GiNaC::ex inner = hamilton_.in_velocities(
            with_dotted_definitions(resolve_operators(definitions_.expand(e.op(0), current_offset_))));
        if (TextDefinitions::has_vector(inner, ctx_)) return ddt(inner);  // kept: vectors are not compared
        TextDefinitions::require_defined(inner, ctx_, "time derivative");
        // (λ̇: a multiplier changes along the motion, and is no function of the state here: not 0.)
        if (std::any_of(multipliers_.begin(), multipliers_.end(), [&](const GiNaC::symbol& l) { return inner.has(l); }))
            throw std::runtime_error("the time derivative of a constraint's multiplier is not read (it changes along "
                                     "the motion)");
        return time_derivative(inner, model_);
    }
    if (is_ex_the_function(e, pdiff)) {
        // `\frac{\partial}{\partial t}\frac{\partial L}{\partial \dot r}`: ∂/∂t of a derivative by a velocity is the
        // Euler–Lagrange equation's d/dt, written with a ∂ (as a partial by t it would be 0 there, or nearly).
        if (e.op(1).is_equal(model_.t) && is_ex_the_function(e.op(0), pdiff) &&
            std::any_of(model_.coordinates.begin(), model_.coordinates.end(),
                        [&](const Coordinate& c) { return e.op(0).op(1).is_equal(c.qd); })) {
            const std::string note = "reads $\\frac{\\partial}{\\partial t}$ of a derivative by a velocity as the "
                                     "Euler–Lagrange equation's $\\frac{d}{dt}$";
            add_note_once(operator_notes_, note);
            return resolve_operators(ddt(e.op(0)));
        }
        // By a coordinate, the text's constants of the motion (J = p_φ) are held fixed, put in after (definitions.hpp).
        GiNaC::exmap held;
        const bool by_coordinate = std::any_of(model_.coordinates.begin(), model_.coordinates.end(),
                                               [&](const Coordinate& c) { return e.op(1).is_equal(c.q); });
        const GiNaC::ex inner = with_dotted_definitions(resolve_operators(
            by_coordinate ? definitions_.expand_holding(e.op(0), current_offset_, held)
                          : definitions_.expand(e.op(0), current_offset_)));
        if (!held.empty()) {
            const GiNaC::ex d = GiNaC::diff(inner, GiNaC::ex_to<GiNaC::symbol>(e.op(1))).subs(held);
            return resolve_operators(d);
        }
        if (!GiNaC::is_a<GiNaC::symbol>(e.op(1)))
            throw std::runtime_error("a derivative with respect to an expression");
        if (const FreeName* f = ctx_.free_name_of(e.op(1)))
            throw UndefinedInDerivative(f->name, "a partial derivative with respect to $" + f->name +
                                                     "$, which is not a coordinate, a velocity or a parameter "
                                                     "of the model");
        if (TextDefinitions::has_vector(inner, ctx_)) return pdiff(inner, e.op(1));
        if (hamilton_.has_hamiltonian(inner)) return hamilton_.derivative(inner, GiNaC::ex_to<GiNaC::symbol>(e.op(1)));
        TextDefinitions::require_defined(inner, ctx_, "partial derivative");
        const GiNaC::symbol& x = GiNaC::ex_to<GiNaC::symbol>(e.op(1));
        for (const Kink& k : surfaces_without_derivative(inner, x)) kinks_.emplace_back(k, x);
        return GiNaC::diff(inner, x);
    }
    // d/ds by a name the text defines as a multiple of t (τ = t/T): (1/c) d/dt.
    if (is_ex_the_function(e, dby)) {
        // (Inside another derivative by it, the name has its definition put in already.)
        const FreeName* f = ctx_.free_name_of(e.op(1));
        const GiNaC::ex* value = definitions_.value_at(e.op(1), current_offset_);
        const GiNaC::ex by = value ? *value : e.op(1);
        const GiNaC::ex c = GiNaC::normal(by / model_.t);
        if (f && !value)
            throw UndefinedInDerivative(f->name, "a derivative with respect to $" + f->name +
                                                     "$, which the text does not define");
        if (c.is_zero() || c.has(model_.t) || depends_on_state(c) || has_acceleration(c) || ctx_.free_name_of(by))
            throw std::runtime_error("a derivative with respect to a variable the text does not define as a multiple "
                                     "of t");
        const GiNaC::ex inner = resolve_operators(definitions_.expand(e.op(0), current_offset_));
        TextDefinitions::require_defined(inner, ctx_, "derivative by a new time");
        // A change of the time variable, not a quantity the text defines: the side is compared as an equation of
        // motion, not as that definition's derivative (the uses are said in a note).
        for (const std::string& n : definitions_.take_used()) add_note_once(operator_notes_, n);
        return time_derivative(inner, model_) / c;
    }
    if (is_ex_the_function(e, limat)) {  // \lim_{x \to a} f: f at a, or its series' constant term there
        const GiNaC::ex inner = resolve_operators(e.op(0));
        const GiNaC::relational& at = GiNaC::ex_to<GiNaC::relational>(e.op(1).op(0));
        if (const std::optional<GiNaC::ex> there = subs_unless_pole(inner, GiNaC::exmap{{at.lhs(), at.rhs()}}))
            return *there;
        const GiNaC::ex s = inner.series(at, 4);
        if (!GiNaC::is_a<GiNaC::pseries>(s) || GiNaC::ex_to<GiNaC::pseries>(s).ldegree(at.lhs()) < 0)
            throw std::runtime_error("the limit is not finite (a pole at the point)");
        return GiNaC::ex_to<GiNaC::pseries>(s).coeff(at.lhs(), 0);
    }
    if (is_ex_the_function(e, evalat))  // the point of an evaluation bar, after the derivatives under it
        return resolve_operators(e.op(0)).subs(GiNaC::ex_to<GiNaC::lst>(e.op(1)));
    if (is_ex_the_function(e, pbracket))
        return hamilton_.poisson(resolve_operators(definitions_.expand(e.op(0), current_offset_)),
                                 resolve_operators(definitions_.expand(e.op(1), current_offset_)));
    if (e.nops() == 0) return e;
    // A power whose base the operators make 0 (1/\frac{d}{dt}l, l a constant): refused here, before GiNaC builds
    // it inside map() and throws from its evaluation, leaking the node (found by the sanitized fuzzer).
    if (GiNaC::is_a<GiNaC::power>(e)) {
        const GiNaC::ex base = resolve_operators(e.op(0)), exponent = resolve_operators(e.op(1));
        if (base.is_zero() && !(GiNaC::is_a<GiNaC::numeric>(exponent) && GiNaC::ex_to<GiNaC::numeric>(exponent).is_positive()))
            throw std::runtime_error("division by zero: a derivative in a denominator is 0");
        return GiNaC::pow(base, exponent);
    }
    struct Each : GiNaC::map_function {
        const Checker* self;
        explicit Each(const Checker* c) : self(c) {}
        GiNaC::ex operator()(const GiNaC::ex& x) override { return self->resolve_operators(x); }
    } each(this);
    return e.map(each);
}

bool Checker::is_part(const GiNaC::ex& e, std::string* name, GiNaC::ex* whole) const {
    const FreeName* f = ctx_.free_name_of(e);
    if (!f || f->kind != NameKind::Unknown) return false;
    const std::string& n = f->name;
    if (n.size() < 4 || (n[0] != 'T' && n[0] != 'V' && n[0] != 'U') || n[1] != '_') return false;
    // U_{1} is a part only where U is the potential energy (not a model's own name).
    if (n[0] == 'U') {
        const auto letter = ctx_.names.find(n.substr(0, 1));
        if (letter == ctx_.names.end() || !truth_.count(letter->second)) return false;
    }
    // V_{eff}, V_{\text{eff}}: the effective potential of a reduced problem, a quantity of its own, not a part of V.
    if (n.find("eff") != std::string::npos) return false;
    // T_0 = 2\pi\sqrt{l/g}: a period, which the text sets to a constant; no part of T is one.
    if (not_parts_.count(n)) return false;
    if (name) *name = n;
    if (whole) *whole = n[0] == 'T' ? eq_.T : eq_.V;
    return true;
}

Prepared Checker::prepare(const PSide& s, const GiNaC::ex* exclude_part) {
    Prepared p;
    const Side& side = *s.side;
    if (side.empty()) {
        p.problem = "a side is empty (an incomplete equation)";
        return p;
    }
    if (!side.ok) {
        p.problem =
            "cannot read " + m(side.source) + " at " + where(s.base + side.error_offset) + ": " + side.error;
        return p;
    }
    for (const std::string& n : side.notes) p.notes.push_back(n);
    // A letter the text has given another quantity's meaning (`p_\theta = L`): that quantity, outside ∂·/∂·.
    GiNaC::ex value = discourse_ ? discourse_->renamed(side.value, s.base + side.begin, p.notes) : side.value;
    value = labels_under_derivatives(value, shadowed_labels_, model_, p.notes);  // ∂L/∂ẋ with a length L
    try {
        GiNaC::exmap subs;
        ExSet symbols;
        std::vector<GiNaC::ex> stack{value};
        while (!stack.empty()) {
            GiNaC::ex x = stack.back();
            stack.pop_back();
            if (GiNaC::is_a<GiNaC::symbol>(x)) symbols.insert(x);
            for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
        }
        for (const GiNaC::ex& sym : symbols) {
            // The momenta stay variables while the text differentiates (∂H/∂p_θ), and H inside ∂ is H(q, p, t).
            if (hamilton_.is_momentum(sym) && truth_.count(sym)) {
                p.has_truth_label = p.has_truth_label || value.is_equal(sym);
                p.has_momenta = true;
                continue;
            }
            if (hamilton_.is_hamiltonian(sym) && !value.is_equal(sym)) continue;
            auto t = truth_.find(sym);
            // h and H are common letters (a height): they stand for the energy function only as a whole side.
            if (t != truth_.end() && bare_only_.count(sym) && !value.is_equal(sym)) {
                subs[sym] = ctx_.free_symbol(GiNaC::ex_to<GiNaC::symbol>(sym).get_name(), NameKind::Unknown);
                continue;
            }
            if (t != truth_.end()) {
                subs[sym] = t->second;
                // A declared result is the reference only as a whole side (`a = ...`); inside an expression
                // it is a value like a map entry's.
                const bool result = result_labels_.count(sym) != 0;
                p.has_truth_label = p.has_truth_label || !result || value.is_equal(sym);
                continue;
            }
            std::string pname;
            if (is_part(sym, &pname) && !(exclude_part && exclude_part->is_equal(sym))) {
                auto pv = part_value_.find(sym);
                if (pv != part_value_.end()) {
                    subs[sym] = pv->second;
                    p.has_part = true;
                    p.notes.push_back("uses " + m(pname) + " as the text gives it at " +
                                      part_origin_.at(sym));
                }
            }
        }
        GiNaC::ex v = subs.empty() ? value : value.subs(subs);
        current_offset_ = s.base + side.begin;
        definitions_.take_used();
        const bool H_inside = hamilton_.has_hamiltonian(v);
        // A Poisson bracket is eomgen's to compute: the side is a reference, like a label.
        if (v.has(pbracket(GiNaC::wild(0), GiNaC::wild(1)))) p.has_truth_label = p.has_momenta = true;
        kinks_.clear();
        v = resolve_operators(v);
        // A derivative through a jump or a kink holds away from its surface only: said, with the surface.
        for (const auto& [kink, x] : kinks_)
            p.notes.push_back("the derivative in $" + latex(x) + "$ does not exist where $" + latex(kink.surface) +
                              " = 0$ (" + (kink.jump ? "the function jumps there" : "its slopes on the two sides differ") +
                              "): the side holds away from it");
        kinks_.clear();
        for (const std::string& n : definitions_.take_used()) {
            p.notes.push_back(n);
            p.from_definition = true;
        }
        p.notes.insert(p.notes.end(), operator_notes_.begin(), operator_notes_.end());
        operator_notes_.clear();
        // The text's abbreviations ("with \Omega = ..."), everywhere in the rest of their section.
        definitions_.take_abbreviations();
        v = definitions_.abbreviate(v, current_offset_);
        for (const std::string& n : definitions_.take_abbreviations()) p.notes.push_back(n);
        v = dotted_definitions(definitions_, v, current_offset_, ctx_, model_, p.notes);
        if (H_inside && !hamilton_.has_hamiltonian(v)) p.has_truth_label = p.has_momenta = true;
        if (hamilton_.has_hamiltonian(v))  // H outside a derivative, inside an expression: a letter (a height)
            v = v.subs(ctx_.names.at("H") == ctx_.free_symbol("H", NameKind::Unknown));
        p.value_p = v;
        v = hamilton_.in_velocities(v);
        // Every comparison expands or normalizes the side: refuse one too large for that up front.
        if (const double terms = expanded_terms(v); terms > kMaxExpandedTerms) {
            std::ostringstream os;
            os << "too large to compare within the budget: " << m(side.source) << " expands to up to "
               << std::setprecision(3) << terms << " terms (at most " << static_cast<long>(kMaxExpandedTerms) << ")";
            p.problem = os.str();
            return p;
        }
        p.value = v;
        // Free names left over.
        ExSet left;
        std::vector<GiNaC::ex> stack2{v};
        while (!stack2.empty()) {
            GiNaC::ex x = stack2.back();
            stack2.pop_back();
            if (GiNaC::is_a<GiNaC::symbol>(x)) left.insert(x);
            for (std::size_t i = 0; i < x.nops(); ++i) stack2.push_back(x.op(i));
        }
        for (const GiNaC::ex& sym : left) {
            const FreeName* f = ctx_.free_name_of(sym);
            if (!f) continue;
            if (exclude_part && exclude_part->is_equal(sym)) continue;
            if (f->kind == NameKind::Vector)
                p.vectors.push_back(f);
            else if (f->kind == NameKind::Unit)
                p.units.push_back(f);
            else if (is_constant_name(f->name))
                p.constants.push_back(sym);
            else
                p.unknown.push_back(f);
        }
        auto by_name = [](const FreeName* x, const FreeName* y) { return x->name < y->name; };
        std::sort(p.vectors.begin(), p.vectors.end(), by_name);
        std::sort(p.units.begin(), p.units.end(), by_name);
        std::sort(p.unknown.begin(), p.unknown.end(), by_name);
        std::sort(p.notes.begin(), p.notes.end());
        p.ok = true;
    } catch (const UndefinedInDerivative& u) {
        std::string at;
        for (const NameUse& use : side.uses)
            if (use.name == u.name) {
                at = " (" + where(s.base + use.offset) + ")";
                break;
            }
        std::string why = u.what();
        const std::string shown = "$" + u.name + "$";
        if (const std::size_t k = why.find(shown); k != std::string::npos) why.insert(k + shown.size(), at);
        p.problem = why;
    } catch (const std::exception& e) {
        p.problem = "cannot evaluate " + m(side.source) + ": " + e.what();
    }
    return p;
}


std::vector<Complex> Checker::signature(const GiNaC::ex& e) {
    auto hit = signatures_.find(e);
    if (hit != signatures_.end()) return hit->second;
    std::vector<Complex> s;
    const SignedStates signed_states(numbers_, has_nonsmooth(e));
    for (unsigned seed = 201; seed <= 203; ++seed) {
        const auto v = numbers_.value(e, numbers_.point(seed));
        s.push_back(v ? *v : Complex(std::nan(""), 0));
    }
    signatures_[e] = s;
    return s;
}

bool Checker::same_signature(const std::vector<Complex>& a, const std::vector<Complex>& b, double tol) const {
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::isnan(a[i].real()) || std::isnan(b[i].real())) return false;
        if (std::abs(a[i] - b[i]) > tol * std::max({std::abs(a[i]), std::abs(b[i]), 1e-300})) return false;
    }
    return true;
}

Tri Checker::equal(const GiNaC::ex& a, const GiNaC::ex& b, double tol) {
    const SignedStates signed_states(numbers_, has_nonsmooth(a) || has_nonsmooth(b));
    const GiNaC::ex diff = a - b;
    if (tol <= 1e-9) {  // exact numbers: a symbolic zero settles it
        try {
            if (diff.expand().is_zero()) return Tri::Yes;
        } catch (...) {
        }
        try {
            if (GiNaC::normal(diff).is_zero()) return Tri::Yes;
        } catch (...) {
        }
    }
    // Roots of the parameters alone (`\sqrt{(R - r)/g}`) stand for real quantities: points where one is the root of
    // a negative number (R < r) are outside what the text means, and the branches there would tell 1/√x from √(1/x).
    std::vector<GiNaC::ex> radicands;
    if (has_root(a) || has_root(b))
        for (std::vector<GiNaC::ex> stack{a, b}; !stack.empty();) {
            const GiNaC::ex e = stack.back();
            stack.pop_back();
            for (std::size_t i = 0; i < e.nops(); ++i) stack.push_back(e.op(i));
            if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
                !GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer() && !depends_on_state(e.op(0)) &&
                !has_acceleration(e.op(0)) && !e.op(0).has(model_.t))
                radicands.push_back(e.op(0));
        }
    const auto real_roots = [&](const GiNaC::exmap& at) {
        for (const GiNaC::ex& x : radicands) {
            const auto v = numbers_.value(x, at);
            if (v && std::abs(v->imag()) <= 1e-12 * std::abs(v->real()) && v->real() < 0) return false;
        }
        return true;
    };
    int good = 0;
    for (unsigned seed = 1; seed <= (radicands.empty() ? 10u : 24u) && good < 4; ++seed) {
        const GiNaC::exmap at = numbers_.point(seed);
        if (!real_roots(at)) continue;
        const auto va = numbers_.value(a, at), vb = numbers_.value(b, at);
        if (!va || !vb) continue;
        const double scale =
            std::max({numbers_.scale(a, at), numbers_.scale(b, at), std::abs(*va), std::abs(*vb)});
        if (std::abs(*va - *vb) > tol * scale + 1e-300) return Tri::No;
        ++good;
    }
    return good >= 2 ? Tri::Yes : Tri::Unknown;
}

Tri Checker::euler_lagrange_combination(const GiNaC::ex& r, double tol, int* only, std::string* factor,
                                            std::vector<std::string>* acting, std::vector<bool>* terms,
                                            int multipliers) {
    const std::size_t n = model_.dof();
    const SignedStates signed_states(numbers_, has_nonsmooth(r) || std::any_of(motion_.begin(), motion_.end(),
                                                                               [](const GiNaC::ex& e) { return has_nonsmooth(e); }));
    std::vector<GiNaC::ex> motion = motion_;  // = 0; with the multipliers, EL − Q − (±Aᵀλ)
    if (multipliers != 0) {
        acting = nullptr;  // the constraint forces are in the equations: none is missing
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t k = 0; k < eq_.constraints.size(); ++k)
                motion[i] -= multipliers * eq_.constraints[k].jacobian[i] * multipliers_[k];
    }
    std::vector<GiNaC::ex> a(n);
    for (std::size_t j = 0; j < n; ++j) {
        a[j] = GiNaC::diff(r, model_.coordinates[j].qdd);
        for (std::size_t k = 0; k < n; ++k)
            if (!GiNaC::diff(a[j], model_.coordinates[k].qdd).expand().is_zero())
                return Tri::No;  // not linear in q̈
    }
    int good = 0;
    std::vector<bool> used(n, false);
    std::vector<double> first_c;
    for (unsigned seed = 1; seed <= 10 && good < 3; ++seed) {
        const GiNaC::exmap at = numbers_.point(seed);
        Eigen::VectorXcd av(static_cast<Eigen::Index>(n));
        Eigen::MatrixXcd Mv(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
        bool ok = true;
        for (std::size_t j = 0; j < n && ok; ++j) {
            auto v = numbers_.value(a[j], at);
            ok = ok && v;
            if (v) av(Eigen::Index(j)) = *v;
            for (std::size_t k = 0; k < n && ok; ++k) {
                auto mv = numbers_.value(eq_.M(unsigned(j), unsigned(k)), at);
                ok = ok && mv;
                if (mv) Mv(Eigen::Index(j), Eigen::Index(k)) = *mv;
            }
        }
        if (!ok) continue;
        const Eigen::VectorXcd c = Mv.fullPivLu().solve(av);
        auto rv = numbers_.value(r, at);
        if (!rv) continue;
        Complex res = *rv;
        double scale = numbers_.scale(r, at);
        bool ok2 = true;
        for (std::size_t i = 0; i < n; ++i) {
            auto ev = numbers_.value(motion[i], at);
            if (!ev) {
                ok2 = false;
                break;
            }
            res -= c(Eigen::Index(i)) * *ev;
            scale += std::abs(c(Eigen::Index(i))) * numbers_.scale(motion[i], at);
        }
        if (!ok2) continue;
        if (std::abs(res) > tol * scale + 1e-300) return Tri::No;
        const double cmax = c.cwiseAbs().maxCoeff();
        if (cmax == 0) return Tri::No;
        // With constraints, Σ c_i EL_i = Σ_k (c·A_k) λ_k: the combination holds without multipliers only when
        // c·A_k = 0 for every constraint k.
        if (acting)
            for (const ConstraintEquations& k : eq_.constraints) {
                Complex dot = 0;
                double size = 0;
                for (std::size_t i = 0; i < n; ++i)
                    if (auto av = numbers_.value(k.jacobian[i], at)) {
                        dot += c(Eigen::Index(i)) * *av;
                        size += cmax * std::abs(*av);  // round-off in c must not count as a force
                    }
                if (std::abs(dot) > 1e-8 * std::max(size, 1e-300) &&
                    std::find(acting->begin(), acting->end(), k.name) == acting->end())
                    acting->push_back(k.name);
            }
        for (std::size_t i = 0; i < n; ++i)
            if (std::abs(c(Eigen::Index(i))) > 1e-9 * cmax) used[i] = true;
        ++good;
    }
    if (good < 2) return Tri::Unknown;
    if (terms) *terms = used;
    const auto count = std::count(used.begin(), used.end(), true);
    *only = -1;
    if (count == 1) *only = int(std::find(used.begin(), used.end(), true) - used.begin());
    if (*only >= 0) {
        // The factor, symbolically when it is simple: the ratio of the q̈_i coefficients.
        const GiNaC::symbol& qi = model_.coordinates[std::size_t(*only)].qdd;
        try {
            // sin² + cos² = 1 first: (m₁ + m₂)/(m₁ + m₂ sin² θ₁ + m₂ cos² θ₁) is 1, not a factor.
            const GiNaC::ex c = trig::readable_ratio(GiNaC::diff(r, qi),
                                                     GiNaC::diff(motion[std::size_t(*only)], qi), hints_);
            if (!c.is_equal(1)) *factor = latex(c);
        } catch (...) {
        }
    }
    return Tri::Yes;
}

bool Checker::proportional_in_state(const GiNaC::ex& r, const GiNaC::ex& target, double tol, GiNaC::ex* c) {
    const SignedStates signed_states(numbers_, has_nonsmooth(r) || has_nonsmooth(target));
    int settled = 0;
    for (unsigned ps = 1; ps <= 4 && settled < 2; ++ps) {
        std::vector<Complex> ratios;
        for (unsigned ss = 1; ss <= 6 && ratios.size() < 3; ++ss) {
            const GiNaC::exmap at = numbers_.point(ps, 100 + ss);
            const auto tv = numbers_.value(target, at), rv = numbers_.value(r, at);
            if (!tv || !rv) continue;
            const double ts = numbers_.scale(target, at);
            if (std::abs(*tv) <= 1e-9 * ts) continue;
            ratios.push_back(*rv / *tv);
        }
        if (ratios.size() < 3) continue;
        for (const Complex& q : ratios)
            if (std::abs(q - ratios[0]) > std::max(tol, 1e-8) * std::max(std::abs(ratios[0]), 1e-300))
                return false;
        if (std::abs(ratios[0]) < 1e-12) return false;
        ++settled;
    }
    if (settled < 2) return false;
    try {
        *c = GiNaC::normal(r / target);
        if (has_velocity(*c) || has_acceleration(*c)) *c = GiNaC::ex(1);
    } catch (...) {
        *c = 1;
    }
    return true;
}

ConstraintReduction Checker::reduction(const GiNaC::ex& keep, std::string* shown) {
    const ConstraintReduction red = reduce_on_constraints(model_, eq_, keep);
    std::string list;
    for (const Coordinate& c : model_.coordinates)
        for (const GiNaC::exmap* map : {&red.coordinates, &red.velocities})
            for (const GiNaC::symbol* s : {&c.q, &c.qd}) {
                auto it = map->find(*s);
                if (it == map->end()) continue;
                list += (list.empty() ? "" : ", ") + m(latex(*s) + " = " + latex(it->second));
            }
    if (shown) *shown = list;
    return red;
}

bool Checker::proportional_to_constraint(const GiNaC::ex& r, std::size_t index, double tol) {
    const GiNaC::ex& target = eq_.constraints[index].velocity;
    int settled = 0;
    for (unsigned base = 1; base <= 4 && settled < 2; ++base) {
        std::vector<Complex> ratios;
        for (unsigned v = 1; v <= 6 && ratios.size() < 3; ++v) {
            GiNaC::exmap at = numbers_.point(base);
            const GiNaC::exmap other = numbers_.point(base, 300 + v);
            for (const Coordinate& c : model_.coordinates) at[c.qd] = other.at(c.qd);
            const auto tv = numbers_.value(target, at), rv = numbers_.value(r, at);
            if (!tv || !rv || std::abs(*tv) <= 1e-9 * numbers_.scale(target, at)) continue;
            ratios.push_back(*rv / *tv);
        }
        if (ratios.size() < 3) continue;
        for (const Complex& q : ratios)
            if (std::abs(q - ratios[0]) > std::max(tol, 1e-8) * std::max(std::abs(ratios[0]), 1e-300)) return false;
        if (std::abs(ratios[0]) < 1e-12) return false;
        ++settled;
    }
    return settled >= 2;
}

bool Checker::linear_in_velocities(const GiNaC::ex& r) const {
    bool any = false;
    for (const Group& g : groups(r)) {
        int degree = 0;
        for (const Coordinate& c : model_.coordinates) degree += g.monomial.degree(c.qd) + g.monomial.degree(c.qdd);
        if (degree > 1) return false;
        any = any || degree == 1;
    }
    return any;
}

}  // namespace eomgen::checker::detail
