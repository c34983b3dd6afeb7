// `passlab run PRESET`: the live lab. A window shows the preset's output; every file the preset
// read (TOML, shaders, includes, images) is watched, and a change rebuilds the graph off the
// frame path. A failed rebuild keeps the last good executor rendering and prints the error;
// `--events FILE` logs JSON lines (reload-started, reload-ok, reload-failed, frame-presented)
// so tests can follow what happened.
#include "verbs.hpp"

#include "exec/build.hpp"
#include "exec/executor.hpp"
#include "image/image.hpp"
#include "scene/camera.hpp"
#include "reload/watcher.hpp"
#include "window.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace fs = std::filesystem;

namespace pl::lab {

namespace {

std::string json_string(const std::string& s) {
    std::string o = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') o += '\\', o += c;
        else if (c == '\n') o += "\\n";
        else if (static_cast<unsigned char>(c) < 0x20) o += ' ';
        else o += c;
    }
    return o + "\"";
}

class EventLog {
  public:
    explicit EventLog(const std::string& file) {
        if (!file.empty()) out_.open(file, std::ios::trunc);
        t0_ = std::chrono::steady_clock::now();
    }
    double now_ms() const { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0_).count(); }
    void write(const std::string& event, const std::string& fields = "") {
        if (!out_) return;
        char t[64];
        // wall_ms (Unix epoch) lets a benchmark relate events to the moment it edited a file.
        auto wall = std::chrono::duration<double, std::milli>(std::chrono::system_clock::now().time_since_epoch()).count();
        std::snprintf(t, sizeof t, "%.1f,\"wall_ms\":%.1f", now_ms(), wall);
        out_ << "{\"event\":\"" << event << "\",\"t_ms\":" << t << (fields.empty() ? "" : "," + fields) << "}\n";
        out_.flush();
    }

  private:
    std::ofstream out_;
    std::chrono::steady_clock::time_point t0_;
};

} // namespace

