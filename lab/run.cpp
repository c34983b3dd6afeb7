// `passlab run PRESET`: the live lab. A window shows the preset's output with a Dear ImGui
// panel over it (panel.cpp); every file the preset read (TOML, shaders, includes, images) is
// watched, and a change rebuilds the graph. A failed rebuild keeps the last good executor
// rendering and shows the error in an overlay and the terminal; `--events FILE` logs JSON lines
// (reload-started, reload-ok, reload-failed, frame-presented) so tests can follow what happened.
#include "verbs.hpp"
#include "sources.hpp"

#include "events.hpp"
#include "exec/build.hpp"
#include "exec/executor.hpp"
#include "exec/params.hpp"
#include "image/image.hpp"
#include "overlay.hpp"
#include "panel.hpp"
#include "reload/watcher.hpp"
#include "warm_up.hpp"
#include "exec/param_sidecar.hpp"
#include "wall_clock.hpp"
#include "vk/check.hpp"
#include "window.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <future>
#include <map>
#include <optional>

namespace fs = std::filesystem;

namespace pl::lab {

namespace {

// F12. Never overwrite: the first N for which passlab-screenshot-N.png (the graph's output at
// its own size) and passlab-window-N.png (the window as shown: the view, or the image viewer,
// and the panel when it is shown; Tab first for the view alone) are both free.
void screenshot(exec::Executor& ex, Window& window, int& counter) {
    fs::path file, shown;
    do {
        ++counter;
        file = "passlab-screenshot-" + std::to_string(counter) + ".png";
        shown = "passlab-window-" + std::to_string(counter) + ".png";
    } while (fs::exists(file) || fs::exists(shown));
    auto img = ex.read(ex.graph().desc.output);
    if (img && image::save_image(*img, file)) std::fprintf(stderr, "passlab: screenshot %s\n", file.string().c_str());
    else std::fprintf(stderr, "passlab: screenshot failed\n");
    window.capture_next(shown.string());  // written after this frame presents (it says so)
}

// A counter above its buffer's capacity: warned once per episode (frames in a row above it), not
// every frame; keyed by buffer name so a reload does not repeat the warning of an ongoing one.
void warn_counter_overflow(const exec::Executor& ex, std::map<std::string, bool>& overflowing, EventLog& log) {
    for (const auto& c : ex.counters()) {
        bool& was = overflowing[c.buffer];
        if (c.overflow() && !was) {
            std::fprintf(stderr, "passlab: warning: buffer '%s' counted %u > capacity %llu (frame %d)\n", c.buffer.c_str(), c.count,
                         static_cast<unsigned long long>(c.capacity), c.frame);
            log.write("counter-overflow", {{"buffer", c.buffer}, {"count", c.count}, {"capacity", c.capacity}});
        }
        was = c.overflow();
    }
}

// The panel's param edits outlive reloads: re-applied to every new executor where the param
// still exists with the same type; the others are forgotten.
void reapply_touched(LabState& s, exec::Executor& ex) {
    for (auto it = s.touched.begin(); it != s.touched.end();) {
        auto& params = ex.params();
        auto p = std::find_if(params.begin(), params.end(), [&](const graph::ParamDesc& d) { return d.name == it->first; });
        if (p == params.end()) {
            it = s.touched.erase(it);
            continue;
        }
        p->value = it->second;
        ++it;
    }
}

// Saved values from the sidecar become "touched" values; `--set` on the command line wins.
// Returns how many values it applied.
int apply_sidecar(LabState& s, exec::Executor& ex, const fs::path& file, const std::vector<std::string>& cli_sets) {
    auto sets = exec::load_sidecar(file);
    if (!sets) {
        std::fprintf(stderr, "passlab: ignoring %s: %s\n", file.string().c_str(), sets.error().format().c_str());
        return 0;
    }
    if (sets->empty()) return 0;
    int applied = 0;
    for (const auto& a : *sets) {
        std::string name = a.substr(0, a.find('='));
        if (exec::assigns(cli_sets, name)) continue;
        if (auto st = exec::apply_param_override(ex.params(), a); !st) {
            std::fprintf(stderr, "passlab: %s: ignoring '%s': %s\n", file.string().c_str(), a.c_str(), st.error().message.c_str());
            continue;
        }
        for (const auto& p : ex.params())
            if (p.name == name) s.touched[name] = p.value;
        ++applied;
    }
    std::fprintf(stderr, "passlab: %d param value(s) from %s (delete it, or --no-sidecar, for the preset's own)\n", applied,
                 file.string().c_str());
    return applied;
}

// build_graph (parse, include expansion, glslang, reflection: no device) on a worker thread, so
// frames keep coming while a reload compiles.
struct BackgroundBuild {
    std::future<Result<exec::CompiledGraph>> future;
    double t0 = 0;       // when the reload started (EventLog ms)
    bool again = false;  // files changed during the build

