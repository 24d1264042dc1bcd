/** @file hamiltonian_check.hpp  How the checker reads Hamiltonian mechanics: the momenta p_q as variables, H
 * in momenta or in velocities, Hamilton's equations q̇ = ∂H/∂p, ṗ = −∂H/∂q (partial derivatives at fixed p,
 * the canonical convention; Goldstein §8.1). */
#pragma once

#include "mechanics/hamiltonian.hpp"

#include <ginac/ginac.h>

#include <map>
#include <optional>
#include <string>

namespace eomgen::checker {

/**
 * The text's p_{q} (the label symbols the checker made for the momenta) are independent variables while the
 * text differentiates (∂H/∂p_θ, ∂H/∂θ at fixed p); a side is compared once every p is replaced by p(q, q̇)
 * (mechanics/hamiltonian.hpp: a function of (q, p) is determined by its composition with p(q, q̇), which is
 * one to one where M is regular). The label H inside a partial derivative is eomgen's H(q, p, t); as a whole
 * side it stays the energy function h(q, q̇), its value in velocities.
 */
class HamiltonianReading {
  public:
    HamiltonianReading(const Model& model, const Equations& eq);

    /// Registers the label symbols: `momenta[i]` stands for p_i, `H` for the Hamiltonian.
    void set_labels(const std::vector<GiNaC::ex>& momenta, const GiNaC::ex& H);

    bool is_momentum(const GiNaC::ex& symbol) const { return to_velocities_.count(symbol) != 0; }
    bool is_hamiltonian(const GiNaC::ex& symbol) const { return !H_label_.is_zero() && symbol.is_equal(H_label_); }
    bool has_hamiltonian(const GiNaC::ex& e) const { return !H_label_.is_zero() && e.has(H_label_); }

    /// e with every momentum label replaced by p_i(q, q̇, t).
    GiNaC::ex in_velocities(const GiNaC::ex& e) const { return e.subs(to_velocities_); }

    /**
     * ∂e/∂wrt where e holds the label H: for e = H alone by the canonical identities ∂H/∂p_i = q̇_i, ∂H/∂q_i = −∂L/∂q_i, ∂H/∂t = −∂L/∂t; for H inside an expression
     * with H(q, p, t) substituted when M⁻¹ is formed (else throws std::runtime_error with the reason).
     */
    GiNaC::ex derivative(const GiNaC::ex& e, const GiNaC::symbol& wrt) const;

    /// e with every velocity replaced by q̇_i(q, p, t) in the label symbols (unchanged when M⁻¹ is not formed):
    /// a correction printed in the momenta the text uses.
    GiNaC::ex in_momenta(const GiNaC::ex& e) const;

    /**
     * The reading a text sets up when it writes H in velocities (`H = \frac12 m l^2 \dot\theta^2 - …`) and then
     * differentiates it by a coordinate: h(q, q̇) at fixed q̇, not H(q, p) at fixed p. While `on`, derivative()
     * reads ∂H/∂q, ∂H/∂t (and ∂H/∂a of a parameter) so; ∂H/∂p stays q̇.
     */
    void set_velocity_reading(bool on) { velocity_reading_ = on; }
    bool velocity_reading() const { return velocity_reading_; }

    /**
     * The Poisson bracket {a, b} = Σ_i ∂a/∂q_i ∂b/∂p_i − ∂a/∂p_i ∂b/∂q_i (Goldstein (9.67)), a and b in q, the
     * momentum labels and t (H is H(q, p, t), a velocity q̇(q, p)). Throws std::runtime_error when a or b holds
     * H or a velocity and M⁻¹ is not formed.
     */
    GiNaC::ex poisson(const GiNaC::ex& a, const GiNaC::ex& b) const;

    /// H(q, p, t) in the label symbols, or std::nullopt when M⁻¹ is not formed.
    std::optional<GiNaC::ex> hamiltonian() const;

  private:
    const Model& model_;
    const Equations& eq_;
    Hamiltonian ham_;
    GiNaC::exmap to_velocities_;  ///< p label → p_i(q, q̇, t)
    GiNaC::exmap to_labels_;      ///< mechanics' p_i symbol → the label symbol
    std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> index_;  ///< p label → i
    GiNaC::ex H_label_ = 0;
    bool velocity_reading_ = false;
};

}  // namespace eomgen::checker
