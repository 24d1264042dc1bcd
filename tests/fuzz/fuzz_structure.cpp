// Structural fuzzing of models (issue 30): the input bytes are not the model file itself but the choices that
// build one, so that nearly every input is a well-formed model and the fuzzer reaches the mechanics instead of
// the TOML reader. A small reader hands out the bytes as choices (0, the simplest choice, once they run out);
// from them a model is written out as TOML: a random tree of point masses in T (pendulum links, carts, vertical
// and inclined sliders, polar (r, phi) and Cartesian (x, y) joints, a support driven in t), [[bodies]] (a shape
// or an inertia tensor, on a link or as a heavy top in Euler angles; oriented by a chain of rotations or placed on
// and oriented from another body), a coin rolling on the ground and wheels on any body ([[contacts]]),
// [[springs]], [forces], a Rayleigh R,
// holonomic and nonholonomic [[constraints]] (couplings, circles, lines, rheonomic ones, redundant ones, ones
// that hold identically, that fix every coordinate, that are singular at the initial state, that are not
// linear in the velocities), a coordinate that appears nowhere, parameter values including 0, and a few
// deliberately broken files.
//
// Each model goes through what the commands do, in process: parse_model, derive_equations (generate, show,
// modes, run and check all start there), emit_model_header (generate), derive_hamiltonian (show),
// small_oscillations (modes), a steady motion about a random rate of the last coordinate (modes --steady), the
// animation's scene at the initial state (run --animate), the interpreter's table there (run --interpret) and a short run (RK4 on M q'' = f + A^T lambda, A q'' = gamma, from the model's
// initial state and parameter values, M and f evaluated with GiNaC). Properties, each a finding (an abort with
// the model's text) when broken:
//   - no crash, no hang (the driver's --slow limit), and no exception but a ModelError located at
//     fuzzed.toml:line:col, or a ModesError from small_oscillations or the steady motion;
//   - every number the steady motion reports (state, multipliers, A, M, C, K, eigenvalues) is finite;
//   - every number small_oscillations reports (equilibria, M, K, C, G, A, B, multipliers, tangent bases,
//     eigenvalues, omega^2 and shapes of the modes, growth rates) is finite;
//   - the header has no NUL byte and no `nan` or `inf` token;
//   - the run: M, f (and A, gamma) at a state are real finite numbers, or the state is a detected singularity
//     (a pole GiNaC refuses, a complex value, M or the constraint system without full rank): never a NaN that
//     passes silently; M is symmetric; the derived quantities agree with one another there
//     (euler_lagrange = M q'' - f + Q for any q'', and H(q, p(q, q')) = h(q, q') where H is formed).
// With EOMGEN_FUZZ_STATS set, the counts of what happened are printed at exit (docs/reliability.md); with
// EOMGEN_FUZZ_STRUCTURE_TOML set, each input is taken as a model file's text instead (to replay a finding of
// tests/fuzz/findings_structure/); with EOMGEN_FUZZ_STRUCTURE_PRINT set, each generated model is printed.
#include "animation/frames.hpp"
#include "codegen/cpp_emitter.hpp"
#include "interpreter/interpreted_table.hpp"
#include "harness.hpp"
#include "mechanics/pole_free_subs.hpp"
#include "mechanics/hamiltonian.hpp"
#include "mechanics/lagrangian.hpp"
#include "mechanics/small_oscillations.hpp"
#include "mechanics/steady_motion.hpp"
#include "model/model_file.hpp"

#include <Eigen/Dense>
#include <ginac/ginac.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr const char* harness = "fuzz_structure";
constexpr const char* file = "fuzzed.toml";

// ---------------------------------------------------------------------------------------------------------------
// The bytes as choices.

class ByteReader {
public:
    ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    /// A choice among k (0 … k−1); 0 once the bytes run out.
    unsigned below(std::size_t k) {
        if (k <= 1) return 0;
        if (at_ >= size_) return 0;
        return unsigned(data_[at_++] % k);
    }
    /// True with about `percent` % chance; false once the bytes run out.
    bool chance(unsigned percent) { return at_ < size_ && data_[at_++] % 100 < percent; }
    template <class T>
    const T& one_of(const std::vector<T>& v) { return v[below(v.size())]; }

private:
    const std::uint8_t* data_;
    std::size_t size_, at_ = 0;
};

// ---------------------------------------------------------------------------------------------------------------
// The model, written out.

/// A sum of terms, each with its sign in front ("-l*cos(q)"), as an expression.
std::string sum(const std::vector<std::string>& terms) {
    if (terms.empty()) return "0";
    std::string s;
    for (const std::string& t : terms) {
        if (s.empty())
            s = t;
        else if (t[0] == '-')
            s += " - " + t.substr(1);
        else
            s += " + " + t;
    }
    return s;
}

std::string toml_string(const std::string& s) { return "\"" + s + "\""; }

/// A number as a TOML float ("0.5", "2.0"), a constant expression ("pi/2") as a string.
std::string toml_value(const std::string& s) {
    if (s.find_first_not_of("0123456789.-") != std::string::npos) return toml_string(s);
    return s.find('.') == std::string::npos ? s + ".0" : s;
}

std::string triple(const std::string& a, const std::string& b, const std::string& c) {
    return "[" + toml_string(a) + ", " + toml_string(b) + ", " + toml_string(c) + "]";
}

/// A point of the planar tree: its horizontal and vertical position and velocity, as sums of terms.
struct Point {
    std::vector<std::string> x, y, vx, vy;
    std::string angle;  ///< the coordinate of the link that carries it, "" when none
};

enum class Kind { Angle, Length, Radial };

struct Coord {
    std::string name, initial, rate;
    Kind kind = Kind::Angle;
    bool write_initial = true;
};

class ModelWriter {
public:
    explicit ModelWriter(ByteReader& in) : in_(in) {}

    std::string write() {
        // About one model in four is meant to be degenerate (the choices marked rare() below are open to it
        // alone); the others are meant to be valid, though random parameter values and initial states still
        // make some of them singular.
        degenerate_ = in_.chance(25);
        // ≤ 4 coordinates mostly, up to 6 now and then: one input stays well under a second.
        const std::size_t target = in_.chance(10) ? 1 + in_.below(6) : 1 + in_.below(4);
        while (coords_.size() < target) add_joint(target);
        if (rare(10) && coords_.size() < 6) unused_ = new_coord("u", Kind::Length).name;  // appears nowhere
        extras();
        constraints();
        return text();
    }

private:
    ByteReader& in_;
    std::vector<Coord> coords_;
    std::vector<std::pair<std::string, std::string>> params_;  // name, value (in order of first use)
    std::vector<Point> points_{Point{}};                       // [0]: the ground
    std::vector<std::string> T_, V_, bodies_, springs_, constraints_, body_names_, contacts_;
    std::vector<std::pair<std::string, std::string>> forces_;
    std::vector<std::string> holonomic_, nonholonomic_;  // for redundant constraints
    std::string R_, unused_, outputs_, extra_sections_;
    bool gravity_ = false, broken_T_ = false, degenerate_ = false, generate_stiffness_ = false, generate_jacobians_ = false;

    /// A degenerate choice, taken with about `percent` % chance in a degenerate model only.
    bool rare(unsigned percent) { return degenerate_ && in_.chance(percent); }
    int counter_ = 0;

