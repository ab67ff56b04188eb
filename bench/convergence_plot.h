#pragma once
// The convergence plot, written by hand as SVG: one log-log panel per experiment with relMSE against
// render time, a polyline with markers per strategy, and a dashed line of slope -1 through each
// strategy's first point (an unbiased estimator's relMSE falls as 1 / time: it should follow it).
// Points marked hollow are drawn as rings, explained in the legend.
#include <string>
#include <vector>

struct Plot_Series {
	std::string label;        // legend text
	std::vector<double> x, y; // seconds and relMSE, all > 0
	std::vector<bool> hollow; // per point: drawn as a ring (a mean carried by a few renders)
};

struct Plot_Panel {
	std::string title;
	std::vector<Plot_Series> series;
};

// Throws Input_Error if the file cannot be written.
void write_convergence_svg(const std::string& path, const std::string& title, const std::vector<Plot_Panel>& panels);
