// The similarity report's HTML pages: the summary (index.html), one page per task with its pairs
// ranked, and one page per listed pair with the two files side by side and the code they share
// marked. Self-contained pages: no script, no file from elsewhere.

const STYLE = `
body { font-family: sans-serif; max-width: 1400px; margin: 0 auto; padding: 1em 2em; color: #1f2328; line-height: 1.45; }
h2 { border-bottom: 1px solid #d0d7de; padding-bottom: 0.2em; margin-top: 1.6em; }
table { border-collapse: collapse; }
th, td { text-align: left; padding: 0.25em 0.8em; border-bottom: 1px solid #d0d7de; white-space: nowrap; }
td.number { text-align: right; font-variant-numeric: tabular-nums; }
tr.flagged td { background: #ffebe9; }
.bar { display: inline-block; height: 0.7em; background: #cf222e; margin-right: 0.4em; }
.note { color: #59636e; }
.files { display: grid; grid-template-columns: minmax(0, 1fr) minmax(0, 1fr); gap: 1em; }
.code { font-family: monospace; font-size: 0.85em; border: 1px solid #d0d7de; overflow-x: auto; }
.line { white-space: pre; padding: 0 0.5em; min-height: 1.3em; }
.line .n { display: inline-block; width: 3em; color: #8c959f; user-select: none; }
.line .f { display: inline-block; width: 2.5em; color: #1f2328; font-weight: bold; user-select: none; }
.longest { box-shadow: inset 4px 0 #cf222e; }
`;

// Background colours of the shared fragments, in turn.
const COLOURS = ["#fff3b0", "#c8f0d0", "#cde4ff", "#f5d0f0", "#ffd8b5", "#d9d2ff", "#c7f3ef", "#f0e0c8"];

// Lines from-to, or one line.
export function span(lines) {
	return lines.from === lines.to ? `${lines.from}` : `${lines.from}-${lines.to}`;
}

function lines(range) {
	return `line${range.from === range.to ? "" : "s"} ${span(range)}`;
}

function escape(text) {
	return String(text).replace(/[&<>"']/g, c => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" })[c]);
}

function page(title, body) {
	return `<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n<title>${escape(title)}</title>\n` +
		`<style>${STYLE}</style>\n</head>\n<body>\n${body}</body>\n</html>\n`;
}

function percent(similarity) {
	return `<span class="bar" style="width: ${(similarity * 6).toFixed(2)}em"></span>${(100 * similarity).toFixed(1)} %`;
}

function who(file) {
	return file.kind === "reference" ? "<em>the reference solution</em>" : escape(file.name);
}

function longestCell(pair) {
	const longest = pair.fragments[0];
	if (!longest) return '<span class="note">none</span>';
	return `${lines(longest.a)} of ${who(pair.a)} = ${lines(longest.b)} of ${who(pair.b)}`;
}

// Table rows of pairs; with `task`, a first column names the task.
function pairRows(pairs, task = null) {
	return pairs.map(pair => `<tr${pair.flagged ? ' class="flagged"' : ""}>` +
		(task ? `<td>task ${task.number}</td>` : "") + `<td class="number">${pair.rank}</td><td>${who(pair.a)}</td><td>${who(pair.b)}</td>` +
		`<td>${percent(pair.similarity)}</td><td>${longestCell(pair)}</td>` +
		`<td>${pair.page ? `<a href="${pair.page}">side by side</a>` : ""}</td></tr>\n`).join("");
}

const PAIR_HEAD = "<tr><th>rank</th><th>submission</th><th>compared with</th><th>similarity</th>" +
	"<th>longest shared fragment</th><th></th></tr>\n";

function howToRead(threshold) {
	return `<p class="note">Similarity is the share of two files' code fingerprints (k-grams of their syntax
trees, found by <a href="https://dolos.ugent.be">Dolos</a>) that the two have in common: 100 % for
copies, also with every name changed or the functions in another order, since names, numbers and
comments are not part of a syntax tree's shape. The code of the stub every student starts from
(<code>student/</code>) counts for no pair. Pairs at or above ${(100 * threshold).toFixed(0)} % are marked
red: look at them side by side. Code that the handout dictates is similar in honest solutions too,
so a high similarity is a reason to look, not a verdict.</p>\n`;
}

