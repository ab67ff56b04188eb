// ./lab view in Firefox (label viewer): Debian's Firefox ESR, driven over WebDriver BiDi, the
// protocol Firefox speaks itself (a WebSocket, with ws from npm, tests/viewer/browser/). The full
// walk through the page is test_browser.mjs, in Chromium; this one proves that the page works in
// Firefox too, with the reference's renderer on both sides:
//   1. two successive pictures of the student's side differ (the stream and the canvas drawing);
//   2. the z-map is drawn and pale (the same code on both sides);
//   3. a click on a floor pixel shows its path, the floor's material in the table's first row;
//   4. the page logs no uncaught error.
import {spawn} from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import {fileURLToPath} from "node:url";

const wsModule = path.join(path.dirname(fileURLToPath(import.meta.url)), "browser/node_modules/ws/wrapper.mjs");
if (!fs.existsSync(wsModule)) {
	console.error("viewer Firefox test: ws is missing: ./lab test installs it (npm ci in tests/viewer/browser)");
	process.exit(1);
}
const {default: WebSocket} = await import(wsModule);

const args = {};
for (let i = 2; i < process.argv.length; i += 2) args[process.argv[i].replace(/^--/, "")] = process.argv[i + 1];
for (const name of ["root", "viewer", "reference", "firefox"]) {
	if (!args[name]) throw new Error(`missing --${name}`);
}

const failures = [];
const check = (ok, what) => {
	console.log(`${ok ? "ok" : "FAILED"}: ${what}`);
	if (!ok) failures.push(what);
};
const sleep = (ms) => new Promise((done) => setTimeout(done, ms));

// A process's first line of output that matches `pattern` (within `seconds`).
function awaitOutput(child, stream, pattern, seconds, what) {
	let printed = "";
	return new Promise((resolve, reject) => {
		child[stream].on("data", (data) => {
			printed += data;
			const found = printed.match(pattern);
			if (found) resolve(found);
		});
		child.on("exit", (status) => reject(new Error(`${what} ended (status ${status}): ${printed.slice(-2000)}`)));
		setTimeout(() => reject(new Error(`${what} printed no ${pattern} within ${seconds} s: ${printed.slice(-2000)}`)),
			seconds * 1000);
	});
}

// A WebDriver BiDi session: command(method, params) answers with the result, or throws the error.
class Bidi {
	constructor(socket) {
		this.socket = socket;
		this.next = 1;
		this.waiting = new Map();
		this.errors = [];
		socket.on("message", (text) => {
			const message = JSON.parse(text);
			if (message.id && this.waiting.has(message.id)) {
				const {resolve, reject} = this.waiting.get(message.id);
				this.waiting.delete(message.id);
				if (message.type === "error") reject(new Error(`${message.error}: ${message.message}`));
				else resolve(message.result);
			} else if (message.method === "log.entryAdded" && message.params.level === "error") {
				this.errors.push(message.params.text);
			}
		});
	}
	command(method, params = {}) {
		const id = this.next++;
		this.socket.send(JSON.stringify({id, method, params}));
		return new Promise((resolve, reject) => this.waiting.set(id, {resolve, reject}));
	}
}

