// One task's files compared pairwise by Dolos (@dodona/dolos-lib): each file is parsed by
// tree-sitter's C++ grammar into the sequence of its syntax tree's node types (names, literals,
// operators and comments are not in it, so renaming changes nothing), its k-grams are hashed and
// winnowed into fingerprints, and two files are as similar as the share of their fingerprints they
// have in common. Fingerprints of the stub (the code every student starts from) count for no pair.

import { Dolos } from "@dodona/dolos-lib";
import { File } from "@dodona/dolos-core";

// compareTask(files, stub): files are { name, path, text }, stub is { path, text }.
// Returns every pair of files, each { a, b, similarity, fragments }: a and b the two files (in the
// order of `files`), similarity in [0, 1], and the code they share as fragments, each
// { a: {from, to}, b: {from, to}, kgrams } with 1-based line numbers, longest first.
export async function compareTask(files, stub) {
	// Dolos needs two files besides the stub; one file alone is similar to nothing.
	if (files.length < 2) return [];
	const dolosFiles = files.map(file => new File(file.path, file.text));
	const order = new Map(dolosFiles.map((dolosFile, i) => [dolosFile, i]));
	const dolos = new Dolos({ language: "cpp" });
	const report = await dolos.analyze(dolosFiles, "task", new File(stub.path, stub.text));
	return report.allPairs().map(pair => {
		let a = order.get(pair.leftFile.file), b = order.get(pair.rightFile.file);
		const swapped = a > b;
		if (swapped) [a, b] = [b, a];
		const fragments = pair.buildFragments().map(fragment => {
			const left = lines(fragment.leftSelection), right = lines(fragment.rightSelection);
			return { a: swapped ? right : left, b: swapped ? left : right, kgrams: fragment.pairs.length };
		});
		fragments.sort((x, y) => y.kgrams - x.kgrams || x.a.from - y.a.from);
		return { a: files[a], b: files[b], similarity: pair.similarity, fragments };
	});
}

// A Dolos region's rows (0-based, tree-sitter's) as 1-based line numbers.
function lines(region) {
	return { from: region.startRow + 1, to: region.endRow + 1 };
}
