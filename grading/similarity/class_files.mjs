// A class as ./lab grade-class takes it: one sub-folder per student (its name is the student's id)
// holding any of the seven task files, named as in student/. Other files are ignored.

import fs from "node:fs";
import path from "node:path";

// An error in the input, reported as it is (no stack) with the exit status given.
export class InputError extends Error {
	constructor(message, status = 2) {
		super(message);
		this.status = status;
	}
}

// The task files' names, from the folder of the stubs: task1_camera.cpp ... task7_env_light.cpp.
export function taskFileNames(stubs) {
	const names = fs.readdirSync(stubs).filter(name => /^task[1-7]_\w+\.cpp$/.test(name)).sort();
	if (names.length !== 7) throw new InputError(`similarity: ${stubs} should hold the seven task files, has ${names.length}`);
	return names;
}

// readClass(folder, names) -> { submissions: [{ id, files: {name: {path, text}} }], empty: [ids] }:
// every sub-folder's task files, read; `empty` the sub-folders that hold none. Throws an
// InputError naming the folder, or every file that cannot be read and why.
export function readClass(folder, names) {
	let entries;
	try {
		entries = fs.readdirSync(folder, { withFileTypes: true });
	} catch (error) {
		throw new InputError(`similarity: ${folder}: ${why(error, "folder")} (expected a folder of submissions, one sub-folder per student)`);
	}
	const ids = entries.filter(entry => entry.isDirectory()).map(entry => entry.name).sort();
	if (ids.length === 0) throw new InputError(`similarity: ${folder} has no submission folders (expected one sub-folder per student)`);
	const submissions = [], empty = [], unreadable = [];
	for (const id of ids) {
		const files = {};
		const present = names.map(name => path.join(folder, id, name)).filter(isPresent);
		for (const file of present) {
			try {
				files[path.basename(file)] = { path: file, text: fs.readFileSync(file, "utf8") };
			} catch (error) {
				unreadable.push(`similarity: cannot read ${file}: ${why(error, "file")}`);
			}
		}
		if (present.length === 0) empty.push(id);
		else submissions.push({ id, files });
	}
	if (unreadable.length > 0) throw new InputError(unreadable.join("\n"), 1);
	if (submissions.length === 0) {
		throw new InputError(`similarity: no submission in ${folder} holds a task file (expected any of ${names.join(", ")} in its sub-folders)`);
	}
	return { submissions, empty };
}

// A file is present if its name is there, even as a link to nothing (which then cannot be read).
function isPresent(file) {
	try {
		fs.lstatSync(file);
		return true;
	} catch {
		return false;
	}
}

function why(error, expected) {
	switch (error.code) {
	case "ENOENT": return expected === "folder" ? "no such folder" : "it is a link to a file that does not exist";
	case "ENOTDIR": return "not a folder";
	case "EISDIR": return "it is a folder, not a file";
	case "EACCES": return "permission denied";
	default: return error.message;
	}
}