    bool busy() const { return future.valid(); }
    void start(const fs::path& toml, const exec::BuildOptions& bo, double t_start) {
        t0 = t_start;
        future = std::async(std::launch::async, [toml, bo] { return exec::build_graph(toml, bo); });
    }
    std::optional<Result<exec::CompiledGraph>> take() {
        if (!future.valid() || future.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
        return future.get();
    }
};

} // namespace

// Flags that would otherwise do nothing, silently: --capture without --frames never captures,
// and --inspect of an image the graph does not have would show the output instead.
static Status check_run_flags(const RunOptions& o, const graph::GraphDesc& d) {
    if (!o.capture.empty() && o.frames <= 0) {
        Error e = make_error("--capture " + o.capture + " needs --frames N: the window is captured after the last of N frames");
        e.code = ExitCode::usage;
        return e;
    }
    if (!o.capture.empty())
        if (auto s = check_output_file(o.capture, "--capture"); !s) return s;
    if (!o.inspect.empty() && !d.find_image(o.inspect)) {
        Error e = make_error("--inspect " + o.inspect + ": the graph has no image '" + o.inspect + "'");
        std::vector<std::string> names;
        for (const auto& i : d.images) names.push_back(i.name);
        suggest(e, o.inspect, names, "images");
        return e;
    }
    return ok_status();
}

int run(const RunOptions& o, const CommonOptions& c) {
    auto lp = resolve_and_configure(o.preset, o.size, o.set, c);
    if (!lp) return report(lp.error());
    const fs::path toml = lp->toml;
    exec::BuildOptions& bo = lp->options;
    EventLog log(o.events);

    // The first build must succeed: there is no last good frame yet.
    auto built = exec::build_graph(toml, bo);
    if (!built) return report(built.error());
    describe_exercise(c, *built);
    if (auto s = check_run_flags(o, built->desc); !s) return report(s.error());
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
    const std::string preset_name = fs::proximate(toml.parent_path()).string();
    const std::string title = "passlab — " + preset_name;
    // The panel docks beside the view: the window is the view plus the panel's strip.
    auto window = Window::create(**ctx, built->view[0] + (o.ui ? static_cast<int>(kPanelWidth) : 0), built->view[1], title, mode);
    if (!window) return report(window.error());
    auto overlay = Overlay::create(**ctx, **window);
    if (!overlay) return report(overlay.error());
    auto viewer = std::make_unique<ViewerTexture>(**ctx);

    reload::DirWatcher watcher;
    exec::PipelineCache pipelines;  // unchanged passes keep their pipeline across reloads
    BackgroundBuild reload;
    // Drivers that compile at first draw are CPU drivers in practice (llvmpipe, SwiftShader);
    // a GPU driver compiles when the pipeline is created, where a warm-up would only repeat it.
    const bool cpu_device = (*ctx)->properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    std::unique_ptr<WarmUpServer> warm_up;
    if (o.warm_up == "on" || (o.warm_up == "auto" && cpu_device)) {
        std::string why;
        warm_up = WarmUpServer::start(co.device, why);
        if (!warm_up) std::fprintf(stderr, "passlab: no warm-up process (%s): a reload compiles in one place\n", why.c_str());
        else warm_up->send(toml, bo);  // it learns the first build's code (and warms the lab's start)
    }
    bool first_new_frame = false;
    std::array<int, 2> pending_size{0, 0};  // a window size waiting to settle
    std::array<int, 2> built_size = built->view;
    auto resize_at = std::chrono::steady_clock::now();
    // An imported source (Shadertoy, ISF) runs from its scratch folder; its own files are watched
    // too, and a change imports it again before the rebuild.
    auto watch_all = [&](std::vector<fs::path> deps) {
        for (const auto& si : scratch_imports()) deps.insert(deps.end(), si.inputs.begin(), si.inputs.end());
        watcher.watch(deps);
    };
    auto reimport_changed = [&](const std::set<fs::path>& changed) {
        for (const auto& si : scratch_imports())
            for (const auto& f : changed)
                if (std::find(si.inputs.begin(), si.inputs.end(), fs::absolute(f)) != si.inputs.end()) {
                    ScratchImport copy = si;
                    if (auto s = reimport(copy); !s) std::fputs(map_scratch_error(s.error()).format().c_str(), stderr);
                    break;
                }
    };
    watch_all(built->dependencies);
    auto ex = exec::Executor::create(**ctx, std::move(built.value()), &pipelines);
    if (!ex) return report(ex.error());
    if (auto s = (*ex)->check_showable((*ex)->graph().desc.output); !s) return report(s.error());
    std::unique_ptr<exec::Executor> current = std::move(ex.value());
    // A runaway shader is cut off after --timeout: the watchdog reports which passes were in the
    // frame. The device cannot be trusted after that (lavapipe cannot cancel a shader), so the
    // lab ends with the message rather than render on a hung queue.
    const auto frame_timeout = timeout(c);
    current->set_timeout(frame_timeout);
    // Shadertoy's iDate and ISF's DATE show the wall clock live (pinned in renders and tests).
    const std::time_t started = std::time(nullptr);
    apply_wall_clock(current->params(), o.set, started);
    std::vector<graph::ParamDesc> base_params = current->params();  // preset.toml + --set: "Reset" returns here

    LabState st;
    st.time = o.time;
    st.show_ui = o.ui;
    // The panel's strip in framebuffer pixels (HiDPI: scaled like the window; larger with the
    // UI's content scale); the view is the rest of the framebuffer.
    auto dock_px = [&] {
        if (!st.show_ui) return 0;
        int ww = 0, wh = 0;
        glfwGetWindowSize((*window)->handle(), &ww, &wh);
        const auto fb = (*window)->framebuffer_size();
        const double fb_per_unit = ww > 0 ? double(fb[0]) / ww : 1.0;
        return static_cast<int>(std::lround(kPanelWidth * (*window)->content_scale() * fb_per_unit));
    };
    auto view_size = [&]() -> std::array<int, 2> {
        const auto fb = (*window)->framebuffer_size();
        return {fb[0] - st.dock_px, fb[1]};
    };
    st.dock_px = dock_px();
    st.show_viewer = !o.inspect.empty();
    st.viewer_image = o.inspect;
    const fs::path sidecar = exec::sidecar_path(toml);
    int from_sidecar = o.sidecar ? apply_sidecar(st, *current, sidecar, o.set) : 0;
    log.write("started", {{"preset", toml.string()}, {"sidecar_values", from_sidecar}});

    // A newly built executor takes over (after a reload, or on a new device): the watchdog, the
    // wall clock, "Reset"'s values, the params set in the panel and the watched files follow it.
    auto install = [&](std::unique_ptr<exec::Executor> next) {
        current = std::move(next);
        current->set_timeout(frame_timeout);
        apply_wall_clock(current->params(), o.set, started);
        base_params = current->params();
        reapply_touched(st, *current);
        watch_all(current->graph().dependencies);
    };
    // A runaway shader (the watchdog fired): lavapipe cannot cancel it and the device may still
    // run it, so nothing is destroyed or waited for; the lab says so, logs a terminal event and
    // ends the process (on a GPU the driver's reset arrives as a device loss instead, below).
    auto end_on_runaway = [&](int rc, const std::string& why) {
        std::fprintf(stderr, "passlab: a shader runs away and this driver cannot cancel it: the lab ends (fix the shader and start it again)\n");
        log.write("ended", {{"reason", "runaway"}, {"message", why}, {"exit_code", rc}});
        exit_after_hang(rc);
    };
    // VK_ERROR_DEVICE_LOST (on a GPU: the driver reset it, usually after a runaway shader):
    // everything on the old device goes, a new device, window and panel are made, and the graph
    // is built again from the files (a reload's rules: the params set in the panel return, the
    // camera and clock go on). Three losses in one session end the lab: something is wrong.
    int losses = 0;
    auto recover_device = [&](const std::string& why) -> Status {
        ++losses;
        std::fprintf(stderr, "passlab: the Vulkan device was lost (%s)%s\n", why.c_str(),
                     losses <= 3 ? ": recreating it and rebuilding the graph" : "");
        log.write("device-lost", {{"message", why}, {"loss", losses}});
        if (losses > 3) return make_error("the Vulkan device was lost " + std::to_string(losses) + " times in this session: giving up");
        int ww = 0, wh = 0;
        glfwGetWindowSize((*window)->handle(), &ww, &wh);
        current.reset();
        pipelines = exec::PipelineCache{};
        viewer.reset();
        overlay->reset();
        window->reset();
        ctx->reset();  // destroying is allowed on a lost device; nothing is waited for
        ctx = vk::Context::create(co);
        if (!ctx) return ctx.error();
        window = Window::create(**ctx, std::max(1, ww), std::max(1, wh), title, mode);
        if (!window) return window.error();
        overlay = Overlay::create(**ctx, **window);
        if (!overlay) return overlay.error();
        viewer = std::make_unique<ViewerTexture>(**ctx);
        bo.size = built_size;
        auto again = exec::build_graph(toml, bo);
        if (!again) return again.error();
        auto next = exec::Executor::create(**ctx, std::move(again.value()), &pipelines);
        if (!next) return next.error();
        install(std::move(next.value()));
        log.write("device-recreated", {{"loss", losses}, {"device", (*ctx)->device_description()}});
        return ok_status();
    };
    // Submits: a Vulkan call that reports the loss throws (vk/check.hpp); the fence waits say so.
    bool lost = false;
    auto on_device = [&](const std::function<Status()>& submit) -> Status {
        try {
            Status r = submit();
            if (!r && (*ctx)->lost()) lost = true;
            return r;
        } catch (const vk::DeviceLost& e) {
            lost = true;
            return make_error(e.what());
        }
    };

    auto last = std::chrono::steady_clock::now();
    graph::OrbitCamera camera = current->graph().desc.view.orbit;
    glm::vec4 mouse(0.0f);
    int frame = 0, screenshots = 0;
    std::map<std::string, bool> overflowing;  // buffers whose counter is above capacity now
    double elapsed = 0;
    std::fprintf(stderr, "passlab: drag to orbit, wheel to zoom (the image viewer: pan, zoom), space pause, -> step, F12 screenshot, Tab panel, F1 keys, Esc quit\n");
    while (!(*window)->should_close()) {
        if ((*ctx)->lost()) {  // seen by a readback (viewer, screenshot) of the last frame
            if (auto r = recover_device("a readback reported it"); !r) return report(r.error());
        }
        (*window)->poll();
        auto now = std::chrono::steady_clock::now();
        double dt = std::chrono::duration<double>(now - last).count();
        last = now;
        elapsed += dt;
        if (o.seconds > 0 && elapsed >= o.seconds) break;
        if (o.frames > 0 && frame >= o.frames) break;
        st.frame_ms.push_back(static_cast<float>(dt * 1000.0));
        if (st.frame_ms.size() > 240) st.frame_ms.pop_front();

        // Input: orbit camera, Shadertoy iMouse (xy while the button is down, zw = click
        // position, negative once released), keys. What the panel is using is not the scene's.
        WindowInput input = (*window)->take_input();
        const bool inspecting = st.show_viewer && viewer->ready();
        if (!(*overlay)->wants_mouse() && inspecting) {
            // The viewer has the mouse: the wheel zooms about the cursor, a drag pans.
            const auto vs = view_size();
            const FitRect r = view_rect(st.viewer_view, viewer->width(), viewer->height(), vs[0], vs[1]);
            if (input.scroll != 0.0)
                zoom_at(st.viewer_view, r, input.scroll, static_cast<float>(input.x - st.dock_px), static_cast<float>(input.y));
            else if (input.drag_dx != 0.0 || input.drag_dy != 0.0)
                pan_by(st.viewer_view, r, static_cast<float>(input.drag_dx), static_cast<float>(input.drag_dy));
        } else if (!(*overlay)->wants_mouse()) {
            camera.yaw -= static_cast<float>(input.drag_dx) * 0.3f;
            camera.pitch = std::clamp(camera.pitch + static_cast<float>(input.drag_dy) * 0.3f, -89.0f, 89.0f);
            camera.distance = std::clamp(camera.distance * static_cast<float>(std::pow(0.9, input.scroll)), 0.01f, 1e4f);
            // Shadertoy's convention (since 2020): w > 0 only on the frame of the click.
            if (input.left) {
                const bool click_frame = mouse.z <= 0.0f || mouse.z != static_cast<float>(input.click_x) ||
                                         std::fabs(mouse.w) != static_cast<float>(input.click_y);
                // In the view's pixels: the docked panel's strip is not part of the view.
                const double x = input.x - st.dock_px, cx = input.click_x - st.dock_px;
                mouse = glm::vec4(x, input.y, cx, click_frame ? input.click_y : -input.click_y);
            }
        }
        if (!input.left) mouse = glm::vec4(mouse.x, mouse.y, -std::fabs(mouse.z), -std::fabs(mouse.w));
        if (!(*overlay)->wants_keyboard()) {
            if (input.pause_toggled) st.paused = !st.paused;
            if (input.step) st.step = true;
            if (input.screenshot) st.screenshot = true;
            if (input.toggle_ui) {
                // The window shrinks or grows by the panel's strip, so the view keeps its size
                // (where the window manager refuses, the view is rebuilt at what is left).
                int ww = 0, wh = 0;
                glfwGetWindowSize((*window)->handle(), &ww, &wh);
                const int strip = static_cast<int>(std::lround(kPanelWidth * (*window)->content_scale()));
                st.show_ui = !st.show_ui;
                glfwSetWindowSize((*window)->handle(), std::max(1, ww + (st.show_ui ? strip : -strip)), wh);
            }
            if (input.toggle_help) st.show_help = !st.show_help;
        }
        double delta = st.paused ? (st.step ? 1.0 / 60.0 : 0.0) : dt * st.speed;
        st.step = false;
        st.time += delta;

        // Resize: once the framebuffer size has settled, rebuild at that size; images sized from
        // the view are recreated (history restarts), the others keep their contents.
        // (Each size is built once: a size that fails to build is not retried every frame.)
        // Tab resizes the window by the panel's strip: until the window follows, the view looks
        // a strip smaller or larger; once it is back at the built size nothing is rebuilt.
        st.dock_px = dock_px();
        if (auto vs = view_size(); vs[0] > 0 && vs[1] > 0) {
            if (vs == built_size) pending_size = {0, 0};
            else if (vs != pending_size) pending_size = vs, resize_at = now + std::chrono::milliseconds(150);
        }
        if (pending_size[0] > 0 && now >= resize_at && !reload.busy()) {
            built_size = pending_size;
            bo.size = pending_size;
            log.write("resize", {{"size", {pending_size[0], pending_size[1]}}});
            reload.start(toml, bo, log.now_ms());
            pending_size = {0, 0};
        }

        // Reload: collect a burst of changes and compile them on a worker thread while the last
        // good graph keeps rendering; swap only when everything built.
        auto changed = watcher.poll(std::chrono::milliseconds(0), std::chrono::milliseconds(15));
        if (!changed.empty()) {
            nlohmann::ordered_json files = nlohmann::ordered_json::array();
            for (const auto& f : changed) files.push_back(fs::proximate(f).string());
            log.write("reload-started", {{"files", files}});
            reimport_changed(changed);
            if (reload.busy()) reload.again = true;  // edited while compiling: compile once more after
            else reload.start(toml, bo, log.now_ms());
        }
        if (warm_up)
            if (auto a = warm_up->poll()) {
                auto done = nlohmann::ordered_json::parse(*a, nullptr, false);
                if (!done.is_discarded()) log.write("warm-up-done", done);
            }
        if (auto next = reload.take()) {
            if (reload.again) {
                // The result is already stale: the files changed while it compiled.
                reload.again = false;
                reload.start(toml, bo, reload.t0);
            } else {
                double t_compiled = log.now_ms();
                // The build compiled: the warm-up process builds it too, from the SPIR-V cache the
                // worker just filled (no second glslang run competing with this one), and starts
                // compiling its half while this thread creates the executor and draws.
                if (warm_up && *next) log.write("warm-up", {{"sent", warm_up->send(toml, bo)}});
                Result<std::unique_ptr<exec::Executor>> next_ex =
                    *next ? exec::Executor::create(**ctx, std::move(next->value()), &pipelines)
                          : Result<std::unique_ptr<exec::Executor>>(next->error());
                if (next_ex)
                    if (auto a = (*next_ex)->check_showable((*next_ex)->graph().desc.output); !a) next_ex = a.error();
                if (next_ex)
                    if (auto a = (*next_ex)->adopt_contents(*current); !a) next_ex = a.error();
                if (!next_ex) {
                    const Error e = map_scratch_error(next_ex.error());  // an import's tab, not its scratch copy
                    std::fputs(e.format().c_str(), stderr);
                    std::fprintf(stderr, "passlab: keeping the last good frame\n");
                    log.write("reload-failed", {{"file", e.loc.file}, {"line", e.loc.line}, {"col", e.loc.col}, {"pass", e.pass}, {"message", e.message}});
                    (*window)->set_title(title + " — ERROR " + e.loc.str() + ": " + e.message);
                    st.error = e;
                    if ((*ctx)->hung()) end_on_runaway(1, e.message);
                } else {
                    // The old executor is retired, not destroyed: it goes once the GPU work
                    // submitted so far has finished (Context::collect after the next frame's fence).
                    (*ctx)->retire(std::move(current));
                    install(std::move(next_ex.value()));

                    std::vector<std::string> all;
                    for (const auto& p : current->graph().passes) all.push_back(p.desc->name);
                    log.write("reload-ok", {{"passes", all},
                                            {"rebuilt", current->rebuilt_passes()},
                                            {"ms", EventLog::tenth(log.now_ms() - reload.t0)},
                                            {"compile_ms", EventLog::tenth(t_compiled - reload.t0)}});
                    std::fprintf(stderr, "passlab: reloaded in %.1f ms (%zu of %zu pipelines rebuilt)\n", log.now_ms() - reload.t0,
                                 current->rebuilt_passes().size(), all.size());
                    if (st.error) (*window)->set_title(title);
                    st.error.reset();
                    first_new_frame = true;
                }
            }
        }

        exec::FrameInput in;
        in.index = frame;
        in.time = st.time;
        in.delta = delta;
        in.camera = camera;
        in.mouse = mouse;
        // The shader's keyboard; the panel's text fields keep theirs.
        if (!(*overlay)->wants_keyboard()) in.keys = input.keys;
        if (auto s = on_device([&] { return current->render(in); }); !s) {
            if (lost) {
                lost = false;
                if (auto r = recover_device(s.error().message); !r) return report(r.error());
                continue;
            }
            int rc = report(s.error());
            if ((*ctx)->hung()) end_on_runaway(rc, s.error().message);
            return rc;
        }
        warn_counter_overflow(*current, overflowing, log);
        if (st.screenshot) screenshot(*current, **window, screenshots);
        st.screenshot = false;
        if (st.show_viewer) {
            if (auto img = current->read(st.viewer_image.empty() ? current->graph().desc.output : st.viewer_image, st.viewer_mip,
                                         st.viewer_layer)) {
                st.viewer_stats = image_stats(*img, st.viewer_mapping.channel);
                if (st.viewer_auto_exposure) st.viewer_mapping.exposure_ev = auto_exposure_ev(st.viewer_stats);
                // Another size (image, level): fit it again; the same size keeps the zoomed
                // region, so two images can be compared texel for texel.
                if (img->width != viewer->width() || img->height != viewer->height()) st.viewer_view.fitted = true;
                viewer->update(*img, st.viewer_mapping);
                st.viewer_pixels = std::move(*img);
            }
        }

        (*overlay)->begin_frame();
        draw_panel(st, *current, viewer.get(), fs::absolute(toml.parent_path()).lexically_normal().string());
        (*overlay)->end_frame();
        if (st.save_sidecar) {
            auto s = exec::save_sidecar(sidecar, current->params(), st.touched);
            st.status = s ? "saved " + std::to_string(st.touched.size()) + " value(s) to " + sidecar.string()
                          : "save failed: " + s.error().message;
            std::fprintf(stderr, "passlab: %s\n", st.status.c_str());
        }
        if (!st.copy_line.empty()) std::fprintf(stderr, "passlab: %s\n", st.copy_line.c_str());
        if (st.reset_params) current->params() = base_params, st.touched.clear();
        if (st.reset_camera) camera = current->graph().desc.view.orbit;
        st.save_sidecar = st.reset_params = st.reset_camera = false;
        st.copy_line.clear();

        const std::string output = current->graph().desc.output;
        if (!o.capture.empty() && o.frames > 0 && frame == o.frames - 1) (*window)->capture_next(o.capture);
        Window::Recorders rec;
        rec.blit = [&](VkCommandBuffer cb, VkImage dst, VkExtent2D ext) {
            const int dock = std::min(st.dock_px, static_cast<int>(ext.width) - 1);
            const VkRect2D view{{dock, 0}, {ext.width - static_cast<uint32_t>(dock), ext.height}};
            if (!st.show_viewer || !viewer->ready()) return current->record_blit_to(cb, output, dst, view);
            viewer->record_blit(cb, dst, view,
                                view_rect(st.viewer_view, viewer->width(), viewer->height(), static_cast<int>(view.extent.width),
                                          static_cast<int>(view.extent.height)));
            return ok_status();
        };
        rec.overlay = [&](VkCommandBuffer cb) { (*overlay)->record(cb); };
        if (auto presented = on_device([&] { return (*window)->present(rec); }); !presented) {
            if (!lost) return report(presented.error());
            lost = false;
            if (auto r = recover_device(presented.error().message); !r) return report(r.error());
            continue;
        }
        nlohmann::ordered_json presented = {{"frame", frame}, {"broken", st.error.has_value()}};
        if (first_new_frame) presented["first_after_reload"] = true;
        log.write("frame-presented", presented);
        first_new_frame = false;
        ++frame;
    }
    const bool capture_failed = (*window)->capture_failed();
    current.reset();
    overlay->reset();
    window->reset();
    glfwTerminate();
    return capture_failed ? static_cast<int>(ExitCode::environment) : 0;
}

} // namespace pl::lab