    std::string param(const std::string& name) {
        for (const auto& p : params_)
            if (p.first == name) return name;
        static const std::vector<std::string> values = {"1", "0.5", "2", "9.81", "0", "1e-3", "1e3", "0.3", "-1"};
        params_.emplace_back(name, in_.one_of(values));
        return name;
    }

    Coord& new_coord(const std::string& prefix, Kind kind) {
        Coord c;
        c.name = prefix + std::to_string(++counter_);
        c.kind = kind;
        static const std::vector<std::string> angles = {"0.5", "0", "-0.3", "pi/2", "pi", "1", "0.1", "2"};
        static const std::vector<std::string> lengths = {"0", "1", "0.5", "-0.2", "2"};
        static const std::vector<std::string> radii = {"1", "0.5", "0", "2"};
        static const std::vector<std::string> rates = {"0", "0.2", "-1", "3", "0.5"};
        c.initial = in_.one_of(kind == Kind::Angle ? angles : kind == Kind::Length ? lengths : radii);
        c.rate = in_.one_of(rates);
        c.write_initial = !in_.chance(5);  // the defaults, 0 and 0
        if (!c.write_initial) c.initial = c.rate = "0";
        coords_.push_back(c);
        return coords_.back();
    }

    std::string coord(std::size_t i) const { return coords_[i].name; }
    std::string random_coord() { return coords_.empty() ? "0" : coord(in_.below(coords_.size())); }
    /// Another coordinate than `a` where there is one.
    std::string other_coord(const std::string& a) {
        std::string b = random_coord();
        for (std::size_t i = 0; b == a && i < coords_.size(); ++i) b = coord(i);
        return b;
    }

    std::string mass(const std::string& index) {
        switch (in_.below(5)) {
            case 1: return param("m1");
            case 2: return "2";
            case 3: return rare(40) ? "0" : "1";  // a literal 0: that mass is not there
            default: return param("m" + index);
        }
    }

    std::string length(const std::string& index) {
        switch (in_.below(6)) {
            case 1: return param("l1");
            case 2: return "1";
            case 3: return rare(40) ? "0" : "0.5";  // a link of length 0: its angle appears nowhere
            default: return param("l" + index);
        }
    }

    /// One more joint of the tree, hung from a random point already there.
    void add_joint(std::size_t target) {
        const std::size_t room = target - coords_.size();
        const std::size_t parent_index = in_.below(points_.size());
        Point p = points_[parent_index];
        p.angle.clear();
        if (parent_index == 0 && in_.chance(6)) {  // a support driven in t (explicit time in T)
            const std::string A = param("amp"), w = param("omega");
            p.x.push_back(A + "*cos(" + w + "*t)");
            p.vx.push_back("-" + A + "*" + w + "*sin(" + w + "*t)");
        }
        unsigned joint = in_.below(8);
        if ((joint == 4 || joint == 5) && room < 2) joint = 0;
        if (joint == 6 && room < 3) joint = 1;
        const std::string index = std::to_string(counter_ + 1);
        switch (joint) {
            case 1: {  // cart along x
                const std::string q = new_coord("x", Kind::Length).name;
                p.x.push_back(q);
                p.vx.push_back(q + "'");
                break;
            }
            case 2: {  // slider along the vertical
                const std::string q = new_coord("s", Kind::Length).name;
                p.y.push_back(q);
                p.vy.push_back(q + "'");
                break;
            }
            case 3: {  // slider on an incline
                const std::string q = new_coord("s", Kind::Length).name, a = param("alpha");
                p.x.push_back(q + "*cos(" + a + ")");
                p.y.push_back(q + "*sin(" + a + ")");
                p.vx.push_back("cos(" + a + ")*" + q + "'");
                p.vy.push_back("sin(" + a + ")*" + q + "'");
                break;
            }
            case 4: {  // polar: a spring pendulum
                const std::string r = new_coord("r", Kind::Radial).name, ph = new_coord("ph", Kind::Angle).name;
                p.x.push_back(r + "*sin(" + ph + ")");
                p.y.push_back("-" + r + "*cos(" + ph + ")");
                p.vx.push_back(r + "'*sin(" + ph + ")");
                p.vx.push_back(r + "*cos(" + ph + ")*" + ph + "'");
                p.vy.push_back("-" + r + "'*cos(" + ph + ")");
                p.vy.push_back(r + "*sin(" + ph + ")*" + ph + "'");
                p.angle = ph;
                break;
            }
            case 5: {  // Cartesian (x, y)
                const std::string x = new_coord("x", Kind::Length).name, y = new_coord("y", Kind::Length).name;
                p.x.push_back(x);
                p.y.push_back(y);
                p.vx.push_back(x + "'");
                p.vy.push_back(y + "'");
                break;
            }
            case 6:  // a heavy top in Euler angles: three coordinates, a body, no point mass
                add_top();
                return;
            default: {  // a pendulum link
                const std::string q = new_coord("th", Kind::Angle).name, l = length(index);
                p.x.push_back(l + "*sin(" + q + ")");
                p.y.push_back("-" + l + "*cos(" + q + ")");
                p.vx.push_back(l + "*cos(" + q + ")*" + q + "'");
                p.vy.push_back(l + "*sin(" + q + ")*" + q + "'");
                p.angle = q;
            }
        }
        points_.push_back(p);
        const std::string X = sum(p.x), Y = sum(p.y);
        if (in_.chance(25)) {
            add_body(p, index);
        } else {
            const std::string m = mass(index);
            T_.push_back("1/2*" + m + "*((" + sum(p.vx) + ")^2 + (" + sum(p.vy) + ")^2)");
            if (!p.y.empty() && !in_.chance(15)) V_.push_back(m + "*" + param("g") + "*(" + Y + ")");
        }
        if (in_.chance(8) && outputs_.size() < 200) outputs_ += "out" + index + " = " + toml_string(X) + "\n";
    }

    std::string shape_and_inertia(const std::string& index) {
        static const std::vector<std::pair<std::string, int>> shapes = {
            {"thin_disk", 1}, {"thin_rod", 1}, {"ring", 1}, {"solid_sphere", 1}, {"hollow_sphere", 1},
            {"solid_cone", 2}, {"cylinder", 2}, {"box", 3}, {"rectangular_plate", 2}, {"right_triangle_plate", 2}};
        std::string s;
        switch (in_.below(4)) {
            case 1:  // a diagonal tensor
                s += "inertia = " + triple(param("I1"), param("I2"), param("I3")) + "\n";
                break;
            case 2:  // a full symmetric one
                s += "inertia = [[" + toml_string(param("I1")) + ", " + toml_string(param("I12")) + ", 0], [" +
                     toml_string(param("I12")) + ", " + toml_string(param("I2")) + ", 0], [0, 0, " + toml_string(param("I3")) + "]]\n";
                break;
            default: {
                const auto& [shape, n] = in_.one_of(shapes);
                int dims = n;
                std::string name = shape;
                if (rare(10)) dims = n + 1;     // the wrong number of dimensions: an error at the body
                if (rare(5)) name = "sphere";   // an unknown shape: the same
                s += "shape = " + toml_string(name) + "\ndimensions = [";
                for (int d = 0; d < dims; ++d) s += (d ? ", " : "") + toml_string(rare(20) ? "0" : param("a" + index + "_" + std::to_string(d)));
                s += "]\n";
            }
        }
        return s;
    }

