// The live lab's page (./lab view): plain JavaScript, no library, no build step.
// It listens to the viewer's events (server-sent events, /api/events), fetches each new picture
// as float32 RGB (/api/image), tone-maps it here (so exposure changes cost no request), and asks
// for a clicked pixel's paths (/api/path). Every request carries the page's token.
"use strict";

const token = new URLSearchParams(location.search).get("token") || "";
const $ = (id) => document.getElementById(id);

// What the page knows; window.labViewer lets a browser test read it.
const lab = {
	state: null,
	images: {},          // side -> {width, height, samples, mean: Float32Array, nonFinite: Uint8Array|null, rate: Uint8Array|null}
	updates: {student: 0, reference: 0}, // pictures drawn per side
	firstPictureMs: null, // since the page loaded
	comparison: null,
	zUpdates: 0,
	path: null,           // the last path document
	pathSide: null,
	build: null,
	builds: 0,           // builds finished, and the student's pictures drawn before the last one ended
	updatesAtBuild: 0,
	grade: {task: 0, lines: [], status: null},
};
window.labViewer = lab;

function url(path, params = {}) {
	const query = new URLSearchParams({...params, token});
	return `${path}?${query}`;
}

async function post(path, params = {}) {
	const response = await fetch(url(path, params), {method: "POST"});
	const body = await response.json();
	if (!response.ok) throw new Error(body.error || response.statusText);
	return body;
}

// ---- Pictures -----------------------------------------------------------------------------------

function toneMap(value, exposureScale, tonemap) {
	let v = value * exposureScale;
	if (tonemap === "reinhard") v = v / (1 + v);
	v = Math.min(Math.max(v, 0), 1);
	// sRGB encoding, as write_png does (IEC 61966-2-1).
	v = v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055;
	return Math.round(v * 255);
}

function drawFloat(canvas, image, columns = null) {
	if (!image) return;
	const {width, height, mean, nonFinite} = image;
	canvas.width = width;
	canvas.height = height;
	const context = canvas.getContext("2d");
	const pixels = context.createImageData(width, height);
	const scale = Math.pow(2, Number($("exposure").value));
	const tonemap = $("tonemap").value;
	const showNaN = $("nan-map").checked && nonFinite;
	for (let i = 0; i < width * height; i++) {
		const x = i % width;
		if (columns && (x < columns[0] || x >= columns[1])) continue;
		for (let c = 0; c < 3; c++) pixels.data[4 * i + c] = toneMap(mean[3 * i + c], scale, tonemap);
		pixels.data[4 * i + 3] = 255;
		if (showNaN && nonFinite[i]) pixels.data.set([255, 0, 255, 255], 4 * i);
	}
	return {context, pixels};
}

// The samples map (the viewer's samples layer, sRGB bytes): each pixel's samples so far.
function drawRate(canvas, image) {
	const {width, height, rate} = image;
	canvas.width = width;
	canvas.height = height;
	const context = canvas.getContext("2d");
	const pixels = context.createImageData(width, height);
	for (let i = 0; i < width * height; i++) pixels.data.set([rate[3 * i], rate[3 * i + 1], rate[3 * i + 2], 255], 4 * i);
	return {context, pixels};
}

function drawSide(side) {
	const image = lab.images[side];
	const drawn = image && image.rate && $("rate-map").checked ? drawRate($(`${side}-canvas`), image) : drawFloat($(`${side}-canvas`), image);
	if (drawn) drawn.context.putImageData(drawn.pixels, 0, 0);
	drawWipe();
	drawPathOverlay();
}

function drawWipe() {
	const student = lab.images.student, reference = lab.images.reference;
	if (!student || !reference || student.width !== reference.width) return;
	const split = Math.round(Number($("wipe").value) * student.width);
	const left = drawFloat($("wipe-canvas"), student, [0, split]);
	const right = drawFloat($("wipe-canvas"), reference, [split, reference.width]);
	for (let i = 0; i < student.width * student.height; i++) {
		if (i % student.width < split) right.pixels.data.set(left.pixels.data.subarray(4 * i, 4 * i + 4), 4 * i);
	}
	right.context.putImageData(right.pixels, 0, 0);
	const context = right.context;
	context.strokeStyle = "#ff0";
	context.beginPath();
	context.moveTo(split + 0.5, 0);
	context.lineTo(split + 0.5, student.height);
	context.stroke();
}

