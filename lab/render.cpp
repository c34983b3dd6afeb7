// `passlab render`: headless, deterministic. Frames are rendered with a fixed step; the last one
// is at --time. The output image (and every --pass image) is written as PNG for 8-bit formats
// and EXR for float formats, named <preset>[.<image>].<ext> in the output folder. `--sequence`
// also writes the output of every frame (<preset>.00000.png, ...); `--video FILE` encodes those
// frames with ffmpeg (lab/video.hpp) from a scratch folder that is removed afterwards.
#include "verbs.hpp"
#include "sources.hpp"
#include "video.hpp"

#include "exec/build.hpp"
#include "exec/executor.hpp"
#include "image/image.hpp"
#include "vk/context.hpp"
#include "vk/formats.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace fs = std::filesystem;

namespace pl::lab {

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// A float image is written as EXR, anything 8-bit as PNG (unless --format says otherwise).
std::string extension_for(const graph::GraphDesc& desc, const std::string& image, const std::string& forced) {
    if (!forced.empty()) return forced;
    const graph::ImageDesc* d = desc.find_image(image);
    const vk::FormatInfo* fi = d ? vk::find_format(d->format) : nullptr;
    bool hdr = fi && (fi->bytes_per_texel / std::max(1, fi->components)) >= 2 && !fi->is_integer;
    return hdr ? "exr" : "png";
}

// The frames --video encodes, in a scratch folder of their own that never outlives the render.
struct ScratchDir {
    fs::path path;
    ~ScratchDir() {
        std::error_code ec;
        if (!path.empty()) fs::remove_all(path, ec);
    }
};

} // namespace

int render(const RenderOptions& o, const CommonOptions& c) {
    auto t0 = Clock::now();
    auto lp = resolve_and_configure(o.preset, o.size, o.set, c);
    if (!lp) return report(lp.error());
    const auto toml = &lp->toml;
    auto built = exec::build_graph(*toml, lp->options);
    if (!built) return report(built.error());
    double t_build = ms_since(t0);

    // Validate every requested image name before touching the GPU.
    std::vector<std::string> images = {built->desc.output};
    for (const auto& p : o.passes) {
        if (!built->desc.find_image(p)) {
            std::vector<std::string> names;
            for (const auto& i : built->desc.images) names.push_back(i.name);
            Error e = make_error("--pass " + p + ": no image of that name in " + toml->string());
            std::string near = nearest_name(p, names);
            if (!near.empty()) e.hint = "did you mean '" + near + "'?";
            e.code = ExitCode::usage;
            return report(e);
        }
        images.push_back(p);
    }
    if (!o.video.empty()) {
        if (auto s = check_video_target(o.video); !s) return report(s.error());
        if (extension_for(built->desc, built->desc.output, o.format) != "png") {
            Error e = make_error("--video: the output image '" + built->desc.output +
                                 "' is not 8-bit; a video needs the preset's display image (drop --format exr)");
            e.code = ExitCode::usage;
            return report(e);
        }
    }
    std::error_code dir_ec;
    fs::create_directories(o.out_dir, dir_ec);
    if (dir_ec) {
        Error e = make_error("cannot create output folder '" + o.out_dir + "': " + dir_ec.message());
        e.code = ExitCode::environment;
        return report(e);
    }
    ScratchDir scratch;
    if (!o.video.empty()) {
        scratch.path = fs::temp_directory_path(dir_ec) / ("passlab-video-" + std::to_string(getpid()));
        fs::create_directories(scratch.path, dir_ec);
        if (dir_ec) {
            Error e = make_error("--video: cannot create a scratch folder " + scratch.path.string() + ": " + dir_ec.message());
            e.code = ExitCode::environment;
            return report(e);
        }
    }

    auto t1 = Clock::now();
    vk::ContextOptions co;
    co.validation = c.validation;
    co.device = c.device;
    auto ctx = vk::Context::create(co);
    if (!ctx) return report(ctx.error());
    double t_device = ms_since(t1);

    auto t2 = Clock::now();
    const std::string stem = preset_name(built->desc.dir);
    const std::string out_ext = extension_for(built->desc, built->desc.output, o.format);
    auto ex = exec::Executor::create(**ctx, std::move(built.value()));
    if (!ex) return report(ex.error());
    (*ex)->set_timeout(timeout(c));
    double t_setup = ms_since(t2);

    auto t3 = Clock::now();
    for (int f = 0; f < o.frames; ++f) {
        exec::FrameInput in;
        in.index = f;
        in.delta = o.step;
        in.time = o.time - static_cast<double>(o.frames - 1 - f) * o.step;
        if (auto s = (*ex)->render(in); !s) {
            int rc = report(s.error());
            if ((*ctx)->hung()) exit_after_hang(rc);
            return rc;
        }
        for (const fs::path& dir : {o.sequence ? fs::path(o.out_dir) : fs::path(), scratch.path}) {
            if (dir.empty()) continue;
            auto img = (*ex)->read((*ex)->graph().desc.output);
            if (!img) return report(img.error());
            char num[16];
            std::snprintf(num, sizeof num, "%05d", f);
            fs::path file = dir / (stem + "." + num + "." + out_ext);
            if (auto s = image::save_image(*img, file); !s) return report(s.error());
            if (dir == fs::path(o.out_dir)) std::printf("%s\n", file.string().c_str());
        }
    }
    double t_frames = ms_since(t3);
    if (!o.video.empty()) {
        double fps = o.step > 0 ? 1.0 / o.step : 60.0;
        if (auto s = encode_video(scratch.path, stem, fps, o.video); !s) return report(s.error());
        std::printf("%s\n", o.video.c_str());
    }

    auto t4 = Clock::now();
    const auto& g = (*ex)->graph();
    for (size_t k = 0; k < images.size(); ++k) {
        const std::string& name = images[k];
        auto img = (*ex)->read(name);
        if (!img) return report(img.error());
        std::string ext = extension_for(g.desc, name, o.format);
        fs::path file = fs::path(o.out_dir) / (stem + (k == 0 ? "" : "." + name) + "." + ext);
        if (auto s = image::save_image(*img, file); !s) return report(s.error());
        std::printf("%s\n", file.string().c_str());
    }
    double t_write = ms_since(t4);
    std::fprintf(stderr, "render: %dx%d, %d frame(s); build %.1f ms, device %.1f ms, setup %.1f ms, frames %.1f ms, write %.1f ms, total %.1f ms\n",
                 g.view[0], g.view[1], o.frames, t_build, t_device, t_setup, t_frames, t_write, ms_since(t0));
    for (const auto& t : (*ex)->timings()) std::fprintf(stderr, "  pass %-20s %8.3f ms GPU\n", t.name.c_str(), t.gpu_ms);
    // A counter above its buffer's capacity means appends were dropped (or written out of
    // bounds): the render is wrong, so it fails like a validation message.
    bool overflow = false;
    for (const auto& cnt : (*ex)->counters())
        if (cnt.overflow_frame >= 0) {
            std::fprintf(stderr, "render: %s\n", exec::overflow_message(cnt).c_str());
            overflow = true;
        }
    if (overflow) return 1;
    if ((*ctx)->validation_message_count() > 0) {
        std::fprintf(stderr, "render: %zu validation message(s)\n", (*ctx)->validation_message_count());
        return 1;
    }
    return 0;
}

} // namespace pl::lab
