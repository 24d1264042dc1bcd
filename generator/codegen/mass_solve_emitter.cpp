/** @file mass_solve_emitter.cpp  The unrolled LDL^T solve of M q'' = f in generated headers. */
#include "codegen/mass_solve_emitter.hpp"

#include <fmt/format.h>

#include <sstream>

namespace eomgen::codegen {

std::string emit_mass_solve(const std::vector<std::vector<bool>>& zero) {
    const std::size_t n = zero.size();
    // L's pattern: M's lower triangle and its fill-in (L_ij != 0 when some k < j has L_ik and L_jk != 0).
    std::vector<std::vector<bool>> nz(n, std::vector<bool>(n, false));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < i; ++j) {
            bool v = !zero[i][j];
            for (std::size_t k = 0; k < j && !v; ++k) v = nz[i][k] && nz[j][k];
            nz[i][j] = v;
        }
    std::ostringstream os;
    os << "    /// q'' from M q'' = f by M = L D L^T, unrolled (L unit lower triangular; its entries that are zero for every q\n"
          "    /// left out). The pivots D are tested as eomgen::solve_mass_matrix tests them: a singular M throws\n"
          "    /// eomgen::SingularMassMatrix, a non-finite M, f or q'' eomgen::NonFiniteState, never a NaN.\n";
    os << "    static void solve_for_accelerations(const Scalar& t, const State& x_, const MassMatrix& M_, const Config& f_,\n"
          "                                        Config& qdd_) {\n";
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (!nz[i][j]) continue;
            std::string u = zero[i][j] ? "" : fmt::format("M_({}, {})", i, j);
            for (std::size_t k = 0; k < j; ++k)
                if (nz[i][k] && nz[j][k]) u += fmt::format("{}u{}_{}_ * l{}_{}_", u.empty() ? "-" : " - ", i, k, j, k);
            os << fmt::format("        const Scalar u{0}_{1}_ = {2};\n", i, j, u);
        }
        std::string d = fmt::format("M_({0}, {0})", i);
        for (std::size_t j = 0; j < i; ++j) {
            if (!nz[i][j]) continue;
            os << fmt::format("        const Scalar l{0}_{1}_ = u{0}_{1}_ * inv_d{1}_;\n", i, j);
            d += fmt::format(" - u{0}_{1}_ * l{0}_{1}_", i, j);
        }
        os << fmt::format("        const Scalar d{}_ = {};\n", i, d);
        os << fmt::format("        const Scalar inv_d{0}_ = Scalar(1) / d{0}_;\n", i);
    }
    os << "        if (!eomgen::pivots_regular(std::array<Scalar, " << n << ">{";
    for (std::size_t i = 0; i < n; ++i) os << (i ? ", " : "") << "d" << i << "_";
    os << "}))\n            eomgen::throw_solve_failure(M_, f_, true, t, x_);\n";
    for (std::size_t i = 0; i < n; ++i) {
        std::string y = fmt::format("f_({})", i);
        for (std::size_t k = 0; k < i; ++k)
            if (nz[i][k]) y += fmt::format(" - l{}_{}_ * y{}_", i, k, k);
        os << fmt::format("        const Scalar y{}_ = {};\n", i, y);
    }
    for (std::size_t i = n; i-- > 0;) {
        std::string q = fmt::format("y{0}_ * inv_d{0}_", i);
        for (std::size_t k = i + 1; k < n; ++k)
            if (nz[k][i]) q += fmt::format(" - l{}_{}_ * qdd_({})", k, i, k);
        os << fmt::format("        qdd_({}) = {};\n", i, q);
    }
    os << "        if (!qdd_.allFinite()) eomgen::throw_solve_failure(M_, f_, false, t, x_);\n    }\n";
    return os.str();
}

}  // namespace eomgen::codegen
