// docs/runtime.md, "Stiff models": radau5 with the exact Jacobian, on examples/stiff_spring_pendulum.toml.
#include "eomgen/model_jacobian.hpp"
#include "eomgen/models/stiff_spring_pendulum.hpp"
#include "eomgen/radau5.hpp"

#include <iostream>

using Model = eomgen::models::stiff_spring_pendulum::Model<double>;

int main() {
    Model::Params p;
    const Model::State x0 = Model::default_state();
    auto f = [&p](const double& t, const Model::State& x, Model::State& xdot) { Model::rhs(t, x, p, xdot); };
    auto jac = [&p](const double& t, const Model::State& x, auto& J) { eomgen::model_jacobian<Model>(t, x, p, J); };
    eomgen::Radau5Options<double> options;
    options.rtol = 1e-8;
    options.atol = 1e-10;
    const auto r = eomgen::integrate_radau5(f, jac, 0.0, x0, 10.0, options);
    std::cout << "t = " << r.t << ", " << r.accepted_steps << " steps, " << r.jacobian_evaluations
              << " Jacobians, " << r.lu_decompositions << " LU decompositions\n";
}
