/** @file families.cpp  n-link pendulum and rod-chain model files, written out as a user would write them. */
#include "model/families.hpp"

#include <cctype>
#include <sstream>
#include <stdexcept>

namespace eomgen {
namespace {

/// Σ_{k<i} l_k f(θ_k) θ̇_k (+ 1/2 l_i f(θ_i) θ̇_i for a rod's centre; + l_i f(θ_i) θ̇_i for the mass).
std::string velocity_sum(const std::string& f, int i, bool half_last) {
    std::string s;
    for (int k = 1; k <= i; ++k) {
        const std::string kk = std::to_string(k);
        s += (k > 1 ? " + " : "") + std::string(k == i && half_last ? "1/2*" : "") + "l" + kk + "*" + f +
             "(theta" + kk + ")*theta" + kk + "'";
    }
    return s;
}

/// Σ_{k<i} l_k cos θ_k (+ 1/2 l_i cos θ_i or l_i cos θ_i): the depth of body i below the pivot.
std::string depth_sum(int i, bool half_last) {
    std::string s;
    for (int k = 1; k <= i; ++k) {
        const std::string kk = std::to_string(k);
        s += (k > 1 ? " + " : "") + std::string(k == i && half_last ? "1/2*" : "") + "l" + kk + "*cos(theta" +
             kk + ")";
    }
    return s;
}

}  // namespace

std::vector<std::string> family_names() {
    return {"pendulum", "rods"};
}

FamilySpec parse_family_spec(const std::string& spec) {
    const auto colon = spec.find(':');
    FamilySpec out;
    out.family = spec.substr(0, colon);
    bool known = false;
    for (const std::string& f : family_names()) known = known || f == out.family;
    if (!known)
        throw std::invalid_argument("unknown model family '" + out.family + "' (known: pendulum, rods)");
    const std::string rest = colon == std::string::npos ? std::string() : spec.substr(colon + 1);
    if (rest.rfind("n=", 0) != 0)
        throw std::invalid_argument("family '" + spec + "' needs the number of links, e.g. " + out.family +
                                    ":n=8");
    const std::string digits = rest.substr(2);
    bool ok = !digits.empty() && digits.size() <= 4;
    for (char c : digits) ok = ok && std::isdigit(static_cast<unsigned char>(c));
    if (ok) out.n = std::stoi(digits);
    if (!ok || out.n < 1 || out.n > kMaxFamilyLinks)
        throw std::invalid_argument("family '" + spec + "': n must be a whole number from 1 to " +
                                    std::to_string(kMaxFamilyLinks));
    return out;
}

std::string family_model_name(const FamilySpec& spec) {
    return spec.family + "_" + std::to_string(spec.n);
}

std::string family_model_text(const FamilySpec& spec) {
    const bool rods = spec.family == "rods";
    const int n = spec.n;
    std::ostringstream os;
    os << "# Written by `eomgen generate --family " << spec.family << ":n=" << n
       << "` (generator/model/families.cpp).\n";
    os << "name = \"" << family_model_name(spec) << "\"\n";
    if (rods)
        os << "title = \"" << n << "-link planar chain of uniform rods\"\n";
    else
        os << "title = \"" << n << "-link planar pendulum of point masses\"\n";
    os << "source = \"eomgen model family " << spec.family << ":n=" << n << "\"\n";
    os << "description = \"\"\"\n";
    if (rods)
        os << "Uniform rods (mass m_i, length l_i) joined end to end by pins, the first hanging from a fixed "
              "pivot.\n";
    else
        os << "Point masses m_i on massless links of length l_i, the first link hanging from a fixed "
              "pivot.\n";
    os << "theta_i is link i's absolute angle from the downward vertical.\"\"\"\n";
    for (int i = 1; i <= n; ++i)
        os << "\n[[coordinates]]\nname = \"theta" << i << "\"\ninitial = 0.5\nrate = 0.0\nunit = \"rad\"\n";
    for (int i = 1; i <= n; ++i)
        os << "\n[[parameters]]\nname = \"m" << i
           << "\"\nvalue = 1.0\nunit = \"kg\"\ndescription = \"mass of " << (rods ? "rod " : "body ") << i
           << "\"\n";
    for (int i = 1; i <= n; ++i)
        os << "\n[[parameters]]\nname = \"l" << i
           << "\"\nvalue = 1.0\nunit = \"m\"\ndescription = \"length of link " << i << "\"\n";
    os << "\n[[parameters]]\nname = \"g\"\nvalue = 9.81\nunit = \"m/s^2\"\ndescription = \"gravitational "
          "acceleration\"\n";

    // T = Σ m_i/2 (ẋ_i² + ẏ_i²) [+ (1/2)(m_i l_i²/12) θ̇_i² for rods], x_i = Σ l_k sin θ_k, y_i = −Σ l_k cos
    // θ_k.
    os << "\n[lagrangian]\nT = \"\"\"\n";
    for (int i = 1; i <= n; ++i) {
        const std::string ii = std::to_string(i);
        os << (i > 1 ? "+ " : "  ") << "1/2*m" << ii << "*((" << velocity_sum("cos", i, rods) << ")^2 + ("
           << velocity_sum("sin", i, rods) << ")^2)\n";
        if (rods) os << "+ 1/24*m" << ii << "*l" << ii << "^2*theta" << ii << "'^2\n";
    }
    os << "\"\"\"\nV = \"\"\"\n";
    for (int i = 1; i <= n; ++i) os << "- m" << i << "*g*(" << depth_sum(i, rods) << ")\n";
    os << "\"\"\"\n";
    return os.str();
}

}  // namespace eomgen
