// `lensrt render --frames`: a sequence of frames of one animated scene, each
// written as a single render of it would be. The file is read once
// (api/scene_sequence.h); under MPI whole frames go to the ranks in turn,
// each rendering its frames alone, so every frame is bit for bit the
// render of one process (with --focus auto, one given the first frame's focus).
// Beside each frame's image goes its camera (api/frame_camera.h):
// out/f.0001.exr gets out/f.0001.camera.json.
#pragma once

#include <string>
#include <vector>

#include "run/mpi_job.h"
#include "run/render_to_file.h"

namespace lensrt {

struct SequenceFrame {
  double seconds = 0;  // when the shutter opens
  std::string output;  // the frame's file
};

// Renders `frames` of `job` (whose output and time each frame replaces).
// --focus auto is resolved at the first frame and held for all of them.
// Returns the exit status: 0, or that of the first frame that did not finish.
int renderSequence(const FileRender& job, const std::vector<SequenceFrame>& frames, MpiJob& mpi);

}  // namespace lensrt
