// ./lab view in a real browser (label viewer): Debian's Chromium, driven by playwright-core (npm,
// tests/viewer/browser/; no browser is downloaded). The student side is a scratch tree: the
// reference's seven files copied as a finished student's (tests/viewer/CMakeLists.txt), so the
// picture converges to the reference's and the test may edit them. The page must:
//   1. show the pictures converging: two successive updates differ, and the graders' relMSE
//      against the reference falls as the samples grow;
//   2. show a clicked floor pixel's path whose first vertex lies on the floor (y = 0, material
//      'white'), as a table and over the picture;
//   3. switch to the z-map, which is pale (the same code on both sides passes the z-test);
//   4. show a compile error of an edited student file with its file and line, then, once the file
//      compiles, the new picture (here task 4 returning emission only: a darker picture);
//   5. save the picture into the output folder, and log no uncaught error.
// It prints the timings of the "Measure" list (not checked: timed runs, not tests) and
// keeps screenshots in --out (README and handout pictures are copied from there).
import {spawn, execFileSync} from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import {fileURLToPath} from "node:url";

const playwright = path.join(path.dirname(fileURLToPath(import.meta.url)), "browser/node_modules/playwright-core/index.mjs");
if (!fs.existsSync(playwright)) {
	console.error("viewer browser test: playwright-core is missing: ./lab test installs it (npm ci in tests/viewer/browser)");
	process.exit(1);
}
const {chromium} = await import(playwright);

const args = {};
for (let i = 2; i < process.argv.length; i += 2) args[process.argv[i].replace(/^--/, "")] = process.argv[i + 1];
for (const name of ["root", "build", "viewer", "reference", "student", "student-dir", "reference-files", "out"]) {
	if (!args[name]) throw new Error(`missing --${name}`);
}
fs.mkdirSync(args.out, {recursive: true});

const failures = [];
let checks = 0;
const check = (ok, what) => {
	checks++;
	console.log(`${ok ? "ok" : "FAILED"}: ${what}`);
	if (!ok) failures.push(what);
};
const measured = {};
const sleep = (ms) => new Promise((done) => setTimeout(done, ms));

// The scratch tree starts as the reference's files (an earlier run may have been cut short).
const taskFiles = fs.readdirSync(args["reference-files"]).filter((f) => f.endsWith(".cpp"));
function restoreScratch() {
	for (const file of taskFiles) {
		const original = fs.readFileSync(path.join(args["reference-files"], file));
		const scratch = path.join(args["student-dir"], file);
		if (!fs.existsSync(scratch) || !original.equals(fs.readFileSync(scratch))) fs.writeFileSync(scratch, original);
	}
}
restoreScratch();
execFileSync(path.join(args.root, "lab"), ["build", "pathtracer_scratch"], {env: {...process.env, LAB_BUILD_DIR: args.build}, stdio: "inherit"});

// The viewer, on a free port.
const started = Date.now();
const viewer = spawn(args.viewer, [path.join(args.root, "scenes/cornell_box.json"), "--port", "0",
	"--reference-renderer", args.reference, "--student-renderer", args.student, "--student-dir", args["student-dir"],
	"--lab", path.join(args.root, "lab"), "--build-dir", args.build, "--rebuild-target", "pathtracer_scratch",
	"--out-dir", path.join(args.out, "snapshots"), "--max-spp", "4096"], {stdio: ["ignore", "pipe", "inherit"]});
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
measured.url_printed_ms = Date.now() - started;

