/** @file html_page.cpp  The animation's HTML: layout, JSON of the frames, the player inline. */
#include "animation/html_page.hpp"

#include "text/escape.hpp"

#include <cmath>
#include <cstdio>

namespace eomgen::animation {

extern const char* const kPlayerJs;  // player.js, embedded by the build (player_js.cpp.in)

namespace {

const char* kind_name(PrimitiveKind k) {
    switch (k) {
        case PrimitiveKind::Point: return "point";
        case PrimitiveKind::Polyline: return "polyline";
        case PrimitiveKind::Spring: return "spring";
        case PrimitiveKind::Circle: return "circle";
        case PrimitiveKind::Trace: return "trace";
        case PrimitiveKind::Ground: return "ground";
        case PrimitiveKind::Solid: return "solid";
    }
    return "point";
}

const char* shape_name(SolidShape s) {
    switch (s) {
        case SolidShape::Box: return "box";
        case SolidShape::Ellipsoid:
        case SolidShape::InertiaEllipsoid: return "ellipsoid";
        case SolidShape::Rod: return "rod";
        case SolidShape::Disk: return "disk";
        case SolidShape::Ring: return "ring";
        case SolidShape::Cylinder: return "cylinder";
        case SolidShape::Cone: return "cone";
        case SolidShape::Triangle: return "triangle";
    }
    return "box";
}

/// Seven significant digits: positions to well under a pixel on any screen, in half the bytes of round-trip.
void number(std::string& out, double x) {
    char buf[32];
    if (!std::isfinite(x)) x = 0;  // frames.cpp refuses non-finite positions; a readout's NaN shows as 0
    std::snprintf(buf, sizeof buf, "%.7g", x);
    out += buf;
}

void numbers(std::string& out, const std::vector<double>& v) {
    out += '[';
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (i) out += ',';
        number(out, v[i]);
    }
    out += ']';
}

std::string json_of(const Page& page) {
    using text::json_string;
    const Frames& f = page.frames;
    std::string j = "{\"title\":" + json_string(page.title) + ",\"equations\":[";
    for (std::size_t i = 0; i < page.equations.size(); ++i)
        j += (i ? ",[" : "[") + json_string(page.equations[i].first) + "," + json_string(page.equations[i].second) + "]";
    j += "],\"legend\":[";
    for (std::size_t i = 0; i < page.legend.size(); ++i)
        j += (i ? ",[" : "[") + json_string(page.legend[i].first) + "," + json_string(page.legend[i].second) + "]";
    j += "],\"planar\":";
    j += f.planar ? "true" : "false";
    j += ",\"up\":";
    numbers(j, {f.up[0], f.up[1], f.up[2]});
    j += ",\"t\":";
    numbers(j, f.t);
    j += ",\"items\":[";
    for (std::size_t k = 0; k < f.items.size(); ++k) {
        const Primitive& p = f.items[k];
        const std::size_t stride = f.t.empty() ? 0 : f.values[k].size() / f.t.size();
        j += (k ? ",{" : "{");
        j += "\"kind\":\"" + std::string(kind_name(p.kind)) + "\",\"shape\":\"" + shape_name(p.shape) + "\"";
        j += ",\"label\":" + json_string(p.label) + ",\"colour\":" + json_string(p.colour);
        j += ",\"fill\":" + std::string(p.fill ? "true" : "false") + ",\"coils\":" + std::to_string(p.coils);
        j += ",\"axis\":\"" + std::string(1, p.ground_axis) + "\",\"has_radius\":" + (p.has_radius ? "true" : "false");
        j += ",\"stride\":" + std::to_string(stride) + ",\"v\":";
        numbers(j, f.values[k]);
        j += "}";
    }
    j += "],\"readout\":{\"names\":[";
    for (std::size_t i = 0; i < page.readout_names.size(); ++i) j += (i ? "," : "") + json_string(page.readout_names[i]);
    j += "],\"units\":[";
    for (std::size_t i = 0; i < page.readout_units.size(); ++i) j += (i ? "," : "") + json_string(page.readout_units[i]);
    j += "],\"v\":[";
    for (std::size_t r = 0; r < page.readout.size(); ++r) {
        if (r) j += ',';
        numbers(j, page.readout[r]);
    }
    j += "]}}";
    // Inside <script>, "</script>" or "<!--" in a string would end or change the element: '<' is never needed raw.
    std::string safe;
    safe.reserve(j.size());
    for (const char c : j) safe += c == '<' ? std::string("\\u003c") : std::string(1, c);
    return safe;
}

}  // namespace

std::string html_page(const Page& page) {
    std::string h;
    h += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<title>eomgen animation</title>\n<style>\n"
         "body { font: 14px sans-serif; margin: 12px; color: #222; }\n"
         "h1 { font-size: 18px; margin: 0 0 6px 0; }\n"
         "#main { display: flex; gap: 12px; align-items: flex-start; }\n"
         "#view { flex: 1 1 0; min-width: 0; max-width: 960px; height: min(70vh, 640px); border: 1px solid #ccc; "
         "touch-action: none; cursor: grab; }\n"
         "#side { flex: 0 0 240px; overflow-x: auto; }\n"
         "#controls { margin: 8px 0; display: flex; gap: 8px; align-items: center; }\n"
         "#scrub { flex: 1 1 auto; }\n"
         "#readout td { padding: 1px 6px; font-family: monospace; }\n"
         "#legend { padding-left: 16px; margin: 4px 0; font-family: monospace; }\n"
         "#equations { font-family: monospace; font-size: 12px; white-space: pre-wrap; }\n"
         "#probe { display: none; }\n"
         "</style>\n</head>\n<body>\n<h1 id=\"title\"></h1>\n"
         "<div id=\"main\"><canvas id=\"view\"></canvas>\n"
         "<div id=\"side\"><div id=\"time\"></div><ul id=\"legend\"></ul><table id=\"readout\"></table></div></div>\n"
         "<div id=\"controls\"><button id=\"play\" type=\"button\">Play</button>"
         "<input id=\"scrub\" type=\"range\" min=\"0\" max=\"0\" step=\"1\" value=\"0\" aria-label=\"time\">"
         "<label>speed <select id=\"speed\"><option>0.25</option><option>0.5</option>"
         "<option selected>1</option><option>2</option><option>4</option></select></label>"
         "<button id=\"reset\" type=\"button\">Reset view</button></div>\n"
         "<p>Drag to turn the view (3-D) or move it (2-D); the wheel zooms; space plays and pauses; the arrow keys step one frame.</p>\n"
         "<ul id=\"equations\"></ul>\n<pre id=\"probe\"></pre>\n"
         "<script type=\"application/json\" id=\"eomgen-data\">";
    h += json_of(page);
    h += "</script>\n<script>\n";
    h += kPlayerJs;
    h += "</script>\n</body>\n</html>\n";
    return h;
}

}  // namespace eomgen::animation
