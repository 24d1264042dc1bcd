/** @file html_page.hpp  One self-contained HTML file that plays a run's frames: the data as JSON and the player
 * (player.js) inline, nothing fetched from a network. */
#pragma once

#include "animation/frames.hpp"

#include <string>
#include <utility>
#include <vector>

namespace eomgen::animation {

struct Page {
    std::string title;
    /// Shown under the title as "name = text": the model's T, V, R and constraints as its file writes them.
    std::vector<std::pair<std::string, std::string>> equations;
    Frames frames;
    /// The values listed beside the view at each frame (coordinates, outputs, energy), with their units.
    std::vector<std::string> readout_names, readout_units;
    std::vector<std::vector<double>> readout;  ///< per frame
    /// An ensemble's members: each member's values ("k=0.1") and its colour, listed beside the view.
    std::vector<std::pair<std::string, std::string>> legend;
};

/// The HTML text of the page. Every text from the model is in the JSON (escaped, `<` as \u003c) and set by the
/// player with textContent, never as markup.
std::string html_page(const Page& page);

}  // namespace eomgen::animation
