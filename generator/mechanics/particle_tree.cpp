/** @file particle_tree.cpp  Finding a tree of point masses in T (particle_tree.hpp). */
#include "mechanics/particle_tree.hpp"

#include "mechanics/differentiator.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <set>

namespace eomgen {

using GiNaC::ex;

namespace {

/// Past these, the search is not worth its time: the dense solve stays.
constexpr std::size_t kMaxSquares = 4096;
constexpr std::size_t kMaxComponents = 6;

struct NotATree {};

/// One squared speed of T: ½ w s², s = Σ_k alpha[k] q̇_k.
struct Square {
    ex w, s;
    std::vector<ex> alpha;       ///< per coordinate
    std::vector<int> support;    ///< coordinates with alpha ≠ 0
    int component = -1;
    ex scale = 1;                ///< s·scale is the component's velocity (w / scale² its weight)
};

class Finder {
  public:
    Finder(const Model& model, const Equations& eq)
        : model_(model), eq_(eq), n_(model.dof()), support_(symbols(model)) {
        // Which of t, q, q̇, q̈ a node holds, from one walk of each tree (SymbolSupport): e.has(x) for every
        // coordinate, on every term and lever, was most of finding the 60-link pendulum's tree.
        std::vector<GiNaC::ex> time_or_velocity{model.t};
        for (const Coordinate& c : model.coordinates) time_or_velocity.push_back(c.qd);
        moving_ = support_.mask(symbols(model));
        time_or_velocity_ = support_.mask(time_or_velocity);
        for (std::size_t k = 0; k < n_; ++k) {
            velocity_.push_back(support_.mask({model.coordinates[k].qd}));
            std::vector<GiNaC::ex> others;
            for (std::size_t j = 0; j < n_; ++j)
                if (j != k) others.push_back(model.coordinates[j].q);
            other_coordinates_.push_back(support_.mask(others));
        }
    }

    ParticleTree find() {
        if (!eq_.constraints.empty() || eq_.T.has(model_.t) || eq_.V.has(model_.t)) throw NotATree{};
        for (const Coordinate& c : model_.coordinates)
            if (eq_.V.has(c.qd)) throw NotATree{};
        squares(eq_.T, 1);
        split_joint_inertia();
        check_reconstruction();
        canonical_order();
        build_tree();
        assign_components();
        return result();
    }

  private:
    static std::vector<ex> symbols(const Model& model) {
        std::vector<ex> out{model.t};
        for (const Coordinate& c : model.coordinates) out.insert(out.end(), {c.q, c.qd, c.qdd});
        return out;
    }
    bool moving(const ex& e) { return support_.holds(e, moving_); }

    /// T's terms as ½ w s²: sums term by term, constant factors into w, squares (also products of squares,
    /// which GiNaC makes of (a·b)²) as s.
    void squares(const ex& e, const ex& weight) {
        if (out_.size() > kMaxSquares) throw NotATree{};
        if (GiNaC::is_a<GiNaC::add>(e)) {
            for (const ex& term : e) squares(term, weight);
            return;
        }
        if (!moving(e)) {
            if (!e.is_zero()) throw NotATree{};  // a term of T without velocities
            return;
        }
        if (GiNaC::is_a<GiNaC::mul>(e)) {
            ex constant = 1, root = 1;
            std::vector<ex> rest;
            for (const ex& f : e) {
                if (!moving(f))
                    constant *= f;
                else
                    rest.push_back(f);
            }
            if (rest.size() == 1) return squares(rest[0], weight * constant);
            // A product of even powers: the square of the product of their square roots.
            for (const ex& f : rest) {
                if (!GiNaC::is_a<GiNaC::power>(f) || !f.op(1).info(GiNaC::info_flags::even) ||
                    !f.op(1).info(GiNaC::info_flags::positive))
                    throw NotATree{};
                root *= GiNaC::pow(f.op(0), f.op(1) / 2);
            }
            return add_square(2 * weight * constant, root);
        }
        if (GiNaC::is_a<GiNaC::power>(e) && e.op(1).is_equal(2)) return add_square(2 * weight, e.op(0));
        throw NotATree{};
    }

