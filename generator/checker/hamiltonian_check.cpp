/** @file hamiltonian_check.cpp  Momenta as variables, H and Hamilton's equations in a derivation. */
#include "checker/hamiltonian_check.hpp"

#include <stdexcept>

namespace eomgen::checker {

HamiltonianReading::HamiltonianReading(const Model& model, const Equations& eq)
    : model_(model), eq_(eq), ham_(derive_hamiltonian(model, eq)) {}

void HamiltonianReading::set_labels(const std::vector<GiNaC::ex>& momenta, const GiNaC::ex& H) {
    for (std::size_t i = 0; i < momenta.size() && i < ham_.p.size(); ++i) {
        if (!GiNaC::is_a<GiNaC::symbol>(momenta[i])) continue;
        to_velocities_[momenta[i]] = ham_.momenta[i];
        to_labels_[ham_.p[i]] = momenta[i];
        index_[momenta[i]] = i;
    }
    H_label_ = GiNaC::is_a<GiNaC::symbol>(H) ? H : GiNaC::ex(0);
}

GiNaC::ex HamiltonianReading::in_momenta(const GiNaC::ex& e) const {
    if (!ham_.symbolic || to_labels_.size() != ham_.p.size()) return e;
    GiNaC::exmap m;
    for (std::size_t i = 0; i < ham_.velocities.size(); ++i)
        m[model_.coordinates[i].qd] = ham_.velocities[i].subs(to_labels_);
    return e.subs(m);
}

std::optional<GiNaC::ex> HamiltonianReading::hamiltonian() const {
    if (!ham_.symbolic || to_labels_.size() != ham_.p.size()) return std::nullopt;
    return ham_.H.subs(to_labels_);
}

GiNaC::ex HamiltonianReading::poisson(const GiNaC::ex& a, const GiNaC::ex& b) const {
    const auto H = hamiltonian();
    auto canonical = [&](const GiNaC::ex& e) {
        GiNaC::ex x = e;
        if (has_hamiltonian(x)) {
            if (!H) throw std::runtime_error("a Poisson bracket of H: " + ham_.why_not_symbolic);
            x = x.subs(H_label_ == *H);
        }
        for (const Coordinate& c : model_.coordinates)
            if (x.has(c.qd) && !H)
                throw std::runtime_error("a Poisson bracket of velocities: " + ham_.why_not_symbolic);
        return in_momenta(x);
    };
    const GiNaC::ex A = canonical(a), B = canonical(b);
    GiNaC::ex sum = 0;
    for (const auto& [label, i] : index_) {
        const GiNaC::symbol& q = model_.coordinates[i].q;
        const GiNaC::symbol& p = GiNaC::ex_to<GiNaC::symbol>(label);
        sum += GiNaC::diff(A, q) * GiNaC::diff(B, p) - GiNaC::diff(A, p) * GiNaC::diff(B, q);
    }
    return sum;
}

GiNaC::ex HamiltonianReading::derivative(const GiNaC::ex& e, const GiNaC::symbol& wrt) const {
    if (!e.is_equal(H_label_)) {
        // H inside an expression: H(q, p, t) itself, when M⁻¹ is formed.
        if (const auto H = hamiltonian()) return GiNaC::diff(e.subs(H_label_ == *H), wrt);
        throw std::runtime_error(ham_.why_not_symbolic.empty()
                                     ? "the momenta of this model are not all p_q labels"
                                     : ham_.why_not_symbolic + ", so only ∂H/∂p, ∂H/∂q and ∂H/∂t of H alone are read");
    }
    // H alone: the canonical identities, through p = p(q, q̇) (Goldstein (8.14)–(8.16)), compact where the
    // derivative of H(q, p, t) is not (the heavy top's ∂H/∂θ): ∂H/∂p_i = q̇_i and, for a coordinate, time or a
    // parameter a, ∂H/∂a at fixed p = −∂L/∂a at fixed q̇.
    if (auto it = index_.find(wrt); it != index_.end()) return model_.coordinates[it->second].qd;
    if (velocity_reading_) return GiNaC::diff(eq_.energy, wrt);  // h(q, q̇, t) at fixed q̇
    for (const Coordinate& c : model_.coordinates)
        if (wrt.is_equal(c.qd) || wrt.is_equal(c.qdd))
            throw std::runtime_error("H is a function of the coordinates and momenta: ∂H/∂" + wrt.get_name() +
                                     " is not read");
    return -GiNaC::diff(eq_.L, wrt);
}

}  // namespace eomgen::checker
