// The similarity report's folder and files: index.html, taskN.html, pairs/*.html (pages.mjs) and
// similarity.csv, every pair of every task.

import fs from "node:fs";
import path from "node:path";
import { InputError } from "./class_files.mjs";
import { indexPage, pairPage, span, taskPage } from "./pages.mjs";

// The report folder holds this file, so that a new report replaces an earlier one and nothing else.
const MARK = ".lab-similarity";
const WRITTEN = /^(index\.html|similarity\.csv|task[1-7]\.html|pairs)$/;

// The pairs a task's page lists (and writes a side-by-side page for): the flagged ones, and at
// least this many from the top; the CSV has them all.
const LISTED = 30;

// openReportFolder(dir) -> its absolute path: a new or empty folder, or an earlier report's, whose
// files are removed.
export function openReportFolder(dir) {
	if (fs.existsSync(dir)) {
		if (!fs.statSync(dir).isDirectory()) throw new InputError(`similarity: --out ${dir} is a file, not a folder`);
		const names = fs.readdirSync(dir);
		if (names.length > 0 && !names.includes(MARK)) {
			throw new InputError(`similarity: --out ${dir} holds files but no earlier similarity report (${MARK}): ` +
				"give a new or an empty folder");
		}
		for (const name of names.filter(name => WRITTEN.test(name))) fs.rmSync(path.join(dir, name), { recursive: true });
	}
	fs.mkdirSync(path.join(dir, "pairs"), { recursive: true });
	fs.writeFileSync(path.join(dir, MARK), "a similarity report (./lab similarity): rewritten by the next one\n");
	return path.resolve(dir);
}

// writeReport(dir, { tasks, threshold, class, submissions, empty }): tasks are { number, file,
// submitted, pairs } with pairs ranked, most similar first (compare.mjs).
export function writeReport(dir, report) {
	const rows = [["task", "a", "b", "kind", "similarity", "flagged", "longest_fragment_lines_a",
		"longest_fragment_lines_b", "longest_fragment_kgrams", "fragments", "page"]];
	for (const task of report.tasks) {
		const listed = Math.max(LISTED, task.pairs.filter(pair => pair.similarity >= report.threshold).length);
		task.pairs.forEach((pair, i) => {
			pair.rank = i + 1;
			pair.flagged = pair.similarity >= report.threshold;
			pair.page = i < listed ? `pairs/task${task.number}-${pair.rank}.html` : null;
			if (pair.page) fs.writeFileSync(path.join(dir, pair.page), pairPage(task, pair));
			const longest = pair.fragments[0];
			rows.push([task.number, pair.a.name, pair.b.name, pair.b.kind === "reference" ? "reference" : "students",
				pair.similarity.toFixed(4), pair.flagged ? 1 : 0, longest ? span(longest.a) : "", longest ? span(longest.b) : "",
				longest ? longest.kgrams : 0, pair.fragments.length, pair.page || ""]);
		});
		task.listed = Math.min(listed, task.pairs.length);
		fs.writeFileSync(path.join(dir, `task${task.number}.html`), taskPage(task, report));
	}
	fs.writeFileSync(path.join(dir, "index.html"), indexPage(report));
	fs.writeFileSync(path.join(dir, "similarity.csv"), rows.map(row => row.map(csvField).join(",")).join("\n") + "\n");
}

// RFC 4180: a field with a comma, a quote or a line break is quoted, its quotes doubled.
function csvField(value) {
	const text = String(value);
	return /[",\r\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
}