    void add_body(const Point& p, const std::string& index) {
        const std::string name = "body" + index;
        std::string b = "[[bodies]]\nname = " + toml_string(name) + "\nmass = " +
                        (in_.chance(20) ? std::string("2") : toml_string(param("mb" + index))) + "\n";
        b += shape_and_inertia(index);
        std::string angle = p.angle.empty() ? "0" : p.angle;
        if (in_.chance(15)) angle = random_coord();
        if (!body_names_.empty() && in_.chance(15)) {
            // on the body before: a point of it, oriented from it by one more rotation (or as it, or from a body not
            // yet declared: an error at its place)
            const std::string parent = rare(10) ? std::string("later") : body_names_.back();
            b += "position = { body = " + toml_string(parent) + ", point = " + triple("0", "0", param("l1")) + " }\n";
            b += "orientation = { body = " + toml_string(parent) +
                 (in_.chance(50) ? ", rotations = [[" + toml_string(in_.one_of(std::vector<std::string>{"x", "y", "z", "w"})) +
                                       ", " + toml_string(angle) + "]] }\n"
                                 : std::string(" }\n"));
            bodies_.push_back(b);
            body_names_.push_back(name);
            gravity_ = true;
            return;
        }
        b += "position = " + triple("0", sum(p.x), sum(p.y)) + "\n";
        if (in_.chance(15)) {
            // a chain of one to three rotations about body axes
            std::string chain = "[";
            const unsigned n = 1 + in_.below(3);
            for (unsigned k = 0; k < n; ++k)
                chain += std::string(k ? ", " : "") + "[" + toml_string(in_.one_of(std::vector<std::string>{"x", "y", "z"})) + ", " +
                         toml_string(k == 0 ? angle : random_coord()) + "]";
            b += "orientation = " + chain + "]\n";
        } else if (rare(15) && coords_.size() < 6) {
            // spinning about its own z axis, by a coordinate nothing else moves: with a thin rod, no inertia
            b += "orientation = " + triple("0", angle, new_coord("sp", Kind::Angle).name) + "\n";
        } else if (angle != "0" || in_.chance(50)) {
            b += "orientation = " + triple("0", angle, "0") + "\n";
        }
        if (in_.chance(10) && (b.find("orientation = [[") == std::string::npos || rare(30)))
            b += "sequence = " + toml_string(in_.one_of(std::vector<std::string>{"zxz", "zyz", "xyz", "zyx", "xzx"})) + "\n";
        if (in_.chance(15)) b += "force = " + triple(param("F0"), "0", "0") + "\n";
        if (in_.chance(10)) b += "torque = " + triple("0", "0", "-" + param("c") + "*" + random_coord() + "'") + "\n";
        bodies_.push_back(b);
        body_names_.push_back(name);
        gravity_ = true;
    }

    void add_top() {
        const std::string phi = new_coord("phi", Kind::Angle).name, theta = new_coord("theta", Kind::Angle).name,
                          psi = new_coord("psi", Kind::Angle).name;
        const std::string index = std::to_string(counter_);
        const std::string L = rare(30) ? "0" : param("h" + index);  // L = 0: a top with its centre at the pivot
        std::string b = "[[bodies]]\nname = \"top" + index + "\"\nmass = " + toml_string(param("M" + index)) + "\n";
        b += shape_and_inertia(index);
        b += "position = " + triple(L + "*sin(" + theta + ")*sin(" + phi + ")", "-" + L + "*sin(" + theta + ")*cos(" + phi + ")",
                                    L + "*cos(" + theta + ")") + "\n";
        b += "orientation = " + triple(phi, theta, psi) + "\n";
        bodies_.push_back(b);
        body_names_.push_back("top" + index);
        gravity_ = true;
    }

    /// A coin rolling on the ground in its own five coordinates (as models/rolling_disc.toml), or a wheel on a body
    /// the model already has (any geometry: its contact may be singular or hold identically).
    void contacts() {
        if (coords_.size() <= 2 && in_.chance(8)) {
            const std::string x = new_coord("cx", Kind::Length).name, y = new_coord("cy", Kind::Length).name,
                              h = new_coord("head", Kind::Angle).name, lean = new_coord("lean", Kind::Angle).name,
                              spin = new_coord("spin", Kind::Angle).name, R = param("R"), idx = std::to_string(++counter_);
            std::string b = "[[bodies]]\nname = \"coin" + idx + "\"\nmass = " + toml_string(param("mc")) + "\n";
            b += "inertia = " + triple(R + "^2/4", R + "^2/2", R + "^2/4") + "\n";
            b += "position = " + triple(x + " + " + R + "*sin(" + lean + ")*sin(" + h + ")",
                                        y + " - " + R + "*sin(" + lean + ")*cos(" + h + ")", R + "*cos(" + lean + ")") + "\n";
            b += "orientation = [[\"z\", " + toml_string(h) + "], [\"x\", " + toml_string(lean) + "], [\"y\", " +
                 toml_string("-" + spin) + "]]\n";
            bodies_.push_back(b);
            body_names_.push_back("coin" + idx);
            contacts_.push_back("[[contacts]]\nname = \"ground" + idx + "\"\nbody = \"coin" + idx + "\"\nradius = " +
                                toml_string(R) + "\naxis = \"y\"\n" + (in_.chance(30) ? "tube = " + toml_string(param("rho")) + "\n" : ""));
            gravity_ = true;
        }
        if (!body_names_.empty() && in_.chance(6)) {
            const std::string idx = std::to_string(++counter_);
            contacts_.push_back("[[contacts]]\nname = \"wheel" + idx + "\"\nbody = " +
                                toml_string(rare(10) ? std::string("nobody") : in_.one_of(body_names_)) + "\nradius = " +
                                toml_string(param("r")) + "\naxis = " +
                                toml_string(in_.one_of(std::vector<std::string>{"x", "y", "z"})) + "\n" +
                                (in_.chance(30) ? "normal = " + toml_string(in_.one_of(std::vector<std::string>{"+z", "-y", "+x", "up"})) + "\n" : ""));
        }
    }

