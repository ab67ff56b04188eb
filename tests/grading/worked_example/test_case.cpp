
TEST_CASE("generate_ray: every ray of a film grid starts at the camera's position", "[id:t1.ray.grid-origin][fn:generate_ray]") {
	Vec3 position{3.0f, -2.0f, 5.0f};
	Camera camera = Camera::look_at(position, Vec3{0.0f}, Vec3{0.0f, 1.0f, 0.0f}, 50.0f, 1.5f);
	std::vector<Vec2> grid;
	for (int i = 0; i <= 4; i++) {
		for (int j = 0; j <= 4; j++) grid.push_back(Vec2{0.25f * i, 0.25f * j});
	}
	std::vector<Ray> rays = judge::ask(protocol::Film_Grid_Rays{camera, grid});
	for (size_t k = 0; k < grid.size(); k++) {
		INFO("generate_ray(" << grid[k].x << ", " << grid[k].y << ") started at " << show(DVec3(rays[k].point))
		     << ": every ray starts at the camera's position " << show(DVec3(position)) << " (handout §1.2)");
		CHECK(near(DVec3(rays[k].point), DVec3(position), 1e-5));
	}
}
