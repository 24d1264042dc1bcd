/** @file state_symbols.hpp  Whether an expression holds the model's state: its coordinates, velocities and (unless
 * told otherwise) accelerations. One helper for the checker's stages that ask it of plain expressions. */
#pragma once

#include "model/model.hpp"

#include <ginac/ginac.h>

namespace eomgen::checker {

/// e holds a coordinate or a velocity of the model, or (with `accelerations`) an acceleration.
inline bool holds_state(const GiNaC::ex& e, const Model& model, bool accelerations = true) {
    for (const Coordinate& c : model.coordinates)
        if (e.has(c.q) || e.has(c.qd) || (accelerations && e.has(c.qdd))) return true;
    return false;
}

/// e is a coordinate, a velocity or an acceleration of the model, alone.
inline bool state_symbol(const GiNaC::ex& e, const Model& model) {
    for (const Coordinate& c : model.coordinates)
        if (e.is_equal(c.q) || e.is_equal(c.qd) || e.is_equal(c.qdd)) return true;
    return false;
}

}  // namespace eomgen::checker
