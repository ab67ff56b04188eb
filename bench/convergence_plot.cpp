#include "convergence_plot.h"
#include "error.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace {

constexpr double PANEL_W = 440, PANEL_H = 330, TITLE_H = 58, ROW = 17;
constexpr double LEFT = 66, RIGHT = 32, TOP = 52, BOTTOM = 48; // the plot area inside a panel

// Below each panel: one legend row per strategy, the slope -1 line and the ring.
double legend_height(const std::vector<Plot_Panel>& panels) {
	size_t rows = 0;
	for (const Plot_Panel& p : panels) rows = std::max(rows, p.series.size() + 2);
	return ROW * double(rows) + 16;
}
const char* const COLOURS[] = {"#c0392b", "#1f6fb4", "#2e8b57", "#8e44ad", "#d68910"};

// Appends printf-formatted text.
void add(std::string& svg, const char* format, ...) {
	char buffer[512];
	va_list args;
	va_start(args, format);
	std::vsnprintf(buffer, sizeof buffer, format, args);
	va_end(args);
	svg += buffer;
}

// A line segment with extra attributes (stroke, dashes, clipping).
void line(std::string& svg, double x1, double y1, double x2, double y2, const std::string& attributes) {
	add(svg, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" %s/>\n", x1, y1, x2, y2, attributes.c_str());
}

// A point of a series: a filled disc, or a ring for a point the caller marks (see Plot_Series).
void marker(std::string& svg, double x, double y, const std::string& colour, bool ring) {
	add(svg, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%s\" fill=\"%s\" stroke=\"%s\" stroke-width=\"1.5\"/>\n", x, y,
	    ring ? "4.5" : "3.5", ring ? "white" : colour.c_str(), colour.c_str());
}

// The decades [lo, hi] (powers of ten) that cover `values`.
struct Decades {
	int lo = 0, hi = 1;
};
Decades covering(const std::vector<double>& values) {
	auto [min, max] = std::minmax_element(values.begin(), values.end());
	Decades d{int(std::floor(std::log10(*min))), int(std::ceil(std::log10(*max)))};
	if (d.hi == d.lo) d.hi++;
	return d;
}

// Data -> SVG coordinates of one panel's plot area (log10 on both axes; SVG's y grows downwards).
struct Axes {
	double left, top, width, height;
	Decades x, y;
	double px(double value) const {
		return left + (std::log10(value) - x.lo) / (x.hi - x.lo) * width;
	}
	double py(double value) const {
		return top + height - (std::log10(value) - y.lo) / (y.hi - y.lo) * height;
	}
};

// "10" with the exponent raised; U+2212 is the typographic minus.
std::string power_of_ten(int exponent) {
	std::string sign = exponent < 0 ? "\u2212" : "";
	return "10<tspan dy=\"-7\" font-size=\"10\">" + sign + std::to_string(std::abs(exponent)) + "</tspan>";
}