const viewer = spawn(args.viewer, [path.join(args.root, "scenes/cornell_box.json"), "--port", "0",
	"--reference-renderer", args.reference, "--student-renderer", args.reference,
	"--out-dir", fs.mkdtempSync(path.join(os.tmpdir(), "lab-viewer-firefox-out-")), "--max-spp", "4096"],
{stdio: ["ignore", "pipe", "inherit"]});
const profile = fs.mkdtempSync(path.join(os.tmpdir(), "lab-viewer-firefox-"));
let firefox;
try {
	const [address] = await awaitOutput(viewer, "stdout", /http:\/\/127\.0\.0\.1:\d+\/\?token=[0-9a-f]{32}/, 10, "lab_viewer");
	firefox = spawn(args.firefox, ["--headless", "--no-remote", "--profile", profile, "--remote-debugging-port", "0",
		"--width", "1280", "--height", "1000"], {stdio: ["ignore", "ignore", "pipe"], env: {...process.env, MOZ_CRASHREPORTER_DISABLE: "1"}});
	const [, endpoint] = await awaitOutput(firefox, "stderr", /WebDriver BiDi listening on (ws:\/\/[0-9.:]+)/, 60, "Firefox");
	const socket = new WebSocket(`${endpoint}/session`);
	await new Promise((resolve, reject) => socket.once("open", resolve).once("error", reject));
	const bidi = new Bidi(socket);
	const session = await bidi.command("session.new", {capabilities: {}});
	console.log(`browser: ${session.capabilities.browserName} ${session.capabilities.browserVersion}`);
	await bidi.command("session.subscribe", {events: ["log.entryAdded"]});
	const {contexts} = await bidi.command("browsingContext.getTree");
	const context = contexts[0].context;
	await bidi.command("browsingContext.navigate", {context, url: address, wait: "complete"});

	// The value of a page expression, through JSON (BiDi's own serialization is richer than needed).
	const evaluate = async (expression) => {
		const answer = await bidi.command("script.evaluate", {
			expression: `JSON.stringify(${expression})`, target: {context}, awaitPromise: true});
		if (answer.type !== "success") throw new Error(`${expression}: ${JSON.stringify(answer.exceptionDetails)}`);
		return answer.result.value === undefined ? undefined : JSON.parse(answer.result.value);
	};
	const waitFor = async (expression, what, seconds = 60) => {
		for (const until = Date.now() + seconds * 1000; Date.now() < until; await sleep(50)) {
			if (await evaluate(expression)) return;
		}
		throw new Error(`waited ${seconds} s for ${what} (${expression})`);
	};

	// 1. Successive pictures, read with the number of the update they belong to.
	const picture = `(() => ({update: window.labViewer.updates.student,
		pixels: Array.from(document.getElementById("student-canvas").getContext("2d").getImageData(0, 0, 256, 256).data
			.filter((_, i) => i % 97 === 0))}))()`;
	await waitFor("window.labViewer.updates.student >= 1", "the student's first picture");
	const before = await evaluate(picture);
	await waitFor(`window.labViewer.updates.student > ${before.update}`, "the student's next picture");
	const after = await evaluate(picture);
	check(before.pixels.some((v, i) => v !== after.pixels[i]), "two successive updates of the student's picture differ");

	// 2. The z-map.
	await evaluate(`(() => { const layout = document.getElementById("layout"); layout.value = "z";
		layout.dispatchEvent(new Event("change")); return true; })()`);
	await waitFor("window.labViewer.zUpdates >= 1", "the z-map");
	const pale = await evaluate(`(() => {
		const data = document.getElementById("z-canvas").getContext("2d").getImageData(0, 0, 256, 256).data;
		let light = 0;
		for (let i = 0; i < data.length; i += 4) if (data[i] > 120 && data[i + 1] > 120 && data[i + 2] > 120) light++;
		return light / (data.length / 4); })()`);
	check(pale > 0.99, `the z-map of the same code on both sides is pale: ${(100 * pale).toFixed(2)} % of pixels`);
	await evaluate(`(() => { const layout = document.getElementById("layout"); layout.value = "side";
		layout.dispatchEvent(new Event("change")); return true; })()`);

	// 3. A real click (BiDi input actions) on floor pixel (128, 240) of the 256 x 256 picture.
	const box = await evaluate(`(() => { const r = document.getElementById("student-canvas").getBoundingClientRect();
		return {x: r.left, y: r.top, width: r.width, height: r.height}; })()`);
	const at = {x: Math.round(box.x + (128.5 / 256) * box.width), y: Math.round(box.y + (240.5 / 256) * box.height)};
	await bidi.command("input.performActions", {context, actions: [{type: "pointer", id: "mouse", actions: [
		{type: "pointerMove", x: at.x, y: at.y}, {type: "pointerDown", button: 0}, {type: "pointerUp", button: 0}]}]});
	await waitFor("window.labViewer.path && window.labViewer.path.pixel[1] >= 238 && window.labViewer.path.pixel[1] <= 242",
		"the clicked pixel's path");
	const row = await evaluate(`document.querySelector("#path-table tbody tr:first-child").textContent`);
	check(row.includes("white (object"), `the path table's first row names the floor's material: ${row.slice(0, 100)}`);

	// 4. No uncaught error.
	check(bidi.errors.length === 0, `the page logged no error${bidi.errors.length ? ": " + bidi.errors.join("; ") : ""}`);
	await bidi.command("session.end").catch(() => {});
	socket.close();
} catch (error) {
	check(false, error.message);
} finally {
	if (firefox) firefox.kill("SIGKILL");
	viewer.kill("SIGTERM");
	fs.rmSync(profile, {recursive: true, force: true});
}
console.log(`${failures.length ? "FAILED" : "passed"}: ${failures.length} of the checks failed`);
process.exit(failures.length ? 1 : 0);
