/** @file frames.cpp  Evaluating a scene at a run's samples. */
#include "animation/frames.hpp"

#include "mechanics/double_evaluator.hpp"

#include <cmath>
#include <sstream>

namespace eomgen::animation {
namespace {

std::string fixed(double x) {
    std::ostringstream os;
    os << x;
    return os.str();
}

}  // namespace

Frames evaluate_frames(const Scene& scene, const Model& model, const std::map<std::string, double>& parameters,
                       const SampleTable& samples) {
    auto column = [&](const std::string& name) -> std::size_t {
        const int i = samples.column(name);
        if (i < 0) throw std::runtime_error("the samples have no column '" + name + "'");
        return std::size_t(i);
    };
    const std::size_t t_column = column("t");
    std::vector<std::size_t> q_column, qd_column;
    for (const Coordinate& c : model.coordinates) {
        q_column.push_back(column(c.name));
        qd_column.push_back(column(c.name + "_dot"));
    }
    SymbolValues constants;
    for (const Parameter& p : model.parameters) {
        const auto it = parameters.find(p.name);
        constants[p.symbol] = it != parameters.end() ? it->second : p.value;
    }

    Frames frames;
    frames.planar = scene.planar;
    frames.items = scene.items;
    frames.values.resize(scene.items.size());
    {  // up, from the parameters alone (gravity is constant)
        DoubleEvaluator at(constants);
        std::array<double, 3> u{};
        double norm = 0;
        for (int i = 0; i < 3; ++i) {
            const std::optional<double> v = at(scene.up[i]);
            u[i] = v ? *v : 0;
            norm += u[i] * u[i];
        }
        if (norm > 0 && std::isfinite(norm))
            for (int i = 0; i < 3; ++i) frames.up[i] = u[i] / std::sqrt(norm);
    }
    for (const std::vector<double>& row : samples.rows) {
        SymbolValues values = constants;
        values[model.t] = row[t_column];
        for (std::size_t i = 0; i < model.coordinates.size(); ++i) {
            values[model.coordinates[i].q] = row[q_column[i]];
            values[model.coordinates[i].qd] = row[qd_column[i]];
        }
        DoubleEvaluator at(std::move(values));
        frames.t.push_back(row[t_column]);
        for (std::size_t k = 0; k < scene.items.size(); ++k) {
            const Primitive& p = scene.items[k];
            std::vector<double> numbers;
            for (const GiNaC::ex& e : p.values) {
                const std::optional<double> v = at(e);
                if (!v)
                    throw std::runtime_error(p.where.str() + ": " + p.what + " is not a finite number at t = " +
                                             fixed(row[t_column]) + " (" + [&] {
                                                 std::ostringstream os;
                                                 os << e;
                                                 return os.str();
                                             }() + ")");
                numbers.push_back(*v);
            }
            if (p.kind == PrimitiveKind::Solid && p.shape == SolidShape::InertiaEllipsoid) {
                // The uniform ellipsoid of mass m with principal moments I1, I2, I3: I1 = m (b² + c²)/5, ...,
                // so a² = 5 (I2 + I3 − I1) / (2m). Moments that no ellipsoid has (a point, a rod) give 0 there.
                const double I1 = numbers[12], I2 = numbers[13], I3 = numbers[14], m = numbers[15];
                auto semi = [&](double s) { return m > 0 && s > 0 ? std::sqrt(5 * s / (2 * m)) : 0.0; };
                const double a = semi(I2 + I3 - I1), b = semi(I1 + I3 - I2), c = semi(I1 + I2 - I3);
                numbers.resize(12);
                numbers.insert(numbers.end(), {a, b, c});
            }
            frames.values[k].insert(frames.values[k].end(), numbers.begin(), numbers.end());
        }
    }
    for (Primitive& p : frames.items)
        if (p.kind == PrimitiveKind::Solid && p.shape == SolidShape::InertiaEllipsoid) p.shape = SolidShape::Ellipsoid;
    return frames;
}

}  // namespace eomgen::animation
