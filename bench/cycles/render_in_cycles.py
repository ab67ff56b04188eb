# Renders a PathTracer Lab scene (scenes/*.json, format: scenes/README.md) with Blender Cycles, with
# the lab's conventions and Cycles' path tracer at settings matched to ours; writes the linear image
# as 32-bit float OpenEXR, which the lab's read_image reads. Run inside Blender:
#
#   blender -b --factory-startup --python-exit-code 1 -P bench/cycles/render_in_cycles.py -- \
#       SCENE.json --out IMAGE.exr [--spp N] [--seed S] [--threads T] [--max-depth D] [--width W --height H]
#
# Prints "cycles: export X s, render Y s" (render: the bpy.ops.render.render call alone: Cycles'
# scene sync, BVH build and sampling; export: building the Blender scene from the JSON).
#
# Correspondences (lab -> Cycles):
# - coordinates: kept as they are (+y up); nothing in Cycles depends on the up axis except the
#   environment lookup, which is built here from the lab's own formula (framework/api/env_light.h).
# - camera: Camera::look_at's frame (framework/scene/camera.cpp) is Blender's camera frame (looks down -z,
#   +y up); the vertical field of view is the sensor's, fitted vertically.
# - max_depth D (a surface scatters while the ray's depth < D; D = 1 is direct light) is Cycles'
#   max_bounces D - 1 (0 is direct light), for every kind of bounce.
# - lambertian: Diffuse BSDF, roughness 0 (Lambert). mirror: Glossy BSDF, sharp. glass: Glass BSDF,
#   sharp, Fresnel-weighted reflection and refraction (needs reflectance == transmittance).
# - emission: one-sided, from the front (the side the normal points to): Emission x not-backfacing.
# - spheres (analytic in the lab): a latitude-longitude mesh with the exact sphere normal at every
#   vertex, smooth-shaded; SPHERE_SEGMENTS sets how fine.
# - mesh normals: the lab's area-weighted vertex normals (framework/scene/mesh_builder.h) or the scene's,
#   set as custom normals; flat_shading: face normals.
# - environment: constant -> Background colour; image -> the equirectangular lookup of env_light.h
#   (u = atan2(z, x) / 2 pi, v = acos(y) / pi, v = 0 the top row), bilinear, times "scale".
import argparse
import json
import math
import os
import sys
import time

import bpy
import numpy as np
from mathutils import Matrix

SPHERE_SEGMENTS = 512 # around the equator; half as many rings from pole to pole

# --cycles-default NAME puts back Cycles' own default for a group of the settings matched here, to
# measure what each one changes (bench/README.md: Cycles' darker Cornell box).
CYCLES_DEFAULT_GROUPS = {
	"bounces": ["max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
	            "transparent_max_bounces", "volume_bounces"],
	"clamp": ["sample_clamp_direct", "sample_clamp_indirect"],
	"light-threshold": ["light_sampling_threshold"],
	"filter": ["pixel_filter_type", "filter_width"],
}


class SceneError(Exception):
	pass


# ---- Transforms (scenes/README.md: steps applied in order, the first step first) ----------------

def rotation(axis, degrees):
	# Rodrigues' formula: counter-clockwise seen from the tip of the axis.
	a = np.asarray(axis, dtype=np.float64)
	a = a / np.linalg.norm(a)
	t = math.radians(degrees)
	k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
	m = np.eye(4)
	m[:3, :3] = np.eye(3) + math.sin(t) * k + (1 - math.cos(t)) * (k @ k)
	return m


def step_matrix(step, where):
	m = np.eye(4)
	if "translate" in step:
		m[:3, 3] = step["translate"]
	elif "scale" in step:
		s = step["scale"]
		m[:3, :3] = np.diag([s, s, s] if isinstance(s, (int, float)) else s)
	elif "rotate" in step:
		m = rotation(step["rotate"]["axis"], step["rotate"]["degrees"])
	elif "matrix" in step:
		m = np.array(step["matrix"], dtype=np.float64)
	else:
		raise SceneError(f"{where}: expected translate, scale, rotate or matrix, found {sorted(step)}")
	return m