export function indexPage(report) {
	let body = `<h1>Similarity report</h1>\n<p>${report.submissions.length} submissions in ` +
		`<code>${escape(report.class)}</code>, each task file compared with every other submission's and ` +
		`with the reference's. Every pair is in <a href="similarity.csv">similarity.csv</a>.</p>\n` +
		howToRead(report.threshold);
	body += "<h2>Tasks</h2>\n<table>\n<tr><th>task</th><th>submissions with the file</th><th>pairs</th>" +
		"<th>marked</th><th>most similar pair</th><th>similarity</th></tr>\n";
	for (const task of report.tasks) {
		const top = task.pairs[0], marked = task.pairs.filter(pair => pair.flagged).length;
		body += `<tr${marked > 0 ? ' class="flagged"' : ""}><td><a href="task${task.number}.html">task ${task.number}</a>` +
			` (<code>${escape(task.file)}</code>)</td><td class="number">${task.submitted}</td>` +
			`<td class="number">${task.pairs.length}</td><td class="number">${marked}</td>` +
			`<td>${top ? `${who(top.a)} and ${who(top.b)}` : '<span class="note">no pair</span>'}</td>` +
			`<td>${top ? percent(top.similarity) : ""}</td></tr>\n`;
	}
	body += "</table>\n";
	const flagged = report.tasks.flatMap(task => task.pairs.filter(pair => pair.flagged).map(pair => ({ task, pair })));
	body += `<h2>Marked pairs (${flagged.length})</h2>\n`;
	if (flagged.length > 0) {
		body += "<table>\n<tr><th>task</th>" + PAIR_HEAD.slice(4);
		for (const { task, pair } of flagged) body += pairRows([pair], task);
		body += "</table>\n";
	} else {
		body += "<p>None.</p>\n";
	}
	if (report.empty.length > 0) {
		body += `<h2>Submissions without a task file (${report.empty.length})</h2>\n<p>` +
			report.empty.map(escape).join(", ") + "</p>\n";
	}
	return page("Similarity report", body);
}

export function taskPage(task, report) {
	let body = `<p><a href="index.html">Similarity report</a></p>\n<h1>Task ${task.number}: ` +
		`<code>${escape(task.file)}</code></h1>\n<p>${task.submitted} submissions have this file; ` +
		`${task.pairs.length} pairs, most similar first.</p>\n` + howToRead(report.threshold);
	if (task.pairs.length === 0) return page(`Task ${task.number}: similarity`, body + "<p>No pair to compare.</p>\n");
	body += "<table>\n" + PAIR_HEAD + pairRows(task.pairs.slice(0, task.listed)) + "</table>\n";
	if (task.listed < task.pairs.length) {
		body += `<p class="note">${task.pairs.length - task.listed} less similar pairs are in ` +
			`<a href="similarity.csv">similarity.csv</a>.</p>\n`;
	}
	return page(`Task ${task.number}: similarity`, body);
}

export function pairPage(task, pair) {
	let body = `<p><a href="../index.html">Similarity report</a> › <a href="../task${task.number}.html">task ` +
		`${task.number}</a></p>\n<h1>${who(pair.a)} and ${who(pair.b)}: ${(100 * pair.similarity).toFixed(1)} %</h1>\n` +
		`<p>Task ${task.number}, rank ${pair.rank}. ${pair.fragments.length} shared fragments, each in its own colour and ` +
		`numbered in the margin; the longest (${longestCell(pair)}) has a red bar at its left.</p>\n`;
	body += `<div class="files">\n${fileColumn(pair.a, pair.fragments.map(f => f.a))}${fileColumn(pair.b, pair.fragments.map(f => f.b))}</div>\n`;
	return page(`Task ${task.number}: ${pair.a.name} and ${pair.b.name}`, body);
}

// One file's lines, numbered, each line of a shared fragment in that fragment's colour (the first
// fragment that covers it, in the order longest first).
function fileColumn(file, spans) {
	const lines = file.text.split("\n");
	if (lines.length > 1 && lines[lines.length - 1] === "") lines.pop();
	let html = `<div><h2>${who(file)}</h2>\n<div class="code">\n`;
	lines.forEach((text, i) => {
		const line = i + 1;
		const fragment = spans.findIndex(s => s.from <= line && line <= s.to);
		const start = fragment >= 0 && spans[fragment].from === line;
		const style = fragment >= 0 ? ` style="background: ${COLOURS[fragment % COLOURS.length]}"` : "";
		html += `<div class="line${fragment === 0 ? " longest" : ""}"${style}><span class="n">${line}</span>` +
			`<span class="f">${start ? fragment + 1 : ""}</span>${escape(text)}</div>\n`;
	});
	return html + "</div>\n</div>\n";
}
