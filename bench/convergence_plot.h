#pragma once
// The convergence plots, written by hand as SVG: a grid of log-log panels of relMSE against spp (or
// time), one per experiment, with a polyline with markers per strategy, a dashed line of slope -1
// through each strategy's first point (an unbiased estimator's relMSE falls as 1 / spp: it should
// follow it) and the panel's headline under its title. Points marked hollow are drawn as rings,
// explained in the legend.
#include <string>
#include <vector>

struct Plot_Series {
	std::string label;        // legend text
	std::vector<double> x, y; // spp or seconds, and relMSE, all > 0
	std::vector<bool> hollow; // per point: drawn as a ring (a mean carried by a few renders)
};

struct Plot_Panel {
	std::string title;    // what is compared
	std::string headline; // the result, in a few words
	std::vector<Plot_Series> series;
};

struct Plot {
	std::string title, subtitle; // subtitle: film, threads, how time was measured
	std::string x_label = "samples per pixel";
	std::vector<Plot_Panel> panels;
	size_t columns = 4;
};

// Throws Input_Error if the file cannot be written.
void write_convergence_svg(const std::string& path, const Plot& plot);
