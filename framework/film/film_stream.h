#pragma once
// The film as a stream of frames (film_frame.h), for ./lab view: a renderer started with --stream
// renders progressively and writes a frame to its standard output after each batch of samples;
// the viewer reads them from a pipe.
//
// Layout (native byte order: writer and reader are programs of one build on one machine):
//   "LABF", version (uint32), width, height, samples per pixel so far (uint32 each),
//   seconds of rendering so far (double),
//   then four planes of width x height values, row by row from the top-left: mean RGB and
//   variance RGB (float32 x 3 each), finite samples and non-finite samples (uint32 each).
#include "film_frame.h"

#include <cstdint>
#include <iosfwd>

constexpr uint32_t FILM_STREAM_VERSION = 2;
// The largest frame a reader accepts: Render_Settings::MAX_PIXELS pixels.
constexpr uint64_t FILM_STREAM_MAX_PIXELS = 4096 * 4096;

// Writes the frame and flushes.
void write_frame(std::ostream& out, const Film_Frame& frame);

// Reads the next frame into `frame`: false at the end of the stream (before a frame starts);
// throws Input_Error for a stream that is cut inside a frame or is not a film stream.
bool read_frame(std::istream& in, Film_Frame& frame);
