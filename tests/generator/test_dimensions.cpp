/** @file test_dimensions.cpp  Units and dimensional analysis (model/units.hpp, model/dimensions.hpp): UDUNITS-2's
 * factors and dimensions, the split of an expression's text into terms, and the dimension of an expression. */
#include "model/dimensions.hpp"
#include "model/units.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace {

eomgen::Dims dims(std::array<double, 7> e) {
    eomgen::Dims d;
    d.e = e;
    return d;
}

}  // namespace

TEST_CASE("units: factors to SI and dimensions, deg and rev added, offsets refused", "[units]") {
    const eomgen::Unit deg = eomgen::parse_unit("deg");
    CHECK(deg.to_si == Approx(M_PI / 180).epsilon(1e-15));
    CHECK(deg.dimension.dimensionless());
    CHECK(deg.si() == "rad");
    CHECK(eomgen::parse_unit("rev").to_si == Approx(2 * M_PI).epsilon(1e-15));
    CHECK(eomgen::parse_unit("g").to_si == Approx(1e-3).epsilon(1e-15));
    CHECK(eomgen::parse_unit("rpm").si() == "rad/s");
    const eomgen::Unit spring = eomgen::parse_unit("N/m");
    CHECK(spring.to_si == 1.0);
    CHECK(spring.dimension.str() == "kg/s^2");
    CHECK(eomgen::parse_unit("kg·m²").dimension == eomgen::parse_unit("kg m^2").dimension);
    CHECK_THROWS_AS(eomgen::parse_unit("banana"), eomgen::UnitError);
    CHECK_THROWS_AS(eomgen::parse_unit("degC"), eomgen::UnitError);
    CHECK_THROWS_AS(eomgen::parse_unit(""), eomgen::UnitError);
    const auto value = eomgen::split_value_with_unit("2*pi rad/s", [](const std::string& s) {
        if (s != "2*pi") throw std::runtime_error("not a number");
        return 2 * M_PI;
    });
    REQUIRE(value);
    CHECK(value->first == Approx(2 * M_PI));
    CHECK(value->second.text == "rad/s");
}

TEST_CASE("dimensions: an expression's text split at its top-level terms", "[units]") {
    using T = std::vector<std::pair<std::string, std::size_t>>;
    CHECK(eomgen::top_level_terms("m/2*x'^2 - k*x") == T{{"m/2*x'^2 ", 0}, {"- k*x", 9}});
    CHECK(eomgen::top_level_terms("-a*(b - c) + d") == T{{"-a*(b - c) ", 0}, {"+ d", 11}});
    CHECK(eomgen::top_level_terms("x^-2 + 1e-3*y") == T{{"x^-2 ", 0}, {"+ 1e-3*y", 5}});
    CHECK(eomgen::top_level_terms("2.5E+3*x") == T{{"2.5E+3*x", 0}});
}

TEST_CASE("dimensions: of products, powers, sums and functions, with the inconsistencies named", "[units]") {
    const GiNaC::symbol m("m"), l("l"), g("g"), th("th"), unknown("u");
    std::map<GiNaC::ex, eomgen::Dims, GiNaC::ex_is_less> table{
        {m, dims({1, 0, 0, 0, 0, 0, 0})}, {l, dims({0, 1, 0, 0, 0, 0, 0})}, {g, dims({0, 1, -2, 0, 0, 0, 0})},
        {th, eomgen::Dims{}}};
    CHECK(*eomgen::dimension_of(m * g * l * GiNaC::cos(th), table) == eomgen::energy_dims());
    CHECK(*eomgen::dimension_of(GiNaC::sqrt(l / g), table) == dims({0, 0, 1, 0, 0, 0, 0}));
    CHECK(*eomgen::dimension_of(m * (l * l + l * l * GiNaC::sin(th)), table) == dims({1, 2, 0, 0, 0, 0, 0}));
    CHECK_FALSE(eomgen::dimension_of(m * unknown, table).has_value());  // not judged
    CHECK_FALSE(eomgen::dimension_of(GiNaC::ex(0), table).has_value());  // 0 has every dimension
    CHECK_THROWS_AS(eomgen::dimension_of(GiNaC::sin(l * th), table), eomgen::DimensionError);
    CHECK_THROWS_AS(eomgen::dimension_of(m + l, table), eomgen::DimensionError);
    CHECK_THROWS_AS(eomgen::dimension_of(GiNaC::pow(l, th), table), eomgen::DimensionError);
    CHECK(eomgen::dimension_of(l + l * th, table).has_value());  // th is dimensionless
}

TEST_CASE("dimensions: a unit's factor as an exact number", "[units]") {
    CHECK(eomgen::exact_factor(0.01)->is_equal(GiNaC::numeric(1, 100)));
    CHECK(eomgen::exact_factor(M_PI / 180)->is_equal(GiNaC::numeric(1, 180) * GiNaC::Pi));
    CHECK(eomgen::exact_factor(1609.344)->is_equal(GiNaC::numeric(201168, 125)));
    CHECK_FALSE(eomgen::exact_factor(std::sqrt(2.0)).has_value());
}
