// load_obj (framework/scene/obj_loader.h): triangles from Wavefront OBJ files via tinyobjloader. Normals
// come from the file or are computed (area-weighted); degenerate faces are kept; a file that is
// missing, has no triangles or refers to vertices it does not define is an Input_Error naming it.
#include "error.h"
#include "obj_loader.h"
#include "temp_dir.h"

#include "lab_catch2.h"

#include <fstream>

namespace {

std::vector<Triangle> load_text(const Temp_Dir& dir, const std::string& text) {
	std::string path = dir.file("mesh.obj");
	std::ofstream(path) << text;
	return load_obj(path);
}

// Loading `text` must fail with a message that starts with the file's name and contains `expected`.
void require_obj_error(const std::string& text, const std::string& expected) {
	Temp_Dir dir;
	CAPTURE(text);
	try {
		load_text(dir, text);
		FAIL("load_obj accepted a bad OBJ file; expected an Input_Error about: " << expected);
	} catch (const Input_Error& e) {
		std::string message = e.what();
		CAPTURE(message);
		CHECK(message.rfind(dir.file("mesh.obj") + ": ", 0) == 0);
		CHECK(message.find(expected) != std::string::npos);
	}
}

void require_near(Vec3 actual, Vec3 expected, const char* what) {
	INFO(what << ": expected (" << expected.x << ", " << expected.y << ", " << expected.z << "), got (" << actual.x
	          << ", " << actual.y << ", " << actual.z << ")");
	CHECK(glm::length(actual - expected) < 1e-6f);
}

float area(const Triangle& t) {
	return 0.5f * glm::length(glm::cross(t.v1.position - t.v0.position, t.v2.position - t.v0.position));
}

} // namespace

TEST_CASE("load_obj reads the shipped meshes with their documented triangle counts", "[obj]") {
	// Counts from /work/shared/assets/SOURCES.md (what tinyobjloader reports).
	CHECK(load_obj("scenes/meshes/cornell_box.obj").size() == 32);
	CHECK(load_obj("scenes/meshes/bunny_npm_lowres.obj").size() == 3674);
	CHECK(load_obj("scenes/meshes/dragon_vrip_res4.obj").size() == 11102);
}

TEST_CASE("load_obj keeps the winding of the file: the Cornell box light faces down", "[obj]") {
	std::vector<Triangle> triangles = load_obj("scenes/meshes/cornell_box.obj");
	// The last two triangles are the light (SOURCES.md: its normal is -y by winding).
	for (size_t i = 30; i < 32; i++) {
		const Triangle& t = triangles[i];
		CHECK(t.v0.position.y == Approx(548.7f));
		Vec3 face = glm::normalize(glm::cross(t.v1.position - t.v0.position, t.v2.position - t.v0.position));
		require_near(face, Vec3{0.0f, -1.0f, 0.0f}, "the light's face normal");
		require_near(t.v0.normal, Vec3{0.0f, -1.0f, 0.0f}, "the light's computed vertex normal");
	}
}

TEST_CASE("load_obj computes missing normals as area-weighted averages of the face normals", "[obj]") {
	// Two faces folded along the edge (0,0,0)-(0,0,2): A has normal +y and area 2, B has normal
	// +x and area 1. The shared vertices get normalize(2 * (0,1,0) + 1 * (1,0,0)) = (1,2,0)/sqrt(5),
	// not the plain average (1,1,0)/sqrt(2); each other vertex gets its own face's normal.
	Temp_Dir dir;
	std::vector<Triangle> triangles = load_text(dir, "v 0 0 0\nv 0 0 2\nv 2 0 0\nv 0 1 0\n"
	                                                 "f 1 2 3\nf 1 4 2\n");
	REQUIRE(triangles.size() == 2);
	const Vec3 shared = glm::normalize(Vec3{1.0f, 2.0f, 0.0f});
	const Triangle& a = triangles[0];
	const Triangle& b = triangles[1];
	require_near(a.v0.normal, shared, "face A, shared vertex 1");
	require_near(a.v1.normal, shared, "face A, shared vertex 2");
	require_near(a.v2.normal, Vec3{0.0f, 1.0f, 0.0f}, "face A, its own vertex 3");
	require_near(b.v0.normal, shared, "face B, shared vertex 1");
	require_near(b.v1.normal, Vec3{1.0f, 0.0f, 0.0f}, "face B, its own vertex 4");
	require_near(b.v2.normal, shared, "face B, shared vertex 2");
}

TEST_CASE("load_obj uses the file's normals where a face has them, normalized", "[obj]") {
	Temp_Dir dir;
	std::vector<Triangle> triangles = load_text(dir, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
	                                                 "vn 0 0 2\nvn 0 3 4\n"
	                                                 "f 1//1 2//2 3//1\n" // normals given
	                                                 "f 2 4 3\n");        // none: computed
	REQUIRE(triangles.size() == 2);
	require_near(triangles[0].v0.normal, Vec3{0.0f, 0.0f, 1.0f}, "vn 0 0 2 normalized");
	require_near(triangles[0].v1.normal, Vec3{0.0f, 0.6f, 0.8f}, "vn 0 3 4 normalized");
	// The second face lies in z = 0 with counter-clockwise winding seen from +z.
	require_near(triangles[1].v1.normal, Vec3{0.0f, 0.0f, 1.0f}, "computed normal of a face without vn");
}

