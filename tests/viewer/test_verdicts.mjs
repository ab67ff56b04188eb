// ./lab view judges like with like (label viewer; issue 40): the page's verdict compares the
// student's render with a reference of the same estimator, so code that passes its graders is never
// shown FAIL. In Debian's Chromium, driven by playwright-core (tests/viewer/browser/), on the Cornell
// box, two students:
//   1. --correct: tasks 1, 2 and 4 done (the reference's, as are 3, 5 and 7), task 6 still the
//      stub, whose sample_incoming samples the BSDF only. Its picture is heavy-tailed at a few hundred samples
//      (a pixel of the floor meets the small light rarely); beside next-event estimation it looked
//      "too dark" (z = -43 at 384 spp). Every verdict the page shows while both sides have 64 to 1024
//      samples must be PASS, and it must say that the reference samples the BSDF only, as the student.
//   2. --mistaken: the same with task 4's new rays started exactly at the hit point, without
//      spawn_ray (self-intersection: too dark): the page must show FAIL somewhere in that range, so
//      the first check can fail. (A subtler mistake, a roulette that does not divide by q, darkens
//      the picture by a few percent: no per-pixel test of 1024 samples sees that, the graders'
//      furnaces do.)
// Screenshots of the last verdict of each go to --out.
import {spawn} from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import {fileURLToPath} from "node:url";

const playwright = path.join(path.dirname(fileURLToPath(import.meta.url)), "browser/node_modules/playwright-core/index.mjs");
if (!fs.existsSync(playwright)) {
	console.error("viewer verdicts test: playwright-core is missing: ./lab test installs it (npm ci in tests/viewer/browser)");
	process.exit(1);
}
const {chromium} = await import(playwright);

const args = {};
for (let i = 2; i < process.argv.length; i += 2) args[process.argv[i].replace(/^--/, "")] = process.argv[i + 1];
for (const name of ["root", "viewer", "reference", "correct", "mistaken", "out"]) {
	if (!args[name]) throw new Error(`missing --${name}`);
}
fs.mkdirSync(args.out, {recursive: true});

const FIRST = 64, LAST = 1024;
const failures = [];
const check = (ok, what) => {
	console.log(`${ok ? "ok" : "FAILED"}: ${what}`);
	if (!ok) failures.push(what);
};

// Runs the viewer with `student` as the student's renderer until both sides have LAST samples (or,
// with `untilFail`, until a FAIL in range), and returns every verdict the page showed while both
// sides had FIRST to LAST samples.
async function verdicts(student, name, untilFail = false) {
	const viewer = spawn(args.viewer, [path.join(args.root, "scenes/cornell_box.json"), "--port", "0",
		"--reference-renderer", args.reference, "--student-renderer", student, "--max-spp", String(LAST),
		"--out-dir", path.join(args.out, "snapshots")], {stdio: ["ignore", "pipe", "inherit"]});
	let printed = "";
	const address = await new Promise((resolve, reject) => {
		viewer.stdout.on("data", (data) => {
			printed += data;
			const found = printed.match(/http:\/\/127\.0\.0\.1:\d+\/\?token=[0-9a-f]{32}/);
			if (found) resolve(found[0]);
		});
		viewer.on("exit", (status) => reject(new Error(`lab_viewer ended (status ${status}) before printing its URL: ${printed}`)));
		setTimeout(() => reject(new Error(`lab_viewer printed no URL within 10 s: ${printed}`)), 10000);
	});
	const profile = fs.mkdtempSync(path.join(os.tmpdir(), "lab-viewer-verdicts-"));
	const browser = await chromium.launchPersistentContext(profile, {
		executablePath: "/usr/bin/chromium", headless: true, viewport: {width: 1280, height: 1000},
		args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
			"--disable-component-update", "--disable-sync", "--disable-dev-shm-usage"],
	});
	try {
		const page = browser.pages()[0] || await browser.newPage();
		const uncaught = [];
		page.on("pageerror", (error) => uncaught.push(error.message));
		await page.goto(address);
		// Every comparison the page receives, as it shows it (the verdict's text with it).
		await page.evaluate(() => {
			window.seenVerdicts = [];
			let last = null;
			setInterval(() => {
				const c = window.labViewer.comparison;
				if (!c || c === last) return;
				last = c;
				window.seenVerdicts.push({student: c.student_samples, reference: c.reference_samples, pass: c.pass,
					text: document.getElementById("verdict").textContent});
			}, 10);
		});
		await page.waitForFunction(([first, last, untilFail]) => {
			const c = window.labViewer.comparison;
			if (untilFail && window.seenVerdicts.some((v) => !v.pass && Math.min(v.student, v.reference) >= first)) return true;
			return c && c.student_samples >= last && c.reference_samples >= last;
		}, [FIRST, LAST, untilFail], {timeout: 1500000, polling: 100});
		await page.waitForTimeout(200);
		await page.screenshot({path: path.join(args.out, `verdict_${name}.png`), fullPage: false});
		const seen = await page.evaluate(() => window.seenVerdicts);
		check(uncaught.length === 0, `${name}: no uncaught error in the page${uncaught.length ? ": " + uncaught.join("; ") : ""}`);
		return seen.filter((v) => Math.min(v.student, v.reference) >= FIRST && Math.max(v.student, v.reference) <= LAST);
	} finally {
		await browser.close();
		fs.rmSync(profile, {recursive: true, force: true});
		viewer.kill();
	}
}

try {
	const correct = await verdicts(args.correct, "task6_stub");
	const failed = correct.filter((v) => !v.pass);
	console.log(`tasks 1, 2, 4 done, task 6 the stub: ${correct.length} verdicts from ${FIRST} to ${LAST} spp, ` +
		`${failed.length} FAIL`);
	check(correct.length >= 5, `the page showed verdicts from ${FIRST} to ${LAST} spp (${correct.length})`);
	check(failed.length === 0, `correct code is never shown FAIL from ${FIRST} to ${LAST} spp` +
		(failed.length ? `; first: ${failed[0].text}` : ""));
	check(correct.length > 0 && correct.every((v) => v.text.includes("sampling the BSDF only")),
		`the verdict says the reference samples the BSDF only, as the student's code does: ${correct.length ? correct[correct.length - 1].text : ""}`);

	const mistaken = await verdicts(args.mistaken, "no_offset", true);
	const caught = mistaken.filter((v) => !v.pass);
	console.log(`the same with new rays started on the surface: ${mistaken.length} verdicts, ${caught.length} FAIL`);
	check(caught.length > 0, `a task-4 mistake is shown FAIL between ${FIRST} and ${LAST} spp` +
		(caught.length ? `: ${caught[caught.length - 1].text}` : ""));
} catch (error) {
	check(false, `the test ran to its end: ${error.stack || error}`);
}
console.log(failures.length ? `${failures.length} checks failed` : "all checks passed");
process.exit(failures.length ? 1 : 0);
