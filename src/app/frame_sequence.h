// `lensrt render --frames A:B[:STEP] -o out/f.####.exr`: a sequence of frames
// of an animated scene, each rendered as `--frame N` would be, to a file
// named by the output's pattern.
#pragma once

#include <string>

namespace lensrt {

struct FrameRange {
  int first = 0, last = 0, step = 1;
};

// "A:B" or "A:B:STEP" (A <= B, STEP >= 1), frames counted at --fps. Throws
// UsageError("--frames").
FrameRange parseFrames(const std::string& text);

// The output file of frame `frame`: a run of '#' becomes the frame number
// zero-padded to its length (f.####.exr -> f.0012.exr), or a printf-style
// %d / %0Nd does. Throws UsageError("-o") when `pattern` has neither.
std::string frameFileName(const std::string& pattern, int frame);

}  // namespace lensrt
