// What the page says of a video or an image, read from the file itself rather than trusted from a
// record: a PNG's size from its header, an MP4's duration and frame size from its movie header
// (`mvhd`) and its video track's header (`tkhd`), as ISO/IEC 14496-12 lays them out. Only what the
// page shows, and only the boxes ffmpeg writes.
#pragma once

#include <optional>
#include <string>

namespace render::page {

struct MediaInfo {
  int width = 0, height = 0;  // pixels
  double duration = 0.0;      // s, 0 for an image
};

// the size of a PNG (its IHDR chunk); none when the file is not a PNG
std::optional<MediaInfo> pngInfo(const std::string& path);
// the duration and frame size of an MP4 (the movie's duration, the first track with a frame size);
// none when the file is not an MP4 with those boxes
std::optional<MediaInfo> mp4Info(const std::string& path);

}  // namespace render::page
