// The camera options live in the lensrt executable (src/app), which is not a
// library: compile them into this test binary so their derivations are tested.
#include "app/camera_options.cpp"  // NOLINT(bugprone-suspicious-include)
