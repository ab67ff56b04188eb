# Renders a PathTracer Lab scene (scenes/*.json, format: scenes/README.md) with Blender Cycles, with
# the lab's conventions and Cycles' path tracer at settings matched to ours; writes the linear image
# as 32-bit float OpenEXR, which the lab's read_image reads. Run inside Blender:
#
#   blender -b --factory-startup --python-exit-code 1 -P bench/cycles/render_in_cycles.py -- \
#       SCENE.json --out IMAGE.exr [--spp N] [--seed S] [--threads T] [--max-depth D] [--width W --height H]
#       [--cycles-default GROUP]... [--light-as-mesh] [--subdivide-lights N] [--sphere-segments N]
#       [--no-light-sampling] [--world-map-resolution N]
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
# - an emissive rectangle (the Cornell boxes' lights): a Cycles rectangle area light in its place, of
#   power 4 A L for radiance L and area A (Cycles 3.4 gives an area light the radiance power / (4 A)),
#   one-sided, spread 180 degrees, unseen by the camera, a hair in front of the mesh; the mesh stays,
#   emitting to camera rays alone, and stops the rays that reach it as the lab's does (Cycles' lights
#   let rays through). As a mesh light (--light-as-mesh) Cycles 3.4 gets the direct light of
#   such a light wrong by -65 to +4 % (bench/README.md, `./lab bench cycles-direct-light`): it samples
#   a light triangle over its solid angle, which it computes in float by Girard's formula (the
#   spherical triangle's three angles minus pi) with a polynomial acos of error up to 4.5e-5 rad, off
#   by -50 to +38 % for the 1e-4 to 1e-3 sr these triangles subtend. The area light agrees with ours
#   and with Lambert's closed form to 0.03 % over the image (0.2 % on the walls right below the
#   light's plane). On many_lights' floor (120 squares of 0.3 m, 3.2 m up, seen from up to 45 m) it
#   is off by -0.6 to +0.3 % per region of a 4 x 4 grid (-0.4 to +0.2 % with every lamp alike),
#   where ours agrees with the closed form within 0.07 % (bench/cycles/floor_closed_form.py); the
#   float solid angle of Cycles' rect_light_sample is not it (< 0.001 %); the cause is not known.
# - an emissive sphere (furnace_closed): its mesh is not sampled as a light; Cycles finds it by BSDF
#   sampling alone. Sampled as a light, Cycles 3.4 renders the closed furnace 0.085 % too dark with
#   this mesh, 0.04 % with 64 segments and 1.24 % with 2048, where BSDF sampling alone agrees with the
#   closed form (bench/README.md); no other shipped scene has an emissive sphere.
# - shadow terminator: Cycles moves the origin of shadow rays from smooth-shaded triangles by a
#   per-object "geometry offset" (default 0.1; it brightened bunny_sun's bunny by 0.1-0.3 %); the
#   lab moves ray origins only by a rounding-error distance (framework/api/spawn_ray.h), so it is 0
#   here (--cycles-default shadow-terminator: 0.1).
# - spheres (analytic in the lab): a latitude-longitude mesh with the exact sphere normal at every
#   vertex, smooth-shaded; SPHERE_SEGMENTS (--sphere-segments) sets how fine.
# - mesh normals: the lab's area-weighted vertex normals (framework/scene/mesh_builder.h) or the scene's,
#   set as custom normals; flat_shading: face normals.
# - environment: constant -> Background colour; image -> the equirectangular lookup of env_light.h
#   (u = atan2(z, x) / 2 pi, v = acos(y) / pi, v = 0 the top row), bilinear, times "scale".
#   Cycles' importance map of it (world sample_map_resolution, the map's width) is 8192 wide
#   (--world-map-resolution): Cycles 3.4's direct light from a small bright sun depends on that
#   width, which it should not (only the noise should): on bunny_sun's ground without the bunny
#   (max depth 1, against a quadrature of the environment) -1.2 % at 256, +0.24 % at 1024 (the
#   image's width), -0.08 % at 2048, +0.04 % at 4096, -0.01 +- 0.004 % at 8192, where ours is
#   +0.01 +- 0.01 % (bench/README.md). The finer map costs Cycles time to build (the ground's
#   render: 15 s at 1024, 70 s at 8192 on a loaded machine).
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
WORLD_MAP_RESOLUTION = 8192 # Cycles' importance map of an image environment (see the header)