def object_to_world(obj, where):
	m = np.eye(4)
	for i, step in enumerate(obj.get("transform", [])):
		m = step_matrix(step, f"{where}.transform[{i}]") @ m # later steps act after
	return m


# ---- Geometry -----------------------------------------------------------------------------------

def read_obj(path, where):
	# Positions and faces (fan-triangulated); the lab's meshes carry no normals or texture coordinates.
	positions, triangles = [], []
	with open(path) as f:
		for number, line in enumerate(f, 1):
			fields = line.split()
			if not fields:
				continue
			if fields[0] == "v":
				positions.append([float(x) for x in fields[1:4]])
			elif fields[0] == "vn":
				raise SceneError(f"{where}: {path}: line {number}: normals in an OBJ file are not exported (none of the lab's meshes has them)")
			elif fields[0] == "f":
				corners = [int(c.split("/")[0]) for c in fields[1:]]
				corners = [c - 1 if c > 0 else len(positions) + c for c in corners]
				for k in range(1, len(corners) - 1):
					triangles.append([corners[0], corners[k], corners[k + 1]])
	return np.array(positions, dtype=np.float64), np.array(triangles, dtype=np.int64)


def area_weighted_normals(positions, triangles):
	# framework/scene/mesh_builder.h: n(v) = normalize(sum over the triangles around v of cross(p1 - p0, p2 - p0)).
	p0, p1, p2 = (positions[triangles[:, k]] for k in range(3))
	area = np.cross(p1 - p0, p2 - p0)
	sums = np.zeros_like(positions)
	for k in range(3):
		np.add.at(sums, triangles[:, k], area)
	length = np.linalg.norm(sums, axis=1, keepdims=True)
	return np.where(length > 0, sums / np.where(length > 0, length, 1), [0.0, 1.0, 0.0])


def uv_sphere(radius):
	# Latitude-longitude mesh; its triangles wind counter-clockwise seen from outside.
	rings, segments = SPHERE_SEGMENTS // 2, SPHERE_SEGMENTS
	theta = np.linspace(0, math.pi, rings + 1)[1:-1]
	phi = np.linspace(0, 2 * math.pi, segments, endpoint=False)
	t, p = np.meshgrid(theta, phi, indexing="ij")
	directions = np.stack([np.sin(t) * np.cos(p), np.cos(t), np.sin(t) * np.sin(p)], axis=-1).reshape(-1, 3)
	directions = np.vstack([[0, 1, 0], directions, [0, -1, 0]])
	top, bottom = 0, len(directions) - 1
	ring = lambda r, s: 1 + r * segments + s % segments
	triangles = []
	for s in range(segments):
		triangles.append([top, ring(0, s + 1), ring(0, s)])
		for r in range(rings - 2):
			a, b, c, d = ring(r, s), ring(r, s + 1), ring(r + 1, s + 1), ring(r + 1, s)
			triangles += [[a, b, c], [a, c, d]]
		triangles.append([bottom, ring(rings - 2, s), ring(rings - 2, s + 1)])
	return radius * directions, np.array(triangles, dtype=np.int64), directions


def mesh_data(obj, scene_dir, where):
	# Positions, triangles, per-vertex normals (None: flat shading), in the object's own space.
	if obj["type"] == "sphere":
		return uv_sphere(float(obj["radius"]))
	if "file" in obj:
		positions, triangles = read_obj(os.path.join(scene_dir, obj["file"]), f"{where}.file")
	else:
		positions = np.array(obj["vertices"], dtype=np.float64)
		triangles = np.array(obj["triangles"], dtype=np.int64)
	if obj.get("flat_shading", False):
		return positions, triangles, None
	if "normals" in obj:
		normals = np.array(obj["normals"], dtype=np.float64)
		return positions, triangles, normals / np.linalg.norm(normals, axis=1, keepdims=True)
	return positions, triangles, area_weighted_normals(positions, triangles)


