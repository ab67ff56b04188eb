// Camera::generate_ray(film_uv) of one camera for each film point.
struct Film_Grid_Rays {
	static constexpr Kind KIND{100};
	static constexpr const char* NAME = "film_grid_rays";
	static constexpr const char* FUNCTIONS = "Camera::generate_ray";
	Camera camera;
	std::vector<Vec2> film_uvs;
	template<class A> void fields(A& a) { a(camera, film_uvs); }
	using Answer = std::vector<Ray>;
	bool fits(const Answer& a) const { return a.size() == film_uvs.size(); }
};

