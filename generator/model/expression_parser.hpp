/** @file expression_parser.hpp  Parser of the model expression language into exact GiNaC expressions. */
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace eomgen {

/// A problem in an expression, with the 0-based byte offset into the expression text of the character
/// it is about (the model file reader turns that into file:line:col). what() is the message alone.
class ExpressionError : public std::runtime_error {
  public:
    ExpressionError(std::size_t offset, const std::string& message);
    std::size_t offset() const { return offset_; }
    const std::string& message() const { return message_; }

  private:
    std::size_t offset_;
    std::string message_;
};

/// The names an expression may use.
struct SymbolTable {
    /// Coordinates, parameters and time `t`: name → what the name stands for.
    std::map<std::string, GiNaC::ex> symbols;
    /// Coordinate name → its velocity symbol, for `q'` and `dot(q)`. A name is a coordinate iff it is here.
    std::map<std::string, GiNaC::ex> velocities;
};

/// What an expression may contain beyond the grammar.
struct ParseOptions {
    /// When not empty, a velocity (`q'`, `dot(q)`) is an error at its position, with this as the
    /// reason, e.g. "V(q, t) must not depend on velocities".
    std::string forbid_velocities;
    /// When true, the expression must be a constant: a name from the table is an error at its position
    /// (initial values and parameter values: numbers, `pi` and functions only).
    bool constants_only = false;
};

/**
 * Parses the expression language of docs/model_files.md into a GiNaC expression.
 *
 *   expr    := term (('+' | '-') term)*
 *   term    := unary (('*' | '/') unary)*
 *   unary   := ('-' | '+') unary | power          -x^2 = -(x^2)
 *   power   := postfix ('^' unary)?               right-associative: a^b^c = a^(b^c); a^-b allowed
 *   postfix := primary "'"?                       q' is the velocity of coordinate q
 *   primary := number | name | function '(' expr (',' expr)* ')' | 'dot' '(' name ')' | '(' expr ')'
 *
 * Numbers are exact rationals ("0.5" → 1/2, "2.5e-3" → 1/400), never floats, so derived equations stay
 * exact. `pi` is GiNaC::Pi. Functions: sin cos tan exp log sqrt sinh cosh tanh asin acos atan, atan2(y, x).
 *
 * @param text     the expression, e.g. "1/6 * m * w^2 * psi'^2"
 * @param symbols  names it may use and the coordinates' velocities
 * @param options  restrictions (no velocities in V, constants only for initial values)
 * @return         the expression
 * @throws ExpressionError with the byte offset of the offending character; never anything else
 */
GiNaC::ex parse_expression(std::string_view text, const SymbolTable& symbols,
                           const ParseOptions& options = {});

/**
 * Evaluates a constant expression ("pi/4", "2.5e-3", "sqrt(2)/2") to a double.
 * Names from `symbols` are reported as "not a constant" at their position.
 * @throws ExpressionError also when the value is not a finite real number (offset 0)
 */
double evaluate_constant(std::string_view text, const SymbolTable& symbols = {});

/// The functions the expression language knows (sin, cos, ..., atan2), sorted.
const std::vector<std::string>& expression_function_names();

}  // namespace eomgen
