// Is a video file complete? ffmpeg 5.1 exits 0 after "Error writing trailer …: No space left on
// device", leaving an MP4 without its index, so a video is published only after its container has
// been read back: every top-level element accounted for up to the file's end, the index present
// and, for MP4, one sample per frame written.
#pragma once

#include <string>

#include "render/video/video.h"

namespace render::video {

// what is wrong with the video in `path` that should hold `frames` frames, or "" when it is whole
std::string videoDefect(const std::string& path, VideoFormat format, long frames);

}  // namespace render::video
