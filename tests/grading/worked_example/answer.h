Film_Grid_Rays::Answer answer(const Film_Grid_Rays& request) {
	Film_Grid_Rays::Answer rays;
	for (Vec2 film_uv : request.film_uvs) rays.push_back(request.camera.generate_ray(film_uv));
	return rays;
}