const fetching = {};
async function fetchImage(side) {
	if (fetching[side]) { fetching[side] = "again"; return; }
	fetching[side] = true;
	try {
		const response = await fetch(url("api/image", {side, layer: "mean"}));
		if (response.ok) {
			const width = Number(response.headers.get("X-Width")), height = Number(response.headers.get("X-Height"));
			const samples = Number(response.headers.get("X-Samples"));
			const generation = Number(response.headers.get("X-Generation"));
			const mean = new Float32Array(await response.arrayBuffer());
			const shown = lab.images[side];
			// (frames come faster than pictures are fetched at first: the latest may be the one shown)
			const extra = $("nan-map").checked || $("rate-map").checked;
			if (shown && shown.samples === samples && shown.generation === generation && !extra) return;
			let nonFinite = null, rate = null;
			if ($("nan-map").checked) {
				const nan = await fetch(url("api/image", {side, layer: "non_finite"}));
				if (nan.ok) nonFinite = new Uint8Array(await nan.arrayBuffer());
			}
			if ($("rate-map").checked) {
				const samplesMap = await fetch(url("api/image", {side, layer: "samples"}));
				if (samplesMap.ok) rate = new Uint8Array(await samplesMap.arrayBuffer());
			}
			lab.images[side] = {width, height, samples, generation, mean, nonFinite, rate};
			lab.updates[side]++;
			if (lab.firstPictureMs === null) lab.firstPictureMs = performance.now();
			drawSide(side);
		}
	} finally {
		const again = fetching[side] === "again";
		fetching[side] = false;
		if (again) fetchImage(side);
	}
}

let fetchingZ = false;
async function fetchZ() {
	if (fetchingZ || $("layout").value !== "z") return;
	fetchingZ = true;
	try {
		const response = await fetch(url("api/image", {side: "student", layer: "z"}));
		if (!response.ok) return;
		const width = Number(response.headers.get("X-Width")), height = Number(response.headers.get("X-Height"));
		const rgb = new Uint8Array(await response.arrayBuffer());
		const canvas = $("z-canvas");
		canvas.width = width;
		canvas.height = height;
		const context = canvas.getContext("2d");
		const pixels = context.createImageData(width, height);
		for (let i = 0; i < width * height; i++) pixels.data.set([rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], 255], 4 * i);
		context.putImageData(pixels, 0, 0);
		lab.zUpdates++;
	} finally {
		fetchingZ = false;
	}
}

// ---- Numbers and text ---------------------------------------------------------------------------

const number = (v) => (v === null || v === undefined ? "?" : Math.abs(v) >= 1e4 || (v !== 0 && Math.abs(v) < 1e-3) ? v.toExponential(2) : Number(v.toPrecision(4)).toString());
const vector = (v) => (v ? `(${v.map(number).join(", ")})` : "");
const luminance = (v) => (v ? 0.2126 * (v[0] ?? 0) + 0.7152 * (v[1] ?? 0) + 0.0722 * (v[2] ?? 0) : 0);
function withUnit(v) {
	const units = ["", " k", " M", " G"];
	let i = 0;
	for (; v >= 1000 && i < 3; i++) v /= 1000;
	return `${v.toFixed(1)}${units[i]}`;
}

function showFrame(event) {
	const side = event.side;
	$(`${side}-stats`).textContent =
		`${event.samples} spp, ${event.seconds.toFixed(1)} s, ${withUnit(event.samples_per_second)} samples/s` +
		(event.non_finite ? `, ${event.non_finite} NaN/inf samples` : "");
	$(`${side}-state`).textContent = "rendering";
}

function showComparison(c) {
	lab.comparison = c;
	const verdict = $("verdict");
	if (!c) { verdict.textContent = "waiting for both pictures"; return; }
	verdict.innerHTML = "";
	const status = document.createElement("span");
	status.className = c.pass ? "pass" : "fail";
	status.textContent = c.pass ? "PASS" : "FAIL";
	verdict.append(status, ` at ${c.student_samples} spp (reference ${c.reference_samples} spp of ` +
		`${c.reference_estimator}): ${c.message}`);
	fetchZ();
}

function showState(state) {
	lab.state = state;
	const fill = (select, names, chosen) => {
		if (select.options.length !== names.length) {
			select.innerHTML = "";
			for (const name of names) select.add(new Option(name, name));
		}
		select.value = chosen;
	};
	fill($("scene"), state.scenes, state.scene);
	fill($("view"), state.views, state.view);
	$("pause").textContent = state.paused ? "resume" : "pause";
	if (document.activeElement !== $("seed")) $("seed").value = state.seed;
	if (document.activeElement !== $("adaptive")) $("adaptive").value = state.adaptive;
	$("pictures").classList.toggle("alone", !state.compare);
	for (const [side, info] of Object.entries(state.sides)) {
		$(`${side}-state`).textContent = info.state;
		$(`${side}-message`).textContent = info.message; // why a renderer failed (a crash of task code)
		if (info.frame && !lab.images[side]) fetchImage(side); // a page opened on a running render
	}
	if (state.build !== "none") $("build-state").textContent = `(build: ${state.build})`;
	showComparison(state.comparison);
}