    void add_square(const ex& w, const ex& s) {
        Square sq{w, s, std::vector<ex>(n_, 0), {}, -1, 1};
        ex rebuilt = 0;
        for (std::size_t k = 0; k < n_; ++k) {
            if (!support_.holds(s, velocity_[k])) continue;
            const ex a = s.diff(model_.coordinates[k].qd);
            if (a.is_zero()) continue;
            // The lever of q̇_k: of q_k alone (and the parameters).
            if (support_.holds(a, time_or_velocity_) || support_.holds(a, other_coordinates_[k])) throw NotATree{};
            sq.alpha[k] = a;
            sq.support.push_back(int(k));
            rebuilt += a * model_.coordinates[k].qd;
        }
        if (sq.support.empty() || !(s - rebuilt).expand().is_zero()) throw NotATree{};  // s linear in q̇
        out_.push_back(std::move(sq));
    }

    /// Squares of one velocity with a constant lever: ½ J q̇_k², no point of the tree.
    void split_joint_inertia() {
        joint_inertia_.assign(n_, 0);
        std::vector<Square> kept;
        for (Square& sq : out_) {
            if (sq.support.size() == 1 && !moving(sq.alpha[std::size_t(sq.support[0])])) {
                const ex a = sq.alpha[std::size_t(sq.support[0])];
                joint_inertia_[std::size_t(sq.support[0])] += sq.w * a * a;
            } else {
                kept.push_back(std::move(sq));
            }
        }
        out_ = std::move(kept);
    }

    /// The squares in an order of their own: GiNaC's order of T's terms changes from process to process (it
    /// hashes addresses), and the components' numbering, hence the header's bytes, follows the squares' order.
    /// By the coordinates moved, then by the first lever's and the weight's values at a fixed point.
    void canonical_order() {
        const GiNaC::exmap at = random_point(model_, 7);
        auto value = [&](const ex& e) {
            const ex v = GiNaC::evalf(e.subs(at, GiNaC::subs_options::no_pattern));
            return GiNaC::is_a<GiNaC::numeric>(v) ? GiNaC::ex_to<GiNaC::numeric>(v).to_double() : 0.0;
        };
        struct Key {
            std::vector<int> support;
            double lever, weight;
        };
        std::vector<std::pair<Key, Square>> keyed;
        for (Square& sq : out_)
            keyed.push_back({{sq.support, value(sq.alpha[std::size_t(sq.support.front())]), value(sq.w)}, std::move(sq)});
        auto before = [](double a, double b) { return a < b - 1e-9 * std::max(std::abs(a), std::abs(b)); };
        std::stable_sort(keyed.begin(), keyed.end(), [&](const auto& x, const auto& y) {
            if (x.first.support != y.first.support) return x.first.support.size() != y.first.support.size()
                                                               ? x.first.support.size() < y.first.support.size()
                                                               : x.first.support < y.first.support;
            if (before(x.first.lever, y.first.lever) || before(y.first.lever, x.first.lever))
                return before(x.first.lever, y.first.lever);
            return before(x.first.weight, y.first.weight);
        });
        out_.clear();
        for (auto& [key, sq] : keyed) out_.push_back(std::move(sq));
    }