# --cycles-default NAME puts back Cycles' own default for a group of the settings matched here, to
# measure what each one changes (bench/README.md: Cycles' darker Cornell box).
CYCLES_DEFAULT_GROUPS = {
	"bounces": ["max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
	            "transparent_max_bounces", "volume_bounces"],
	"clamp": ["sample_clamp_direct", "sample_clamp_indirect"],
	"light-threshold": ["light_sampling_threshold"],
	"filter": ["pixel_filter_type", "filter_width"],
	"shadow-terminator": [], # per object: Object.cycles.shadow_terminator_geometry_offset, set in add_mesh
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


def uv_sphere(radius, segments=SPHERE_SEGMENTS):
	# Latitude-longitude mesh; its triangles wind counter-clockwise seen from outside.
	rings = segments // 2
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


def mesh_data(obj, scene_dir, where, sphere_segments=SPHERE_SEGMENTS):
	# Positions, triangles, per-vertex normals (None: flat shading), in the object's own space.
	if obj["type"] == "sphere":
		return uv_sphere(float(obj["radius"]), sphere_segments)
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


def subdivide(positions, triangles, n):
	# Each triangle as n x n smaller ones (a barycentric grid), for --subdivide-lights.
	points, faces = [], []
	for a, b, c in triangles:
		pa, pb, pc = positions[a], positions[b], positions[c]
		index = {}
		for i in range(n + 1):
			for j in range(n + 1 - i):
				index[i, j] = len(points)
				points.append(pa + (pb - pa) * i / n + (pc - pa) * j / n)
		for i in range(n):
			for j in range(n - i):
				faces.append([index[i, j], index[i + 1, j], index[i, j + 1]])
				if i + j < n - 1:
					faces.append([index[i + 1, j], index[i + 1, j + 1], index[i, j + 1]])
	return np.array(points), np.array(faces, dtype=np.int64)


def rectangle(positions, triangles):
	# (centre, edge u, edge v, unit front normal) when the mesh is one planar rectangle of two
	# triangles, else None. The front is the side cross(p1 - p0, p2 - p0) of its triangles points to.
	if len(positions) != 4 or len(triangles) != 2 or sorted(set(triangles.ravel())) != [0, 1, 2, 3]:
		return None
	p = positions
	u, v = p[1] - p[0], p[3] - p[0]
	normals = [np.cross(p[b] - p[a], p[c] - p[a]) for a, b, c in triangles]
	normal = normals[0] / np.linalg.norm(normals[0])
	size = max(np.linalg.norm(u), np.linalg.norm(v))
	if (abs(np.dot(u, v)) > 1e-6 * size ** 2 or np.linalg.norm(p[0] + u + v - p[2]) > 1e-6 * size
	        or np.dot(normals[0], normals[1]) <= 0):
		return None
	return p.mean(axis=0), u, v, normal


def add_area_light(name, centre, u, v, normal, radiance):
	# A Cycles rectangle area light for an emissive rectangle (see the header). It emits from its
	# local -z side, one-sided, spread 180 degrees. Cycles 3.4 gives an area light of power P and area
	# A the radiance P / (4 A) (kernel/light/light.h: eval_fac = 0.25 / area; the light's strength is
	# colour x power), so P = 4 A L. Rays pass through a Cycles light, so the rectangle's mesh stays
	# as the surface that stops them; the light sits a hair in front of it, so that shadow rays to
	# the light end before the mesh.
	size = max(np.linalg.norm(u), np.linalg.norm(v))
	centre = centre + max(1e-4 * size, 1e-5 * np.abs(centre).max()) * normal
	light = bpy.data.lights.new(name, "AREA")
	light.shape = "RECTANGLE"
	light.size, light.size_y = float(np.linalg.norm(u)), float(np.linalg.norm(v))
	light.spread = math.pi
	area = light.size * light.size_y
	light.energy = 4.0 * area * max(radiance)
	light.color = [float(r) / max(radiance) for r in radiance]
	x, y = u / np.linalg.norm(u), v / np.linalg.norm(v)
	z = -normal
	if np.dot(np.cross(x, y), z) < 0:
		x, y = y, x
		light.size, light.size_y = light.size_y, light.size
	m = np.eye(4)
	m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = x, y, z, centre
	obj = bpy.data.objects.new(name, light)
	obj.matrix_world = Matrix(m.tolist())
	obj.visible_camera = False # the camera sees the emissive mesh in its place
	bpy.context.scene.collection.objects.link(obj)


def add_mesh(name, positions, triangles, normals, material, terminator_offset):
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
	obj.cycles.shadow_terminator_geometry_offset = terminator_offset # see the header
	bpy.context.scene.collection.objects.link(obj)
	return obj


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


def camera_only_emission(material):
	# A copy of `material` whose emission only camera rays see (the light in its place emits to the
	# rest), not sampled as a light.
	copy = material.copy()
	nodes, links = copy.node_tree.nodes, copy.node_tree.links
	emission = next(node for node in nodes if node.type == "EMISSION")
	links.new(nodes.new("ShaderNodeLightPath").outputs["Is Camera Ray"], emission.inputs["Strength"])
	copy.cycles.sample_as_light = False
	return copy


# ---- Environment --------------------------------------------------------------------------------

def make_world(spec, scene_dir, map_resolution):
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
		world.cycles.sample_map_resolution = map_resolution # see the header
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
	parser.add_argument("--light-as-mesh", action="store_true",
	                    help="emissive rectangles as mesh lights too, not as Cycles area lights (see the header)")
	parser.add_argument("--subdivide-lights", type=int, default=1, metavar="N",
	                    help="each emissive triangle as N x N smaller ones, a mesh light")
	parser.add_argument("--sphere-segments", type=int, default=SPHERE_SEGMENTS, metavar="N",
	                    help=f"segments around a sphere's equator (default {SPHERE_SEGMENTS})")
	parser.add_argument("--world-map-resolution", type=int, default=WORLD_MAP_RESOLUTION, metavar="N",
	                    help=f"width of Cycles' importance map of an image environment (default {WORLD_MAP_RESOLUTION})")
	parser.add_argument("--no-light-sampling", action="store_true",
	                    help="emissive meshes not sampled as lights: Cycles finds them by BSDF sampling alone")
	parser.add_argument("--adaptive-threshold", type=float, metavar="T",
	                    help="Cycles' adaptive sampling on, at noise threshold T (minimum samples: Cycles' automatic "
	                         "choice); --spp is then the most a pixel takes")
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
	if args.adaptive_threshold is not None:
		scene.cycles.use_adaptive_sampling = True
		scene.cycles.adaptive_threshold = args.adaptive_threshold
		scene.cycles.adaptive_min_samples = 0 # automatic
	for group in args.cycles_default:
		for name in CYCLES_DEFAULT_GROUPS[group]:
			setattr(scene.cycles, name, scene.cycles.bl_rna.properties[name].default)
	terminator_offset = 0.1 if "shadow-terminator" in args.cycles_default else 0.0 # 0.1: Cycles' default
	materials = {name: make_material(name, spec, f"{args.scene}: materials.{name}") for name, spec in lab["materials"].items()}
	for material in materials.values():
		material.cycles.sample_as_light = not args.no_light_sampling
	extent = 0.0
	for i, obj in enumerate(lab["objects"]):
		where = f"{args.scene}: objects[{i}]"
		positions, triangles, normals = to_world(*mesh_data(obj, scene_dir, where, args.sphere_segments), object_to_world(obj, where))
		extent = max(extent, float(np.abs(positions).max()))
		name = obj.get("name", f"object {i}")
		emission = lab["materials"][obj["material"]].get("emission", [0, 0, 0])
		emissive = any(e > 0 for e in emission)
		if emissive and args.subdivide_lights > 1:
			positions, triangles = subdivide(positions, triangles, args.subdivide_lights)
			normals = None if normals is None else area_weighted_normals(positions, triangles) # a planar light's
		rect = rectangle(positions, triangles) if emissive and not args.light_as_mesh else None
		mesh_object = add_mesh(name, positions, triangles, normals, materials[obj["material"]], terminator_offset)
		if rect is not None:
			add_area_light(name + " (area light)", *rect, emission)
			mesh_object.active_material = camera_only_emission(mesh_object.active_material)
		elif emissive and obj["type"] == "sphere":
			mesh_object.active_material = mesh_object.active_material.copy()
			mesh_object.active_material.cycles.sample_as_light = False # see the header
	scene.world = make_world(lab.get("environment"), scene_dir, args.world_map_resolution)
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