const profile = fs.mkdtempSync(path.join(os.tmpdir(), "lab-viewer-chromium-"));
const browser = await chromium.launchPersistentContext(profile, {
	executablePath: "/usr/bin/chromium", headless: true, viewport: {width: 1280, height: 1000},
	args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
		"--disable-component-update", "--disable-sync", "--disable-dev-shm-usage"],
});
const uncaught = [];
try {
	const page = browser.pages()[0] || await browser.newPage();
	page.on("pageerror", (error) => uncaught.push(error.message));
	const opened = Date.now();
	await page.goto(address);
	const lab = (expression) => page.evaluate(expression);
	const waitFor = (predicate, argument, timeout = 60000) => page.waitForFunction(predicate, argument, {timeout, polling: 20});

	// 1. Live convergence.
	await waitFor(() => window.labViewer.updates.reference >= 1);
	measured.first_picture_reference_ms = Date.now() - opened;
	measured.first_picture_in_page_ms = Math.round(await lab(() => window.labViewer.firstPictureMs)); // since navigation began
	await waitFor(() => window.labViewer.updates.student >= 1);
	measured.first_picture_student_ms = Date.now() - opened; // after the student's renderer's build check
	measured.first_picture_student_since_start_ms = Date.now() - started;
	// The picture drawn and its number, read at once (a picture may be drawn between two reads).
	const picture = () => lab(() => ({
		update: window.labViewer.updates.student,
		samples: window.labViewer.images.student.samples,
		pixels: Array.from(document.getElementById("student-canvas").getContext("2d").getImageData(0, 0, 256, 256).data
			.filter((_, i) => i % 97 === 0)),
	}));
	const before = await picture();
	await waitFor((n) => window.labViewer.updates.student > n, before.update);
	const after = await picture();
	check(before.pixels.some((v, i) => v !== after.pixels[i]),
		`two successive updates of the student's picture differ (${before.samples} and ${after.samples} spp)`);
	await waitFor(() => window.labViewer.comparison && window.labViewer.comparison.student_samples >= 4);
	const early = await lab(() => window.labViewer.comparison);
	const windowStart = {time: Date.now(), updates: await lab(() => window.labViewer.updates.student)};
	await waitFor((s) => window.labViewer.comparison && window.labViewer.comparison.student_samples >= s &&
		window.labViewer.comparison.reference_samples >= s, 4 * early.student_samples);
	const late = await lab(() => window.labViewer.comparison);
	measured.updates_per_second = (await lab(() => window.labViewer.updates.student) - windowStart.updates) /
		((Date.now() - windowStart.time) / 1000);
	check(late.rel_mse < early.rel_mse,
		`the picture converges towards the reference: relMSE ${early.rel_mse.toFixed(4)} at ${early.student_samples} spp, ` +
		`${late.rel_mse.toFixed(4)} at ${late.student_samples} spp`);
	const stats = await page.textContent("#student-stats");
	measured.student_stats = stats;
	measured.reference_stats = await page.textContent("#reference-stats");

	// 2. A floor pixel's path: pixel (128, 240) of 256 x 256, drawn 384 pixels wide.
	const clicked = Date.now();
	await page.click("#student-canvas", {position: {x: 128.5 * 1.5, y: 240.5 * 1.5}});
	await waitFor(() => window.labViewer.path && window.labViewer.path.pixel[0] === 128 && window.labViewer.path.pixel[1] === 240);
	measured.click_to_path_ms = Date.now() - clicked;
	const first = await lab(() => window.labViewer.path.samples[0].ray.hit);
	check(first && Math.abs(first.position[1]) < 1e-3 && first.material === "white",
		`the path's first vertex lies on the floor: ${JSON.stringify(first && {position: first.position, material: first.material})}`);
	const firstRow = await page.textContent("#path-table tbody tr:first-child");
	check(firstRow.includes("white (object"), `the path table's first row names the floor's material: ${firstRow.slice(0, 120)}`);
	await page.screenshot({path: path.join(args.out, "viewer_side_by_side.png"), fullPage: false});
	await page.click("#save");
	await page.waitForFunction(() => document.getElementById("saved").textContent !== "", null, {timeout: 10000});
	const saved = path.join(args.out, "snapshots", "cornell_box_view_student.png");
	check(fs.existsSync(saved) && (await page.textContent("#saved")) === `wrote ${saved}`,
		`"save PNG" writes the student's picture into the output folder: ${await page.textContent("#saved")}`);

	// 3. The z-map.
	await page.selectOption("#layout", "z");
	await waitFor(() => window.labViewer.zUpdates >= 1);
	const pale = await lab(() => {
		const data = document.getElementById("z-canvas").getContext("2d").getImageData(0, 0, 256, 256).data;
		let light = 0;
		for (let i = 0; i < data.length; i += 4) if (data[i] > 120 && data[i + 1] > 120 && data[i + 2] > 120) light++;
		return light / (data.length / 4);
	});
	check(pale > 0.99, `the z-map of the same code on both sides is pale (noise only): ${(100 * pale).toFixed(2)} % of pixels`);
	const verdict = await page.textContent("#verdict");
	check(verdict.startsWith("PASS"), `the grader's verdict is PASS for the same code: ${verdict}`);
	await page.screenshot({path: path.join(args.out, "viewer_z_map.png"), fullPage: false});
	await page.selectOption("#layout", "side");

	// 4. Edits: a compile error, then a change the picture shows.
	const task4 = path.join(args["student-dir"], "task4_path.cpp");
	const original4 = fs.readFileSync(task4, "utf8");
	const lines = original4.split("\n");
	const broken = [...lines.slice(0, 84), "this is not C++;", ...lines.slice(84)].join("\n");
	fs.writeFileSync(task4, broken);
	await waitFor(() => window.labViewer.build && window.labViewer.build.state === "failed", null, 120000);
	const shown = await page.textContent("#diagnostics");
	check(/task4_path\.cpp:85:\d+: error/.test(shown), `the compile error is shown with its file and line: ${shown.slice(0, 160)}`);
	await page.screenshot({path: path.join(args.out, "viewer_build_error.png"), fullPage: true});

	// The share of pixels that receive any light: all of them in the Cornell box, only the light
	// itself when task 4 returns emission only.
	const lit = () => lab(() => {
		const mean = window.labViewer.images.student.mean;
		let count = 0;
		for (let i = 0; i < mean.length; i += 3) if (mean[i] + mean[i + 1] + mean[i + 2] > 0) count++;
		return count / (mean.length / 3);
	});
	const litBefore = await lit();
	// After an edit: a finished build, then a picture of the rebuilt renderer.
	const newPicture = (builds) => waitFor((b) => window.labViewer.builds > b && window.labViewer.build.state === "ok" &&
		window.labViewer.updates.student > window.labViewer.updatesAtBuild, builds, 120000);
	const emissionOnly = original4.replace("Spectrum radiance = material.emitted(frame.to_local(out_dir));",
		"Spectrum radiance = material.emitted(frame.to_local(out_dir));\n\treturn radiance; // the browser test's edit");
	check(emissionOnly !== original4, "the test's edit applies to task 4's file");
	let builds = await lab(() => window.labViewer.builds);
	const edited4 = Date.now();
	fs.writeFileSync(task4, emissionOnly);
	await newPicture(builds);
	measured.edit_to_picture_task4_ms = Date.now() - edited4;
	measured.rebuild_task4_s = await lab(() => window.labViewer.build.seconds);
	const litAfter = await lit();
	check(litBefore > 0.8 && litAfter < 0.2, `the edited picture is the new one (emission only): ${(100 * litAfter).toFixed(1)} % of ` +
		`the pixels receive light, ${(100 * litBefore).toFixed(1)} % before`);

	const task1 = path.join(args["student-dir"], "task1_camera.cpp");
	builds = await lab(() => window.labViewer.builds);
	const edited1 = Date.now();
	fs.appendFileSync(task1, "// edited by the browser test\n");
	await newPicture(builds);
	measured.edit_to_picture_task1_ms = Date.now() - edited1;
	measured.rebuild_task1_s = await lab(() => window.labViewer.build.seconds);

	check(uncaught.length === 0, `the page threw no uncaught error${uncaught.length ? ": " + uncaught.join("; ") : ""}`);
} finally {
	await browser.close();
	fs.rmSync(profile, {recursive: true, force: true});
	restoreScratch();
	viewer.kill("SIGTERM");
	await new Promise((done) => viewer.exitCode !== null ? done() : viewer.on("exit", done));
}
// Leave the scratch renderer as the reference's again, for the next run.
execFileSync(path.join(args.root, "lab"), ["build", "pathtracer_scratch"], {env: {...process.env, LAB_BUILD_DIR: args.build}, stdio: "ignore"});

console.log(`measured: ${JSON.stringify(measured)}`);
console.log(`load: ${fs.readFileSync("/proc/loadavg", "utf8").trim()}`);
console.log(`${checks - failures.length} passed, ${failures.length} failed`);
process.exit(failures.length ? 1 : 0);