TEST_CASE("load_obj triangulates polygons and keeps degenerate faces", "[obj]") {
	Temp_Dir dir;
	// A unit square as one quad, and a face whose three vertices are collinear.
	std::vector<Triangle> triangles = load_text(dir, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
	                                                 "f 1 2 3 4\nf 1 2 5\n");
	REQUIRE(triangles.size() == 3);
	CHECK(area(triangles[0]) + area(triangles[1]) == Approx(1.0f));
	INFO("the degenerate face must be kept (the intersector copes) and get finite unit normals");
	CHECK(area(triangles[2]) == 0.0f);
	for (Vec3 n : {triangles[2].v0.normal, triangles[2].v1.normal, triangles[2].v2.normal}) {
		CHECK(is_finite(n));
		CHECK(glm::length(n) == Approx(1.0f));
	}
}

TEST_CASE("load_obj rejects a missing file, a file without triangles and bad indices", "[obj][errors]") {
	SECTION("a missing file") {
		Temp_Dir dir;
		std::string path = dir.file("nowhere.obj");
		REQUIRE_THROWS_WITH(load_obj(path), starts_with_text(path + ": cannot read the file"));
	}
	SECTION("no faces at all") {
		require_obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\n", "no triangles");
	}
	SECTION("only lines and points, no faces") {
		require_obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\np 3\n", "no triangles");
	}
	SECTION("an empty file") {
		require_obj_error("", "no triangles");
	}
}

TEST_CASE("load_obj names the line and the index as written when a face refers to nothing", "[obj][errors]") {
	const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
	const std::string range = "(expected 1 to 3, or -1 to -3 counting back from this line)";
	require_obj_error(triangle + "f 1 2 9\n", "line 4: face index 9 refers to a vertex the file does not define " + range);
	// tinyobjloader resolves -7 to 3 - 7 = -4 and used to be reported as "vertex -3".
	require_obj_error(triangle + "f 1 2 -7\n", "line 4: face index -7 refers to a vertex the file does not define " + range);
	require_obj_error(triangle + "f 0 1 2\n", "line 4: face index 0 refers to a vertex");
	require_obj_error("v 0 0 0\nf 1 -1 -2\nv 1 0 0\nv 0 1 0\n",
	                  "line 2: face index -2 refers to a vertex the file does not define (expected 1 to 3, or -1 to -1 counting");
	require_obj_error(triangle + "vn 0 0 1\nf 1//1 2//1 3//4\n", "line 5: face index 4 refers to a normal");
	require_obj_error(triangle + "f 1/1 2/1 3/1\n", "line 4: face index 1 refers to a texture coordinate the file does "
	                                                 "not define (the file defines no texture coordinates)");
	// A quad with a bad index, which tinyobjloader would drop silently.
	require_obj_error(triangle + "v 1 1 0\nf 1 2 3\nf 1 2 4 7\n", "line 6: face index 7 refers to a vertex");
	require_obj_error(triangle + "f 1 2 x\n", "line 4: face index 'x' is not a whole number");
	require_obj_error(triangle + "f 1 2 3.5\n", "line 4: face index '3.5' is not a whole number");
	require_obj_error(triangle + "f 1 2 3/1/1/1\n", "line 4: '3/1/1/1' is not a face corner");
}

TEST_CASE("load_obj names the line and the value of a coordinate that is not a finite number", "[obj][errors]") {
	const std::string rest = "v 1 0 0\nv 0 1 0\nf 1 2 3\n";
	// tinyobjloader reads "nan" and "x" as 0.
	require_obj_error("v nan 0 0\n" + rest, "line 1: vertex coordinate 'nan' is not a finite number (expected \"v x y z\")");
	require_obj_error("v 0 x 0\n" + rest, "line 1: vertex coordinate 'x' is not a finite number");
	require_obj_error("v 1e999 0 0\n" + rest, "line 1: vertex coordinate '1e999' is not a finite number");
	require_obj_error("v 0 0 4e38\n" + rest, "line 1: vertex coordinate '4e38'"); // beyond a float
	require_obj_error("v 0 0\n" + rest, "line 1: expected three coordinates \"v x y z\", found 2");
	require_obj_error("v 0 0 0\n" + rest + "vn 0 inf 1\n", "line 5: normal coordinate 'inf' is not a finite number");
	// Lines end with \n, \r\n or a lone \r, as tinyobjloader counts them.
	require_obj_error("# a mesh\r\nv 0 0 0\rv 1 0 0\nv 0 -nan 0\n", "line 4: vertex coordinate '-nan'");
}

TEST_CASE("load_obj reads relative (negative) indices, signs and extra vertex values as OBJ defines them", "[obj]") {
	Temp_Dir dir;
	std::vector<Triangle> absolute = load_text(dir, "v 0 0 0 1\nv +1 0 0\nv 0 1.5e0 0\nf 1 2 3\n");
	std::vector<Triangle> relative = load_text(dir, "v 0 0 0 1\nv +1 0 0\nv 0 1.5e0 0\nf -3 -2 -1\n");
	REQUIRE(absolute.size() == 1);
	REQUIRE(relative.size() == 1);
	require_near(relative[0].v1.position, Vec3{1.0f, 0.0f, 0.0f}, "vertex -2 counted back from line 4");
	require_near(relative[0].v2.position, absolute[0].v2.position, "vertex -1 is vertex 3");
}