    /// T is exactly Σ ½ w s² + Σ ½ J q̇²: the reading above lost nothing.
    void check_reconstruction() const {
        ex rebuilt = 0;
        for (const Square& sq : out_) rebuilt += sq.w * GiNaC::pow(sq.s, 2) / 2;
        for (std::size_t k = 0; k < n_; ++k)
            rebuilt += joint_inertia_[k] * GiNaC::pow(model_.coordinates[k].qd, 2) / 2;
        // At random points: expanding both sides would cost O(n³) terms for an n-link chain.
        for (unsigned seed = 1; seed <= 3; ++seed) {
            const GiNaC::exmap at = random_point(model_, seed);
            const ex a = GiNaC::evalf(eq_.T.subs(at, GiNaC::subs_options::no_pattern)),
                     b = GiNaC::evalf(rebuilt.subs(at, GiNaC::subs_options::no_pattern));
            if (!GiNaC::is_a<GiNaC::numeric>(a) || !GiNaC::is_a<GiNaC::numeric>(b)) throw NotATree{};
            const double x = GiNaC::ex_to<GiNaC::numeric>(a).to_double(), y = GiNaC::ex_to<GiNaC::numeric>(b).to_double();
            if (!(std::abs(x - y) <= 1e-10 * std::max(std::abs(x), std::abs(y)))) throw NotATree{};
        }
    }

    /// Each square moves the path from a root to its deepest coordinate: the ancestors of k are the coordinates
    /// every square through k also moves.
    void build_tree() {
        std::vector<std::set<int>> ancestors(n_);
        std::vector<bool> seen(n_, false);
        for (const Square& sq : out_)
            for (int k : sq.support) {
                std::set<int> others(sq.support.begin(), sq.support.end());
                others.erase(k);
                if (!seen[std::size_t(k)]) {
                    ancestors[std::size_t(k)] = others;
                    seen[std::size_t(k)] = true;
                } else {
                    std::set<int> both;
                    std::set_intersection(ancestors[std::size_t(k)].begin(), ancestors[std::size_t(k)].end(),
                                          others.begin(), others.end(), std::inserter(both, both.begin()));
                    ancestors[std::size_t(k)] = both;
                }
            }
        for (std::size_t k = 0; k < n_; ++k)
            if (!seen[k] && joint_inertia_[k].is_zero()) throw NotATree{};  // q_k moves nothing: M singular
        // Parents: the ancestor with the most ancestors of its own; they must nest.
        parent_.assign(n_, -1);
        for (std::size_t k = 0; k < n_; ++k) {
            for (int a : ancestors[k]) {
                const std::set<int>& up = ancestors[std::size_t(a)];
                if (up.count(int(k))) throw NotATree{};
                if (parent_[k] < 0 || up.size() > ancestors[std::size_t(parent_[k])].size()) parent_[k] = a;
            }
            // The path above k is its parent and the parent's path.
            if (parent_[k] >= 0) {
                std::set<int> path = ancestors[std::size_t(parent_[k])];
                path.insert(parent_[k]);
                if (path != ancestors[k]) throw NotATree{};
            }
        }
        // Every square is a whole path: its deepest coordinate and that one's ancestors.
        for (Square& sq : out_) {
            const std::set<int> support(sq.support.begin(), sq.support.end());
            bool whole = false;
            for (int k : sq.support) {
                std::set<int> path = ancestors[std::size_t(k)];
                path.insert(k);
                if (path == support) {
                    whole = true;
                    end_.push_back(k);
                    break;
                }
            }
            if (!whole) throw NotATree{};
        }
        order_.clear();
        std::vector<std::size_t> depth(n_);
        for (std::size_t k = 0; k < n_; ++k) depth[k] = ancestors[k].size();
        for (std::size_t k = 0; k < n_; ++k) order_.push_back(int(k));
        std::stable_sort(order_.begin(), order_.end(),
                         [&](int a, int b) { return depth[std::size_t(a)] < depth[std::size_t(b)]; });
    }

    /// a / b when it is free of the state, else nothing.
    std::optional<ex> constant_ratio(const ex& a, const ex& b) {
        ex r;
        try {
            r = (a / b).normal();
        } catch (const std::exception&) {
            return std::nullopt;
        }
        if (moving(r)) return std::nullopt;
        return r;
    }

