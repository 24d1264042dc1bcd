/** @file modes_support.hpp  What the small-oscillation tests share: a model derived from text or a file, and the
 * equilibrium found at a given q. */
#pragma once

#include "test_paths.hpp"
#include "mechanics/lagrangian.hpp"
#include "mechanics/small_oscillations.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace modes_support {

struct Derived {
    eomgen::Model model;
    eomgen::Equations eq;
};

inline Derived derive(const std::string& text) {
    Derived d{eomgen::parse_model(text, "modes_test.toml"), {}};
    d.eq = eomgen::derive_equations(d.model);
    return d;
}

inline Derived load(const std::string& relative) {
    Derived d{eomgen::load_model(eomgen_test::source_dir() + "/" + relative), {}};
    d.eq = eomgen::derive_equations(d.model);
    return d;
}

/// The equilibrium at q (to 1e-9), or FAIL.
inline const eomgen::Equilibrium& at(const eomgen::ModesResult& r, const std::vector<double>& q) {
    for (const auto& e : r.equilibria) {
        bool same = true;
        for (std::size_t i = 0; i < q.size(); ++i) same = same && std::abs(e.q[i] - q[i]) < 1e-9;
        if (same) return e;
    }
    FAIL("no equilibrium at the given q among " << r.equilibria.size());
    return r.equilibria.front();
}

}  // namespace modes_support
