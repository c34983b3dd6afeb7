#include "video.hpp"

#include "child.hpp"
#include "verbs.hpp"

#include <cstdio>

namespace fs = std::filesystem;

namespace pl::lab {

namespace {

Error with_code(std::string msg, ExitCode code) {
    Error e = make_error(std::move(msg));
    e.code = code;
    return e;
}

} // namespace

Status check_video_target(const std::string& file) {
    const std::string ext = fs::path(file).extension().string();
    if (ext != ".mp4" && ext != ".gif")
        return with_code("--video " + file + ": the file must end in .mp4 (H.264) or .gif", ExitCode::usage);
    std::error_code ec;
    if (fs::exists(file, ec) || fs::is_symlink(file, ec))
        return with_code("--video " + file + ": the file exists; passlab never overwrites files (choose a new name)",
                         ExitCode::usage);
    if (auto s = check_output_file(file, "--video"); !s) return s;
    if (find_on_path("ffmpeg").empty()) {
        Error e = with_code("--video needs ffmpeg, which is not installed (not found on PATH)", ExitCode::environment);
        e.hint = "scripts/deps.sh --video installs it (apt-get install ffmpeg); --sequence writes the frames as PNGs without it";
        return e;
    }
    return ok_status();
}

Status encode_video(const fs::path& dir, const std::string& stem, double fps, const fs::path& file) {
    char rate[32];
    std::snprintf(rate, sizeof rate, "%.6g", fps);
    std::vector<std::string> args = {"-hide_banner", "-loglevel", "error", "-nostdin", "-n",
                                     "-framerate", rate, "-i", (dir / (stem + ".%05d.png")).string()};
    if (file.extension() == ".gif") {
        // One palette for the whole clip, computed from it (ffmpeg's default palette bands).
        args.insert(args.end(), {"-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse"});
    } else {
        // H.264 in yuv420p, what every player reads; it needs even sizes.
        args.insert(args.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"});
    }
    args.push_back(file.string());
    ChildResult r = run_program("ffmpeg", args, 600.0);
    if (!r.error.empty()) return with_code("--video: " + r.error, ExitCode::environment);
    if (r.timed_out) return with_code("--video: ffmpeg did not finish within 600 s", ExitCode::environment);
    if (r.exit_code != 0) {
        Error e = with_code("--video: ffmpeg failed (exit " + std::to_string(r.exit_code) + ") writing " + file.string(),
                            ExitCode::environment);
        if (!r.output.empty()) e.notes.push_back("ffmpeg: " + r.output.substr(0, 2000));
        return e;
    }
    std::error_code ec;
    if (!fs::is_regular_file(file, ec) || fs::file_size(file, ec) == 0)
        return with_code("--video: ffmpeg reported success but " + file.string() + " is missing or empty",
                         ExitCode::environment);
    return ok_status();
}

} // namespace pl::lab
