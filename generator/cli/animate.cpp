/** @file animate.cpp  `eomgen run --animate`: samples → frames → page. */
#include "cli/animate.hpp"

#include "animation/frames.hpp"
#include "animation/html_page.hpp"
#include "cli/process.hpp"
#include "output/atomic_file.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <cctype>
#include <filesystem>
#include <map>
#include <sstream>

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

namespace {

/// One run's frames and readout, from its CSV and the parameters' values it ran with.
struct RunFrames {
    animation::Frames frames;
    std::vector<std::string> names, units;  ///< the readout's columns
    std::vector<std::vector<double>> readout;
};

RunFrames frames_of_run(const Model& model, const animation::Scene& scene, const eomgen::sim::Options& options) {
    RunFrames r;
    const animation::SampleTable samples = animation::read_sample_table(options.csv);
    std::map<std::string, double> parameters;
    for (const Parameter& p : model.parameters) parameters[p.name] = p.value;
    for (const std::string& s : options.set) {  // already checked and in SI by the run
        const auto [name, value] = eomgen::sim::parse_assignment(s, "--set");
        parameters[name] = value;
    }
    r.frames = animation::evaluate_frames(scene, model, parameters, samples);
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
                r.names.push_back(name);
                r.units.push_back(samples.units[i]);
            }
    for (const std::vector<double>& row : samples.rows) {
        std::vector<double> values;
        for (std::size_t i : columns) values.push_back(row[i]);
        r.readout.push_back(std::move(values));
    }
    return r;
}

/// The page's title and the model's T, V, R and constraints as its file writes them.
animation::Page page_of(const Model& model) {
    animation::Page page;
    page.title = model.title.empty() ? model.name : model.title;
    auto equation = [&](const std::string& name, const SourceExpression& e) {
        if (!e.text.empty() && e.text != "0") page.equations.push_back({name, e.text});
    };
    equation("T", model.T);
    equation("V", model.V);
    equation("R", model.R);
    for (const Constraint& c : model.constraints) page.equations.push_back({c.name, c.expr.text + " = 0"});
    return page;
}

int write_page(const animation::Page& page, const std::string& path, const std::string& command) {
    try {
        output::write_atomically(path, animation::html_page(page));
    } catch (const std::exception& e) {
        std::cerr << command << ": --animate: cannot write " << path << ": " << e.what() << "\n";
        return 3;
    }
    return 0;
}

/// "k=0.1, theta=0.5": a member's values, shortest round trip.
std::string member_label(const EnsembleDesign& design, std::size_t member) {
    std::string label;
    const std::vector<double> values = design.values(member);
    for (std::size_t k = 0; k < values.size(); ++k) {
        std::ostringstream os;
        os.precision(6);
        os << design.variables()[k].name << "=" << values[k];
        label += (label.empty() ? "" : ", ") + os.str();
    }
    return label;
}

const char* const kMemberColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
                                      "#e377c2", "#17becf", "#bcbd22", "#7f7f7f", "#393b79", "#ad494a"};

}  // namespace

int write_animation(const Model& model, const animation::Scene& scene, const eomgen::sim::Options& options,
                    const std::string& path, const std::string& command) {
    animation::Page page = page_of(model);
    try {
        RunFrames r = frames_of_run(model, scene, options);
        page.frames = std::move(r.frames);
        page.readout_names = std::move(r.names);
        page.readout_units = std::move(r.units);
        page.readout = std::move(r.readout);
    } catch (const std::runtime_error& e) {
        std::cerr << command << ": --animate: " << e.what() << "\n";
        return 2;
    }
    return write_page(page, path, command);
}

int write_ensemble_animation(const Model& model, const animation::Scene& scene, const eomgen::sim::Options& base,
                             const EnsembleDesign& design, const std::string& path, const RunMember& run) {
    static_assert(sizeof(kMemberColours) / sizeof(kMemberColours[0]) == kMaxAnimatedMembers);
    if (design.size() > kMaxAnimatedMembers) {
        std::cerr << "eomgen run: --animate overlays at most " << kMaxAnimatedMembers << " members; this ensemble has "
                  << design.size() << " (" << design.describe() << "): fewer --sweep values, or a smaller --sample\n";
        return 2;
    }
    const TempDir dir(std::filesystem::temp_directory_path(), "eomgen-animate.");
    animation::Page page = page_of(model);
    std::size_t longest = 0;
    std::vector<RunFrames> members;
    for (std::size_t m = 0; m < design.size(); ++m) {
        eomgen::sim::Options o = base;
        const std::vector<double> values = design.values(m);
        for (std::size_t k = 0; k < values.size(); ++k) {
            std::ostringstream assignment;
            assignment.precision(17);
            assignment << design.variables()[k].name << "=" << values[k];
            (design.variables()[k].is_state ? o.init : o.set).push_back(assignment.str());
        }
        o.csv = (dir.path() / ("member_" + std::to_string(m) + ".csv")).string();
        o.report_csv = false;
        const std::string label = member_label(design, m);
        std::string errors;
        if (const int code = run(o, errors); code != 0) {
            std::cerr << "eomgen run: --animate: member " << m << " (" << label << "): " << errors;
            return code == eomgen::sim::kExitOutput ? 3 : 2;
        }
        try {
            members.push_back(frames_of_run(model, scene, o));
        } catch (const std::runtime_error& e) {
            std::cerr << "eomgen run: --animate: member " << m << " (" << label << "): " << e.what() << "\n";
            return 2;
        }
        if (members.back().frames.t.size() > members[longest].frames.t.size()) longest = m;
        page.legend.push_back({label, kMemberColours[m]});
    }
    // One scene of every member's items, each member in its colour; a member that stopped early (--until) holds
    // its last frame. The ground once.
    animation::Frames& all = page.frames;
    all.t = members[longest].frames.t;
    all.planar = members[0].frames.planar;
    all.up = members[0].frames.up;
    for (std::size_t m = 0; m < members.size(); ++m) {
        const animation::Frames& f = members[m].frames;
        const std::size_t rows = f.t.size();
        for (std::size_t k = 0; k < f.items.size(); ++k) {
            animation::Primitive p = f.items[k];
            if (p.kind == animation::PrimitiveKind::Ground && m > 0) continue;
            if (p.kind != animation::PrimitiveKind::Ground) p.colour = kMemberColours[m];
            if (m > 0) p.label.clear();  // the legend names the members
            const std::size_t stride = f.values[k].size() / rows;
            std::vector<double> values;
            for (std::size_t row = 0; row < all.t.size(); ++row) {
                const std::size_t from = std::min(row, rows - 1) * stride;
                values.insert(values.end(), f.values[k].begin() + long(from), f.values[k].begin() + long(from + stride));
            }
            all.items.push_back(std::move(p));
            all.values.push_back(std::move(values));
        }
        // The readout: each member's values, named after it.
        for (std::size_t c = 0; c < members[m].names.size(); ++c) {
            page.readout_names.push_back(members[m].names[c] + " (" + std::to_string(m + 1) + ")");
            page.readout_units.push_back(members[m].units[c]);
        }
    }
    page.readout.resize(all.t.size());
    for (std::size_t row = 0; row < all.t.size(); ++row)
        for (const RunFrames& r : members) {
            const std::vector<double>& v = r.readout[std::min(row, r.readout.size() - 1)];
            page.readout[row].insert(page.readout[row].end(), v.begin(), v.end());
        }
    return write_page(page, path, "eomgen run");
}

}  // namespace eomgen::cli
