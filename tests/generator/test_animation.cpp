/** @file test_animation.cpp  [[draw]] read with its errors at their places, the scene built from it and from the
 *  bodies, springs and contacts, its numbers at samples against positions computed here by hand, and the page's
 *  escaping of a model's text. */
#include "animation/frames.hpp"
#include "animation/html_page.hpp"
#include "animation/scene.hpp"
#include "model/model_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <string>

namespace {

using eomgen::ModelError;
using eomgen::animation::Frames;
using eomgen::animation::PrimitiveKind;
using eomgen::animation::SampleTable;
using eomgen::animation::SolidShape;

const char* kPendulum = R"~(
name = "pend"
[[coordinates]]
name = "phi"
initial = 0.5
[[parameters]]
name = "l"
value = 2.0
[lagrangian]
T = "1/2*l^2*phi'^2"
V = "-l*cos(phi)"
)~";

eomgen::Model model_with(const std::string& extra, const char* base = kPendulum) {
    return eomgen::parse_model(std::string(base) + extra, "m.toml");
}

/// The message of the ModelError reading `extra` after the pendulum throws, with its place.
std::string error_of(const std::string& extra, const char* base = kPendulum) {
    try {
        model_with(extra, base);
    } catch (const ModelError& e) {
        return e.where().str() + ": " + e.message();
    }
    return "no error";
}

/// One row per time: t, phi, phi_dot.
SampleTable pendulum_samples(const std::vector<double>& times) {
    SampleTable s;
    s.columns = {"t", "phi", "phi_dot"};
    s.units = {"s", "rad", "rad/s"};
    for (double t : times) s.rows.push_back({t, 0.5 * std::cos(t), -0.5 * std::sin(t)});
    return s;
}

const char* kTwoBodies = R"~(
name = "bodies"
[[coordinates]]
name = "q"
initial = 0.3
[[parameters]]
name = "a"
value = 0.5
[[bodies]]
name = "arm"
mass = 2
shape = "box"
dimensions = ["a", "0.1", "0.2"]
position = ["0", "0", "1"]
orientation = [["z", "q"]]
[[bodies]]
name = "wheel"
mass = 1
inertia = ["0.25", "0.5", "0.25"]
position = { body = "arm", point = ["a", "0", "0"] }
orientation = { body = "arm", rotations = [["y", "2*q"]] }
[[contacts]]
name = "tyre"
body = "wheel"
radius = "0.3"
axis = "y"
[gravity]
vector = ["0", "0", "-9.81"]
)~";

}  // namespace

TEST_CASE("[[draw]] entries are read with their points, options and colours", "[animation]") {
    const eomgen::Model m = model_with(R"~(
[[draw]]
link = [["0", "0"], ["l*sin(phi)", "-l*cos(phi)"]]
colour = "#abc"
[[draw]]
point = ["l*sin(phi)", "-l*cos(phi)", "0"]
radius = "0.1"
label = "bob"
color = "Red"
[[draw]]
spring = [["0", "1"], ["l*sin(phi)", "-l*cos(phi)"]]
coils = 5
[[draw]]
circle = ["0", "0"]
radius = "l"
fill = true
[[draw]]
trace = ["l*sin(phi)", "-l*cos(phi)"]
[[draw]]
ground = "y"
height = "-l"
)~");
    REQUIRE(m.drawing.size() == 6);
    CHECK(m.drawing[0].kind == eomgen::DrawKind::Link);
    CHECK(m.drawing[0].points.size() == 2);
    CHECK(m.drawing[0].planar_given);
    CHECK(m.drawing[0].colour == "#aabbcc");
    CHECK(m.drawing[1].colour == "#d62728");  // "Red", a name, any case
    CHECK(m.drawing[1].label == "bob");
    CHECK_FALSE(m.drawing[1].radius.is_zero());
    CHECK(m.drawing[2].coils == 5);
    CHECK(m.drawing[3].fill);
    CHECK(m.drawing[4].kind == eomgen::DrawKind::Trace);
    CHECK(m.drawing[5].ground_axis == 'y');
    CHECK(m.drawing[0].where.line == 14);  // the value of `link`
}

