/**
 * @file nonsmooth.hpp  sign, heaviside, max and min as the generated headers call them (`eomgen::sign<Scalar>(x)`):
 * one definition for double, long double, Eigen's AutoDiffScalar (the derivative of the chosen branch: 0 for sign
 * and heaviside, that of the larger argument for max) and CUDA device code (EOMGEN_HD). abs is std::abs (or the
 * scalar's own, found by argument-dependent lookup).
 *
 * Conventions, the same as eomgen's symbolic side: sign(0) = 0, heaviside(0) = 1/2, max(a, a) = a. Where a
 * derivative does not exist (sign and heaviside at 0, abs at 0, max and min where their arguments meet), the code
 * returns the one-sided value its branch picks; the header's comments name those surfaces.
 */
#pragma once

#include "eomgen/device.hpp"

namespace eomgen {

template <class Scalar>
EOMGEN_HD inline Scalar sign(const Scalar& x) {
    if (x > Scalar(0)) return Scalar(1);
    if (x < Scalar(0)) return Scalar(-1);
    return Scalar(0);
}

template <class Scalar>
EOMGEN_HD inline Scalar heaviside(const Scalar& x) {
    if (x > Scalar(0)) return Scalar(1);
    if (x < Scalar(0)) return Scalar(0);
    return Scalar(0.5);
}

template <class Scalar>
EOMGEN_HD inline Scalar max(const Scalar& a, const Scalar& b) {
    return a < b ? b : a;
}

template <class Scalar>
EOMGEN_HD inline Scalar min(const Scalar& a, const Scalar& b) {
    return b < a ? b : a;
}

}  // namespace eomgen