// Grid lines and tick labels at the decades, short ticks at 2..9 times each decade.
void draw_axes(std::string& svg, const Axes& a, const std::string& x_label, const std::string& y_label) {
	double right = a.left + a.width, bottom = a.top + a.height;
	for (int k = a.x.lo; k <= a.x.hi; k++) {
		double x = a.px(std::pow(10.0, k));
		line(svg, x, a.top, x, bottom, "stroke=\"#ddd\"");
		add(svg, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%s</text>\n", x, bottom + 20, power_of_ten(k).c_str());
		for (int m = 2; m <= 9 && k < a.x.hi; m++) {
			double minor = a.px(m * std::pow(10.0, k));
			line(svg, minor, bottom, minor, bottom - 4, "stroke=\"#444\"");
		}
	}
	for (int k = a.y.lo; k <= a.y.hi; k++) {
		double y = a.py(std::pow(10.0, k));
		line(svg, a.left, y, right, y, "stroke=\"#ddd\"");
		add(svg, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">%s</text>\n", a.left - 6, y + 4, power_of_ten(k).c_str());
		for (int m = 2; m <= 9 && k < a.y.hi; m++) {
			double minor = a.py(m * std::pow(10.0, k));
			line(svg, a.left, minor, a.left + 4, minor, "stroke=\"#444\"");
		}
	}
	add(svg, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"#444\"/>\n", a.left, a.top,
	    a.width, a.height);
	add(svg, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%s</text>\n", a.left + a.width / 2, bottom + 40,
	    x_label.c_str());
	add(svg, "<text transform=\"translate(%.1f %.1f) rotate(-90)\" text-anchor=\"middle\">%s</text>\n", a.left - 46,
	    a.top + a.height / 2, y_label.c_str());
}

// A strategy: the dashed slope -1 line through its first point, then the polyline and its markers.
void draw_series(std::string& svg, const Axes& a, const Plot_Series& s, const char* colour, const std::string& clip) {
	// y = y_1 * x_1 / x, drawn across the whole panel and clipped to the plot area.
	double x_lo = std::pow(10.0, a.x.lo), x_hi = std::pow(10.0, a.x.hi), c = s.x[0] * s.y[0];
	std::string dashed = "stroke=\"" + std::string(colour) + "\" stroke-dasharray=\"5 4\" stroke-opacity=\"0.6\"";
	line(svg, a.px(x_lo), a.py(c / x_lo), a.px(x_hi), a.py(c / x_hi), dashed + " clip-path=\"url(#" + clip + ")\"");
	svg += "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" + std::string(colour) + "\" points=\"";
	for (size_t i = 0; i < s.x.size(); i++) add(svg, "%.1f,%.1f ", a.px(s.x[i]), a.py(s.y[i]));
	svg += "\"/>\n";
	for (size_t i = 0; i < s.x.size(); i++) {
		bool ring = i < s.hollow.size() && s.hollow[i];
		marker(svg, a.px(s.x[i]), a.py(s.y[i]), colour, ring);
	}
}

// Under the panel's plot area (whose top edge is at `bottom`), left-aligned with it.
void draw_legend(std::string& svg, const Axes& a, double bottom, const std::vector<Plot_Series>& series) {
	double x = a.left, y = bottom;
	for (size_t i = 0; i < series.size() + 2; i++) {
		double cy = y + ROW * double(i) + 8;
		bool ideal = i == series.size(), ring = i == series.size() + 1;
		const char* colour = i < series.size() ? COLOURS[i % 5] : "#666";
		if (!ring)
			line(svg, x, cy, x + 22, cy,
			     "stroke=\"" + std::string(colour) + (ideal ? "\" stroke-dasharray=\"5 4\"" : "\" stroke-width=\"2\""));
		if (!ideal) marker(svg, x + 11, cy, colour, ring);
		std::string label = ideal ? "slope \u22121 through the first point"
		                    : ring ? "mean > 2 \u00d7 the median render's"
		                           : series[i].label;
		add(svg, "<text x=\"%.1f\" y=\"%.1f\">%s</text>\n", x + 28, cy + 4, label.c_str());
	}
}

// Panel `index` of the grid, whose cells are `cell_h` high below the title.
void draw_panel(std::string& svg, const Plot& plot, size_t index, double cell_h) {
	const Plot_Panel& panel = plot.panels[index];
	std::vector<double> xs, ys;
	for (const Plot_Series& s : panel.series) {
		xs.insert(xs.end(), s.x.begin(), s.x.end());
		ys.insert(ys.end(), s.y.begin(), s.y.end());
	}
	double left = PANEL_W * double(index % plot.columns), top = TITLE_H + cell_h * double(index / plot.columns);
	Axes a{left + LEFT, top + TOP, PANEL_W - LEFT - RIGHT, PANEL_H - TOP - BOTTOM, covering(xs), covering(ys)};
	std::string clip = "plot" + std::to_string(index);
	add(svg, "<clipPath id=\"%s\"><rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\"/></clipPath>\n",
	    clip.c_str(), a.left, a.top, a.width, a.height);
	add(svg, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-weight=\"bold\">%s</text>\n", left + PANEL_W / 2,
	    top + 20, panel.title.c_str());
	add(svg, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" fill=\"#333\">%s</text>\n", left + PANEL_W / 2,
	    top + 38, panel.headline.c_str());
	draw_axes(svg, a, plot.x_label, "relMSE");
	for (size_t i = 0; i < panel.series.size(); i++) draw_series(svg, a, panel.series[i], COLOURS[i % 5], clip);
	draw_legend(svg, a, top + PANEL_H, panel.series);
}

} // namespace

void write_convergence_svg(const std::string& path, const Plot& plot) {
	size_t columns = std::max<size_t>(1, std::min(plot.columns, plot.panels.size()));
	size_t rows = (plot.panels.size() + columns - 1) / columns;
	double cell_h = PANEL_H + legend_height(plot.panels);
	// Wide enough for the titles too (a character of sans-serif is about 0.6 of its size wide); the
	// panels are centred under them.
	double grid_width = PANEL_W * double(columns), height = TITLE_H + cell_h * double(rows);
	double width = std::max({grid_width, 0.6 * 16 * double(plot.title.size()) + 40,
	                         0.6 * 12 * double(plot.subtitle.size()) + 40});
	Plot grid = plot;
	grid.columns = columns;
	std::string svg;
	add(svg, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
	         "font-family=\"sans-serif\" font-size=\"12\">\n",
	    width, height, width, height);
	add(svg, "<rect width=\"%.0f\" height=\"%.0f\" fill=\"white\"/>\n", width, height);
	add(svg, "<text x=\"%.1f\" y=\"24\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\">%s</text>\n",
	    width / 2, plot.title.c_str());
	add(svg, "<text x=\"%.1f\" y=\"44\" text-anchor=\"middle\" font-size=\"12\" fill=\"#333\">%s</text>\n", width / 2,
	    plot.subtitle.c_str());
	add(svg, "<g transform=\"translate(%.1f,0)\">\n", (width - grid_width) / 2);
	for (size_t i = 0; i < plot.panels.size(); i++) draw_panel(svg, grid, i, cell_h);
	svg += "</g>\n";
	svg += "</svg>\n";

	std::filesystem::path parent = std::filesystem::path(path).parent_path();
	if (!parent.empty()) std::filesystem::create_directories(parent);
	std::ofstream file(path);
	if (!(file << svg)) throw Input_Error(path + ": cannot write the SVG plot");
}