TEST_CASE("A wrong [[draw]] entry is an error at its place", "[animation]") {
    CHECK(error_of("[[draw]]\npoint = [\"0\", \"0\"]\nlink = [[\"0\", \"0\"], [\"1\", \"1\"]]\n") ==
          "m.toml:14:8: a [[draw]] entry draws one thing: this one has both 'point' and 'link' (write a second [[draw]])");
    CHECK(error_of("[[draw]]\nlabel = \"x\"\n").find("m.toml:12:1: a [[draw]] entry needs what it draws") == 0);
    CHECK(error_of("[[draw]]\npoint = [\"0\", \"0\"]\ncoils = 3\n") ==
          "m.toml:14:9: 'coils' belongs to a spring, not a point");
    CHECK(error_of("[[draw]]\nlink = [[\"0\", \"0\"]]\n") == "m.toml:13:8: a link joins two or more points, not 1");
    CHECK(error_of("[[draw]]\npoint = [\"0\"]\n").find("m.toml:13:9: a point of the point is [x, y]") == 0);
    CHECK(error_of("[[draw]]\npoint = [\"l*sin(phi')\", \"0\"]\n") ==
          "m.toml:13:17: velocity phi' not allowed here: a drawing is in the coordinates, the parameters and t, "
          "without velocities");
    CHECK(error_of("[[draw]]\npoint = [\"0\", \"0\"]\ncolour = \"reddish\"\n").find("m.toml:14:11: a colour is") == 0);
    CHECK(error_of("[[draw]]\nground = \"w\"\n").find("m.toml:13:11: 'ground' is the axis normal") == 0);
    CHECK(error_of("[[draw]]\npoint = [\"0\", \"0\"]\nlable = \"x\"\n").find("unknown key 'lable' in [[draw]]; did you mean "
                                                                       "'label'?") != std::string::npos);
    CHECK(error_of("[[draw]]\nbody = \"arms\"\n", kTwoBodies).find("no body named 'arms' in [[bodies]]; did you mean "
                                                                 "'arm'?") != std::string::npos);
    try {
        eomgen::parse_model(std::string("draw = 3\n") + kPendulum, "m.toml");
        FAIL("draw = 3 was read");
    } catch (const ModelError& e) {
        CHECK(e.where().str() + ": " + e.message() ==
              "m.toml:1:8: 'draw' is an array of tables, written [[draw]] (docs/model_files.md, Drawing)");
    }
}

TEST_CASE("A planar drawing is drawn in 2-D, anything off the plane or a body in 3-D", "[animation]") {
    using eomgen::animation::build_scene;
    CHECK(build_scene(model_with("[[draw]]\npoint = [\"l*sin(phi)\", \"-l*cos(phi)\"]\n")).planar);
    CHECK_FALSE(build_scene(model_with("[[draw]]\npoint = [\"l*sin(phi)\", \"0\", \"-l*cos(phi)\"]\n")).planar);
    CHECK_FALSE(build_scene(model_with("[[draw]]\ncircle = [\"0\", \"0\"]\nradius = \"1\"\nnormal = [\"1\", \"0\", \"0\"]\n"))
                    .planar);
    CHECK_FALSE(build_scene(model_with("", kTwoBodies)).planar);
    // Nothing to draw: a ModelError before anything runs.
    CHECK_THROWS_WITH(build_scene(model_with("")),
                      Catch::Contains("nothing to animate: the model has no [[draw]] entries, bodies or springs"));
}

TEST_CASE("The frames hold the drawn points where the coordinates put them", "[animation]") {
    const eomgen::Model m = model_with(R"~(
[[draw]]
link = [["0", "0"], ["l*sin(phi)", "-l*cos(phi)"]]
[[draw]]
point = ["l*sin(phi)", "-l*cos(phi)"]
)~");
    const Frames f = eomgen::animation::evaluate_frames(eomgen::animation::build_scene(m), m, {{"l", 1.5}},
                                                        pendulum_samples({0, 0.5, 1.0}));
    REQUIRE(f.t.size() == 3);
    REQUIRE(f.items.size() == 2);
    for (std::size_t k = 0; k < 3; ++k) {
        const double phi = 0.5 * std::cos(f.t[k]);
        const double* link = &f.values[0][6 * k];
        CHECK(link[3] == Approx(1.5 * std::sin(phi)));  // --set l=1.5, not the file's 2
        CHECK(link[4] == Approx(-1.5 * std::cos(phi)));
        CHECK(f.values[1][3 * k + 1] == Approx(-1.5 * std::cos(phi)));
    }
}