    /// Components: a square joins a component when its levers are proportional, with one constant ratio, to the
    /// component's at every coordinate both pass (scaled to them), and fills in the component's levers where
    /// it is the first to pass; else it starts a component. By construction every square of a component then
    /// has the component's lever at every coordinate it moves.
    void assign_components() {
        std::vector<std::vector<ex>> lever;  // [component][k], 0 = not passed yet
        for (Square& sq : out_) {
            for (std::size_t c = 0; c < lever.size() && sq.component < 0; ++c) {
                std::optional<ex> ratio;
                bool fits = true;
                for (int k : sq.support) {
                    const ex& ref = lever[c][std::size_t(k)];
                    if (ref.is_zero()) continue;
                    const ex& a = sq.alpha[std::size_t(k)];
                    if (!ratio) {
                        ratio = constant_ratio(ref, a);
                        fits = ratio.has_value();
                    } else {
                        // Most levers are the same expression (GiNaC makes their difference 0 at once); the
                        // numeric and exact test is for the rest (it was a tenth of generating the 30-link chain).
                        const ex difference = ref - *ratio * a;
                        fits = difference.is_zero() || is_zero(difference, model_);
                    }
                    if (!fits) break;
                }
                if (fits && ratio) {
                    sq.component = int(c);
                    sq.scale = *ratio;
                }
            }
            if (sq.component < 0) {
                if (lever.size() == kMaxComponents) throw NotATree{};
                lever.emplace_back(n_, 0);
                sq.component = int(lever.size() - 1);
                sq.scale = 1;
            }
            std::vector<ex>& own = lever[std::size_t(sq.component)];
            for (int k : sq.support)
                if (own[std::size_t(k)].is_zero()) own[std::size_t(k)] = sq.scale * sq.alpha[std::size_t(k)];
        }
        lever_ = std::move(lever);
    }

    ParticleTree result() const {
        ParticleTree t;
        t.parent = parent_;
        t.order = order_;
        t.components = lever_.size();
        t.lever.assign(n_, std::vector<ex>(t.components, 0));
        t.bias.assign(n_, std::vector<ex>(t.components, 0));
        t.weight.assign(n_, std::vector<ex>(t.components, 0));
        for (std::size_t k = 0; k < n_; ++k)
            for (std::size_t c = 0; c < t.components; ++c) {
                const Coordinate& q = model_.coordinates[k];
                t.lever[k][c] = lever_[c][k];
                t.bias[k][c] = lever_[c][k].diff(q.q) * GiNaC::pow(q.qd, 2);
            }
        for (std::size_t r = 0; r < out_.size(); ++r) {
            const Square& sq = out_[r];
            t.weight[std::size_t(end_[r])][std::size_t(sq.component)] += sq.w / GiNaC::pow(sq.scale, 2);
        }
        for (std::size_t k = 0; k < n_; ++k)
            for (std::size_t c = 0; c < t.components; ++c) t.weight[k][c] = t.weight[k][c].normal();
        t.joint_inertia = joint_inertia_;
        for (std::size_t k = 0; k < n_; ++k)
            t.force.push_back(eq_.generalized_forces[k] - eq_.V.diff(model_.coordinates[k].q));
        return t;
    }

    const Model& model_;
    const Equations& eq_;
    std::size_t n_;
    SymbolSupport support_;                  ///< over t and every q, q̇, q̈
    std::vector<std::uint64_t> moving_;      ///< t, q, q̇, q̈
    std::vector<std::uint64_t> time_or_velocity_;
    std::vector<std::vector<std::uint64_t>> velocity_;           ///< q̇_k
    std::vector<std::vector<std::uint64_t>> other_coordinates_;  ///< every q_j but q_k
    std::vector<Square> out_;
    std::vector<int> end_;  ///< per square: its deepest coordinate
    std::vector<ex> joint_inertia_;
    std::vector<int> parent_, order_;
    std::vector<std::vector<ex>> lever_;
};

}  // namespace

std::optional<ParticleTree> find_particle_tree(const Model& model, const Equations& eq) {
    try {
        return Finder(model, eq).find();
    } catch (const NotATree&) {
        return std::nullopt;
    }
}

}  // namespace eomgen