    void extras() {
        contacts();
        const std::size_t n = coords_.size();
        for (std::size_t i = 0; i < n; ++i) {
            const std::string q = coord(i);
            if (in_.chance(10)) T_.push_back("1/2*" + param("J") + "*" + q + "'^2");                 // joint inertia
            if (in_.chance(10)) V_.push_back("1/2*" + param("k") + "*(" + q + " - " + param("q0") + ")^2");  // a spring on q
            if (in_.chance(5)) V_.push_back(param("k") + "*cos(" + q + ")");
            if (in_.chance(4)) V_.push_back(in_.chance(50) ? param("k") + "*abs(" + q + ")"  // a V-shaped well
                                                           : "1/2*" + param("k") + "*min(" + q + ", 0)^2");  // one-sided
            if (in_.chance(5) && n > 1) T_.push_back(param("B") + "*" + q + "*" + random_coord() + "'");  // linear in q'
            if (in_.chance(5)) T_.push_back("1/2*" + param("m1") + "*" + param("omega") + "^2*sin(" + q + ")^2");  // T0
            if (in_.chance(12)) {
                // The non-smooth ones (issue 36): quadratic drag, dry friction (also as Q'/sqrt(Q'^2)), a switch,
                // a one-sided spring, a saturated torque.
                static const std::vector<std::string> forms = {
                    "-c*Q'", "F0*cos(omega*t)", "F0", "-c*Q'^3", "F0*sin(P)", "-c*Q'*abs(Q')", "-F0*sign(Q')",
                    "-F0*Q'/sqrt(Q'^2)", "F0*heaviside(P)", "-c*max(P, 0)", "clamp(-c*Q', -F0, F0)",
                    "-F0*sign(Q' - omega)"};
                std::string f = in_.one_of(forms);
                if (f.find('c') != std::string::npos) param("c");
                if (f.find("F0") != std::string::npos) param("F0");
                if (f.find("omega") != std::string::npos) param("omega");
                f = std::regex_replace(f, std::regex("Q"), q);
                f = std::regex_replace(f, std::regex("P"), random_coord());
                if (rare(5)) f = "1/0";  // a force GiNaC refuses as it builds: an error at the character
                forces_.emplace_back(q, f);
            }
        }
        if (in_.chance(12)) {
            const std::string a = random_coord(), b = random_coord();
            R_ = in_.chance(50) ? "1/2*" + param("c") + "*(" + a + "'^2 + " + b + "'^2)"
                                : "1/2*" + param("c") + "*(" + a + "' - " + b + "')^2";
        }
        if (in_.chance(10)) {  // springs: from a fixed point to a body, or to a point of the tree
            const std::string name = "spring" + std::to_string(springs_.size() + 1);
            std::string s = "[[springs]]\nname = " + toml_string(name) + "\nstiffness = " + toml_string(param("k")) + "\n";
            if (in_.chance(50)) s += "length = " + toml_string(param("l0")) + "\n";
            s += "from = " + (in_.chance(50) ? triple("0", "0", "0") : triple("0", "1", "0")) + "\n";
            if (!body_names_.empty() && in_.chance(50)) {
                s += "to = { body = " + toml_string(in_.one_of(body_names_)) + ", point = " + triple("0", "0", "0.5") + " }\n";
            } else {
                const Point& p = points_[in_.below(points_.size())];
                s += "to = " + triple("0", sum(p.x), sum(p.y)) + "\n";
            }
            springs_.push_back(s);
        }
        generate_stiffness_ = in_.chance(3);
        generate_jacobians_ = in_.chance(3);  // an error with constraints: left out below unless degenerate
    }

    void constraint(const std::string& expr, bool holonomic) {
        const std::string name = "c" + std::to_string(constraints_.size() + 1);
        std::string s = "[[constraints]]\nname = " + toml_string(name) + "\n";
        if (!holonomic)
            s += "kind = \"nonholonomic\"\n";
        else if (in_.chance(50))
            s += "kind = \"holonomic\"\n";
        s += "expr = " + toml_string(expr) + "\n";
        constraints_.push_back(s);
        (holonomic ? holonomic_ : nonholonomic_).push_back(expr);
    }

    void constraints() {
        const unsigned r = in_.below(8);
        int count = r < 3 ? 0 : r < 5 ? 1 : r < 7 ? 2 : 3;
        // Valid: fewer constraints than coordinates (as many fix every one); degenerate: anything.
        if (!degenerate_) count = std::min(count, int(coords_.size()) - 1);
        for (int k = 0; k < count; ++k) {
            const std::string a = random_coord(), b = other_coord(a), c = random_coord();
            const Coord ca = coords_[in_.below(coords_.size())];  // a copy: new_coord below may move them
            // 0-3, 7-9: meant to be valid; the others only in a degenerate model
            static const unsigned valid[] = {0, 1, 2, 3, 7, 8, 9};
            const unsigned kind = degenerate_ ? in_.below(13) : valid[in_.below(7)];
            switch (kind) {
                case 1: {  // a point of the tree on a circle about the origin
                    const Point& p = points_[points_.size() > 1 ? 1 + in_.below(points_.size() - 1) : 0];
                    constraint("(" + sum(p.x) + ")^2 + (" + sum(p.y) + ")^2 - " + param("L") + "^2", true);
                    break;
                }
                case 2: {  // on a line
                    const Point& p = points_[points_.size() > 1 ? 1 + in_.below(points_.size() - 1) : 0];
                    constraint(sum(p.y) + " - " + param("slope") + "*(" + sum(p.x) + ")", true);
                    break;
                }
                case 3:  // rheonomic: a prescribed motion
                    constraint(in_.chance(50) ? a + " - " + param("omega") + "*t"
                                              : a + " - " + param("amp") + "*sin(" + param("omega") + "*t)",
                               true);
                    break;
                case 4:  // redundant: a multiple of an earlier one
                    if (!holonomic_.empty())
                        constraint("2*(" + in_.one_of(holonomic_) + ")", true);
                    else if (!nonholonomic_.empty())
                        constraint("-3*(" + in_.one_of(nonholonomic_) + ")", false);
                    else
                        constraint(a + " - 2*" + b, true);
                    break;
                case 5:  // holds identically
                    constraint(in_.chance(50) ? "sin(" + a + ")^2 + cos(" + a + ")^2 - 1" : a + " - " + a, true);
                    break;
                case 6:  // singular at the initial state: a zero gradient there
                    constraint("(" + ca.name + " - (" + ca.initial + "))^2", true);
                    break;
                case 7:  // rolling
                    constraint(a + "' - " + param("R0") + "*" + b + "'", false);
                    break;
                case 8:  // a knife edge: not integrable with three coordinates
                    constraint("cos(" + c + ")*" + a + "' + sin(" + c + ")*" + b + "'", false);
                    break;
                case 9:  // rheonomic, at the velocity level
                    constraint(in_.chance(50) ? a + "' - " + param("v0") : a + "' - " + param("v0") + "*cos(" + param("omega") + "*t)", false);
                    break;
                case 10:  // the velocity form of a holonomic coupling, beside it: redundant
                    constraint(a + " - " + b, true);
                    if (k + 1 < count) {
                        constraint("2*(" + a + "' - " + b + "')", false);
                        ++k;
                    }
                    break;
                case 11:  // not a Pfaffian form, or no velocity at all
                    constraint(in_.chance(50) ? a + "'^2 - " + b + "'" : a + " - 1", false);
                    break;
                case 12:  // a coordinate that appears only here
                    if (coords_.size() < 6) {
                        const std::string u = new_coord("w", Kind::Length).name;
                        constraint(u + " - " + a, true);
                    } else {
                        constraint(a + " + " + b, true);
                    }
                    break;
                default:  // a coupling of two coordinates
                    constraint(a + " - " + (in_.chance(50) ? "2*" : "") + b, true);
            }
        }
        if (rare(15))  // every coordinate fixed
            for (const Coord& q : coords_) constraint(q.name + " - (" + q.initial + ")", true);
        if (!constraints_.empty() && in_.chance(10))
            extra_sections_ += "[stabilization]\nalpha = " + in_.one_of(std::vector<std::string>{"0.0", "5.0", "1.5"}) +
                               "\nbeta = " + in_.one_of(std::vector<std::string>{"0.0", "5.0", "10.0"}) + "\n\n";
    }