def to_world(positions, triangles, normals, m):
	# Baked into the vertices: points by m, normals by its inverse transpose. A mirroring transform
	# (det < 0) turns the object inside out (framework/scene/instance.cpp): its normals turn around, and
	# stay on the side of the transformed triangles' face normals.
	linear = m[:3, :3]
	positions = positions @ linear.T + m[:3, 3]
	if normals is not None:
		normals = normals @ np.linalg.inv(linear) * np.sign(np.linalg.det(linear))
		normals /= np.linalg.norm(normals, axis=1, keepdims=True)
	return positions, triangles, normals


def add_mesh(name, positions, triangles, normals, material):
	mesh = bpy.data.meshes.new(name)
	mesh.vertices.add(len(positions))
	mesh.vertices.foreach_set("co", positions.astype(np.float32).ravel())
	mesh.loops.add(3 * len(triangles))
	mesh.loops.foreach_set("vertex_index", triangles.astype(np.int32).ravel())
	mesh.polygons.add(len(triangles))
	mesh.polygons.foreach_set("loop_start", np.arange(0, 3 * len(triangles), 3, dtype=np.int32))
	mesh.polygons.foreach_set("loop_total", np.full(len(triangles), 3, dtype=np.int32))
	mesh.update(calc_edges=True)
	smooth = normals is not None
	mesh.polygons.foreach_set("use_smooth", np.full(len(triangles), smooth))
	if smooth:
		mesh.use_auto_smooth = True # Cycles then takes the custom normals
		mesh.normals_split_custom_set_from_vertices(normals.astype(np.float32).tolist())
	mesh.materials.append(material)
	obj = bpy.data.objects.new(name, mesh)
	bpy.context.scene.collection.objects.link(obj)


# ---- Materials ----------------------------------------------------------------------------------

def rgb(values):
	return (*[float(v) for v in values], 1.0)


def make_material(name, spec, where):
	material = bpy.data.materials.new(name)
	material.use_nodes = True
	nodes, links = material.node_tree.nodes, material.node_tree.links
	nodes.clear()
	output = nodes.new("ShaderNodeOutputMaterial")
	kind = spec["type"]
	if kind in ("lambertian", "emissive"):
		surface = nodes.new("ShaderNodeBsdfDiffuse")
		surface.inputs["Color"].default_value = rgb(spec["albedo"] if kind == "lambertian" else [0, 0, 0])
		surface.inputs["Roughness"].default_value = 0.0
	elif kind == "mirror":
		surface = nodes.new("ShaderNodeBsdfGlossy")
		surface.distribution = "SHARP"
		surface.inputs["Color"].default_value = rgb(spec.get("reflectance", [1, 1, 1]))
	elif kind == "glass":
		reflectance, transmittance = spec.get("reflectance", [1, 1, 1]), spec.get("transmittance", [1, 1, 1])
		if list(reflectance) != list(transmittance):
			raise SceneError(f"{where}: Cycles' Glass BSDF has one colour: expected reflectance == transmittance, found {reflectance} and {transmittance}")
		surface = nodes.new("ShaderNodeBsdfGlass")
		surface.distribution = "SHARP"
		surface.inputs["Color"].default_value = rgb(reflectance)
		surface.inputs["IOR"].default_value = float(spec.get("index_of_refraction", 1.5))
	else:
		raise SceneError(f"{where}.type: expected lambertian, mirror, glass or emissive, found {kind!r}")
	emission = spec.get("emission", [0, 0, 0])
	if any(e > 0 for e in emission):
		# One-sided: the front emits, the back is the surface alone.
		emit = nodes.new("ShaderNodeEmission")
		emit.inputs["Color"].default_value = rgb(emission)
		emit.inputs["Strength"].default_value = 1.0 # on a mesh: radiance = colour x strength
		front = nodes.new("ShaderNodeAddShader")
		links.new(surface.outputs[0], front.inputs[0])
		links.new(emit.outputs[0], front.inputs[1])
		backfacing = nodes.new("ShaderNodeNewGeometry").outputs["Backfacing"]
		sides = nodes.new("ShaderNodeMixShader")
		links.new(backfacing, sides.inputs["Fac"])
		links.new(front.outputs[0], sides.inputs[1])
		links.new(surface.outputs[0], sides.inputs[2])
		surface = sides
	links.new(surface.outputs[0], output.inputs["Surface"])
	return material