int run(const RunOptions& o, const CommonOptions& c) {
    auto lp = resolve_and_configure(o.preset, o.size, o.set, c);
    if (!lp) return report(lp.error());
    const auto toml = &lp->toml;
    exec::BuildOptions& bo = lp->options;
    EventLog log(o.events);

    // The first build must succeed: there is no last good frame yet.
    auto built = exec::build_graph(*toml, bo);
    if (!built) return report(built.error());
    auto exts = init_glfw_and_list_extensions();
    if (!exts) return report(exts.error());
    vk::ContextOptions co;
    co.device = c.device;
    co.validation = c.validation;
    co.instance_extensions = *exts;
    co.swapchain = true;
    auto ctx = vk::Context::create(co);
    if (!ctx) return report(ctx.error());
    VkPresentModeKHR mode = o.present == "mailbox" ? VK_PRESENT_MODE_MAILBOX_KHR
                            : o.present == "immediate" ? VK_PRESENT_MODE_IMMEDIATE_KHR
                                                       : VK_PRESENT_MODE_FIFO_KHR;
    std::string title = "passlab — " + fs::proximate(toml->parent_path()).string();
    auto window = Window::create(**ctx, built->view[0], built->view[1], title, mode);
    if (!window) return report(window.error());

    reload::DirWatcher watcher;
    watcher.watch(built->dependencies);
    auto ex = exec::Executor::create(**ctx, std::move(built.value()));
    if (!ex) return report(ex.error());
    std::unique_ptr<exec::Executor> current = std::move(ex.value());
    log.write("started", "\"preset\":" + json_string(toml->string()));

    auto last = std::chrono::steady_clock::now();
    double sim_time = o.time;  // the frame clock: advances unless paused (space), steps with ->
    bool paused = false;
    graph::OrbitCamera camera = current->graph().desc.view.orbit;
    glm::vec4 mouse(0.0f);
    int frame = 0, screenshots = 0;
    bool broken = false;
    double elapsed = 0;
    std::fprintf(stderr, "passlab: drag to orbit, wheel to zoom, space pause, -> step, F12 screenshot, Esc quit\n");
    while (!(*window)->should_close()) {
        (*window)->poll();
        auto now = std::chrono::steady_clock::now();
        double dt = std::chrono::duration<double>(now - last).count();
        last = now;
        elapsed += dt;
        if (o.seconds > 0 && elapsed >= o.seconds) break;

        // Input: orbit camera, Shadertoy iMouse (xy while the button is down, zw = click
        // position, negative once released), time controls, screenshots.
        WindowInput input = (*window)->take_input();
        camera.yaw -= static_cast<float>(input.drag_dx) * 0.3f;
        camera.pitch = std::clamp(camera.pitch + static_cast<float>(input.drag_dy) * 0.3f, -89.0f, 89.0f);
        camera.distance = std::clamp(camera.distance * static_cast<float>(std::pow(0.9, input.scroll)), 0.01f, 1e4f);
        if (input.left) mouse = glm::vec4(input.x, input.y, input.click_x, input.click_y);
        else mouse = glm::vec4(mouse.x, mouse.y, -std::fabs(mouse.z), -std::fabs(mouse.w));
        if (input.pause_toggled) paused = !paused;
        double delta = paused ? (input.step ? 1.0 / 60.0 : 0.0) : dt;
        sim_time += delta;
        if (o.frames > 0 && frame >= o.frames) break;

        // Reload: collect a burst of changes, rebuild, swap only when everything built.
        auto changed = watcher.poll(std::chrono::milliseconds(0), std::chrono::milliseconds(15));
        if (!changed.empty()) {
            std::string files;
            for (const auto& f : changed) files += (files.empty() ? "" : ",") + json_string(fs::proximate(f).string());
            log.write("reload-started", "\"files\":[" + files + "]");
            double t0 = log.now_ms();
            auto next = exec::build_graph(*toml, bo);
            Result<std::unique_ptr<exec::Executor>> next_ex = next ? exec::Executor::create(**ctx, std::move(next.value()))
                                                                   : Result<std::unique_ptr<exec::Executor>>(next.error());
            if (!next_ex) {
                const Error& e = next_ex.error();
                std::fputs(e.format().c_str(), stderr);
                std::fprintf(stderr, "passlab: keeping the last good frame\n");
                log.write("reload-failed", "\"file\":" + json_string(e.loc.file) + ",\"line\":" + std::to_string(e.loc.line) +
                                               ",\"col\":" + std::to_string(e.loc.col) + ",\"pass\":" + json_string(e.pass) +
                                               ",\"message\":" + json_string(e.message));
                (*window)->set_title(title + " — ERROR " + e.loc.str() + ": " + e.message);
                broken = true;
                if ((*ctx)->hung()) exit_after_hang(1);
            } else {
                // The old executor is retired, not destroyed: it goes once the GPU work submitted
                // so far has finished (Context::collect after the next frame's fence).
                (*ctx)->retire(std::move(current));
                current = std::move(next_ex.value());
                watcher.watch(current->graph().dependencies);
                std::string passes;
                for (const auto& p : current->graph().passes) passes += (passes.empty() ? "" : ",") + json_string(p.desc->name);
                char ms[32];
                std::snprintf(ms, sizeof ms, "%.1f", log.now_ms() - t0);
                log.write("reload-ok", "\"passes\":[" + passes + "],\"ms\":" + ms);
                std::fprintf(stderr, "passlab: reloaded in %s ms\n", ms);
                if (broken) (*window)->set_title(title);
                broken = false;
            }
        }

        exec::FrameInput in;
        in.index = frame;
        in.time = sim_time;
        in.delta = delta;
        in.camera = camera;
        in.mouse = mouse;
        if (auto s = current->render(in); !s) {
            int rc = report(s.error());
            if ((*ctx)->hung()) exit_after_hang(rc);
            return rc;
        }
        std::string output = current->graph().desc.output;
        if (input.screenshot) {
            // Never overwrite: the first free passlab-screenshot-N.png in the working folder.
            fs::path file;
            do file = "passlab-screenshot-" + std::to_string(++screenshots) + ".png";
            while (fs::exists(file));
            auto img = current->read(output);
            if (img && image::save_image(*img, file)) std::fprintf(stderr, "passlab: screenshot %s\n", file.string().c_str());
            else std::fprintf(stderr, "passlab: screenshot failed\n");
        }
        auto presented = (*window)->present([&](VkCommandBuffer cb, VkImage dst, VkExtent2D ext) {
            return current->record_blit_to(cb, output, dst, ext);
        });
        if (!presented) return report(presented.error());
        log.write("frame-presented", "\"frame\":" + std::to_string(frame) + ",\"broken\":" + (broken ? "true" : "false"));
        ++frame;
    }
    current.reset();
    window->reset();
    glfwTerminate();
    return 0;
}

} // namespace pl::lab
