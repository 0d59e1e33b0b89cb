// The ffmpeg process: frames in, a video that ffprobe reads as asked (codec, pixel format, size,
// frame count); a missing or failing ffmpeg is an error with its message and leaves no file.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include "render/video/container_check.h"
#include "render/video/video.h"

namespace fs = std::filesystem;
using render::draw::Image;
using render::video::VideoFormat;
using render::video::VideoWriter;

namespace {

fs::path scratchDir() {
  const fs::path d = fs::temp_directory_path() / ("rigidreel_video_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

// what ffprobe says of the first video stream: "codec,width,height,pix_fmt,frames"
std::string probe(const fs::path& video) {
  const std::string command =
      "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
      "stream=codec_name,pix_fmt,width,height,nb_read_frames -of csv=p=0 '" +
      video.string() + "'";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 256> buf;
  while (pipe && fgets(buf.data(), buf.size(), pipe.get())) out += buf.data();
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

// a moving bar, so that the encoder has motion to code
Image frame(int k) {
  Image i(64, 48, {1.0, 1.0, 1.0, 1.0});
  for (int y = 10; y < 38; ++y)
    for (int x = k * 4; x < k * 4 + 8; ++x) i.pixel(x, y)[1] = 0;
  return i;
}

}  // namespace

TEST_CASE("an mp4 is H.264 in yuv420p with every frame, and only the video is left") {
  const fs::path dir = scratchDir();
  const fs::path path = dir / "v.mp4";
  VideoWriter video(path.string(), VideoFormat::Mp4, 64, 48, 10.0);
  CHECK(fs::path(video.temporaryPath()).parent_path() == dir);
  for (int k = 0; k < 12; ++k) video.write(frame(k));
  video.finish();
  CHECK(probe(path) == "h264,64,48,yuv420p,12");
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 1);
  fs::remove_all(dir);
}

TEST_CASE("webm and gif encode too") {
  const fs::path dir = scratchDir();
  for (const auto& [format, name, expected] : {std::tuple{VideoFormat::Webm, "v.webm", "vp9,64,48,yuv420p,5"},
                                               std::tuple{VideoFormat::Gif, "v.gif", "gif,64,48,bgra,5"}}) {
    VideoWriter video((dir / name).string(), format, 64, 48, 10.0);
    for (int k = 0; k < 5; ++k) video.write(frame(k));
    video.finish();
    CHECK(probe(dir / name) == expected);
  }
  fs::remove_all(dir);
}

TEST_CASE("an abandoned video leaves nothing behind") {
  const fs::path dir = scratchDir();
  {
    VideoWriter video((dir / "v.mp4").string(), VideoFormat::Mp4, 64, 48, 10.0);
    video.write(frame(0));
  }
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("a missing ffmpeg says what to install") {
  const fs::path dir = scratchDir();
  CHECK_THROWS_WITH_AS(VideoWriter((dir / "v.mp4").string(), VideoFormat::Mp4, 64, 48, 10.0, "rigidreel-no-such-ffmpeg"),
                       doctest::Contains("apt-get install ffmpeg"), std::runtime_error);
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("a failing ffmpeg is an error quoting what it printed") {
  const fs::path dir = scratchDir();
  const fs::path fake = dir / "fake-ffmpeg";
  std::ofstream(fake) << "#!/bin/sh\necho 'first line' >&2\necho \"Unknown encoder 'libx264'\" >&2\nexit 1\n";
  fs::permissions(fake, fs::perms::owner_all);
  std::string message;
  try {
    VideoWriter video((dir / "v.mp4").string(), VideoFormat::Mp4, 64, 48, 10.0, fake.string());
    for (int k = 0; k < 200; ++k) video.write(frame(k % 12));
    video.finish();
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  CHECK(message.find("Unknown encoder 'libx264'") != std::string::npos);
  CHECK(message.find("status 1") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "v.mp4"));
  fs::remove_all(dir);
}

TEST_CASE("format names and ffmpeg's arguments") {
  CHECK(render::video::videoFormatFromName("webm") == VideoFormat::Webm);
  CHECK_FALSE(render::video::videoFormatFromName("avi"));
  const auto args = render::video::ffmpegArguments(VideoFormat::Mp4, 1280, 720, 60.0, "x.mp4");
  const auto has = [&](const std::string& a, const std::string& b) {
    for (size_t i = 0; i + 1 < args.size(); ++i)
      if (args[i] == a && args[i + 1] == b) return true;
    return false;
  };
  CHECK(has("-video_size", "1280x720"));
  CHECK(has("-framerate", "60"));
  CHECK(has("-pix_fmt", "yuv420p"));
  CHECK(has("-movflags", "+faststart"));
  CHECK(args.back() == "x.mp4");
}

namespace {

// a stand-in for ffmpeg that reads the frames, writes `contents` to its output (its last argument),
// prints `said` and exits 0, as ffmpeg 5.1 does when the disk fills while it writes the trailer
fs::path fakeFfmpeg(const fs::path& dir, const std::string& contents, const std::string& said) {
  const fs::path fake = dir / "fake-ffmpeg";
  std::ofstream(fake) << "#!/bin/sh\nfor a; do out=${a#file:}; done\ncat >/dev/null\nprintf '" << contents
                      << "' > \"$out\"\nprintf '" << said << "' >&2\nexit 0\n";
  fs::permissions(fake, fs::perms::owner_all);
  return fake;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// the message of finishing 3 frames through `program` over a good video at dir/v.mp4 (or "")
std::string finishOverGoodVideo(const fs::path& dir, const std::string& program) {
  try {
    VideoWriter video((dir / "v.mp4").string(), VideoFormat::Mp4, 64, 48, 10.0, program);
    for (int k = 0; k < 3; ++k) video.write(frame(k));
    video.finish();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("ffmpeg's error at exit 0 (a full disk at the trailer) keeps the previous video") {
  const fs::path dir = scratchDir();
  {
    VideoWriter good((dir / "v.mp4").string(), VideoFormat::Mp4, 64, 48, 10.0);
    for (int k = 0; k < 3; ++k) good.write(frame(k));
    good.finish();
  }
  const std::string before = slurp(dir / "v.mp4");
  const std::string message = finishOverGoodVideo(
      dir, fakeFfmpeg(dir, "truncated", "Error writing trailer of v.mp4: No space left on device\\n").string());
  CHECK(message.find("the video is incomplete") != std::string::npos);
  CHECK(message.find("No space left on device") != std::string::npos);
  CHECK(slurp(dir / "v.mp4") == before);
  fs::remove(dir / "fake-ffmpeg");
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 1);
  fs::remove_all(dir);
}

TEST_CASE("a silent ffmpeg that leaves a file without its index or frames does not replace the video") {
  const fs::path dir = scratchDir();
  std::ofstream(dir / "v.mp4") << "good";
  // an ftyp box alone (no moov), an mdat box that claims more than the file has, and a whole MP4
  // with 12 frames where 3 were written
  for (const std::string& contents : {std::string("\\0\\0\\0\\10ftyp"), std::string("\\0\\0\\0\\10ftyp\\0\\0\\1\\0mdat")}) {
    const std::string message = finishOverGoodVideo(dir, fakeFfmpeg(dir, contents, "").string());
    CHECK(message.find("the video is incomplete") != std::string::npos);
    CHECK(slurp(dir / "v.mp4") == "good");
  }
  {
    VideoWriter twelve((dir / "twelve.mp4").string(), VideoFormat::Mp4, 64, 48, 10.0);
    for (int k = 0; k < 12; ++k) twelve.write(frame(k));
    twelve.finish();
  }
  const fs::path copier = dir / "copier";
  std::ofstream(copier) << "#!/bin/sh\nfor a; do out=${a#file:}; done\ncat >/dev/null\ncp '" << (dir / "twelve.mp4").string()
                        << "' \"$out\"\n";
  fs::permissions(copier, fs::perms::owner_all);
  CHECK(finishOverGoodVideo(dir, copier.string()).find("holds 12 frames, not the 3 written") != std::string::npos);
  CHECK(slurp(dir / "v.mp4") == "good");
  fs::remove_all(dir);
}

TEST_CASE("a truncated webm or gif is found") {
  const fs::path dir = scratchDir();
  for (const auto& [format, name] : {std::pair{VideoFormat::Webm, "v.webm"}, std::pair{VideoFormat::Gif, "v.gif"}}) {
    {
      VideoWriter video((dir / name).string(), format, 64, 48, 10.0);
      for (int k = 0; k < 5; ++k) video.write(frame(k));
      video.finish();
    }
    const std::string whole = slurp(dir / name);
    CHECK(render::video::videoDefect((dir / name).string(), format, 5) == "");
    std::ofstream(dir / name, std::ios::binary) << whole.substr(0, whole.size() - 40);
    CHECK(render::video::videoDefect((dir / name).string(), format, 5) != "");
  }
  fs::remove_all(dir);
}