    std::string text() {
        // A few deliberately broken files: each must be refused with its place.
        std::string T = sum(T_), V = sum(V_);
        switch (degenerate_ ? in_.below(12) : 0) {
            case 1: T += " + " + coord(0) + "'^3"; break;       // not quadratic in the velocities
            case 2: V += " + " + coord(0) + "'"; break;         // a velocity in V
            case 3: V += " + zz9"; break;                        // an unknown symbol
            case 4: T = "0"; break;                              // no kinetic energy
            case 5: broken_T_ = true; break;                     // [lagrangian] without T
            case 6: params_.push_back(params_.empty() ? std::make_pair(std::string("q"), std::string("1")) : params_.front()); break;  // a duplicate
            default: break;
        }
        std::string s = "name = \"fuzzed\"\n\n";
        for (const Coord& c : coords_) {
            s += "[[coordinates]]\nname = " + toml_string(c.name) + "\n";
            if (c.write_initial) s += "initial = " + toml_value(c.initial) + "\nrate = " + toml_value(c.rate) + "\n";
            s += "\n";
        }
        for (const auto& [name, value] : params_) s += "[[parameters]]\nname = " + toml_string(name) + "\nvalue = " + toml_string(value) + "\n\n";
        const bool lagrangian = !T_.empty() || bodies_.empty() || broken_T_ || !V_.empty() || !R_.empty();
        if (lagrangian) {
            s += "[lagrangian]\n";
            if (!broken_T_) s += "T = " + toml_string(T) + "\n";  // "0" beside bodies
            if (!V_.empty() || V != "0") s += "V = " + toml_string(V) + "\n";
            if (!R_.empty()) s += "R = " + toml_string(R_) + "\n";
            s += "\n";
        }
        if (!forces_.empty()) {
            s += "[forces]\n";
            for (const auto& [q, f] : forces_) s += q + " = " + toml_string(f) + "\n";
            s += "\n";
        }
        for (const std::string& b : bodies_) s += b + "\n";
        for (const std::string& b : springs_) s += b + "\n";
        if (gravity_ || (!springs_.empty() && in_.chance(50))) s += "[gravity]\nvector = " + triple("0", "0", "-" + param_value_free_g()) + "\n\n";
        for (const std::string& c : constraints_) s += c + "\n";
        for (const std::string& c : contacts_) s += c + "\n";
        if (!outputs_.empty()) s += "[outputs]\n" + outputs_ + "\n";
        if (generate_jacobians_ && !constraints_.empty() && !degenerate_) generate_jacobians_ = false;
        if (generate_stiffness_ || generate_jacobians_)
            s += std::string("[generate]\n") + (generate_stiffness_ ? "stiffness = true\n" : "") +
                 (generate_jacobians_ ? "jacobians = true\n" : "") + "\n";
        s += extra_sections_;
        return s;
    }

    /// The gravity vector's g: a parameter declared above, or 9.81 when the model has none.
    std::string param_value_free_g() const {
        for (const auto& p : params_)
            if (p.first == "g") return "g";
        return "9.81";
    }
};

// ---------------------------------------------------------------------------------------------------------------
// What happened, for docs/reliability.md (EOMGEN_FUZZ_STATS).

long findings = 0;         // with EOMGEN_FUZZ_KEEP_GOING

struct Stats {
    long inputs = 0, refused_parse = 0, refused_derive = 0, refused_emit = 0, refused_hamiltonian = 0, derived = 0,
         constrained = 0, modes_ok = 0, modes_refused = 0, modes_refused_model = 0, equilibria = 0, run_finite = 0,
         run_singular = 0, hamiltonian_symbolic = 0, steady_ok = 0, steady_refused = 0, scenes_drawn = 0,
         scenes_empty = 0;
    double seconds_parse = 0, seconds_derive = 0, seconds_emit = 0, seconds_hamiltonian = 0, seconds_modes = 0,
           seconds_run = 0, seconds_steady = 0;
    std::map<std::string, long> refusals;  // the first words of each refusal's message
    double slowest = 0;
    std::string slowest_text, slowest_times;
    ~Stats() {
        if (!std::getenv("EOMGEN_FUZZ_STATS")) return;
        std::fprintf(stderr,
                     "fuzz_structure: %ld inputs, %ld findings: %ld refused when read, %ld when derived, %ld when emitted, %ld by "
                     "the Hamiltonian; %ld derived (%ld with constraints); modes: %ld answered (%ld equilibria), %ld "
                     "refused (ModesError), %ld refused (ModelError); H symbolic for %ld; run: %ld finite, %ld at a "
                     "detected singularity\n",
                     inputs, findings, refused_parse, refused_derive, refused_emit, refused_hamiltonian, derived, constrained,
                     modes_ok, equilibria, modes_refused, modes_refused_model, hamiltonian_symbolic, run_finite,
                     run_singular);
        std::fprintf(stderr, "fuzz_structure: steady motions: %ld answered, %ld refused\n", steady_ok, steady_refused);
        std::fprintf(stderr, "fuzz_structure: animation scenes: %ld drawn, %ld with nothing to draw\n", scenes_drawn,
                     scenes_empty);
        std::fprintf(stderr, "fuzz_structure: seconds in parse %.1f, derive %.1f, emit %.1f, hamiltonian %.1f, modes %.1f, "
                     "steady %.1f, run %.1f\n", seconds_parse, seconds_derive, seconds_emit, seconds_hamiltonian, seconds_modes,
                     seconds_steady, seconds_run);
        for (const auto& [what, n] : refusals) std::fprintf(stderr, "  %6ld  %s\n", n, what.c_str());
        std::fprintf(stderr, "fuzz_structure: the slowest input took %.3f s (%s):\n%s", slowest, slowest_times.c_str(),
                     slowest_text.c_str());
    }
} stats;

/// The message of a refusal without its place and model-specific names, to count refusals by kind.
std::string refusal_kind(const std::string& stage, const std::string& what) {
    std::string m = what;
    if (m.rfind(file, 0) == 0) {
        std::size_t colon = m.find(": ");
        if (colon != std::string::npos) m = m.substr(colon + 2);
    }
    m = std::regex_replace(m, std::regex("'[^']*'"), "'…'");
    m = std::regex_replace(m, std::regex("\\([^()]*\\)"), "(…)");
    if (m.size() > 90) {
        std::size_t cut = 90;
        while (cut > 0 && (static_cast<unsigned char>(m[cut]) & 0xc0) == 0x80) --cut;  // not inside a UTF-8 character
        m = m.substr(0, cut);
    }
    return stage + ": " + m;
}

class Timer {
public:
    explicit Timer(double& into) : into_(into), start_(std::chrono::steady_clock::now()) {}
    ~Timer() { into_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

private:
    double& into_;
    std::chrono::steady_clock::time_point start_;
};

// ---------------------------------------------------------------------------------------------------------------
// Numbers.

std::string text_of_input;  // the model's text, for fail()

/// Thrown instead of aborting with EOMGEN_FUZZ_KEEP_GOING set: the report is printed and the next input taken,
/// to see every finding of a long run at once.
struct KeepGoing {};

[[noreturn]] void finding(const char* what, const std::string& detail) {
    if (std::getenv("EOMGEN_FUZZ_KEEP_GOING")) {
        ++findings;
        std::fprintf(stderr, "%s: FINDING %ld: %s\n--- input ---\n%s\n--- detail ---\n%s\n", harness, findings, what,
                     text_of_input.c_str(), detail.c_str());
        throw KeepGoing{};
    }
    eomgen::fuzz::fail(harness, what, text_of_input, detail);
}

/// e at `at` as a real finite number, or nothing when it is not one there: GiNaC refuses a pole, or the value
/// is complex (a square root of a negative number), or too large for a double. A symbol left over after every
/// symbol of the model is substituted is a finding.
std::optional<double> real_at(const GiNaC::ex& e, const GiNaC::exmap& at) {
    GiNaC::ex v;
    try {
        // Not e.subs(): GiNaC throws on a zero denominator from inside the product it builds, and leaks it
        // (LeakSanitizer, a spring of length |x1| at x1 = 0 once the fuzzer drew abs).
        const std::optional<GiNaC::ex> s = eomgen::subs_unless_pole(e, at, GiNaC::subs_options::no_pattern);
        if (!s) return std::nullopt;
        v = s->evalf();
    } catch (...) {
        return std::nullopt;
    }
    if (!GiNaC::is_a<GiNaC::numeric>(v)) {
        // a function GiNaC leaves unevaluated at a point outside its domain is no number either
        bool symbol_left = false;
        for (GiNaC::const_preorder_iterator it = v.preorder_begin(); it != v.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it)) symbol_left = true;
        if (symbol_left) {
            std::ostringstream s;
            s << "expression: " << e << "\nafter substitution: " << v;
            finding("a symbol of no model coordinate, velocity, parameter or time in a derived quantity", s.str());
        }
        return std::nullopt;
    }
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(v);
    if (!n.is_real()) return std::nullopt;
    const double d = n.to_double();
    if (!std::isfinite(d)) return std::nullopt;
    return d;
}

