/** @file approx.hpp  One Eigen matcher for the whole suite: |a - b| <= atol + rtol |b|, elementwise. */
#pragma once

#include <catch2/catch.hpp>
#include <Eigen/Core>

#include <cmath>
#include <sstream>

namespace eomgen::test {

template <class Expected>
class AllCloseMatcher : public Catch::MatcherBase<Eigen::Matrix<typename Expected::Scalar, Eigen::Dynamic, Eigen::Dynamic>> {
public:
    using Mat = Eigen::Matrix<typename Expected::Scalar, Eigen::Dynamic, Eigen::Dynamic>;
    AllCloseMatcher(const Expected& expected, double rtol, double atol)
        : expected_(expected), rtol_(rtol), atol_(atol) {}
    bool match(const Mat& actual) const override {
        if (actual.rows() != expected_.rows() || actual.cols() != expected_.cols()) return false;
        for (Eigen::Index i = 0; i < actual.rows(); ++i)
            for (Eigen::Index j = 0; j < actual.cols(); ++j) {
                const double a = double(actual(i, j)), b = double(expected_(i, j));
                if (!(std::abs(a - b) <= atol_ + rtol_ * std::abs(b))) return false;
            }
        return true;
    }
    std::string describe() const override {
        std::ostringstream os;
        os.precision(17);
        os << "is close (rtol " << rtol_ << ", atol " << atol_ << ") to\n" << expected_;
        return os.str();
    }

private:
    Mat expected_;
    double rtol_, atol_;
};

/// REQUIRE_THAT(Eigen::MatrixXd(actual), AllClose(expected, 1e-12, 1e-14));
template <class Derived>
AllCloseMatcher<Eigen::Matrix<typename Derived::Scalar, Eigen::Dynamic, Eigen::Dynamic>> AllClose(
    const Eigen::MatrixBase<Derived>& expected, double rtol, double atol = 0.0) {
    return {expected.eval(), rtol, atol};
}

}  // namespace eomgen::test
