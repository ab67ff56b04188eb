// ./lab similarity SUBMISSIONS --out DIR [--threshold T]
//
// Compares, task by task, every pair of submissions and every submission with the reference's file
// (reference/), ignoring the code of the stub every student starts from (student/), and writes
// DIR/index.html (a summary), DIR/taskN.html (the pairs ranked by similarity), DIR/pairs/*.html
// (two files side by side, the code they share marked) and DIR/similarity.csv (every pair).
// Pairs at or above the threshold are flagged (README.md in this folder says how it was chosen).

import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";
import { InputError, readClass, taskFileNames } from "./class_files.mjs";
import { openReportFolder, writeReport } from "./report.mjs";

// The similarity at which a pair is flagged: the midpoint of the gap measured on the test's
// synthetic class between the most similar honest pair and the least similar planted copy
// (README.md in this folder).
const DEFAULT_THRESHOLD = 0.7;

const usage = "usage: ./lab similarity SUBMISSIONS --out DIR [--threshold T]   (T in (0, 1], default " +
	DEFAULT_THRESHOLD + ")";

function parseArguments(args) {
	const options = { submissions: null, out: null, threshold: DEFAULT_THRESHOLD };
	for (let i = 0; i < args.length; i++) {
		const arg = args[i];
		if (arg === "--out" || arg === "--threshold") {
			if (i + 1 >= args.length) throw new InputError(`similarity: ${arg} needs a value\n${usage}`);
			const value = args[++i];
			if (arg === "--out") options.out = value;
			else options.threshold = Number(value);
		} else if (arg === "-h" || arg === "--help") {
			throw new InputError(usage, 0);
		} else if (arg.startsWith("-")) {
			throw new InputError(`similarity: unknown option ${arg}\n${usage}`);
		} else if (options.submissions === null) {
			options.submissions = arg;
		} else {
			throw new InputError(`similarity: one folder of submissions, not two (${options.submissions}, ${arg})\n${usage}`);
		}
	}
	if (options.submissions === null || options.out === null) throw new InputError(usage);
	if (!(options.threshold > 0 && options.threshold <= 1)) {
		throw new InputError(`similarity: --threshold takes a number in (0, 1], e.g. 0.7\n${usage}`);
	}
	return options;
}

async function main() {
	const options = parseArguments(process.argv.slice(2));
	const lab = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "../..");
	const stubs = path.join(lab, "student"), reference = path.join(lab, "reference");
	const names = taskFileNames(stubs);
	const { submissions, empty } = readClass(options.submissions, names);
	// Loaded only now, so that bad input is reported as such where Dolos is missing too.
	const { compareTask } = await import("./compare.mjs").catch(error => {
		throw new InputError(`similarity: Dolos is not installed (${error.message.split("\n")[0]}): run ./lab setup similarity`, 1);
	});
	const out = openReportFolder(options.out);

	const tasks = [];
	for (const name of names) {
		const files = submissions.filter(s => s.files[name]).map(s => ({ name: s.id, kind: "submission", ...s.files[name] }));
		const submitted = files.length;
		files.push({ name: "reference", kind: "reference", path: path.join(reference, name), text: readText(reference, name) });
		const stub = { path: path.join(stubs, name), text: readText(stubs, name) };
		const pairs = await compareTask(files, stub);
		pairs.sort((x, y) => y.similarity - x.similarity || longest(y) - longest(x) ||
			x.a.name.localeCompare(y.a.name) || x.b.name.localeCompare(y.b.name));
		tasks.push({ number: Number(name[4]), file: name, submitted, pairs });
	}
	writeReport(out, { tasks, threshold: options.threshold, class: options.submissions, submissions, empty });
	const flagged = tasks.reduce((n, task) => n + task.pairs.filter(p => p.similarity >= options.threshold).length, 0);
	console.log(`similarity: ${submissions.length} submissions with task files, ${flagged} pairs at or above ${options.threshold}: ` +
		path.join(out, "index.html"));
	for (const id of empty) console.error(`similarity: ${path.join(options.submissions, id)} holds no task file (listed in the report)`);
}

function readText(folder, name) {
	return fs.readFileSync(path.join(folder, name), "utf8");
}

function longest(pair) {
	return pair.fragments.length > 0 ? pair.fragments[0].kgrams : 0;
}

main().catch(error => {
	if (!(error instanceof InputError)) throw error;
	(error.status === 0 ? console.log : console.error)(error.message);
	process.exit(error.status);
});
