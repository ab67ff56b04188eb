#include "report_page.h"

#include "html.h"
#include "image_compare.h"
#include "z_heat_map.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace {

constexpr size_t FAILURES_SHOWN = 3;  // per test case; the other recorded ones fold away
constexpr size_t LONG_MESSAGE = 600; // characters; longer messages fold away after their first line

const char* STYLE = R"(
body { font-family: sans-serif; max-width: 1100px; margin: 0 auto; padding: 1em 2em; color: #1f2328;
	line-height: 1.45; }
h1 { margin-bottom: 0.2em; }
h2 { border-bottom: 1px solid #d0d7de; padding-bottom: 0.2em; margin-top: 2em; }
h3 { font-size: 1em; margin: 0 0 0.4em 0; }
code, pre { font-family: monospace; font-size: 0.9em; }
pre { background: #f6f8fa; padding: 0.6em; overflow-x: auto; white-space: pre-wrap; }
table { border-collapse: collapse; }
th, td { text-align: left; padding: 0.3em 0.9em; border-bottom: 1px solid #d0d7de; white-space: nowrap; }
.badge { display: inline-block; min-width: 5.5em; text-align: center; color: #fff; font-weight: bold;
	border-radius: 4px; padding: 0.1em 0.5em; font-size: 0.9em; }
.PASS { background: #1a7f37; } .FAIL { background: #cf222e; }
.CRASHED { background: #8250df; } .NOT_RUN { background: #6e7781; }
.case { border-left: 4px solid #cf222e; padding: 0.4em 0.9em; margin: 1em 0; background: #fff8f8; }
.case.passed { border-left-color: #1a7f37; background: #f6fff8; }
.check { margin: 0.6em 0; }
.message { white-space: pre-wrap; margin: 0.2em 0; }
.where { color: #57606a; font-size: 0.9em; }
.images { display: flex; flex-wrap: wrap; gap: 1em; margin: 0.6em 0; }
figure { margin: 0; }
figure img { width: 256px; height: auto; image-rendering: pixelated; border: 1px solid #d0d7de; display: block; }
figcaption { font-size: 0.9em; color: #57606a; max-width: 256px; }
.key { display: inline-block; width: 0.9em; height: 0.9em; border: 1px solid #8c959f; vertical-align: middle; }
.missing { width: 256px; height: 256px; border: 1px dashed #8c959f; display: flex; align-items: center;
	justify-content: center; color: #57606a; }
)";

std::string css_class(Status status) {
	return status == Status::not_run ? "NOT_RUN" : status_name(status);
}

std::string badge(Status status) {
	return "<span class=\"badge " + css_class(status) + "\">" + status_name(status) + "</span>";
}

std::string colour(const Srgb8& c) {
	char hex[8];
	std::snprintf(hex, sizeof hex, "#%02x%02x%02x", c[0], c[1], c[2]);
	return hex;
}

std::string key(const Srgb8& c) {
	return "<span class=\"key\" style=\"background: " + colour(c) + "\"></span>";
}

std::string task_heading(const Task_Info& task) {
	return "Task " + std::to_string(task.number) + ": " + task.title;
}

void summary(std::ostream& out, const std::vector<Task_Result>& tasks) {
	out << "<table id=\"summary\">\n<tr><th>Task</th><th>Status</th><th>Test cases passed</th><th>Your file</th>"
	       "</tr>\n";
	for (const Task_Result& t : tasks) {
		std::string passed = t.test_cases.empty() ? "–"
		                                          : std::to_string(t.passed_count()) + " of " +
		                                                std::to_string(t.test_cases.size());
		out << "<tr><td><a href=\"#task" << t.task.number << "\">" << escape(task_heading(t.task)) << "</a></td><td>"
		    << badge(t.status) << "</td><td>" << passed << "</td><td><code>" << escape(t.task.student_file)
		    << "</code></td></tr>\n";
	}
	out << "</table>\n";
}

void how_to_read(std::ostream& out) {
	using namespace z_colours;
	out << "<details><summary>How to read this report</summary>\n"
	       "<p>Each task is graded on its own: the grader of task N links <em>your</em> task N with the reference "
	       "solution of the other six. A task is <b>PASS</b> when every test case of its grader passes, "
	       "<b>FAIL</b> when some fail (their messages say what is wrong and which handout section to read), "
	       "<b>CRASHED</b> when the grader crashed or ran out of time (the end of its output is shown), and "
	       "<b>NOT RUN</b> when it did not build (the compiler's error is shown).</p>\n"
	       "<p>Every grader renders a small scene with your code and compares it with a reference image, pixel "
	       "by pixel, with a z-test that knows the noise of both images: z = (yours − reference) / (its standard "
	       "deviation). The heat map shows, per pixel, the colour channel with the largest |z|: "
	    << key(zero) << " z = 0, " << key(noise_too_bright) << " / " << key(noise_too_dark)
	    << " up to the critical |z| (noise: a correct render looks like this, pale and speckled), "
	    << key(fail_too_bright) << " too bright and " << key(fail_too_dark)
	    << " too dark beyond the critical |z| (the pixel fails), " << key(not_a_number)
	    << " not a number. The critical |z| (under each heat map) keeps the chance that a correct render fails "
	       "anywhere below "
	    << 100 * IMAGE_ALPHA
	    << "% (a Šidák correction over all pixel channels); a few pixels beyond it are normal (a rare bright "
	       "path), and the image passes while they are no more than correct renders have and its noise is no "
	       "more than the reference's.</p>\n</details>\n";
}

// A message on its own; a very long one folds away after its first line.
void message(std::ostream& out, const std::string& text) {
	if (text.size() <= LONG_MESSAGE) {
		out << "<p class=\"message\">" << escape(text) << "</p>\n";
		return;
	}
	std::string first_line = text.substr(0, std::min(text.find('\n'), size_t(200)));
	out << "<details><summary>" << escape(first_line) << " …</summary><p class=\"message\">" << escape(text)
	    << "</p></details>\n";
}

void failure(std::ostream& out, const Failure& f, bool same_messages_as_before) {
	out << "<div class=\"check\">\n";
	if (f.messages.empty()) out << "<p class=\"message\">A " << escape(f.kind) << " failed.</p>\n";
	if (!same_messages_as_before) {
		for (const std::string& text : f.messages) message(out, text);
	}
	// Where the check is in the graders' code and what it evaluated: for instructors, folded away.
	out << "<details class=\"where\"><summary>the check, for instructors</summary>" << escape(f.where);
	if (!f.expression.empty()) out << " · <code>" << escape(f.expression) << "</code>";
	if (!f.expansion.empty()) out << " with values <code>" << escape(f.expansion) << "</code>";
	if (f.expression.empty() && f.kind != "check" && f.kind != "failure") out << " · " << escape(f.kind);
	out << "</details>\n</div>\n";
}

void figure(std::ostream& out, const std::filesystem::path& file, const std::string& caption) {
	std::string uri = png_data_uri(file);
	out << "<figure>";
	if (uri.empty()) {
		out << "<div class=\"missing\">(no image)</div>";
	} else {
		out << "<img src=\"" << uri << "\" alt=\"" << escape(caption) << "\">";
	}
	out << "<figcaption>" << caption << "</figcaption></figure>\n";
}

// The three pictures; the comparison's message too, unless a failed check already shows it.
void image_test(std::ostream& out, const Image_Test& test, bool show_message) {
	char z[32];
	std::snprintf(z, sizeof z, "%.2f", test.z_critical);
	out << "<div class=\"images\">\n";
	figure(out, test.render, "Your render of <code>" + escape(test.scene) + "</code>");
	figure(out, test.reference, "The reference image");
	figure(out, test.z_map,
	       "Where they differ (z per pixel): " + key(z_colours::fail_too_bright) + " too bright, " +
	           key(z_colours::fail_too_dark) + " too dark beyond |z| = " + z + "; pale: noise");
	out << "</div>\n";
	if (show_message) out << "<p class=\"where\">" << escape(test.message) << "</p>\n";
}

// The failures from `first` to `last`; messages that repeat those of the failure before are shown once.
void failures(std::ostream& out, const std::vector<Failure>& all, size_t first, size_t last) {
	for (size_t i = first; i < last; i++) failure(out, all[i], i > first && all[i].messages == all[i - 1].messages);
}

void test_case(std::ostream& out, const Test_Case& c, const std::string& log_file) {
	out << "<div class=\"case" << (c.passed ? " passed" : "") << "\">\n<h3>" << (c.passed ? "✓ " : "✗ ")
	    << escape(c.name) << "</h3>\n";
	for (const Image_Test& test : c.image_tests) image_test(out, test, c.failures.empty());
	if (!c.figures.empty()) {
		out << "<div class=\"images\">\n";
		for (const Figure& f : c.figures) figure(out, f.file, escape(f.caption));
		out << "</div>\n";
	}
	size_t shown = std::min(c.failures.size(), FAILURES_SHOWN);
	failures(out, c.failures, 0, shown);
	if (c.failures.size() > shown) {
		out << "<details><summary>" << c.failures.size() - shown + c.more_failures << " more failed checks</summary>\n";
		failures(out, c.failures, shown, c.failures.size());
		if (c.more_failures > 0) {
			out << "<p>… and " << c.more_failures << " more: see <a href=\"" << escape(log_file) << "\">"
			    << escape(log_file) << "</a>.</p>\n";
		}
		out << "</details>\n";
	}
	out << "</div>\n";
}

void task_section(std::ostream& out, const Task_Result& t) {
	out << "<section id=\"task" << t.task.number << "\">\n<h2>" << badge(t.status) << " "
	    << escape(task_heading(t.task)) << "</h2>\n<p>" << escape(t.why) << " You edit <code>"
	    << escape(t.task.student_file) << "</code>; the handout is <code>" << escape(t.task.handout) << "</code>.";
	if (!t.log_file.empty()) {
		out << " Full output: <a href=\"" << escape(t.log_file) << "\">" << escape(t.log_file) << "</a>.";
	}
	out << "</p>\n";
	if (!t.sandbox.empty()) {
		out << "<p class=\"where\">How your code ran: " << escape(t.sandbox) << "; inputs: " << escape(t.inputs)
		    << ".</p>\n";
	}
	if (!t.not_run.empty()) {
		out << "<p>Test cases that did not run:</p>\n<ul>\n";
		for (const std::string& name : t.not_run) out << "<li>" << escape(name) << "</li>\n";
		out << "</ul>\n";
	}
	if (!t.log_tail.empty()) out << "<pre>" << escape(t.log_tail) << "</pre>\n";
	// The pictures first, then the other failed test cases; passed ones are only listed.
	std::vector<const Test_Case*> quiet;
	for (const Test_Case& c : t.test_cases) {
		if (!c.image_tests.empty()) test_case(out, c, t.log_file);
	}
	for (const Test_Case& c : t.test_cases) {
		if (c.image_tests.empty() && !c.passed) test_case(out, c, t.log_file);
		if (c.image_tests.empty() && c.passed) quiet.push_back(&c);
	}
	if (!quiet.empty()) {
		out << "<details><summary>" << quiet.size() << " other test cases pass</summary>\n<ul>\n";
		for (const Test_Case* c : quiet) out << "<li>✓ " << escape(c->name) << "</li>\n";
		out << "</ul>\n</details>\n";
	}
	out << "</section>\n";
}

} // namespace

void write_report_page(std::ostream& out, const std::vector<Task_Result>& tasks, const std::string& made_at) {
	out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
	       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
	       "<title>PathTracer Lab: grade report</title>\n<style>"
	    << STYLE << "</style>\n</head>\n<body>\n<h1>PathTracer Lab: grade report</h1>\n"
	    << "<p>Your code in <code>student/</code>, graded by <code>./lab report</code> on " << escape(made_at)
	    << ".</p>\n";
	summary(out, tasks);
	how_to_read(out);
	for (const Task_Result& t : tasks) task_section(out, t);
	out << "</body>\n</html>\n";
}