struct Numeric {
    const eomgen::Model& model;
    const eomgen::Equations& eq;
    GiNaC::exmap params;

    GiNaC::exmap state(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd) const {
        GiNaC::exmap at = params;
        at[model.t] = t;
        for (std::size_t i = 0; i < model.dof(); ++i) {
            const auto k = Eigen::Index(i);
            at[model.coordinates[i].q] = q(k);
            at[model.coordinates[i].qd] = qd(k);
            at[model.coordinates[i].qdd] = qdd(k);
        }
        return at;
    }

    /// q'' at (t, q, q'), or nothing at a detected singularity.
    std::optional<Eigen::VectorXd> acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) const {
        const auto n = Eigen::Index(model.dof());
        const GiNaC::exmap at = state(t, q, qd, Eigen::VectorXd::Zero(n));
        const auto m = Eigen::Index(eq.constraints.size());
        Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + m, n + m);
        Eigen::VectorXd rhs(n + m);
        for (Eigen::Index i = 0; i < n; ++i) {
            for (Eigen::Index j = 0; j < n; ++j) {
                const auto v = real_at(eq.M(unsigned(i), unsigned(j)), at);
                if (!v) return std::nullopt;
                K(i, j) = *v;
            }
            const auto f = real_at(eq.f[std::size_t(i)], at);
            if (!f) return std::nullopt;
            rhs(i) = *f;
        }
        const Eigen::MatrixXd M = K.topLeftCorner(n, n);
        const double scale = 1 + M.cwiseAbs().maxCoeff();
        if ((M - M.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) {
            std::ostringstream s;
            s << "M at the state:\n" << M;
            finding("a mass matrix that is not symmetric", s.str());
        }
        for (Eigen::Index k = 0; k < m; ++k) {
            const eomgen::ConstraintEquations& c = eq.constraints[std::size_t(k)];
            for (Eigen::Index i = 0; i < n; ++i) {
                const auto a = real_at(c.jacobian[std::size_t(i)], at);
                if (!a) return std::nullopt;
                K(n + k, i) = *a;
                K(i, n + k) = -*a;
            }
            const auto g = real_at(c.gamma, at);
            if (!g) return std::nullopt;
            rhs(n + k) = *g;
        }
        Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
        lu.setThreshold(1e-12);
        if (!lu.isInvertible()) return std::nullopt;
        const Eigen::VectorXd x = lu.solve(rhs);
        if (!x.allFinite() || (K * x - rhs).norm() > 1e-6 * (1 + rhs.norm()) * (1 + K.norm())) return std::nullopt;
        return Eigen::VectorXd(x.head(n));
    }
};

/// The short run: a few RK4 steps from the model's initial state, each at finite numbers or stopped at a
/// detected singularity. Returns whether it ran through.
bool short_run(const eomgen::Model& model, const eomgen::Equations& eq) {
    Numeric num{model, eq, {}};
    for (const eomgen::Parameter& p : model.parameters) num.params[p.symbol] = p.value;
    const auto n = Eigen::Index(model.dof());
    Eigen::VectorXd q(n), qd(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        q(i) = model.coordinates[std::size_t(i)].initial;
        qd(i) = model.coordinates[std::size_t(i)].rate;
    }

    // The derived quantities agree at the initial state: euler_lagrange = M q'' − f + Q for any q''.
    {
        Eigen::VectorXd qdd(n);
        for (Eigen::Index i = 0; i < n; ++i) qdd(i) = 0.3 + 0.7 * double(i);
        const GiNaC::exmap at = num.state(0, q, qd, qdd);
        for (std::size_t i = 0; i < model.dof(); ++i) {
            GiNaC::ex Mq = 0;
            for (std::size_t j = 0; j < model.dof(); ++j) Mq += eq.M(unsigned(i), unsigned(j)) * model.coordinates[j].qdd;
            const auto el = real_at(eq.euler_lagrange[i], at), mq = real_at(Mq, at), f = real_at(eq.f[i], at),
                       Q = real_at(eq.generalized_forces[i], at);
            if (!el || !mq || !f || !Q) continue;
            const double scale = 1 + std::abs(*el) + std::abs(*mq) + std::abs(*f) + std::abs(*Q);
            if (std::abs(*el - (*mq - *f + *Q)) > 1e-8 * scale) {
                std::ostringstream s;
                s << "coordinate " << model.coordinates[i].name << ": d/dt dL/dq' - dL/dq = " << *el << ", M q'' = " << *mq
                  << ", f = " << *f << ", Q = " << *Q;
                finding("euler_lagrange is not M q'' - f + Q at the initial state", s.str());
            }
        }
    }

    // The interpreter (eomgen run --interpret) at the initial state: its right-hand side and Jacobian are an error
    // or finite numbers, and without constraints (whose Baumgarte terms the run below leaves out) q'' is what GiNaC's
    // values of M and f give.
    {
        std::optional<eomgen::interpreter::InterpretedTable> interpreted;
        try {
            interpreted.emplace(eomgen::interpreter::interpret(model, eq));
        } catch (const std::exception& e) {
            finding("the interpreter cannot record a model whose header was emitted", e.what());
        }
        const eomgen::ModelTable& table = interpreted->table();
        std::vector<std::max_align_t> block(table.params_size / sizeof(std::max_align_t) + 1);
        table.init_params(block.data());
        Eigen::VectorXd x(2 * n), xdot(2 * n);
        x << q, qd;
        if (table.rhs(0, x.data(), block.data(), xdot.data()) == eomgen::kTableOk) {
            if (!xdot.allFinite()) finding("the interpreter's right-hand side is not finite and says nothing", "");
            const auto qdd = eq.constraints.empty() ? num.acceleration(0, q, qd) : std::nullopt;
            if (qdd && (xdot.tail(n) - *qdd).norm() > 1e-6 * (1 + qdd->norm())) {
                std::ostringstream out;
                out << "interpreted q'' = " << xdot.tail(n).transpose() << ", from GiNaC's M and f " << qdd->transpose();
                finding("the interpreter's q'' is not GiNaC's at the initial state", out.str());
            }
            Eigen::MatrixXd J(2 * n, 2 * n);
            if (table.jacobian(0, x.data(), block.data(), J.data()) == eomgen::kTableOk && !J.allFinite())
                finding("the interpreter's Jacobian is not finite and says nothing", "");
        }
    }

    const double dt = 1e-3;
    double t = 0;
    for (int step = 0; step < 3; ++step) {
        const auto k1 = num.acceleration(t, q, qd);
        if (!k1) return false;
        const Eigen::VectorXd q2 = q + dt / 2 * qd, qd2 = qd + dt / 2 * *k1;
        const auto k2 = num.acceleration(t + dt / 2, q2, qd2);
        if (!k2) return false;
        const Eigen::VectorXd q3 = q + dt / 2 * qd2, qd3 = qd + dt / 2 * *k2;
        const auto k3 = num.acceleration(t + dt / 2, q3, qd3);
        if (!k3) return false;
        const Eigen::VectorXd q4 = q + dt * qd3, qd4 = qd + dt * *k3;
        const auto k4 = num.acceleration(t + dt, q4, qd4);
        if (!k4) return false;
        q += dt / 6 * (qd + 2 * qd2 + 2 * qd3 + qd4);
        qd += dt / 6 * (*k1 + 2 * *k2 + 2 * *k3 + *k4);
        t += dt;
        if (!q.allFinite() || !qd.allFinite()) return false;  // overflow from huge accelerations: detected
    }
    return true;
}

