/** @file test_quantity_units.cpp  The SI units of the derived quantities (mechanics/quantity_units.hpp) and the
 * header's unit arrays (codegen/units_emitter.hpp), each against a hand count of dimensions. */
#include "codegen/units_emitter.hpp"
#include "mechanics/lagrangian.hpp"
#include "mechanics/quantity_units.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace {

struct Derived {
    eomgen::Model model;
    eomgen::Equations eq;
    eomgen::QuantityUnits units;
};

Derived derive(const std::string& text) {
    Derived d{eomgen::parse_model(text, "units.toml"), {}, {}};
    d.eq = eomgen::derive_equations(d.model);
    d.units = eomgen::quantity_units(d.model, d.eq);
    return d;
}

using Strings = std::vector<std::string>;

}  // namespace

TEST_CASE("quantity units: a Cartesian pendulum's state, h, momenta, equations and its rod's multiplier", "[units]") {
    const Derived d = derive(R"toml(name = "cartesian"
[[coordinates]]
name = "x"
unit = "m"
initial = 0.5
[[coordinates]]
name = "y"
unit = "cm"
initial = "-sqrt(1 - 0.25)*100"
[[parameters]]
name = "m"
value = 1
unit = "kg"
[[parameters]]
name = "l"
value = 1
unit = "m"
[[parameters]]
name = "g"
value = 9.81
unit = "m/s^2"
[lagrangian]
T = "m/2*(x'^2 + y'^2)"
V = "m*g*y"
[[constraints]]
name = "rod"
expr = "x^2 + y^2 - l^2"
[outputs]
r = { expr = "sqrt(x^2 + y^2)", unit = "mm" }
speed = { expr = "sqrt(x'^2 + y'^2)" }
)toml");
    const eomgen::QuantityUnits& u = d.units;
    CHECK(u.any());
    CHECK(u.state == Strings{"m", "m", "m/s", "m/s"});  // cm is read in SI
    CHECK(u.parameters == Strings{"kg", "m", "m/s^2"});
    CHECK(u.energy == "J");
    CHECK(u.momenta == Strings{"kg m/s", "kg m/s"});
    CHECK(u.equations == Strings{"N", "N"});
    // g = x² + y² − l² is m²: λ ∂g/∂x = λ·2x is a force, so λ is N/m = kg/s².
    CHECK(u.multipliers == Strings{"kg/s^2"});
    // A declared unit is the one the output is recorded in; without one, its SI unit from its expression.
    CHECK(u.outputs == Strings{"mm", "m/s"});
    CHECK(u.conserved.size() == d.eq.conserved.size());
}

TEST_CASE("quantity units: angles give torques and angular momenta, a rolling constraint's multiplier is a force",
          "[units]") {
    const Derived d = derive(R"toml(name = "roller"
[[coordinates]]
name = "x"
unit = "m"
[[coordinates]]
name = "phi"
unit = "deg"
[[parameters]]
name = "M"
value = 2
unit = "kg"
[[parameters]]
name = "I"
value = 0.1
unit = "kg m^2"
[[parameters]]
name = "R"
value = 0.3
unit = "m"
[lagrangian]
T = "M/2*x'^2 + I/2*phi'^2"
[[constraints]]
name = "roll"
kind = "nonholonomic"
expr = "x' - R*phi'"
)toml");
    const eomgen::QuantityUnits& u = d.units;
    CHECK(u.state == Strings{"m", "rad", "m/s", "rad/s"});  // deg is read in SI: rad
    CHECK(u.momenta == Strings{"kg m/s", "kg m^2/s"});
    CHECK(u.equations == Strings{"N", "N m"});
    // c = x' − R φ' is m/s: λ ∂c/∂x' = λ is the force along x.
    CHECK(u.multipliers == Strings{"N"});
    // h is conserved (L has no t), in J.
    bool h = false;
    for (std::size_t k = 0; k < d.eq.conserved.size(); ++k)
        if (d.eq.conserved[k].name == "h") {
            h = true;
            CHECK(u.conserved[k] == "J");
        }
    CHECK(h);
    // The header holds them, and the units as declared for eomgen-sim's --set and --init.
    const std::string header = eomgen::codegen::emit_unit_arrays(d.model, d.eq);
    CHECK(header.find(R"(state_units{"m", "rad", "m/s", "rad/s"})") != std::string::npos);
    CHECK(header.find(R"(energy_unit = "J")") != std::string::npos);
    CHECK(header.find(R"(multiplier_units{"N"})") != std::string::npos);
    CHECK(header.find(R"(coordinate_declared_units{"m", "deg"})") != std::string::npos);
}

TEST_CASE("quantity units: none without units, and none for what uses a symbol without one", "[units]") {
    const Derived none = derive(R"toml(name = "plain"
[[coordinates]]
name = "q"
[[parameters]]
name = "k"
value = 1
[lagrangian]
T = "q'^2/2"
V = "k*q^2/2"
)toml");
    CHECK_FALSE(none.units.any());
    CHECK(none.units.state == Strings{"", ""});
    CHECK(none.units.energy.empty());
    CHECK(eomgen::codegen::emit_unit_arrays(none.model, none.eq).find(R"(state_units{"", ""})") != std::string::npos);

    // m declared, k not: V's term has no known dimension, so neither have h, the momenta nor the equations.
    const Derived partial = derive(R"toml(name = "partial"
[[coordinates]]
name = "x"
unit = "m"
[[parameters]]
name = "m"
value = 1
unit = "kg"
[[parameters]]
name = "k"
value = 1
[lagrangian]
T = "m*x'^2/2"
V = "k*x^2/2"
)toml");
    CHECK(partial.units.state == Strings{"m", "m/s"});
    CHECK(partial.units.energy.empty());
    CHECK(partial.units.momenta == Strings{""});
    CHECK(partial.units.equations == Strings{""});
    CHECK(partial.units.parameters == Strings{"kg", ""});
}
