/** @file frames.cpp  Evaluating a scene at a run's samples, and reading the samples' CSV. */
#include "animation/frames.hpp"

#include "mechanics/double_evaluator.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace eomgen::animation {
namespace {

/// The fields of one CSV line (RFC 4180 quotes).
std::vector<std::string> csv_fields(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                out.back() += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                out.back() += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            out.emplace_back();
        } else if (c != '\r') {
            out.back() += c;
        }
    }
    return out;
}

std::string fixed(double x) {
    std::ostringstream os;
    os << x;
    return os.str();
}

}  // namespace

SampleTable read_sample_table(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read the samples " + path);
    SampleTable table;
    std::string line;
    if (!std::getline(in, line)) throw std::runtime_error(path + " is empty: no header of samples");
    for (std::string h : csv_fields(line)) {
        std::string unit;
        if (const std::size_t b = h.find(" ["); b != std::string::npos && !h.empty() && h.back() == ']') {
            unit = h.substr(b + 2, h.size() - b - 3);
            h = h.substr(0, b);
        }
        table.columns.push_back(h);
        table.units.push_back(unit);
    }
    for (int number = 2; std::getline(in, line); ++number) {
        if (line.empty()) continue;
        const std::vector<std::string> fields = csv_fields(line);
        if (fields.size() != table.columns.size())
            throw std::runtime_error(path + ":" + std::to_string(number) + ": " + std::to_string(fields.size()) +
                                     " fields where the header has " + std::to_string(table.columns.size()));
        std::vector<double> row;
        for (const std::string& f : fields) {
            char* end = nullptr;
            const double x = std::strtod(f.c_str(), &end);
            row.push_back(end != f.c_str() ? x : std::nan(""));
        }
        table.rows.push_back(std::move(row));
    }
    return table;
}

Frames evaluate_frames(const Scene& scene, const Model& model, const std::map<std::string, double>& parameters,
                       const SampleTable& samples) {
    auto column = [&](const std::string& name) -> std::size_t {
        for (std::size_t i = 0; i < samples.columns.size(); ++i)
            if (samples.columns[i] == name) return i;
        throw std::runtime_error("the samples have no column '" + name + "'");
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