/// The double x as the exact rational it is (m 2^e with an integer m).
GiNaC::numeric exact(double x) {
    int e = 0;
    const double m = std::frexp(x, &e);  // x = m 2^e, 1/2 <= |m| < 1
    const long long k = static_cast<long long>(std::ldexp(m, 53));
    return GiNaC::numeric(k) * GiNaC::numeric(2).power(e - 53);
}

/// H(q, p(q, q')) = h(q, q') at the initial state, where H is formed.
void check_hamiltonian(const eomgen::Model& model, const eomgen::Equations& eq, const eomgen::Hamiltonian& h) {
    if (!h.symbolic) return;
    GiNaC::exmap at;
    const auto n = Eigen::Index(model.dof());
    for (const eomgen::Parameter& p : model.parameters) at[p.symbol] = p.value;
    at[model.t] = 0;
    for (const eomgen::Coordinate& c : model.coordinates) {
        at[c.q] = c.initial;
        at[c.qd] = c.rate;
    }
    // Only where M is regular: at a singular configuration (Euler angles at sin(theta) = 0, with theta = pi as a
    // double) M^-1, and with it H, is as large as the rounding of that configuration makes it.
    Eigen::MatrixXd M(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) {
            const auto v = real_at(eq.M(unsigned(i), unsigned(j)), at);
            if (!v) return;
            M(i, j) = *v;
        }
    const Eigen::VectorXd s = Eigen::JacobiSVD<Eigen::MatrixXd>(M).singularValues();
    if (s(n - 1) <= 1e-8 * s(0)) return;
    // H and h at 50 digits from the exact values of the doubles: with masses 10^-3 and 10^3 side by side, the
    // terms of H cancel over six orders of magnitude, and double precision left 10^-4 between equal values.
    GiNaC::exmap exact_at;
    for (const auto& [symbol, value] : at) exact_at[symbol] = exact(GiNaC::ex_to<GiNaC::numeric>(value).to_double());
    const long digits = GiNaC::Digits;
    GiNaC::Digits = 50;
    const auto H = real_at(eomgen::in_velocities(h.H, h), exact_at), energy = real_at(eq.energy, exact_at);
    GiNaC::Digits = digits;
    if (!H || !energy) return;
    if (std::abs(*H - *energy) > 1e-8 * (1 + std::abs(*H) + std::abs(*energy))) {
        std::ostringstream s;
        s << "H = " << *H << ", h = " << *energy << "\nH(q, p) = " << h.H;
        finding("H(q, p(q, q')) is not h(q, q') at the initial state", s.str());
    }
}

void check_finite(double x, const std::string& what) {
    if (!std::isfinite(x)) finding("a number small_oscillations reports is not finite", what);
}

void check_finite(const std::vector<double>& v, const std::string& what) {
    for (double x : v) check_finite(x, what);
}

void check_finite(const std::vector<std::vector<double>>& m, const std::string& what) {
    for (const auto& row : m) check_finite(row, what);
}

/// Every number a steady motion reports is finite (a singular one is a ModesError, never a NaN).
void check_steady(const eomgen::SteadyMotion& r) {
    auto all = [](const auto& m) { return m.size() == 0 || m.allFinite(); };
    for (const std::vector<double>* v : {&r.q, &r.qd, &r.lambda})
        for (double x : *v)
            if (!std::isfinite(x)) finding("a number the steady motion reports is not finite", "state or multiplier");
    if (!all(r.A) || !all(r.Mr) || !all(r.Cr) || !all(r.Kr) || !all(r.M) || !all(r.C) || !all(r.K))
        finding("a number the steady motion reports is not finite", "A, M_r, C_r, K_r, M, C or K");
    for (Eigen::Index k = 0; k < r.eigenvalues.size(); ++k)
        if (!std::isfinite(r.eigenvalues(k).real()) || !std::isfinite(r.eigenvalues(k).imag()))
            finding("a number the steady motion reports is not finite", "eigenvalue");
    if (!std::isfinite(r.growth_rate)) finding("a number the steady motion reports is not finite", "growth rate");
}

void check_modes(const eomgen::ModesResult& r) {
    for (std::size_t e = 0; e < r.equilibria.size(); ++e) {
        const eomgen::Equilibrium& q = r.equilibria[e];
        const std::string at = "equilibrium " + std::to_string(e + 1) + ": ";
        check_finite(q.q, at + "q");
        check_finite(q.M, at + "M");
        check_finite(q.K, at + "K");
        check_finite(q.C, at + "C");
        check_finite(q.G, at + "G");
        check_finite(q.A, at + "A");
        check_finite(q.B, at + "B");
        check_finite(q.multipliers, at + "multipliers");
        check_finite(q.tangent, at + "tangent");
        for (const auto& l : q.eigenvalues)
            if (!std::isfinite(l.real()) || !std::isfinite(l.imag())) finding("a number small_oscillations reports is not finite", at + "eigenvalue");
        for (const eomgen::NormalMode& m : q.modes) {
            check_finite(m.omega2, at + "omega2");
            check_finite(m.shape, at + "a mode's shape");
        }
        check_finite(q.growth_rate, at + "growth rate");
    }
}

/// The animation's scene (the bodies, springs and contacts the model has) at the model's initial state: built, or
/// refused as nothing to draw (false); every number of it finite, or a runtime_error at fuzzed.toml:line:col.
bool check_drawing(const eomgen::Model& model) {
    eomgen::animation::Scene scene;
    try {
        scene = eomgen::animation::build_scene(model);
    } catch (const eomgen::ModelError& e) {
        if (e.message().rfind("nothing to animate", 0) != 0)
            finding("an error of the animation's scene other than nothing to draw", e.what());
        return false;
    }
    eomgen::animation::SampleTable samples;
    samples.columns = {"t"};
    std::vector<double> row{0.0};
    for (const eomgen::Coordinate& c : model.coordinates) {
        samples.columns.push_back(c.name);
        samples.columns.push_back(c.name + "_dot");
        row.push_back(c.initial);
        row.push_back(c.rate);
    }
    samples.units.assign(samples.columns.size(), "");
    samples.rows = {row};
    try {
        const eomgen::animation::Frames frames = eomgen::animation::evaluate_frames(scene, model, {}, samples);
        for (const std::vector<double>& values : frames.values)
            for (double x : values)
                if (!std::isfinite(x)) finding("a number of the animation's frame is not finite", "");
    } catch (const std::runtime_error& e) {
        if (!eomgen::fuzz::located(e.what(), file)) finding("an error of the animation's frames without its place", e.what());
    }
    return true;
}

