/** @file model.hpp  The in-memory model: coordinates, parameters, T and V as GiNaC expressions. */
#pragma once

#include "model/drawing.hpp"
#include "model/rotations.hpp"
#include "model/source_location.hpp"
#include "model/units.hpp"

#include <ginac/ginac.h>

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace eomgen {

/// Every problem with a model is reported as this, with where it is.
class ModelError : public std::runtime_error {
public:
    ModelError(SourceLocation where, const std::string& message);
    const SourceLocation& where() const { return where_; }
    const std::string& message() const { return message_; }

private:
    SourceLocation where_;
    std::string message_;
};

/// A generalized coordinate q_i with its velocity q̇_i and acceleration q̈_i as plain symbols
/// (time derivatives are taken by the chain rule, see mechanics/lagrangian.hpp).
struct Coordinate {
    std::string name;   ///< identifier used in expressions and in generated code
    std::string latex;  ///< LaTeX name, e.g. "\\psi"
    GiNaC::symbol q, qd, qdd;
    double initial = 0.0;  ///< default q(0), in SI (rad for an angle)
    double rate = 0.0;     ///< default q̇(0), in SI
    std::string unit;      ///< the SI unit q is in ("m", "rad"); "" when the file gives none
    std::optional<Unit> declared_unit;  ///< the file's `unit` ("deg"): bare numbers on command lines are in it
    std::string description;
    SourceLocation where;
};

/// A constant of the model, kept symbolic in the equations; `value` is the default for simulation.
struct Parameter {
    std::string name;
    std::string latex;
    std::string unit;         ///< the SI unit `value` is in ("N/m", "rad", "kg m^2"); "" when the file gives none
    std::string given;        ///< the value as the file gives it, where it was converted ("30 deg"); else ""
    std::optional<Unit> declared_unit;  ///< the file's `unit` ("deg"): bare numbers on command lines are in it
    /// The value's own unit where the file gives no `unit` (`value = "40 N/m"`): the parameter's dimension, for the
    /// dimensional analysis; bare numbers on command lines stay SI.
    std::optional<Unit> value_unit;
    std::string description;
    GiNaC::symbol symbol;
    double value = 0.0;       ///< in SI: a file's `value = 30` with `unit = "deg"` is 0.5236 (rad)
    SourceLocation where;
};

/// An expression from the model file with the place where its text starts.
struct SourceExpression {
    GiNaC::ex expr;
    std::string text;
    SourceLocation where;
};

/// A constraint on the motion. Holonomic: g(q,t) = 0. Nonholonomic (Pfaffian): a(q,t)·q̇ + b(q,t) = 0,
/// linear in the velocities. Its multiplier λ carries its name.
enum class ConstraintKind { Holonomic, Nonholonomic };

struct Constraint {
    std::string name;
    ConstraintKind kind = ConstraintKind::Holonomic;
    SourceExpression expr;  ///< g(q,t) or a(q,t)·q̇ + b(q,t), "= 0" understood
    SourceLocation where;   ///< of the name
};

/// A rigid body of a body-based model file ([[bodies]]); its energies are assembled by the mechanics
/// stage (mechanics/bodies.hpp): T = ½ m v_c² + ½ ω'ᵀ I ω', V = −m g·r_c.
struct Body {
    std::string name;
    SourceLocation where;                 ///< of the name
    GiNaC::ex mass;
    std::string shape;                    ///< e.g. "thin_rod"; empty when `inertia` is given
    std::vector<GiNaC::ex> dimensions;    ///< the shape's dimensions, in mechanics/inertia.hpp's order
    GiNaC::matrix inertia{3, 3};          ///< explicit tensor about the centre of mass, body axes
    std::array<GiNaC::ex, 3> centre;      ///< centre of mass in space axes, in q and t
    std::array<GiNaC::ex, 3> angles;      ///< Euler angles (φ, θ, ψ) in q and t
    std::string sequence = "zxz";         ///< Euler sequence (mechanics/kinematics.hpp)
    /// The orientation as a chain of rotations about body axes from space axes, when the file gives one
    /// (`orientation = [["z", "psi"], ["x", "phi"]]`, or `{ body = "B", rotations = [...] }` after B's
    /// chain, resolved when read); empty when the orientation is the Euler angles above.
    std::vector<Rotation> rotations;
    std::array<GiNaC::ex, 3> force{0, 0, 0};   ///< applied at the centre of mass, space axes (q, q̇, t)
    std::array<GiNaC::ex, 3> torque{0, 0, 0};  ///< applied about the centre of mass, body axes (q, q̇, t)
};

/// A wheel rolling without slipping on a plane ([[contacts]]): a body with a symmetry axis (`axis`, body axes)
/// and a rim of radius `radius`, a knife edge (or a torus with a tube radius) touching the plane n·r = height
/// (n a signed space axis). It
/// becomes constraints when read (model/rolling_contacts.hpp): the rim's lowest point P touches the plane
/// (holonomic, `<name>_height`; left out where the coordinates keep it identically), and P's material
/// velocity along the plane is zero (two nonholonomic, `<name>_slip_x`, ...).
struct RollingContact {
    std::string name;
    SourceLocation where;  ///< of the name
    std::string body;
    GiNaC::ex radius;       ///< of the rim (a torus: of the circle through the tube's centres)
    GiNaC::ex tube = 0;     ///< a torus' tube radius (a tyre); 0 for a knife edge
    char axis = 'z';        ///< the wheel's symmetry axis, body axes
    char normal = 'z';      ///< the plane's normal, space axes, pointing to the side the wheel is on ...
    int normal_sign = 1;    ///< ... with this sign
    GiNaC::ex height = 0;   ///< the plane is n·r = height
};

/// One end of a spring: a point fixed in space or moving with q and t (`body` empty, `point` in space
/// axes), or a point of a body (`point` in that body's axes, relative to its centre of mass).
struct SpringEnd {
    std::string body;
    std::array<GiNaC::ex, 3> point{0, 0, 0};
};

/// A linear spring ([[springs]]) between two points: V = ½ k (|r_to − r_from| − l₀)².
struct Spring {
    std::string name;
    SourceLocation where;  ///< of the name
    GiNaC::ex stiffness;
    GiNaC::ex rest_length = 0;
    SpringEnd from, to;
};

/// A closed-form result the model declares ([[results]]): the `eomgen check` compares a derivation's
/// `LATEX = ...` with it; with `equals`, eomgen verifies it against what it derives (docs/model_files.md).
struct Result {
    std::string name;
    std::string latex;        ///< the left-hand side as a derivation writes it: "T", "\\Omega", "I_{1}"
    std::string description;
    SourceExpression expr;    ///< the closed form in the parameters, q, q', t
    std::string equals;       ///< "" or "T", "V", "L", "energy", "p_<coord>", "inertia.<body>.<ij>", ...
    SourceLocation equals_where;
    bool on_constraints = false;  ///< compare after solving the constraints for coordinates and velocities
    SourceLocation where;         ///< of the name
};

/// A quantity the model file asks to record beside the state ([outputs], e.g. x_bob = l*sin(theta)): the
/// generated header computes it in outputs(), each run writes it as a CSV column and plots it against t.
struct DeclaredOutput {
    std::string name;         ///< an identifier, unique among the model's names; the CSV column's name
    std::string latex;        ///< its LaTeX, "x_{bob}" by default
    std::string unit;         ///< e.g. "m"; "" when not given
    std::string description;
    SourceExpression expr;    ///< in the parameters, q, q', t
    SourceLocation where;     ///< of the name (its key in [outputs])
};

/// One condition of a particular motion ([[motions]]): a coordinate, or its velocity, as a function of the
/// motion's constants, the parameters, the coordinates and t ("theta' = 0", "psi' = -Omega").
struct MotionCondition {
    std::size_t coordinate = 0;  ///< index into Model::coordinates
    bool velocity = false;       ///< q' = value (else q = value)
    SourceExpression value;      ///< the right side
    std::string text;            ///< the condition as written
};

/// A particular motion a derivation may speak of ([[motions]]: steady precession, an equilibrium, a circular
/// orbit): `eomgen check` compares the lines that are not identities on it (docs/checker.md).
struct Motion {
    std::string name;
    std::string description;
    std::string section;  ///< "" (every section) or a case-insensitive substring of the headings it applies to
    /// Constants of the motion the conditions use (`Omega`): name, LaTeX, symbol.
    struct Constant {
        std::string name, latex;
        GiNaC::symbol symbol;
    };
    std::vector<Constant> constants;
    std::vector<MotionCondition> conditions;
    SourceLocation where;  ///< of the name
};

/// [generate]: the optional functions a generated header holds. The default header holds what integrating and
/// checking need (M, f, the energies, momenta, conserved quantities, outputs, constraints, linearization() by
/// forward differentiation); these cost generation time that grows fast with the number of coordinates
/// (docs/benchmarks.md, section 9), so a model file or a command (`eomgen generate --with`) asks for them.
struct GenerateRequest {
    /// state_jacobian() and parameter_jacobian() from the symbolic equations (unconstrained models only; the
    /// runtime differentiates any model by forward AD where a header has none: eomgen::model_jacobian).
    bool jacobians = false;
    /// stiffness(), damping() and gyroscopic(): K, C and G about rest (mechanics/rest_linearization.hpp).
    bool stiffness = false;
};

struct Model {
    std::string name;         ///< identifier: namespace of the generated code, file name
    std::string title;        ///< human title
    std::string source;       ///< bibliographic source, e.g. "Goldstein ch. 5, Ex. 30"
    std::string description;  ///< free text
    std::string path;         ///< model file it was read from

    GiNaC::symbol t;  ///< time
    std::vector<Coordinate> coordinates;
    std::vector<Parameter> parameters;
    SourceExpression T;  ///< kinetic energy T(q, q̇, t)
    SourceExpression V;  ///< potential energy V(q, t)
    SourceExpression R;  ///< Rayleigh dissipation function R(q, q̇, t); contributes −∂R/∂q̇ (0 when absent)
    std::vector<SourceExpression> forces;  ///< generalized force Q_i(q, q̇, t) per coordinate (0 when absent)
    std::vector<Constraint> constraints;
    std::vector<Body> bodies;                    ///< [[bodies]]: their T and V add to T and V above
    std::vector<Spring> springs;                 ///< [[springs]]: their V adds to V above
    std::vector<RollingContact> contacts;        ///< [[contacts]]: their constraints are in `constraints`
    std::array<GiNaC::ex, 3> gravity{0, 0, 0};  ///< [gravity] acceleration vector g, space axes
    std::vector<Result> results;                 ///< [[results]]: declared closed forms
    std::vector<DeclaredOutput> outputs;         ///< [outputs]: quantities recorded beside the state, in file order
    std::vector<Motion> motions;                 ///< [[motions]]: particular motions, for `eomgen check`
    std::vector<DrawItem> drawing;               ///< [[draw]]: what an animation shows beside the bodies
    GenerateRequest generate;                    ///< [generate]: optional functions of the header

    /// Baumgarte stabilisation of the constraints, A q̈ = γ − 2α(A q̇ + b) − β² g (0, 0: none).
    double baumgarte_alpha = 0.0;
    double baumgarte_beta = 0.0;

    std::size_t dof() const { return coordinates.size(); }
};

}  // namespace eomgen
