// Generated header of tests/security/reserved_looking.toml: compiles in double and long double, and its
// right-hand side runs (the names are ordinary identifiers in it, not macros or members it clashes with).
#include "eomgen/models/reserved_looking.hpp"

#include <cmath>
#include <cstdio>

template struct eomgen::models::reserved_looking::Model<double>;
template struct eomgen::models::reserved_looking::Model<long double>;

int main() {
    using M = eomgen::models::reserved_looking::Model<double>;
    M::State x = M::default_state(), xdot;
    M::rhs(0.0, x, M::Params{}, xdot);
    std::printf("x'' = %g %g\n", xdot(2), xdot(3));
    return std::isfinite(xdot(2)) && std::isfinite(xdot(3)) ? 0 : 1;
}
