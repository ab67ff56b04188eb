#pragma once
// A renderer started with --stream (film_stream.h), read on a thread of its own: each frame it
// writes is handed to on_frame; when it ends, on_end gets its exit status and what it printed on
// standard error (a crash of the student's code is shown on the page, the viewer goes on).
#include "child_process.h"
#include "film_stream.h"

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

class Render_Process {
public:
	using Frame_Handler = std::function<void(std::shared_ptr<const Film_Frame>)>;
	using End_Handler = std::function<void(int status, const std::string& errors)>;

	// Starts `argv` (a renderer with --stream and its options).
	Render_Process(const std::vector<std::string>& argv, Frame_Handler on_frame, End_Handler on_end);
	~Render_Process(); // stops the renderer and waits for the reader (on_end is not called then)

	void pause() {
		child.pause();
	}
	void resume() {
		child.resume();
	}

private:
	void read_frames();

	Child_Process child;
	Frame_Handler on_frame;
	End_Handler on_end;
	std::string errors;
	std::thread error_reader, frame_reader;
	std::atomic<bool> stopping{false};
};
