#include "terminal.h"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>

#include <cstdlib>
#include <sys/ioctl.h>
#include <unistd.h>

namespace {
constexpr size_t BAR_WIDTH = 30;     // on a terminal wide enough
constexpr size_t SMALLEST_BAR = 10;  // narrower than this, the bar is left out
constexpr size_t DEFAULT_COLUMNS = 80;

// "m:ss", or "h:mm:ss" from one hour on.
std::string clock_time(double seconds) {
	long s = long(seconds + 0.5);
	char text[32];
	if (s >= 3600) {
		std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
	} else {
		std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
	}
	return text;
}
} // namespace

bool stderr_is_terminal() {
	return isatty(STDERR_FILENO) != 0;
}

size_t terminal_columns() {
	winsize size{};
	if (ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
	if (const char* columns = std::getenv("COLUMNS")) {
		long value = std::strtol(columns, nullptr, 10);
		if (value > 0) return size_t(value);
	}
	return DEFAULT_COLUMNS;
}

Progress_Bar::Progress_Bar(std::ostream& out_, bool enabled_, size_t columns_)
    : out(out_), enabled(enabled_), columns(columns_) {
}

Progress_Bar::~Progress_Bar() {
	finish();
}

void Progress_Bar::update(size_t done, size_t total) {
	if (!enabled || total == 0) return;
	std::lock_guard<std::mutex> lock(mutex);
	done_max = std::max(done_max, done); // a late report from a slower thread changes nothing
	int percent = int(100 * done_max / total);
	if (percent == percent_drawn) return;
	percent_drawn = percent;
	draw(done_max, total);
}

void Progress_Bar::draw(size_t done, size_t total) {
	double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	// Remaining time, assuming the remaining work goes at the average speed so far.
	std::string eta = done > 0 ? clock_time(elapsed * double(total - done) / double(done)) : "-:--";
	char percent[8];
	std::snprintf(percent, sizeof percent, "%3d%%", percent_drawn);
	std::string numbers = std::string(percent) + "  ETA " + eta;
	// The line stays below the terminal's width (a line that fills it may wrap): "[bar] " + numbers.
	size_t room = columns > numbers.size() + 4 ? columns - numbers.size() - 4 : 0;
	size_t bar_width = std::min(BAR_WIDTH, room);
	std::string line = numbers;
	if (bar_width >= SMALLEST_BAR) {
		size_t filled = bar_width * done / total;
		line = "[" + std::string(filled, '#') + std::string(bar_width - filled, '-') + "] " + numbers;
	}
	// Carriage return: redraw over the previous bar; pad with spaces if the new line is shorter.
	out << '\r' << line << std::string(line_length > line.size() ? line_length - line.size() : 0, ' ') << std::flush;
	line_length = std::max(line_length, line.size());
}

void Progress_Bar::finish() {
	if (!enabled) return;
	std::lock_guard<std::mutex> lock(mutex);
	if (line_length > 0) out << '\r' << std::string(line_length, ' ') << '\r' << std::flush;
	line_length = 0;
}