# ---- Environment --------------------------------------------------------------------------------

def make_world(spec, scene_dir):
	world = bpy.data.worlds.new("environment")
	world.use_nodes = True
	nodes, links = world.node_tree.nodes, world.node_tree.links
	background = nodes["Background"]
	if spec is None:
		background.inputs["Strength"].default_value = 0.0
		world.cycles.sampling_method = "NONE"
	elif spec["type"] == "constant":
		background.inputs["Color"].default_value = rgb(spec["radiance"])
	elif spec["type"] == "image":
		image = bpy.data.images.load(os.path.join(scene_dir, spec["file"]))
		image.colorspace_settings.name = "Linear"
		texture = nodes.new("ShaderNodeTexImage")
		texture.image = image
		texture.interpolation = "Linear"
		texture.extension = "REPEAT" # wraps in u at the seam; in v it wraps where the lab clamps (half a texel at the poles)

		def math_node(operation, a, b=None, c=None):
			node = nodes.new("ShaderNodeMath")
			node.operation = operation
			for i, value in enumerate((a, b, c)):
				if value is None:
					continue
				if isinstance(value, (int, float)):
					node.inputs[i].default_value = value
				else:
					links.new(value, node.inputs[i])
			return node.outputs[0]

		# The direction the background is seen in (world space), as the lab's (x, y, z).
		direction = nodes.new("ShaderNodeVectorMath")
		direction.operation = "NORMALIZE"
		links.new(nodes.new("ShaderNodeTexCoord").outputs["Generated"], direction.inputs[0])
		xyz = nodes.new("ShaderNodeSeparateXYZ")
		links.new(direction.outputs[0], xyz.inputs[0])
		x, y, z = xyz.outputs
		u = math_node("DIVIDE", math_node("ARCTAN2", z, x), 2 * math.pi)                 # phi / 2 pi
		image_v = math_node("MULTIPLY_ADD", math_node("ARCCOSINE", y), -1 / math.pi, 1.0) # 1 - theta / pi: Blender's v grows upwards
		uv = nodes.new("ShaderNodeCombineXYZ")
		links.new(u, uv.inputs[0])
		links.new(image_v, uv.inputs[1])
		links.new(uv.outputs[0], texture.inputs["Vector"])
		links.new(texture.outputs["Color"], background.inputs["Color"])
		background.inputs["Strength"].default_value = float(spec.get("scale", 1.0))
		world.cycles.sampling_method = "MANUAL" if spec.get("importance_sampling", True) else "NONE"
		world.cycles.sample_map_resolution = max(image.size)
	else:
		raise SceneError(f"environment.type: expected constant or image, found {spec['type']!r}")
	return world


# ---- Camera and render settings -----------------------------------------------------------------

def look_at(position, target, up):
	# Camera::look_at (framework/scene/camera.cpp): z from the target back to the eye, x = up x z, y = z x x.
	position, target, up = (np.asarray(v, dtype=np.float64) for v in (position, target, up))
	z = position - target
	z /= np.linalg.norm(z)
	x = np.cross(up, z)
	x /= np.linalg.norm(x)
	m = np.eye(4)
	m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = x, np.cross(z, x), z, position
	return m


def add_camera(spec, scene_extent):
	camera = bpy.data.cameras.new("camera")
	camera.type = "PERSP"
	camera.sensor_fit = "VERTICAL"
	camera.angle_y = math.radians(float(spec["vertical_fov"]))
	camera.clip_start = 1e-6 * scene_extent # the lab's camera rays start at distance 0 and never end
	camera.clip_end = 1e6 * scene_extent
	obj = bpy.data.objects.new("camera", camera)
	obj.matrix_world = Matrix(look_at(spec["position"], spec["target"], spec.get("up", [0, 1, 0])).tolist())
	bpy.context.scene.collection.objects.link(obj)
	bpy.context.scene.camera = obj