/// A ModelError must say where: fuzzed.toml:line:col (a model of bodies alone, with no T in its file, was refused
/// with the bare file name: tests/fuzz/findings_structure/unlocated_*.toml).
void located(const eomgen::ModelError& e, const char* stage) {
    if (eomgen::fuzz::located(e.what(), file)) return;
    finding((std::string("an error without fuzzed.toml:line:col from ") + stage).c_str(), e.what());
}

}  // namespace

namespace {
void test_one(const std::uint8_t* data, std::size_t size);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        test_one(data, size);
    } catch (const KeepGoing&) {
    }
    return 0;
}

namespace {
/// Keeps the slowest input's model and where its time went (EOMGEN_FUZZ_STATS).
class InputTimer {
public:
    InputTimer()
        : start_(std::chrono::steady_clock::now()),
          before_{stats.seconds_parse, stats.seconds_derive, stats.seconds_emit, stats.seconds_hamiltonian,
                  stats.seconds_modes, stats.seconds_run} {}
    ~InputTimer() {
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        if (s <= stats.slowest) return;
        stats.slowest = s;
        stats.slowest_text = text_of_input;
        char buf[200];
        std::snprintf(buf, sizeof buf, "parse %.3f, derive %.3f, emit %.3f, hamiltonian %.3f, modes %.3f, run %.3f",
                      stats.seconds_parse - before_[0], stats.seconds_derive - before_[1], stats.seconds_emit - before_[2],
                      stats.seconds_hamiltonian - before_[3], stats.seconds_modes - before_[4], stats.seconds_run - before_[5]);
        stats.slowest_times = buf;
    }

private:
    std::chrono::steady_clock::time_point start_;
    double before_[6];
};

void test_one(const std::uint8_t* data, std::size_t size) {
    ++stats.inputs;
    const InputTimer input_timer;
    if (std::getenv("EOMGEN_FUZZ_STRUCTURE_TOML")) {
        text_of_input = eomgen::fuzz::input_text(data, size);
    } else {
        ByteReader in(data, size);
        text_of_input = ModelWriter(in).write();
    }
    if (std::getenv("EOMGEN_FUZZ_STRUCTURE_PRINT")) std::fprintf(stderr, "--- model %ld ---\n%s", stats.inputs, text_of_input.c_str());
    const char* stage = "parse_model";
    try {
        std::optional<eomgen::Model> model;
        try {
            Timer timer(stats.seconds_parse);
            model = eomgen::parse_model(text_of_input, file);
        } catch (const eomgen::ModelError& e) {
            located(e, stage);
            ++stats.refused_parse;
            ++stats.refusals[refusal_kind("read", e.what())];
            return;
        }
        stage = "derive_equations";
        std::optional<eomgen::Equations> eq;
        try {
            Timer timer(stats.seconds_derive);
            eq = eomgen::derive_equations(*model);
        } catch (const eomgen::ModelError& e) {
            located(e, stage);
            ++stats.refused_derive;
            ++stats.refusals[refusal_kind("derive", e.what())];
            return;
        }
        ++stats.derived;
        if (!eq->constraints.empty()) ++stats.constrained;

        stage = "emit_model_header";
        try {
            Timer timer(stats.seconds_emit);
            const std::string header = eomgen::codegen::emit_model_header(*model, *eq, file);
            if (header.find('\0') != std::string::npos) finding("a NUL byte in the header", header);
            static const std::regex non_finite("\\b(nan|inf)\\b");
            std::smatch m;
            if (std::regex_search(header, m, non_finite))
                finding("a nan or inf in the header", header.substr(std::size_t(std::max<long>(0, long(m.position(0)) - 300)), 600));
        } catch (const eomgen::ModelError& e) {
            located(e, stage);
            ++stats.refused_emit;
            ++stats.refusals[refusal_kind("emit", e.what())];
        }

        stage = "derive_hamiltonian";
        try {
            Timer timer(stats.seconds_hamiltonian);
            const eomgen::Hamiltonian h = eomgen::derive_hamiltonian(*model, *eq);
            if (h.symbolic) ++stats.hamiltonian_symbolic;
            check_hamiltonian(*model, *eq, h);
        } catch (const eomgen::ModelError& e) {
            located(e, stage);
            ++stats.refused_hamiltonian;
            ++stats.refusals[refusal_kind("hamiltonian", e.what())];
        }

        stage = "small_oscillations";
        try {
            Timer timer(stats.seconds_modes);
            const eomgen::ModesResult r = eomgen::small_oscillations(*model, *eq, eomgen::ModesOptions{});
            ++stats.modes_ok;
            stats.equilibria += long(r.equilibria.size());
            check_modes(r);
        } catch (const eomgen::ModesError& e) {
            if (std::string(e.what()).empty()) finding("a ModesError without a message", "");
            ++stats.modes_refused;
            ++stats.refusals[refusal_kind("modes", e.what())];
        } catch (const eomgen::ModelError& e) {
            located(e, stage);
            ++stats.modes_refused_model;
            ++stats.refusals[refusal_kind("modes (ModelError)", e.what())];
        }

        stage = "steady_motion";
        if (model->dof() > 0) {
            try {
                // A rate of 3/2 for the last coordinate the equations do not depend on (the last one when none).
                Timer timer(stats.seconds_steady);
                eomgen::SteadyMotionSolver solver(*model, *eq);
                for (std::size_t j = model->dof(); j-- > 0;) {
                    eomgen::SteadyMotionOptions o;
                    o.rates.push_back({j, GiNaC::numeric(3, 2), "q_dot=3/2"});
                    try {
                        const eomgen::SteadyMotion r = solver.solve(o);
                        ++stats.steady_ok;
                        check_steady(r);
                        break;
                    } catch (const eomgen::ModesError& e) {
                        if (j > 0 && std::string(e.what()).find("does not turn at a constant rate") != std::string::npos) continue;
                        throw;
                    }
                }
            } catch (const eomgen::ModesError& e) {
                if (std::string(e.what()).empty()) finding("a ModesError without a message", "");
                ++stats.steady_refused;
                ++stats.refusals[refusal_kind("steady", e.what())];
            } catch (const eomgen::ModelError& e) {
                located(e, stage);
                ++stats.steady_refused;
            }
        }

        stage = "the animation's scene";
        ++(check_drawing(*model) ? stats.scenes_drawn : stats.scenes_empty);

        stage = "the short run";
        {
            Timer timer(stats.seconds_run);
            if (short_run(*model, *eq))
                ++stats.run_finite;
            else
                ++stats.run_singular;
        }
    } catch (const KeepGoing&) {
    } catch (const std::exception& e) {
        finding((std::string("an exception other than ModelError (or ModesError) from ") + stage).c_str(), e.what());
    } catch (...) {
        finding((std::string("an exception of no std type from ") + stage).c_str(), "");
    }
}
}  // namespace
