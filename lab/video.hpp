// `passlab render --video FILE.mp4|.gif`: the rendered frames, written as numbered PNGs into a
// scratch folder, encoded by ffmpeg (a Debian package; `scripts/deps.sh --video` installs it).
// ffmpeg runs without a shell, refuses to overwrite (-n), and its own message is shown if it fails.
#pragma once

#include "util/error.hpp"

#include <filesystem>
#include <string>

namespace pl::lab {

// Checks FILE before any rendering: a known container (.mp4, .gif), not an existing file (never
// overwritten), a writable folder, and ffmpeg on PATH (environment error otherwise).
Status check_video_target(const std::string& file);

// Encodes DIR/<stem>.%05d.png (frames 0..) at `fps` into FILE.
Status encode_video(const std::filesystem::path& dir, const std::string& stem, double fps,
                    const std::filesystem::path& file);

} // namespace pl::lab