def configure_render(scene, width, height, spp, seed, max_depth, threads):
	if max_depth < 1:
		raise SceneError("film.max_depth: Cycles cannot show emitters alone (max_depth 0); expected 1 or more")
	scene.render.engine = "CYCLES"
	scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = width, height, 100
	scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1.0
	scene.render.film_transparent = False
	scene.render.threads_mode = "FIXED"
	scene.render.threads = threads
	c = scene.cycles
	c.device = "CPU"
	c.samples = spp
	c.seed = seed
	c.use_animated_seed = False
	c.use_adaptive_sampling = False
	c.use_denoising = False
	c.pixel_filter_type = "BOX"
	c.filter_width = 1.0 # one pixel: samples uniform over the pixel, as the lab's
	bounces = max_depth - 1
	c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = bounces
	c.transparent_max_bounces = c.volume_bounces = bounces
	c.min_light_bounces = c.min_transparent_bounces = 0
	c.sample_clamp_direct = c.sample_clamp_indirect = 0.0 # no clamping (Cycles' default clamps indirect at 10)
	c.light_sampling_threshold = 0.0 # no light is skipped (default 0.01)
	c.blur_glossy = 0.0
	c.caustics_reflective = c.caustics_refractive = True
	c.use_fast_gi = False
	c.film_exposure = 1.0
	scene.view_settings.view_transform = "Standard"
	scene.view_settings.look = "None"
	scene.view_settings.exposure = 0.0
	scene.view_settings.gamma = 1.0
	settings = scene.render.image_settings
	settings.file_format = "OPEN_EXR"
	settings.color_mode = "RGB"
	settings.color_depth = "32"
	settings.exr_codec = "ZIP"


def main():
	parser = argparse.ArgumentParser(prog="render_in_cycles.py")
	parser.add_argument("scene")
	parser.add_argument("--out", required=True)
	parser.add_argument("--spp", type=int)
	parser.add_argument("--seed", type=int)
	parser.add_argument("--threads", type=int, default=os.cpu_count())
	parser.add_argument("--max-depth", type=int)
	parser.add_argument("--width", type=int)
	parser.add_argument("--height", type=int)
	parser.add_argument("--cycles-default", action="append", default=[], choices=sorted(CYCLES_DEFAULT_GROUPS))
	args = parser.parse_args(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])

	start = time.perf_counter()
	with open(args.scene) as f:
		lab = json.load(f)
	scene_dir = os.path.dirname(os.path.abspath(args.scene))
	film = lab.get("film", {})
	width = args.width or film.get("width", 256)
	height = args.height or film.get("height", 256)
	if args.width and not args.height or args.height and not args.width:
		raise SceneError("give --width and --height together (the lab's film keeps the vertical field of view)")

	bpy.ops.wm.read_factory_settings(use_empty=True)
	scene = bpy.context.scene
	configure_render(scene, width, height, args.spp or film.get("samples", 16),
	                 film.get("seed", 0) if args.seed is None else args.seed,
	                 film.get("max_depth", 8) if args.max_depth is None else args.max_depth, args.threads)
	for group in args.cycles_default:
		for name in CYCLES_DEFAULT_GROUPS[group]:
			setattr(scene.cycles, name, scene.cycles.bl_rna.properties[name].default)
	materials = {name: make_material(name, spec, f"{args.scene}: materials.{name}") for name, spec in lab["materials"].items()}
	extent = 0.0
	for i, obj in enumerate(lab["objects"]):
		where = f"{args.scene}: objects[{i}]"
		positions, triangles, normals = to_world(*mesh_data(obj, scene_dir, where), object_to_world(obj, where))
		extent = max(extent, float(np.abs(positions).max()))
		add_mesh(obj.get("name", f"object {i}"), positions, triangles, normals, materials[obj["material"]])
	scene.world = make_world(lab.get("environment"), scene_dir)
	add_camera(lab["camera"], max(extent, float(np.abs(lab["camera"]["position"]).max()), 1e-3))
	exported = time.perf_counter()

	bpy.ops.render.render()
	rendered = time.perf_counter()
	bpy.data.images["Render Result"].save_render(os.path.abspath(args.out), scene=scene)
	print(f"cycles: export {exported - start:.3f} s, render {rendered - exported:.3f} s")


try:
	main()
except SceneError as e:
	print(f"render_in_cycles.py: {e}", file=sys.stderr)
	sys.exit(1)
