#pragma once
// What makes a picture readable without the text around it: labels drawn
// into the image (stb_easy_font's block letters, scaled), and a colour bar
// that states what a false-colour heatmap's colours mean.

#include "core/image/image.h"

#include <string>

namespace triwalk {

// Height of a line of text at scale (stb_easy_font's 12 pixels a line at 1).
int textHeight(int scale);
int textWidth(const std::string& text, int scale);
// Draws text with its top left corner at `at`; what falls outside is cut.
void drawText(Rgb8Image& image, glm::ivec2 at, const std::string& text, glm::u8vec3 color, int scale);

// image with a band below it: the false-colour scale (falseColor) from 0
// to maxValue as a bar, its two ends labelled, and what it measures
// ("RMS colour difference, 0..1"), so that a heatmap states its scale.
Rgb8Image withColourBar(const Rgb8Image& image, float maxValue, const std::string& quantity);

}  // namespace triwalk