// ---- The build, the grader ----------------------------------------------------------------------

function showBuild(build) {
	lab.build = build;
	const names = {building: "rebuilding ...", ok: "built", failed: "does not build"};
	$("build-state").textContent = `(${names[build.state] || build.state}${build.seconds ? `, ${build.seconds.toFixed(1)} s` : ""})`;
	const list = $("diagnostics");
	if (build.state === "building") return;
	lab.builds++;
	lab.updatesAtBuild = lab.updates.student;
	list.innerHTML = "";
	for (const d of build.diagnostics || []) {
		if (d.severity === "note") continue;
		const item = document.createElement("li");
		item.className = d.severity;
		item.textContent = `${d.file}${d.line ? `:${d.line}` : ""}${d.column ? `:${d.column}` : ""}: ${d.severity}: ${d.message}`;
		list.append(item);
	}
	$("build-log").textContent = build.log || "";
	$("build-log-details").open = build.state === "failed";
	if (build.state === "failed") $("student-state").textContent = "does not build: see below";
}

function showGradeLine(event) {
	if (event.started) {
		lab.grade = {task: event.task, lines: [], status: null};
		$("grade-output").textContent = `./lab grade ${event.task}\n`;
		return;
	}
	lab.grade.lines.push(event.line);
	$("grade-output").textContent += event.line + "\n";
}

// ---- A pixel's path -----------------------------------------------------------------------------

// The vertices of a sample's path: the camera ray, then each ray its vertex continued with.
function vertices(sample) {
	const list = [];
	for (let ray = sample.ray; ray; ray = ray.children[ray.children.length - 1]) list.push(ray);
	return list;
}

function eventsOf(ray, ...kinds) {
	return ray.events.filter((e) => kinds.includes(e.kind)).map((e) => e.text).join("\n");
}

function showPath(doc, side) {
	lab.path = doc;
	lab.pathSide = side;
	$("path-error").textContent = "";
	const [x, y] = doc.pixel;
	$("path-title").textContent = `(${x}, ${y}) of the ${side === "student" ? "student's" : "reference's"} render, seed ${doc.seed}`;
	const sample = doc.samples[0];
	$("path-samples").textContent = doc.samples.map((s) => `sample ${s.index}: value ${vector(s.value)}`).join("; ") +
		(doc.followed > 1 ? ` (the brightest of ${doc.followed} samples)` : "");
	const body = $("path-table").querySelector("tbody");
	body.innerHTML = "";
	if (!sample || !sample.ray) return;
	const rays = vertices(sample);
	const brightest = rays.reduce((best, r, i) => (luminance(r.contribution) > luminance(rays[best].contribution) ? i : best), 0);
	rays.forEach((ray, i) => {
		const row = body.insertRow();
		if (i === brightest && luminance(ray.contribution) > 0) row.className = "brightest";
		const hit = ray.hit;
		const cells = [
			ray.depth,
			hit ? vector(hit.position) : "missed: environment",
			hit ? vector(hit.normal) : "",
			hit ? `${hit.material} (object ${hit.object})` : "",
			eventsOf(ray, "bsdf_sample"),
			eventsOf(ray, "bsdf_pdf", "light_pdf"),
			vector(ray.weight),
			vector(ray.throughput),
			eventsOf(ray, "light_sample"),
			eventsOf(ray, "shadow_ray"),
			vector(ray.emitted),
			vector(ray.contribution),
		];
		cells.forEach((text, c) => {
			const cell = row.insertCell();
			cell.textContent = text;
			if (c >= 4 && c <= 9) cell.className = "events";
		});
	});
	drawPathOverlay();
}

// The path drawn over the picture it was clicked on: the pixel, then each hit where the camera
// sees it; the vertex that added the most light is red.
function drawPathOverlay() {
	for (const name of ["student", "reference", "wipe", "z"]) {
		const overlay = $(`${name}-overlay`), base = $(`${name}-canvas`);
		overlay.width = base.width * 2;
		overlay.height = base.height * 2;
		overlay.style.width = base.clientWidth + "px";
		overlay.style.height = base.clientHeight + "px";
	}
	const doc = lab.path;
	if (!doc || !doc.samples[0] || !doc.samples[0].ray) return;
	const rays = vertices(doc.samples[0]);
	const brightest = rays.reduce((best, r, i) => (luminance(r.contribution) > luminance(rays[best].contribution) ? i : best), 0);
	for (const name of ["student", "reference", "wipe", "z"]) {
		const context = $(`${name}-overlay`).getContext("2d");
		context.scale(2, 2);
		context.lineWidth = 1;
		context.strokeStyle = "#0f0";
		context.fillStyle = "#0f0";
		const [px, py] = doc.pixel;
		context.beginPath();
		context.moveTo(px + 0.5, py + 0.5);
		for (const ray of rays) if (ray.hit && ray.hit.film_pixel) context.lineTo(...ray.hit.film_pixel);
		context.stroke();
		rays.forEach((ray, i) => {
			if (!ray.hit || !ray.hit.film_pixel) return;
			const [x, y] = ray.hit.film_pixel;
			context.fillStyle = i === brightest && luminance(ray.contribution) > 0 ? "#f00" : "#0f0";
			context.beginPath();
			context.arc(x, y, 2.5, 0, 2 * Math.PI);
			context.fill();
			context.font = "8px sans-serif";
			context.fillText(String(ray.depth), x + 3, y - 3);
		});
	}
}

