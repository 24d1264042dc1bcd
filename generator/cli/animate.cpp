/** @file animate.cpp  `eomgen run --animate`: samples → frames → page. */
#include "cli/animate.hpp"

#include "animation/frames.hpp"
#include "animation/html_page.hpp"
#include "output/atomic_file.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <cctype>
#include <map>

namespace eomgen::cli {

std::string animation_request_problem(const std::string& path, double fps) {
    auto ends_with = [&](const std::string& suffix) {
        if (path.size() < suffix.size()) return false;
        std::string tail = path.substr(path.size() - suffix.size());
        std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        return tail == suffix;
    };
    if (!ends_with(".html") && !ends_with(".htm"))
        return "--animate " + path + ": the animation is an HTML page: name it FILE.html";
    if (!std::isfinite(fps) || !(fps > 0) || fps > 1000)
        return "--fps must be a number of frames per second of simulated time in (0, 1000]";
    return "";
}

int animation_samples(double t_end, double fps) {
    const double frames = std::ceil(t_end * fps - 1e-9);
    return int(std::clamp(frames, 1.0, double(kMaxAnimationFrames)));
}

int write_animation(const Model& model, const animation::Scene& scene, const eomgen::sim::Options& options,
                    const std::string& path, const std::string& command) {
    animation::Page page;
    try {
        const animation::SampleTable samples = animation::read_sample_table(options.csv);
        std::map<std::string, double> parameters;
        for (const Parameter& p : model.parameters) parameters[p.name] = p.value;
        for (const std::string& s : options.set) {  // already checked and in SI by the run
            const auto [name, value] = eomgen::sim::parse_assignment(s, "--set");
            parameters[name] = value;
        }
        page.frames = animation::evaluate_frames(scene, model, parameters, samples);
        // Beside the view: the coordinates, the declared outputs and the energy, as the CSV has them.
        std::vector<std::string> shown;
        for (const Coordinate& c : model.coordinates) shown.push_back(c.name);
        for (const DeclaredOutput& o : model.outputs) shown.push_back(o.name);
        shown.push_back("energy");
        std::vector<std::size_t> columns;
        for (const std::string& name : shown)
            for (std::size_t i = 0; i < samples.columns.size(); ++i)
                if (samples.columns[i] == name) {
                    columns.push_back(i);
                    page.readout_names.push_back(name);
                    page.readout_units.push_back(samples.units[i]);
                }
        for (const std::vector<double>& row : samples.rows) {
            std::vector<double> values;
            for (std::size_t i : columns) values.push_back(row[i]);
            page.readout.push_back(std::move(values));
        }
    } catch (const std::runtime_error& e) {
        std::cerr << command << ": --animate: " << e.what() << "\n";
        return 2;
    }
    page.title = model.title.empty() ? model.name : model.title;
    auto equation = [&](const std::string& name, const SourceExpression& e) {
        if (!e.text.empty() && e.text != "0") page.equations.push_back({name, e.text});
    };
    equation("T", model.T);
    equation("V", model.V);
    equation("R", model.R);
    for (const Constraint& c : model.constraints) page.equations.push_back({c.name, c.expr.text + " = 0"});
    try {
        output::write_atomically(path, animation::html_page(page));
    } catch (const std::exception& e) {
        std::cerr << command << ": --animate: cannot write " << path << ": " << e.what() << "\n";
        return 3;
    }
    return 0;
}

}  // namespace eomgen::cli
