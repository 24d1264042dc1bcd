// Includes the header generated from tests/security/hostile.toml, whose text fields try to inject code
// (issue 19). Prints only what main prints: any "PWNED" on the output means text from the model ran.
#include "eomgen/models/hostile.hpp"

#include <cstdio>
#include <cstring>

int main() {
    using M = eomgen::models::hostile::Model<double>;
    // The text survives as data, byte for byte.
    const bool title_ok = std::strstr(M::title, "static const int pwned_title") != nullptr;
    const bool source_ok = std::strstr(M::source, "\n#include <cstdio>\n") != nullptr;
    M::State x = M::default_state(), xdot;
    M::rhs(0.0, x, M::Params{}, xdot);
    std::printf("main ran: title kept %d, source kept %d, x'' = %g\n", title_ok, source_ok, xdot(1));
    return title_ok && source_ok && xdot(1) == -2.0 ? 0 : 1;
}