async function followPixel(side, event) {
	const canvas = event.target;
	const image = lab.images[side === "wipe" || side === "z" ? "student" : side];
	if (!image) return;
	const x = Math.floor((event.offsetX / canvas.clientWidth) * canvas.width);
	const y = Math.floor((event.offsetY / canvas.clientHeight) * canvas.height);
	const actualSide = side === "wipe" ? (x < Number($("wipe").value) * image.width ? "student" : "reference") : side === "z" ? "student" : side;
	const params = {side: actualSide, x, y};
	if ($("path-brightest").checked) Object.assign(params, {samples: Math.max(1, image.samples), brightest: 3});
	$("path-title").textContent = `(${x}, ${y}): following ...`;
	const response = await fetch(url("api/path", params));
	const body = await response.json();
	if (!response.ok) {
		$("path-error").textContent = body.error;
		return;
	}
	showPath(body, actualSide);
}

// ---- Wiring -------------------------------------------------------------------------------------

function layout() {
	const pictures = $("pictures");
	pictures.classList.remove("side", "wipe", "z");
	pictures.classList.add($("layout").value);
	drawWipe();
	fetchZ();
	drawPathOverlay();
}

async function restart(changes) {
	try {
		lab.images = {};
		showState(await post("api/restart", changes));
	} catch (error) {
		alert(error.message);
	}
}

function wire() {
	$("layout").onchange = layout;
	$("exposure").oninput = () => {
		$("exposure-value").textContent = $("exposure").value;
		drawSide("student");
		drawSide("reference");
	};
	$("tonemap").onchange = $("exposure").oninput;
	$("nan-map").onchange = () => { fetchImage("student"); fetchImage("reference"); };
	$("rate-map").onchange = () => {
		for (const side of ["student", "reference"]) { drawSide(side); fetchImage(side); }
	};
	$("adaptive").onchange = () => restart({adaptive: $("adaptive").value || 0});
	$("wipe").oninput = drawWipe;
	$("pause").onclick = async () => showState(await post(lab.state && lab.state.paused ? "api/resume" : "api/pause"));
	$("restart").onclick = () => restart({seed: $("seed").value});
	$("save").onclick = async () => {
		const side = lab.state && lab.state.compare ? "student" : "reference";
		const name = `${lab.state.scene.replace(/\.json$/, "")}_view_${side}.png`;
		try {
			$("saved").textContent = `wrote ${(await post("api/snapshot", {side, name, exposure: $("exposure").value})).wrote}`;
		} catch (error) {
			$("saved").textContent = error.message;
		}
	};
	$("view").onchange = () => restart({view: $("view").value});
	$("scene").onchange = () => restart({scene: $("scene").value});
	for (const side of ["student", "reference", "wipe", "z"]) $(`${side}-canvas`).onclick = (e) => followPixel(side, e);
	for (let task = 1; task <= 8; task++) {
		const button = document.createElement("button");
		button.textContent = `task ${task}`;
		button.onclick = async () => {
			try {
				await post("api/grade", {task});
			} catch (error) {
				$("grade-output").textContent += error.message + "\n";
			}
		};
		$("grade-buttons").append(button);
	}

	const events = new EventSource(url("api/events"));
	const on = (name, handler) => events.addEventListener(name, (e) => handler(JSON.parse(e.data)));
	on("state", showState);
	on("frame", (e) => { showFrame(e); fetchImage(e.side); });
	on("comparison", showComparison);
	on("renderer", (e) => {
		$(`${e.side}-state`).textContent = e.state;
		$(`${e.side}-message`).textContent = e.state === "failed" ? e.message : "";
	});
	on("build", showBuild);
	on("grade", showGradeLine);
	on("graded", (e) => {
		lab.grade.status = e.status;
		$("grade-output").textContent += `\n./lab grade ${e.task} exited with status ${e.status}` +
			(e.status === 0 ? " (every test case passed)\n" : " (some test cases failed: see above)\n");
	});
	layout();
}

wire();