TEST_CASE("Bodies are drawn as their solids, wheels as their rims about the contact's axis", "[animation]") {
    const eomgen::Model m = model_with(R"~(
[[draw]]
point = { body = "arm", point = ["a", "0", "0"] }
)~", kTwoBodies);
    const eomgen::animation::Scene scene = eomgen::animation::build_scene(m);
    // arm (a box), wheel (its rim), the point, the ground under the contact
    REQUIRE(scene.items.size() == 4);
    CHECK(scene.items[0].shape == SolidShape::Box);
    CHECK(scene.items[1].shape == SolidShape::Ring);
    CHECK(scene.items[2].kind == PrimitiveKind::Point);
    CHECK(scene.items[3].kind == PrimitiveKind::Ground);
    SampleTable s;
    s.columns = {"t", "q", "q_dot"};
    s.units = {"s", "", ""};
    s.rows = {{0.0, 0.7, 0.0}};
    const Frames f = eomgen::animation::evaluate_frames(scene, m, {}, s);
    const double q = 0.7, a = 0.5;
    // The arm turned by q about z: its Aᵀ's first column is its x axis in space, (cos q, sin q, 0).
    const std::vector<double>& arm = f.values[0];
    CHECK(arm[3] == Approx(std::cos(q)));
    CHECK(arm[6] == Approx(std::sin(q)));
    CHECK(arm[9] == Approx(0).margin(1e-15));
    CHECK(arm[12] == Approx(a));  // the box's sides
    // The point a along the arm's x axis from its centre (0, 0, 1).
    const std::vector<double>& point = f.values[2];
    CHECK(point[0] == Approx(a * std::cos(q)));
    CHECK(point[1] == Approx(a * std::sin(q)));
    CHECK(point[2] == Approx(1));
    // The rim's own z (its third column) is the wheel's y axis in space: the arm's y, (-sin q, cos q, 0), which
    // the wheel's turn about that axis leaves as it is; its radius the contact's.
    const std::vector<double>& rim = f.values[1];
    CHECK(rim[5] == Approx(-std::sin(q)));
    CHECK(rim[8] == Approx(std::cos(q)));
    CHECK(rim[11] == Approx(0).margin(1e-15));
    CHECK(rim[12] == Approx(0.3));
    CHECK(f.up[2] == Approx(1));  // against gravity
}

TEST_CASE("A body given by its inertia is drawn as the uniform ellipsoid of the same moments", "[animation]") {
    // A uniform ellipsoid of mass 5 and semi-axes 1, 2, 3: I1 = m (b² + c²)/5 = 13, I2 = 10, I3 = 5.
    const eomgen::Model m = eomgen::parse_model(R"~(
name = "egg"
[[coordinates]]
name = "q"
[[bodies]]
name = "shell"
mass = 5
inertia = ["13", "10", "5"]
position = ["0", "0", "0"]
orientation = [["z", "q"]]
)~", "egg.toml");
    SampleTable s;
    s.columns = {"t", "q", "q_dot"};
    s.units = {"", "", ""};
    s.rows = {{0.0, 0.1, 0.0}};
    const Frames f = eomgen::animation::evaluate_frames(eomgen::animation::build_scene(m), m, {}, s);
    REQUIRE(f.items.size() == 1);
    CHECK(f.items[0].shape == SolidShape::Ellipsoid);
    REQUIRE(f.values[0].size() == 15);
    CHECK(f.values[0][12] == Approx(1));
    CHECK(f.values[0][13] == Approx(2));
    CHECK(f.values[0][14] == Approx(3));
}

TEST_CASE("A drawing that is not finite at a sample is an error naming its place and the time", "[animation]") {
    const eomgen::Model m = model_with("[[draw]]\npoint = [\"1/sin(phi)\", \"0\"]\nlabel = \"pole\"\n");
    SampleTable s = pendulum_samples({0.0});
    s.rows.push_back({0.25, 0.0, 0.0});  // phi = 0: 1/sin(phi) has no value
    CHECK_THROWS_WITH(eomgen::animation::evaluate_frames(eomgen::animation::build_scene(m), m, {}, s),
                      Catch::Contains("m.toml:13:9: the [[draw]] point 'pole' is not a finite number at t = 0.25"));
}

TEST_CASE("The samples' CSV is read with its units and quoted fields", "[animation]") {
    const std::string path = "test_animation_samples.csv";
    {
        std::ofstream out(path);
        out << "t [s],phi [rad],\"a, b\"\n0,0.5,1\n0.1,0.4,2\n";
    }
    const SampleTable s = eomgen::animation::read_sample_table(path);
    CHECK(s.columns == std::vector<std::string>{"t", "phi", "a, b"});
    CHECK(s.units == std::vector<std::string>{"s", "rad", ""});
    REQUIRE(s.rows.size() == 2);
    CHECK(s.rows[1][1] == Approx(0.4));
    {
        std::ofstream out(path);
        out << "t,phi\n0,0.5\n0.1\n";
    }
    CHECK_THROWS_WITH(eomgen::animation::read_sample_table(path),
                      Catch::Contains("test_animation_samples.csv:3: 1 fields where the header has 2"));
    std::remove(path.c_str());
}

TEST_CASE("A model's text goes into the page as data, never as markup", "[animation]") {
    eomgen::animation::Page page;
    page.title = "</script><script>alert(1)</script> & <b>";
    page.equations = {{"T", "1/2*m*v^2 <!-- -->"}};
    const std::string html = eomgen::animation::html_page(page);
    CHECK(html.find("<script>alert") == std::string::npos);
    CHECK(html.find("<b>") == std::string::npos);
    CHECK(html.find("<!-- -->") == std::string::npos);
    CHECK(html.find("\\u003c/script>\\u003cscript>alert(1)\\u003c/script> & \\u003cb>") != std::string::npos);
    // The page fetches nothing: no address of a network anywhere in it.
    CHECK(html.find("http://") == std::string::npos);
    CHECK(html.find("https://") == std::string::npos);
    CHECK(html.find("src=") == std::string::npos);
}
