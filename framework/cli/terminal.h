#pragma once
// A progress bar with percentage and estimated time left, redrawn in place on one line:
//   [##############----------------]  47%  ETA 0:12
// It draws only when enabled (the renderer enables it when stderr is a terminal and --quiet is
// not given), so logs and pipes stay clean. update() may be called from any thread. The line is
// shorter than the terminal is wide (the bar shrinks, and is left out when fewer than 10 columns
// remain for it), so that it never wraps: a wrapped line cannot be redrawn in place.
#include <chrono>
#include <cstddef>
#include <iosfwd>
#include <mutex>

bool stderr_is_terminal();

// The width of the terminal on stderr (ioctl TIOCGWINSZ), else $COLUMNS, else 80.
size_t terminal_columns();

class Progress_Bar {
public:
	Progress_Bar(std::ostream& out, bool enabled, size_t columns = terminal_columns());
	~Progress_Bar();

	// `done` of `total` units of work are finished. Calls may arrive out of order from several
	// threads; the bar never moves backwards and is redrawn only when the percentage changes. The
	// first call draws, also with done = 0, so the bar appears as soon as the work starts.
	void update(size_t done, size_t total);
	// Erases the bar so the next output starts on a clean line. Called by the destructor.
	void finish();

private:
	void draw(size_t done, size_t total);

	std::ostream& out;
	bool enabled;
	size_t columns;
	std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
	std::mutex mutex;
	size_t done_max = 0;
	int percent_drawn = -1;
	size_t line_length = 0; // characters on screen, for erasing
};
